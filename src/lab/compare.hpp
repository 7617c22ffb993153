// Simulated against measured: for every row of the paper's Table I, the rig's scene run with the
// paper's mu_k (simulated T, its residual in units of the paper's dT, and the thin formula's own
// bias for the scene's h_c); then mu_k refitted through the full simulation, by root finding on
// mu_k (a few runs per material), so that the simulated period equals the measured one, with the
// uncertainty carried from dT and dl through the simulation's own sensitivities.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/paper_table.hpp"
#include "core/regime.hpp"
#include "scene/scene_yaml.hpp"

namespace fl {

struct CompareOptions {
  std::string scene_file;                // the rig's scene
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
};

// One simulation of the refit.
struct CompareRun {
  double mu_k = 0.0;
  double spacing = 0.0;          // m
  std::optional<double> period;  // s
  std::optional<Regime> regime;
};

struct CompareRow {
  std::string material;  // Table I key
  std::string name;
  double temperature = 300.0;  // K
  Measured period_measured;    // T +- dT [s]
  Measured mu_k_paper;
  double duration = 0.0;  // s simulated per run
  // "compared": simulated (and refitted); "no oscillation": the paper's numbers give no Coulomb
  // oscillation in this rig (reason says why; not fitted); "failed": a run failed (reason).
  std::string status;
  std::string reason;

  // The rig run with the paper's mu_k.
  std::optional<double> period_simulated;      // s, the rig's estimator
  std::optional<double> period_simulated_std;  // s, standard deviation of its periods
  // "hall estimator", or "trajectory (the estimator accepted no period)" (then no spread); empty
  // without a period.
  std::string period_simulated_source;
  std::optional<Regime> regime;
  std::optional<double> residual_sigma;    // (T_sim - T_measured) / dT
  double period_thin = 0.0;                // s, thin formula at the paper's mu_k
  std::optional<double> period_thick;      // s, thick formula at the paper's mu_k and h_c
  std::optional<double> thin_bias_period;  // T_thin / T_thick - 1 at the paper's mu_k
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
  double spacing = 0.0;      // m, the scene's l
  double spacing_err = 0.0;  // m, the paper's dl
  double h_c = 0.0;          // m
  double gravity = 9.81;
  double amplitude = 0.0;  // m, the scene's initial amplitude (at the paper's LEGO mu_k)
  double duration = 0.0;   // s, the scene's simulated time
  std::vector<CompareRow> rows;
  int workers = 0;
  double wall_s = 0.0;
  int simulations = 0;
};

// Throws InputError if the scene cannot be read.
CompareResult run_compare(const PaperTable& table, const CompareOptions& options);

nlohmann::json compare_json(const CompareResult& result);
std::string compare_csv(const CompareResult& result);

}  // namespace fl
