// The spacing series' fit by Monte Carlo: every row's period drawn from N(T, dT) (and its spacing
// from N(l, dl) where dl is given), the thick-plate line refitted to each drawn series. The
// spread of mu_k and h_c over the refits is their uncertainty without the fit's linearisation
// (mu_k = 2 pi^2 / (g s) is not linear in the slope); their correlation is drawn, not derived.
// Seeded and bit-deterministic (core/normal_draws.hpp); no I/O.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/mu_k_monte_carlo.hpp"
#include "core/sample_summary.hpp"
#include "core/thick_plate_fit.hpp"

namespace fl {

struct ThickPlateFitMonteCarlo {
  int draws = 0;     // asked for
  int accepted = 0;  // refits with a rising line (slope > 0)
  // Drawn series left out and counted: a period or spacing drawn <= 0, or a line whose slope is
  // not positive (no mu_k).
  int skipped = 0;
  std::uint64_t seed = 0;
  std::optional<SampleSummary> mu_k;
  std::optional<SampleSummary> h_c;   // [m]
  std::optional<double> correlation;  // of mu_k and h_c over the accepted refits
  std::vector<double> mu_k_samples;   // the accepted refits, in draw order (when kept)
  std::vector<double> h_c_samples;    // [m]
};

// Refuses what fit_thick_plate refuses, and draws <= 0, with fl::DomainError.
ThickPlateFitMonteCarlo thick_plate_fit_monte_carlo(std::span<const SpacingPeriod> series,
                                                    const ThickPlateFitOptions& options,
                                                    const MonteCarloRequest& request);

}  // namespace fl
