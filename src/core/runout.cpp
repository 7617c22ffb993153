#include "core/runout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/domain_check.hpp"
#include "text/describe.hpp"

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
                            double roller_speed, double phase_sum, double amplitude,
                            double friction_lever) {
  require_domain(roller_speed != 0.0, "the rollers must turn for run-out to shake the plate");
  require_domain(spacing > 0.0 && radius_of_gyration >= 0.0 && gravity > 0.0,
                 describe("the spacing and gravity must be positive and k >= 0, got l = ", spacing,
                          " m, k = ", radius_of_gyration, " m, g = ", gravity, " m/s^2"));
  const double d = 0.5 * spacing - std::fabs(amplitude);
  require_domain(d > 0.0, describe("the centre of mass must lie between the rollers, got ",
                                   amplitude, " m off the middle"));
  const double lever = d - friction_lever;  // d'
  require_domain(lever > 0.0, describe("mu_k h_c = ", friction_lever,
                                       " m must be less than the centre of mass's distance ", d,
                                       " m from the pivot roller"));
  const double a = (radius_of_gyration * radius_of_gyration + lever * d) / spacing;
  const double b = lever - a;
  const double r = std::sqrt(std::max(a * a + b * b - 2.0 * a * b * std::cos(phase_sum), 0.0));
  // The two tops' pushes cancel on this roller's load at every angle: it never hops.
  if (r == 0.0) return std::numeric_limits<double>::infinity();
  return lever * gravity / (roller_speed * roller_speed * r);
}

}  // namespace fl
