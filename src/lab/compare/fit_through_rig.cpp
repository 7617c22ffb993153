#include "lab/compare/fit_through_rig.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "core/analytic_model.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "lab/compare/simulated_period.hpp"
#include "lab/sweep/sweep_pool.hpp"

namespace fl {
namespace {

// Every row of the series simulated at mu_k, in parallel; each run is a fresh world, so the
// result does not depend on the order the workers take them in.
std::vector<SimulatedPeriod> simulate_rows(std::span<const SpacingPeriod> series, double mu_k,
                                           const FitThroughRigRequest& request) {
  std::vector<Scene> scenes;
  for (const SpacingPeriod& row : series) {
    Scene scene;
    try {
      scene = scene_with_mu_k(request.scene, mu_k, row.spacing);
    } catch (const std::runtime_error& e) {
      throw InputError(SourceLocation::of_field("through_rig"),
                       fmt::format("row {} (l = {:.1f} mm): the scene {} cannot be built at this "
                                   "spacing ({}); simulate another scene ({}), or fit without {}",
                                   scenes.size() + 1, row.spacing * 1e3, request.scene.name,
                                   e.what(), field_ref("scene"), field_ref("through_rig")));
    }
    scene.world.gravity = request.gravity;
    scene.world.duration = std::max(request.scene.world.duration, request.min_periods * row.period);
    scenes.push_back(std::move(scene));
  }
  std::vector<SimulatedPeriod> out(series.size());
  const int workers = request.workers > 0 ? request.workers : hardware_workers();
  WorkPool<std::pair<std::size_t, SimulatedPeriod>> pool(
      std::min<int>(workers, static_cast<int>(series.size())),
      [&](std::size_t i) { return std::make_pair(i, simulate_period(scenes[i])); });
  for (std::size_t i = 0; i < series.size(); ++i) pool.push(i);
  pool.close();
  while (!pool.finished())
    for (auto& [i, s] : pool.take(std::chrono::milliseconds(250))) out[i] = std::move(s);
  for (std::size_t i = 0; i < series.size(); ++i) {
    if (!out[i].oscillates())
      throw FitThroughRigError(fmt::format(
          "row {} (l = {:.1f} mm): the scene simulated at mu_k = {:.5g} gives no period: {}", i + 1,
          series[i].spacing * 1e3, mu_k, out[i].no_oscillation_reason()));
  }
  return out;
}

// FitThroughRig::resolution: the corrected series fitted again with each row's period error the
// part its simulation's standard error brings (the correction's relative error, sigma_sim / T_sim).
double simulations_resolution(std::span<const SpacingPeriod> corrected,
                              std::span<const SimulatedPeriod> simulated,
                              const ThickPlateFitOptions& options) {
  std::vector<SpacingPeriod> scatter(corrected.begin(), corrected.end());
  for (std::size_t i = 0; i < scatter.size(); ++i) {
    if (!simulated[i].period_std_error || !(*simulated[i].period_std_error > 0.0)) return 0.0;
    scatter[i].period_err =
        scatter[i].period * *simulated[i].period_std_error / *simulated[i].period;
    scatter[i].spacing_err.reset();
  }
  const ThickPlateFit fit = fit_thick_plate(scatter, options);
  if (!fit.mu_k || !fit.mu_k_err) return 0.0;
  return std::sqrt(2.0) * *fit.mu_k_err / *fit.mu_k;
}

}  // namespace

FitThroughRig fit_through_rig(std::span<const SpacingPeriod> series,
                              const FitThroughRigRequest& request) {
  FitThroughRig out;
  out.scene = request.scene.name;
  out.h_c_scene = plate_mass(request.scene).h_c;
  out.gravity = request.gravity;
  out.tolerance = request.tolerance;
  const ThickPlateFitOptions options{.gravity = request.gravity};
  out.closed_form = fit_thick_plate(series, options);
  if (!out.closed_form.mu_k)
    throw DomainError(fmt::format(
        "the closed-form fit has no mu_k (T^2 falls as l grows: slope {:.4g} s^2/m), so there is "
        "no mu_k to simulate the rig at",
        out.closed_form.slope));
  double mu_k = *out.closed_form.mu_k;
  out.mu_k_path.push_back(mu_k);
  out.fit = out.closed_form;
  std::vector<SpacingPeriod> corrected(series.begin(), series.end());
  out.rows.resize(series.size());
  while (out.iterations < request.max_iterations) {
    const std::vector<SimulatedPeriod> simulated = simulate_rows(series, mu_k, request);
    out.simulations += static_cast<int>(series.size());
    ++out.iterations;
    for (std::size_t i = 0; i < series.size(); ++i) {
      FitThroughRigRow& row = out.rows[i];
      row.period_simulated = *simulated[i].period;
      row.period_simulated_source = simulated[i].source();
      // The closed form for the very plate simulated: what the simulation adds to it is the
      // correction, whatever h_c the series itself fits.
      row.period_closed_form =
          period_thick(series[i].spacing, mu_k, out.h_c_scene, request.gravity);
      row.correction = row.period_closed_form / row.period_simulated;
      row.period_corrected = series[i].period * row.correction;
      corrected[i].period = row.period_corrected;
      corrected[i].period_err = series[i].period_err * row.correction;
    }
    out.fit = fit_thick_plate(corrected, options);
    if (!out.fit.mu_k)
      throw DomainError("the corrected series' fit has no mu_k (its line falls as l grows)");
    out.resolution = simulations_resolution(corrected, simulated, options);
    const double next = *out.fit.mu_k;
    out.mu_k_path.push_back(next);
    const bool settled = std::fabs(next / mu_k - 1.0) < std::max(request.tolerance, out.resolution);
    mu_k = next;
    if (settled) {
      out.converged = true;
      break;
    }
  }
  return out;
}

}  // namespace fl
