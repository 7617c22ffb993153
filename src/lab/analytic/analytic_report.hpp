// The analytic model for one set-up, as `frictionlab analytic` reports it: from a given mu_k, a
// measured period T +- dT, or a material of the paper's Table I (its measured period), the thin
// and thick periods, mu_k +- d mu_k through both formulas, the tipping amplitude and the rollers'
// slip.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/analytic_model.hpp"
#include "core/friction_law.hpp"
#include "core/friction_regime.hpp"
#include "core/mu_k_monte_carlo.hpp"
#include "core/paper_table.hpp"

namespace fl {

struct AnalyticSetUp {
  double spacing = 0.089;      // l [m]
  double spacing_err = 0.002;  // dl [m]
  double h_c = 0.0;            // centre of mass above the contact line [m]
  double h_c_err = 0.0;        // its uncertainty, drawn only by the Monte Carlo [m]
  double gravity = kDefaultGravity;
  double roller_radius = 0.010;  // [m]
  double roller_speed = 0.0;     // [rad/s]
  double amplitude = 0.020;      // A, for the slip margin [m]
  // The friction law beyond mu_k (its mu_k is the report's): coulomb with a static limit mu_s
  // (default mu_k), or stribeck with mu_s, v_s and beta (core/friction_law.hpp).
  FrictionLawKind law = FrictionLawKind::kCoulomb;
  std::optional<double> mu_s;
  std::optional<double> v_s;  // [m/s]
  double beta = 0.0;          // [s/m]
};

// The friction law's closed forms at the rollers' surface speed (docs/friction-laws.md).
struct AnalyticLaw {
  FrictionLaw law;
  double surface_speed = 0.0;                  // v_r [m/s]
  double mu_at_surface_speed = 0.0;            // mu(v_r), the effective mu_k
  double full_slip_roller_speed = 0.0;         // [rad/s], the slip threshold for A with this law
  double break_offset = 0.0;                   // x_b: a stuck plate breaks free there [m]
  std::optional<StickSlipCycle> cycle;         // a law without slip dependence, below threshold
  std::optional<LinearisedMotion> linearised;  // growth rate and period about v_r
  FrictionRegimePrediction prediction;         // where the motion from amplitude A ends up
};

struct AnalyticReport {
  AnalyticSetUp set_up;
  std::string source;  // "given mu_k", "given period" or "the paper's LEGO blocks at 300 K"

  // With a material of Table I: its key, the temperature and what the paper printed for mu_k.
  std::optional<std::string> material;
  double temperature = 0.0;  // [K]
  Measured paper_mu_k;

  // With a period (given, or the paper's for the material): T +- dT [s] and mu_k from it.
  std::optional<double> period_measured;
  double period_measured_err = 0.0;
  MuKUncertainty mu_k_thin;   // thin formula (the paper's)
  MuKUncertainty mu_k_thick;  // thick formula, for h_c

  double mu_k = 0.0;  // given, or the thick formula's from the period
  bool restoring_force = false;
  double period_thin = 0.0;  // [s]
  // Only with a restoring force (l > 2 mu_k h_c).
  std::optional<double> period_thick;                // [s]
  std::optional<double> tipping_amplitude;           // [m]
  std::optional<double> roller_speed_for_full_slip;  // [rad/s] at the amplitude
  std::optional<double> slip_margin;                 // at the roller speed
  // With a restoring force, and a law whose closed forms have a meaning here.
  std::optional<AnalyticLaw> friction_law;
  std::optional<std::string> friction_law_refused;  // why not, when they have none

  // With a period and a Monte Carlo asked for: mu_k through the thick formula from T, l and h_c
  // drawn about their values (core/mu_k_monte_carlo.hpp), beside the worst-case and quadrature
  // rules above.
  std::optional<MuKMonteCarlo> monte_carlo;
};

AnalyticReport analytic_for_mu_k(const AnalyticSetUp& set_up, double mu_k);
AnalyticReport analytic_for_period(const AnalyticSetUp& set_up, double period, double period_err);
AnalyticReport analytic_for_material(const AnalyticSetUp& set_up, const PaperMaterial& material,
                                     const PaperMeasurement& row);

// Adds the Monte Carlo of mu_k to a report with a period (fl::DomainError without one, or for
// draws <= 0).
void add_monte_carlo(AnalyticReport& report, const MonteCarloRequest& request);

// The Monte Carlo's summary as the JSON outputs give it: draws, seed, accepted, skipped and mu_k's
// mean, sd and 2.5 % and 97.5 % quantiles (null without an accepted draw).
nlohmann::json monte_carlo_json(const MuKMonteCarlo& mc);

// What tools/plot_mc.py draws: the accepted draws with their summary and the paper's rules.
nlohmann::json monte_carlo_plot_data(const AnalyticReport& report);

// The report as `frictionlab analytic --json` prints it (docs/cli.md; SI, null where there is
// none).
nlohmann::json analytic_json(const AnalyticReport& report);

}  // namespace fl
