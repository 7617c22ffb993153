// A spacing series refitted through simulations of a rig, for what the closed form leaves out
// (the integrator's phase error, the rig's contacts and geometry, the estimator's reading). From
// the closed-form fit's mu_k, each row's spacing is simulated at the current mu_k; its measured
// period is corrected by T_closed_form / T_simulated (the closed form for the scene's own plate,
// h_c included), the closed form is fitted again to the corrected periods, and this repeats
// until mu_k changes by less than the tolerance (docs/physics.md).
#pragma once

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/regime.hpp"
#include "core/thick_plate_fit.hpp"
#include "scene/scene.hpp"

namespace fl {

// A row whose simulation gave no period (the plate did not oscillate, a guard stopped the run):
// the rig cannot say what the closed form leaves out there.
class FitThroughRigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct FitThroughRigRequest {
  Scene scene;  // the rig; each run sets rollers.spacing, friction.mu_k and world.gravity
  double gravity = kDefaultGravity;  // [m/s^2], the series' (the scene is simulated at it)
  // Stop when mu_k changes by less than this, relative, or by less than the simulations
  // themselves resolve it (FitThroughRig::resolution).
  double tolerance = 1e-4;
  int max_iterations = 6;  // rounds of simulations (one per row each)
  // Each run simulates at least this many of the row's periods (or the scene's duration if
  // longer), as compare does: enough for the rig's estimator to average over.
  int min_periods = 15;
  int workers = 0;  // rows simulated in parallel; 0: every core
};

struct FitThroughRigRow {
  double period_simulated = 0.0;        // [s] at the row's spacing and the last simulated mu_k
  std::string period_simulated_source;  // "hall estimator" or "trajectory (...)"
  double period_closed_form = 0.0;      // [s] thick formula, same mu_k, the scene's h_c
  double correction = 1.0;              // T_closed_form / T_simulated
  double period_corrected = 0.0;        // [s] the measured period times the correction
};

struct FitThroughRig {
  std::string scene;       // the scene's name
  double h_c_scene = 0.0;  // [m] the scene's plate, what the simulations have
  double gravity = 0.0;
  ThickPlateFit closed_form;           // the series as measured (where the iteration starts)
  ThickPlateFit fit;                   // the corrected series, at the last iteration
  std::vector<FitThroughRigRow> rows;  // in the series' order
  std::vector<double> mu_k_path;       // mu_k at the start and after each iteration
  int iterations = 0;
  // How far mu_k moves, relative, from the simulations' own scatter alone: the fit's error on
  // mu_k when each row's period carries only its simulation's standard error, times sqrt(2) (two
  // rounds' estimates differ). Two rounds closer than this cannot be told apart. 0 when the
  // simulations give no standard error (a period from the trajectory).
  double resolution = 0.0;
  double tolerance = 0.0;  // the request's
  bool converged = false;  // mu_k changed by less than the tolerance or the resolution
  int simulations = 0;
};

// Throws FitThroughRigError when a row's run gives no period, fl::DomainError for a series the fit
// refuses or whose closed-form fit has no mu_k (a falling line), and InputError naming the row
// and the scene's key when the scene cannot be built at a row's spacing.
FitThroughRig fit_through_rig(std::span<const SpacingPeriod> series,
                              const FitThroughRigRequest& request);

}  // namespace fl
