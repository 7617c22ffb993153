// The common tangent above two rollers of different radii, checked by geometry: the line through
// the tangent points at the angle tangent_tilt gives is at each circle's radius from its centre,
// and the two points are tangent_spacing apart along it.
#include "core/unequal_radii.hpp"

#include <cmath>
#include <utility>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"

namespace fl {
namespace {

TEST(UnequalRadii, TheTangentTouchesBothCirclesAtTheSpacingItGives) {
  const double l = 0.089;
  for (const auto& [a_0, a_1] : {std::pair{0.010, 0.010}, std::pair{0.010, 0.011},
                                 std::pair{0.015, 0.010}, std::pair{0.005, 0.040}}) {
    const double theta = tangent_tilt(l, a_0, a_1);
    // The line's upward normal, and each circle's tangent point: centre + a n.
    const double nx = -std::sin(theta), nz = std::cos(theta);
    const double p0x = -0.5 * l + a_0 * nx, p0z = a_0 * nz;
    const double p1x = 0.5 * l + a_1 * nx, p1z = a_1 * nz;
    // Both points on one line of that direction: the line through them is perpendicular to n.
    EXPECT_NEAR((p1x - p0x) * nx + (p1z - p0z) * nz, 0.0, 1e-15);
    EXPECT_NEAR(std::hypot(p1x - p0x, p1z - p0z), tangent_spacing(l, a_0, a_1), 1e-15);
  }
}

TEST(UnequalRadii, RollersWithoutACommonTangentAboveAreRefused) {
  EXPECT_THROW(tangent_tilt(0.02, 0.005, 0.030), DomainError);
  EXPECT_THROW(tangent_tilt(0.089, 0.0, 0.01), DomainError);
}

}  // namespace
}  // namespace fl
