#include "lab/run/law_resolution.hpp"

#include <cmath>

#include <fmt/format.h>

namespace fl {

std::optional<UnresolvedLaw> unresolved_law(const FrictionLaw& law, double gravity,
                                            double time_step, bool stuck,
                                            std::optional<double> growth_rate) {
  if (stuck && law.kind == FrictionLawKind::kStribeck && law.mu_s > law.mu_k) {
    const double per_step = law.mu_s * gravity * time_step;
    if (per_step > law.v_s) {
      const double step = law.v_s / (law.mu_s * gravity);
      return UnresolvedLaw{
          step, fmt::format("the plate stuck to a roller, and at each breakaway its slip speed "
                            "changes by up to mu_s g dt = {:.3g} mm/s in one step, more than the "
                            "Stribeck drop's width v_s = {:.3g} mm/s: the drop from mu_s to mu_k "
                            "is stepped over, not resolved; set world.time_step to {:.3g} ms or "
                            "less",
                            per_step * 1e3, law.v_s * 1e3, step * 1e3)};
    }
  }
  if (growth_rate && std::fabs(*growth_rate) * time_step > kLargestGrowthPerStep) {
    const double step = kLargestGrowthPerStep / std::fabs(*growth_rate);
    return UnresolvedLaw{
        step, fmt::format("the amplitude e-folds at {:.3g} /s, {:.3g} per step of {:.3g} ms (more "
                          "than {}): the law's growth is not resolved; set world.time_step to "
                          "{:.3g} ms or less",
                          *growth_rate, std::fabs(*growth_rate) * time_step, time_step * 1e3,
                          kLargestGrowthPerStep, step * 1e3)};
  }
  return std::nullopt;
}

}  // namespace fl
