// What `frictionlab fit` reports for a spacing series: the thick-plate line's fit (mu_k and h_c
// with their errors and correlation, chi^2, each row's residual and the thin formula's mu_k for
// contrast), and, when asked for, its Monte Carlo and its refit through simulations of a rig.
// As JSON (`--json`, fit.json) and as one CSV row per measurement (fit.csv).
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/thick_plate_fit.hpp"
#include "core/thick_plate_fit_monte_carlo.hpp"
#include "io/spacing_series_csv.hpp"
#include "lab/compare/fit_through_rig.hpp"

namespace fl {

struct SpacingFitReport {
  SpacingSeries series;
  double gravity = kDefaultGravity;  // [m/s^2]
  ThickPlateFit fit;
  std::optional<ThickPlateFitMonteCarlo> monte_carlo;
  std::optional<FitThroughRig> rig;
};

// Fits the series (and nothing else: the Monte Carlo and the rig are the caller's to add).
SpacingFitReport fit_spacing_series(SpacingSeries series, double gravity);

// docs/cli.md lists the keys; SI, null where there is none.
nlohmann::json spacing_fit_json(const SpacingFitReport& report);
std::string spacing_fit_csv(const SpacingFitReport& report);

}  // namespace fl
