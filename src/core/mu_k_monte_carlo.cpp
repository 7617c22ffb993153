#include "core/mu_k_monte_carlo.hpp"

#include <numbers>

#include "core/domain_check.hpp"
#include "core/normal_draws.hpp"
#include "core/units.hpp"

namespace fl {

MuKMonteCarlo mu_k_monte_carlo(const MuKMeasurement& m, const MonteCarloRequest& request) {
  require_domain(request.draws > 0,
                 describe("a Monte Carlo needs at least one draw, got ", request.draws));
  check_positive(m.period, "the period T", "s");
  check_non_negative(m.period_err, "the period's uncertainty dT", "s");
  check_positive(m.spacing, "the roller spacing l", "m");
  check_non_negative(m.spacing_err, "the spacing's uncertainty dl", "m");
  check_non_negative(m.h_c, "the centre-of-mass height h_c", "m");
  check_non_negative(m.h_c_err, "h_c's uncertainty", "m");
  check_positive(m.gravity, "gravity g", "m/s^2");

  constexpr double kTwoPiSquared = 2.0 * kPi * kPi;
  MuKMonteCarlo out;
  out.draws = request.draws;
  out.seed = request.seed;
  NormalDraws normal(request.seed);
  std::vector<double> samples;
  samples.reserve(static_cast<std::size_t>(request.draws));
  for (int i = 0; i < request.draws; ++i) {
    // Always three draws per trial, in this order, so a quantity held fixed (error 0) leaves
    // the others' draws as they were.
    const double t = normal.next(m.period, m.period_err);
    const double l = normal.next(m.spacing, m.spacing_err);
    const double h = normal.next(m.h_c, m.h_c_err);
    if (!(t > 0.0 && l > 0.0 && h >= 0.0)) {
      ++out.skipped;
      continue;
    }
    samples.push_back(kTwoPiSquared * l / (m.gravity * t * t + 2.0 * kTwoPiSquared * h));
  }
  out.accepted = static_cast<int>(samples.size());
  if (!samples.empty()) out.mu_k = summarise_samples(samples);
  if (request.keep_samples) out.samples = std::move(samples);
  return out;
}

}  // namespace fl
