#include "core/thick_plate_fit_monte_carlo.hpp"

#include "core/domain_check.hpp"
#include "core/normal_draws.hpp"

namespace fl {

ThickPlateFitMonteCarlo thick_plate_fit_monte_carlo(std::span<const SpacingPeriod> series,
                                                    const ThickPlateFitOptions& options,
                                                    const MonteCarloRequest& request) {
  require_domain(request.draws > 0,
                 describe("a Monte Carlo needs at least one draw, got ", request.draws));
  fit_thick_plate(series, options);  // the measured series must itself be one the fit accepts

  ThickPlateFitMonteCarlo out;
  out.draws = request.draws;
  out.seed = request.seed;
  NormalDraws normal(request.seed);
  std::vector<SpacingPeriod> drawn(series.begin(), series.end());
  std::vector<double> mu_k;
  std::vector<double> h_c;
  mu_k.reserve(static_cast<std::size_t>(request.draws));
  h_c.reserve(static_cast<std::size_t>(request.draws));
  for (int i = 0; i < request.draws; ++i) {
    bool usable = true;
    for (std::size_t r = 0; r < series.size(); ++r) {
      // Two draws per row always, so a row without dl leaves the other rows' draws as they were.
      drawn[r].period = normal.next(series[r].period, series[r].period_err);
      drawn[r].spacing = normal.next(series[r].spacing, series[r].spacing_err.value_or(0.0));
      usable = usable && drawn[r].period > 0.0 && drawn[r].spacing > 0.0;
    }
    if (!usable) {
      ++out.skipped;
      continue;
    }
    // Spacings drawn with errors are distinct with probability 1; a drawn series the fit still
    // refuses is skipped like any other outside its domain.
    std::optional<ThickPlateFit> fit;
    try {
      fit = fit_thick_plate(drawn, options);
    } catch (const DomainError&) {
    }
    if (!fit || !fit->mu_k) {
      ++out.skipped;
      continue;
    }
    mu_k.push_back(*fit->mu_k);
    h_c.push_back(*fit->h_c);
  }
  out.accepted = static_cast<int>(mu_k.size());
  if (!mu_k.empty()) {
    out.mu_k = summarise_samples(mu_k);
    out.h_c = summarise_samples(h_c);
    out.correlation = sample_correlation(mu_k, h_c);
  }
  if (request.keep_samples) {
    out.mu_k_samples = std::move(mu_k);
    out.h_c_samples = std::move(h_c);
  }
  return out;
}

}  // namespace fl
