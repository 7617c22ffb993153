#include "lab/compare/compare.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "core/analytic_model.hpp"
#include "core/plausible_range.hpp"
#include "io/csv_table.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "io/json_value.hpp"
#include "lab/compare/simulated_period.hpp"
#include "lab/sweep/sweep_pool.hpp"
#include "scene/compiled_rig.hpp"
#include "text/utf8.hpp"

namespace fl {
namespace {

// Thrown by a simulation the comparison was asked not to start (not a std::exception: a row's
// own failures are caught as those).
struct RowInterrupted {};

class RowSimulator {
 public:
  explicit RowSimulator(const CompareOptions& options)
      : options_(options), paper_(shared_once(options.paper)), parts_(shared_once(options.parts)) {}

  // The rig's scene for a row, read once: the scene's keys, then the row's own keys and the run's
  // length, with mu_k set as a number where the row reports one.
  Scene scene(const MeasuredRow& row, double duration) const {
    std::vector<SceneOverride> overrides = options_.overrides;
    overrides.push_back({"world.duration", fmt::format("{} s", duration)});
    overrides.insert(overrides.end(), row.keys.begin(), row.keys.end());
    if (row.mu_k) overrides.push_back({"friction.mu_k", fmt::format("{}", row.mu_k->value)});
    return load_scene_file(options_.scene_file, overrides, paper_, parts_);
  }

  // The rig's estimator's period; the trajectory's (without a spread) where it accepted none,
  // and the row says so.
  SimulatedPeriod simulate(const Scene& scene) {
    if (options_.control.stopping()) throw RowInterrupted{};
    ++simulations_;
    return simulate_period(scene);
  }

  int simulations() const { return simulations_.load(); }
  const PaperTableSource& paper() const { return paper_; }
  const PartCatalogSource& parts() const { return parts_; }

