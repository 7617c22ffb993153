#include "core/unequal_radii.hpp"

#include <cmath>

#include "core/analytic_model.hpp"
#include "text/describe.hpp"

namespace fl {

double tangent_tilt(double spacing, double radius_0, double radius_1) {
  if (!(radius_0 > 0.0 && radius_1 > 0.0 && std::fabs(radius_1 - radius_0) < spacing))
    throw DomainError(describe("two rollers of radii ", radius_0 * 1e3, " and ", radius_1 * 1e3,
                               " mm, ", spacing * 1e3, " mm apart, have no common tangent above"));
  return std::asin((radius_1 - radius_0) / spacing);
}

double tangent_spacing(double spacing, double radius_0, double radius_1) {
  return spacing * std::cos(tangent_tilt(spacing, radius_0, radius_1));
}

}  // namespace fl
