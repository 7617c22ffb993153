#include "core/roller_warming.hpp"

#include <algorithm>
#include <cmath>

#include "core/domain_check.hpp"
#include "text/describe.hpp"

namespace fl {

RollerWarming::RollerWarming(double start_temperature, double room_temperature,
                             double time_constant, double hold, double mu_k_start, double mu_k_room)
    : start_(start_temperature),
      room_(room_temperature),
      tau_(time_constant),
      hold_(hold),
      mu_start_(mu_k_start),
      mu_room_(mu_k_room) {
  require_domain(std::isfinite(start_) && std::isfinite(room_) && start_ > 0.0 && start_ < room_,
                 describe("the rollers must start colder than the room, both above 0 K: got ",
                          start_, " K and ", room_, " K"));
  require_domain(std::isfinite(tau_) && tau_ > 0.0,
                 describe("the warming time constant must be > 0, got ", tau_, " s"));
  require_domain(std::isfinite(hold_) && hold_ >= 0.0,
                 describe("the cold hold must be >= 0, got ", hold_, " s"));
  require_domain(
      std::isfinite(mu_start_) && std::isfinite(mu_room_) && mu_start_ > 0.0 && mu_room_ > 0.0,
      describe("mu_k must be > 0 at both ends, got ", mu_start_, " and ", mu_room_));
}

double RollerWarming::temperature(double t) const {
  if (t <= hold_) return start_;
  return room_ - (room_ - start_) * std::exp(-(t - hold_) / tau_);
}

double RollerWarming::mu_k_at_temperature(double temperature) const {
  const double s = std::clamp((temperature - start_) / (room_ - start_), 0.0, 1.0);
  return mu_start_ + s * (mu_room_ - mu_start_);
}

}  // namespace fl
