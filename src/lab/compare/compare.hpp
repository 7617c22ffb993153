// Simulated against measured: for every row of a measurements file (lab/measured_rows; the paper's
// Table I is one, assets/paper/table1-measured.csv), the rig's scene with the row's own keys, run
// with the mu_k the row reports (or the scene's): simulated T, its residual in units of the row's
// dT, and the thin formula's own bias for the row's h_c; then mu_k refitted through the full
// simulation, by root finding on mu_k (a few runs per row), so that the simulated period equals
// the measured one, with the uncertainty carried from dT and dl through the simulation's own
// sensitivities.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/paper_table.hpp"
#include "core/regime.hpp"
#include "lab/compare/measured_rows.hpp"
#include "lab/run/job_control.hpp"
#include "scene/scene_yaml.hpp"

namespace fl {

struct CompareOptions {
  std::string scene_file;                // the rig's scene
  PaperTableSource paper;                // the paper's table, for scenes that name its materials
  PartCatalogSource parts;               // the LEGO part index, for a scene with LEGO parts
  std::vector<SceneOverride> overrides;  // --set, --duration; applied before each row's own
  int workers = 0;                       // rows in parallel; 0: every core
  bool refit = true;
  double tolerance = 1e-4;  // the refit stops when |T_sim / T_measured - 1| is below this
  // Where the root finding starts: the thick formula's closed form for the scene's h_c (the
  // default: usually within the tolerance already), or the paper's thin formula (a few % off).
  bool start_from_thin_formula = false;
  int max_refit_runs = 8;    // simulations for the root of one row, at most
  double slope_step = 0.02;  // relative step in mu_k for the simulated d ln T / d ln mu_k
  // Each run simulates at least this many measured periods (the rig averaged 10 to 100), or the
  // scene's duration if longer; 0 keeps the scene's duration (--duration).
  int min_periods = 15;
  // Called on the calling thread as rows finish: (rows done, rows).
  std::function<void(std::size_t, std::size_t)> progress;
  // Asked to stop, no row starts another simulation: the rows finished are kept, the others are
  // "interrupted".
  JobControl control;
};

// One simulation of the refit.
struct CompareRun {
  double mu_k = 0.0;
  double spacing = 0.0;          // m
  std::optional<double> period;  // s
  std::optional<Regime> regime;
};

struct CompareRow {
  std::string label;                      // the row's label (Table I: the material's name)
  std::vector<SceneOverride> keys;        // the row's scene keys
  std::string material;                   // the row's plate material
  double temperature = 300.0;             // K
  Measured period_measured;               // T +- dT [s]
  std::optional<Measured> mu_k_reported;  // the mu_k the row reports (Table I: the paper's)
  double mu_k_simulated = 0.0;        // the first run's mu_k: the reported one, else the scene's
  double spacing = 0.0;               // m, the row's rig
  std::optional<double> spacing_err;  // m, the row's dl
  double h_c = 0.0;                   // m, the row's plate
  double gravity = 9.81;
  double duration = 0.0;  // s simulated per run
  // "compared": simulated (and refitted); "no oscillation": the row's mu_k gives no Coulomb
  // oscillation in this rig (reason says why; not fitted); "failed": a run failed (reason);
  // "interrupted": the comparison was asked to stop before the row was done.
  std::string status;
  std::string reason;

  // The rig run with mu_k_simulated.
  std::optional<double> period_simulated;      // s, the rig's estimator
  std::optional<double> period_simulated_std;  // s, standard deviation of its periods
  // "hall estimator", or "trajectory (the estimator accepted no period)" (then no spread); empty
  // without a period.
  std::string period_simulated_source;
  std::optional<Regime> regime;
  std::optional<double> residual_sigma;    // (T_sim - T_measured) / dT
  double period_thin = 0.0;                // s, thin formula at mu_k_simulated
  std::optional<double> period_thick;      // s, thick formula at mu_k_simulated and h_c
  std::optional<double> thin_bias_period;  // T_thin / T_thick - 1 at mu_k_simulated
  std::optional<double> thin_bias_mu_k;    // mu_thin(T_measured) / mu_thick(T_measured) - 1

  // The refit.
  std::optional<double> mu_k_thick_formula;  // closed form from T_measured and h_c (the start)
  std::optional<double> mu_k_refit;
  std::optional<double> mu_k_refit_err_worst;       // |dmu/dT| dT + |dmu/dl| dl
  std::optional<double> mu_k_refit_err_quadrature;  // the same in quadrature
  std::optional<double> period_at_refit;            // s, simulated at mu_k_refit
  std::optional<double> sensitivity_mu;             // d ln T / d ln mu_k, simulated
  std::optional<double> sensitivity_spacing;        // d ln T / d ln l, simulated
  std::string refit_note;                           // why there is no refit, when there is none
  std::vector<CompareRun> runs;                     // every simulation of the row, in order
};

struct CompareResult {
  std::string scene;
  std::string measurements;           // the file the rows came from
  double spacing = 0.0;               // m, the scene's l
  std::optional<double> spacing_err;  // m, the rows' dl when they all give the same
  double h_c = 0.0;                   // m
  double gravity = 9.81;
  double amplitude = 0.0;  // m, the scene's initial amplitude (at the paper's LEGO mu_k)
  double duration = 0.0;   // s, the scene's simulated time
  std::vector<CompareRow> rows;
  int workers = 0;
  double wall_s = 0.0;
  int simulations = 0;

  // The rows that gave no result: not simulated to a period ("no oscillation", ...), or, with a
  // refit asked, compared but not refitted.
  int rows_without_result(bool refit) const;
  // Rows left "interrupted".
  int rows_interrupted() const;
};

// Throws InputError if the scene cannot be read, or a row's keys do not make a rig (located at the
// row's cell), before any simulation.
CompareResult run_compare(const MeasuredRows& measured, const CompareOptions& options);

// The paper's Table I as measurements: assets/paper/table1-measured.csv under the asset folder.
std::string paper_measurements_path(const std::string& asset_dir);

nlohmann::json compare_json(const CompareResult& result);
std::string compare_csv(const CompareResult& result);

}  // namespace fl