 private:
  const CompareOptions& options_;
  PaperTableSource paper_;
  PartCatalogSource parts_;
  std::atomic<int> simulations_{0};
};

// `mu_k_limit`: the row's rig's l / (2 h_c), above which it has no restoring force.
void refit(RowSimulator& simulator, const Scene& row_scene, std::optional<double> mu_k_limit,
           CompareRow& row, const CompareOptions& options) {
  const double target = row.period_measured.value;
  const double l = row.spacing;
  // Keep every trial below the rig's limit.
  const double mu_ceiling = mu_k_limit ? 0.999 * *mu_k_limit : 1e9;
  const auto run = [&](double mu, std::optional<double> spacing = std::nullopt) {
    CompareRun r;
    r.mu_k = mu;
    r.spacing = spacing.value_or(l);
    const SimulatedPeriod s = simulator.simulate(scene_with_mu_k(row_scene, mu, spacing));
    r.regime = s.regime;
    if (s.oscillates()) r.period = s.period;
    row.runs.push_back(r);
    if (!r.period)
      throw std::runtime_error(fmt::format("at mu_k = {:.5g}: {}", mu, s.no_oscillation_reason()));
    return r;
  };
  const double mu0 = options.start_from_thin_formula
                         ? std::min(mu_k_from_period_thin(target, l, row.gravity), mu_ceiling)
                         : *row.mu_k_thick_formula;
  std::vector<CompareRun> trials{run(mu0)};
  trials.push_back(run(std::min(mu0 * (1.0 + options.slope_step), mu_ceiling)));
  // d ln T / d ln mu from the two runs (about -1/2: T ~ mu^-1/2), then Newton steps in log space
  // from the best trial, refreshing the slope by the secant when two trials are far enough apart.
  double slope = std::log(*trials[1].period / *trials[0].period) / std::log(trials[1].mu_k / mu0);
  if (!(slope < 0.0)) throw std::runtime_error("the simulated period does not fall with mu_k");
  row.sensitivity_mu = slope;
  const auto miss = [target](const CompareRun& r) { return std::fabs(*r.period / target - 1.0); };
  const auto best = [&] {
    return *std::min_element(trials.begin(), trials.end(),
                             [&](const auto& a, const auto& b) { return miss(a) < miss(b); });
  };
  while (miss(best()) > options.tolerance &&
         static_cast<int>(trials.size()) < options.max_refit_runs) {
    const CompareRun from = best();
    const double mu =
        std::min(from.mu_k * std::exp(std::log(target / *from.period) / slope), mu_ceiling);
    const CompareRun next = run(mu);
    if (std::fabs(std::log(next.mu_k / from.mu_k)) > 1e-3) {
      const double secant = std::log(*next.period / *from.period) / std::log(next.mu_k / from.mu_k);
      if (secant < 0.0) slope = secant;
    }
    trials.push_back(next);
  }
  const CompareRun fit = best();
  row.mu_k_refit = fit.mu_k;
  row.period_at_refit = fit.period;
  if (miss(fit) > options.tolerance)
    row.refit_note = fmt::format("not converged: the closest run is {:+.4f} % off after {} runs",
                                 100.0 * (*fit.period / target - 1.0), trials.size());

  // The spacing's sensitivity, from one run at l + dl (2 % of l where the row gives no dl).
  const double spacing_err = row.spacing_err.value_or(0.0);
  const double dl = spacing_err > 0.0 ? spacing_err : 0.02 * l;
  const CompareRun wide = run(fit.mu_k, l + dl);
  const double slope_l = std::log(*wide.period / *fit.period) / std::log((l + dl) / l);
  row.sensitivity_spacing = slope_l;
  // ln mu = (ln T - slope_l ln l) / slope + const: carry dT/T and dl/l through it.
  const double from_period = std::fabs(1.0 / slope) * row.period_measured.uncertainty / target;
  const double from_spacing = std::fabs(slope_l / slope) * spacing_err / l;
  row.mu_k_refit_err_worst = fit.mu_k * (from_period + from_spacing);
  row.mu_k_refit_err_quadrature = fit.mu_k * std::hypot(from_period, from_spacing);
}

// The row's scene and its rig's numbers (spacing, h_c, g, the first run's mu_k, the initial
// amplitude), before any simulation.
struct RowScene {
  Scene scene;
  double amplitude = 0.0;                           // m
  double h_c = 0.0;                                 // m
  double gravity = 0.0;                             // m/s^2
  std::optional<double> mu_k_limit = std::nullopt;  // l / (2 h_c): no restoring force above it
};

CompareRow compare_row(RowSimulator& simulator, CompareRow row, const RowScene& row_setup,
                       const CompareOptions& options) {
  const double l = row.spacing;
  const double h_c = row.h_c;
  const double g = row.gravity;
  const double mu = row.mu_k_simulated;
  const double t_measured = row.period_measured.value;
  const std::string whose = row.mu_k_reported ? "the row's" : "the scene's";
  row.period_thin = period_thin(l, mu, g);
  row.mu_k_thick_formula = mu_k_from_period_thick(t_measured, l, h_c, g);
  row.thin_bias_mu_k = mu_k_from_period_thin(t_measured, l, g) / *row.mu_k_thick_formula - 1.0;
  if (!has_restoring_force(l, mu, h_c)) {
    row.status = "no oscillation";
    row.reason = fmt::format(
        "no restoring force: l = {:.1f} mm <= 2 mu_k h_c = 2 x {} x {:.2f} mm = {:.1f} mm", l * 1e3,
        mu, h_c * 1e3, 2.0 * mu * h_c * 1e3);
    row.refit_note = "not fitted: " + whose + " mu_k gives no Coulomb oscillation";
    return row;
  }
  row.period_thick = period_thick(l, mu, h_c, g);
  row.thin_bias_period = row.period_thin / *row.period_thick - 1.0;

  SimulatedPeriod s;
  try {
    s = simulator.simulate(row_setup.scene);
  } catch (const std::exception& e) {
    row.status = "failed";
    row.reason = plain_fields(e.what());
    return row;
  }
  row.runs.push_back(CompareRun{mu, l, s.period, s.regime});
  row.regime = s.regime;
  if (!s.oscillates()) {
    row.status = "no oscillation";
    const double tipping = tipping_amplitude(l, mu, h_c);
    row.reason = s.no_oscillation_reason();
    if (row_setup.amplitude >= tipping)
      row.reason = fmt::format(
          "the plate tips: its amplitude {:.1f} mm reaches l/2 - mu_k h_c = {:.1f} mm ({})",
          row_setup.amplitude * 1e3, tipping * 1e3, row.reason);
    row.refit_note = "not fitted: " + whose + " mu_k gives no Coulomb oscillation";
    return row;
  }
  row.status = "compared";
  row.period_simulated = s.period;
  row.period_simulated_std = s.period_std;
  row.period_simulated_source = s.source();
  if (row.period_measured.uncertainty > 0.0)
    row.residual_sigma = (*s.period - t_measured) / row.period_measured.uncertainty;
  if (!options.refit) return row;
  try {
    refit(simulator, row_setup.scene, row_setup.mu_k_limit, row, options);
  } catch (const std::exception& e) {
    row.mu_k_refit.reset();
    row.mu_k_refit_err_worst.reset();
    row.mu_k_refit_err_quadrature.reset();
    row.refit_note = "no refit: " + plain_fields(e.what());
  }
  return row;
}

// The row's rig, built (not run) so that a key that makes no rig is refused at its cell before
// any simulation.
RowScene build_row_scene(const RowSimulator& simulator, const MeasuredRow& measured,
                         double duration) {
  try {
    RowScene out{simulator.scene(measured, duration)};
    const CompiledRig compiled = compile_rig(out.scene);
    out.amplitude = compiled.amplitude_initial;
    out.h_c = compiled.plate.h_c;
    out.gravity = compiled.world.gravity;
    out.mu_k_limit = compiled.mu_k_restoring_limit;
    return out;
  } catch (const InputError& e) {
    // An error in one of the row's keys is located at its cell; any other at the row's line.
    SourceLocation where = measured.where;
    for (std::size_t k = 0; k < measured.keys.size(); ++k)
      if (located_at_override(e, measured.keys[k].path)) where = measured.key_cells[k];
    throw InputError(
        where, "row \"" + measured.label + "\": its rig cannot be built: " +
                   (e.where().field == "set" ? without_location(e.what()) : std::string(e.what())));
  } catch (const std::exception& e) {
    throw InputError(measured.where,
                     "row \"" + measured.label + "\": its rig cannot be built: " + e.what());
  }
}

std::string name_or_empty(const std::optional<Regime>& regime) {
  return regime ? regime_name(*regime) : "";
}

}  // namespace

CompareResult run_compare(const MeasuredRows& measured, const CompareOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  RowSimulator simulator(options);
  CompareResult result;
  result.measurements = measured.file;
  // The rig's own numbers, from the scene as the rows will see it (LEGO's mu_k for the amplitude).
  {
    std::vector<SceneOverride> overrides = options.overrides;
    overrides.push_back({"friction.mu_k", "0.29"});
    const Scene base =
        load_scene_file(options.scene_file, overrides, simulator.paper(), simulator.parts());
    result.scene = base.name;
    result.spacing = base.rollers.spacing;
    const CompiledRig compiled = compile_rig(base);
    result.h_c = compiled.plate.h_c;
    result.gravity = compiled.world.gravity;
    result.amplitude = compiled.amplitude_initial;
    result.duration = base.world.duration;
  }
  if (!measured.rows.empty() &&
      std::all_of(measured.rows.begin(), measured.rows.end(), [&](const MeasuredRow& r) {
        return r.spacing_err == measured.rows.front().spacing_err;
      }))
    result.spacing_err = measured.rows.front().spacing_err;

  // Every row's rig built first: a row whose keys make no rig stops the comparison before any run.
  std::vector<CompareRow> rows;
  std::vector<RowScene> row_scenes;
  for (const MeasuredRow& m : measured.rows) {
    CompareRow row;
    row.label = m.label;
    row.keys = m.keys;
    row.period_measured = m.period;
    row.mu_k_reported = m.mu_k;
    row.spacing_err = m.spacing_err;
    row.duration = std::max(result.duration, options.min_periods * m.period.value);
    RowScene row_setup = build_row_scene(simulator, m, row.duration);
    // The period at the row's own rig: mu_k from it within a rig's range, before any run.
    const double mu_k_thin =
        mu_k_from_period_thin(m.period.value, row_setup.scene.rollers.spacing, row_setup.gravity);
    if (const std::optional<std::string> why = implausible(mu_k_thin, kMuKRange))
      throw InputError(m.period_cell,
                       fmt::format("row \"{}\": T = {:g} s at l = {:g} mm and g = {:g} m/s^2 "
                                   "gives a mu_k no rig has, so it is no rig's period at this "
                                   "spacing: {}; check the period and its unit, and the row's "
                                   "spacing",
                                   m.label, m.period.value, row_setup.scene.rollers.spacing * 1e3,
                                   row_setup.gravity, *why));
    row.material = row_setup.scene.plate.material;
    row.temperature = row_setup.scene.friction.temperature;
    row.mu_k_simulated = row_setup.scene.friction.mu_k;
    row.spacing = row_setup.scene.rollers.spacing;
    row.h_c = row_setup.h_c;
    row.gravity = row_setup.gravity;
    rows.push_back(std::move(row));
    row_scenes.push_back(std::move(row_setup));
  }

  result.workers = options.workers > 0 ? options.workers : hardware_workers();
  result.rows.resize(rows.size());
  {
    WorkPool<std::pair<std::size_t, CompareRow>> pool(
        std::max(1, std::min<int>(result.workers, static_cast<int>(rows.size()))),
        [&](std::size_t i) {
          try {
            return std::make_pair(i, compare_row(simulator, rows[i], row_scenes[i], options));
          } catch (const RowInterrupted&) {
            CompareRow row = rows[i];
            row.status = "interrupted";
            row.reason = "the comparison was stopped (Ctrl-C or SIGTERM) before this row was done";
            row.refit_note = "not fitted: interrupted";
            return std::make_pair(i, std::move(row));
          }
        });
    for (std::size_t i = 0; i < rows.size(); ++i) pool.push(i);
    pool.close();
    std::size_t done = 0;
    while (!pool.finished()) {
      options.control.poll_stopping();
      for (auto& [i, row] : pool.take(std::chrono::milliseconds(250))) {
        result.rows[i] = std::move(row);
        ++done;
        if (options.progress) options.progress(done, rows.size());
      }
    }
  }
  result.simulations = simulator.simulations();
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::string paper_measurements_path(const std::string& asset_dir) {
  return asset_dir + "/paper/table1-measured.csv";
}

nlohmann::json compare_json(const CompareResult& r) {
  nlohmann::json rows = nlohmann::json::array();
  for (const CompareRow& row : r.rows) {
    nlohmann::json runs = nlohmann::json::array();
    for (const CompareRun& run : row.runs)
      runs.push_back({{"mu_k", run.mu_k},
                      {"spacing_m", run.spacing},
                      {"period_s", json_or_null(run.period)},
                      {"regime", name_or_empty(run.regime)}});
    nlohmann::json keys = nlohmann::json::object();
    for (const SceneOverride& k : row.keys) keys[k.path] = k.value;
    rows.push_back({{"label", escape_invalid_utf8(row.label)},
                    {"keys", keys},
                    {"material", row.material},
                    {"temperature_k", row.temperature},
                    {"spacing_m", row.spacing},
                    {"spacing_err_m", json_or_null(row.spacing_err)},
                    {"h_c_m", row.h_c},
                    {"duration_s", row.duration},
                    {"status", row.status},
                    {"reason", row.reason},
                    {"period_measured_s", row.period_measured.value},
                    {"period_measured_err_s", row.period_measured.uncertainty},
                    {"period_simulated_s", json_or_null(row.period_simulated)},
                    {"period_simulated_std_s", json_or_null(row.period_simulated_std)},
                    {"period_simulated_source", row.period_simulated_source},
                    {"regime", name_or_empty(row.regime)},
                    {"residual_sigma", json_or_null(row.residual_sigma)},
                    {"period_thin_s", row.period_thin},
                    {"period_thick_s", json_or_null(row.period_thick)},
                    {"thin_bias_period", json_or_null(row.thin_bias_period)},
                    {"thin_bias_mu_k", json_or_null(row.thin_bias_mu_k)},
                    {"mu_k_reported", row.mu_k_reported ? nlohmann::json(row.mu_k_reported->value)
                                                        : nlohmann::json(nullptr)},
                    {"mu_k_reported_err", row.mu_k_reported && row.mu_k_reported->uncertainty > 0
                                              ? nlohmann::json(row.mu_k_reported->uncertainty)
                                              : nlohmann::json(nullptr)},
                    {"mu_k_simulated", row.mu_k_simulated},
                    {"mu_k_thick_formula", json_or_null(row.mu_k_thick_formula)},
                    {"mu_k_refit", json_or_null(row.mu_k_refit)},
                    {"mu_k_refit_err_worst", json_or_null(row.mu_k_refit_err_worst)},
                    {"mu_k_refit_err_quadrature", json_or_null(row.mu_k_refit_err_quadrature)},
                    {"period_at_refit_s", json_or_null(row.period_at_refit)},
                    {"refit_error",
                     row.period_at_refit
                         ? nlohmann::json(*row.period_at_refit / row.period_measured.value - 1.0)
                         : nlohmann::json(nullptr)},
                    {"sensitivity_mu_k", json_or_null(row.sensitivity_mu)},
                    {"sensitivity_spacing", json_or_null(row.sensitivity_spacing)},
                    {"refit_note", row.refit_note},
                    {"runs", runs}});
  }
  return nlohmann::json{{"scene", escape_invalid_utf8(r.scene)},
                        {"measurements", escape_invalid_utf8(r.measurements)},
                        {"spacing_m", r.spacing},
                        {"spacing_err_m", json_or_null(r.spacing_err)},
                        {"h_c_m", r.h_c},
                        {"gravity_m_s2", r.gravity},
                        {"amplitude_m", r.amplitude},
                        {"simulations", r.simulations},
                        {"rows", rows},
                        {"timing", {{"wall_s", r.wall_s}, {"workers", r.workers}}}};
}

std::string compare_csv(const CompareResult& r) {
  static const char* const kColumns[] = {"label",
                                         "material",
                                         "temperature_k",
                                         "spacing_m",
                                         "status",
                                         "period_measured_s",
                                         "period_measured_err_s",
                                         "period_simulated_s",
                                         "period_simulated_std_s",
                                         "period_simulated_source",
                                         "residual_sigma",
                                         "period_thin_s",
                                         "period_thick_s",
                                         "thin_bias_period",
                                         "thin_bias_mu_k",
                                         "mu_k_reported",
                                         "mu_k_reported_err",
                                         "mu_k_simulated",
                                         "mu_k_thick_formula",
                                         "mu_k_refit",
                                         "mu_k_refit_err_worst",
                                         "mu_k_refit_err_quadrature",
                                         "period_at_refit_s",
                                         "refit_error",
                                         "regime",
                                         "reason"};
  const nlohmann::json j = compare_json(r);
  std::string csv;
  for (const char* c : kColumns) csv += std::string(csv.empty() ? "" : ",") + c;
  csv += "\n";
  for (const nlohmann::json& row : j["rows"]) {
    std::string line;
    for (const char* c : kColumns) {
      const nlohmann::json& v = row[c];
      std::string cell;
      if (v.is_number_float())
        cell = fmt::format("{}", v.get<double>());
      else if (v.is_number())
        cell = v.dump();
      else if (v.is_string())
        cell = v.get<std::string>();
      line += (line.empty() && c == kColumns[0] ? "" : ",") + csv_cell(cell);
    }
    csv += line + "\n";
  }
  return csv;
}

int CompareResult::rows_without_result(bool refit) const {
  int n = 0;
  for (const CompareRow& row : rows)
    if (row.status != "compared" || (refit && !row.mu_k_refit)) ++n;
  return n;
}

int CompareResult::rows_interrupted() const {
  return static_cast<int>(std::count_if(
      rows.begin(), rows.end(), [](const CompareRow& row) { return row.status == "interrupted"; }));
}

}  // namespace fl
