// mu_k's uncertainty by Monte Carlo: the period, the spacing and h_c drawn from Gaussians about
// their measured values, each draw carried through the thick-plate formula
// mu_k = 2 pi^2 l / (g T^2 + 4 pi^2 h_c). Beside the paper's worst-case and quadrature rules it
// shows what linearising leaves out (skewness, a 95 % interval that is not mean +- 2 sd).
// Seeded and bit-deterministic (core/normal_draws.hpp); no I/O.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/analytic_model.hpp"
#include "core/sample_summary.hpp"

namespace fl {

// What was measured, SI; an uncertainty of 0 holds that quantity fixed.
struct MuKMeasurement {
  double period = 0.0;       // T [s], > 0
  double period_err = 0.0;   // dT [s], one standard deviation, >= 0
  double spacing = 0.0;      // l [m], > 0
  double spacing_err = 0.0;  // dl [m], >= 0
  double h_c = 0.0;          // centre of mass above the contact line [m], >= 0
  double h_c_err = 0.0;      // dh_c [m], >= 0
  double gravity = kDefaultGravity;
};

// The most draws a request may ask for: each accepted draw is kept for the histogram (8 bytes a
// quantity).
inline constexpr int kMaxMonteCarloDraws = 10'000'000;

struct MonteCarloRequest {
  int draws = 0;             // > 0
  std::uint64_t seed = 1;    // the same seed gives the same bits
  bool keep_samples = true;  // the accepted draws of mu_k, in draw order, for a histogram
};

struct MuKMonteCarlo {
  int draws = 0;     // asked for
  int accepted = 0;  // carried through the formula
  // Draws outside the formula's domain (T <= 0, l <= 0 or h_c < 0), left out and counted: a
  // count well above 0 says the Gaussian model of the errors is itself in doubt.
  int skipped = 0;
  std::uint64_t seed = 0;
  std::optional<SampleSummary> mu_k;  // absent when no draw was accepted
  std::vector<double> samples;        // accepted mu_k draws (when kept)
};

// Refuses a measurement outside the formula's domain, or draws <= 0, with fl::DomainError.
MuKMonteCarlo mu_k_monte_carlo(const MuKMeasurement& measured, const MonteCarloRequest& request);

}  // namespace fl
