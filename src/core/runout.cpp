#include "core/runout.hpp"

#include <cmath>

#include "core/describe.hpp"
#include "core/domain_check.hpp"

namespace fl {

double runout_free_fall_acceleration(double spacing, double radius_of_gyration, double gravity,
                                     double offset) {
  require_domain(spacing > 0.0 && radius_of_gyration >= 0.0 && gravity > 0.0,
                 describe("the spacing and gravity must be positive and k >= 0, got l = ", spacing,
                          " m, k = ", radius_of_gyration, " m, g = ", gravity, " m/s^2"));
  const double d = 0.5 * spacing - std::fabs(offset);
  require_domain(d > 0.0, describe("the centre of mass must lie between the rollers, got ", offset,
                                   " m off the middle"));
  return gravity * d * spacing / (radius_of_gyration * radius_of_gyration + d * d);
}

double runout_hop_threshold(double spacing, double radius_of_gyration, double gravity,
                            double roller_speed, double amplitude) {
  require_domain(roller_speed != 0.0, "the rollers must turn for run-out to shake the plate");
  return runout_free_fall_acceleration(spacing, radius_of_gyration, gravity, amplitude) /
         (roller_speed * roller_speed);
}

}  // namespace fl
