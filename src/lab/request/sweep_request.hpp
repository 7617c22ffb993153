// A sweep, as every front end asks for it (`frictionlab sweep`, frictionlab.sweep): the sweep
// file, where its results go, how many workers, a shard of it, a fresh start, and its plots.
// prepare_sweep reads and checks every field before any point runs (problems by field);
// execute_sweep runs the points not done yet; the result says how it ended: a sweep whose
// results hold failed or invalid points fails, as a run that failed does (lab/request/outcome).
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab/request/field_checks.hpp"
#include "lab/request/outcome.hpp"
#include "lab/sweep/sweep_run.hpp"
#include "lab/sweep/sweep_spec.hpp"

namespace fl {

struct SweepRequest {
  std::string file;         // "sweep": the sweep file (docs/sweep-format.md)
  std::optional<int> jobs;  // "jobs": workers per process (every core)
  std::string out;          // "out": the results' folder (out/sweep/NAME)
  bool plot = false;        // "plot": the results' plots, when every point is done
  std::string shard;        // "shard": K/N, this process's share of the points
  bool fresh = false;       // "fresh": discard the folder's earlier results
  // "accuracy": each point at the largest step whose predicted period error stays within it
  // (over the file's `accuracy:`), e.g. "0.01%"
  std::optional<QuantityInput> accuracy;
  std::string assets;  // "assets": the lab's data
};

struct PreparedSweep {
  SweepSpec spec;
  SweepRunOptions options;  // without stop and progress: the front end's
  bool plot = false;
};

PreparedSweep prepare_sweep(const SweepRequest& request);

struct SweepResult {
  SweepOutcome outcome;
  std::vector<std::string> plots;  // the PNGs drawn
  std::string plot_failure;        // why they could not be drawn (the results stand)

  int points_without_result() const;  // failed and invalid points, when complete
  Outcome outcome_of() const;
};

// The plots tools/plot_sweep.py draws into a complete sweep's folder (a merge's too); throws
// std::runtime_error when it cannot.
std::vector<std::string> plot_sweep(const std::string& dir);

// Runs what was prepared; `stop` and `progress` as SweepRunOptions has them.
SweepResult execute_sweep(const PreparedSweep& sweep, const std::atomic<bool>* stop,
                          std::function<void(const SweepProgress&)> progress);

// The shards of a sweep joined (`frictionlab merge`, frictionlab.merge): the folders `--shard`
// runs wrote, into one folder (the first, unless `out` names another) holding results.csv and
// sweep.json as the whole sweep run in one go would.
struct MergeRequest {
  std::vector<std::string> dirs;  // "dirs": the shards' folders
  std::string out;                // "out": where the joined results go (the first folder)
  bool plot = false;              // "plot": the results' plots
};

struct MergeResult {
  std::string out;  // the folder written
  MergeOutcome outcome;
  std::vector<std::string> plots;  // the PNGs drawn
  std::string plot_failure;        // why they could not be drawn (the results stand)

  int points_without_result() const;  // failed and invalid points
  Outcome outcome_of() const;
  nlohmann::json json() const;  // `merge --json`'s object
};

// Reads and checks the fields (problems by field), then joins; throws InputError for a folder that
// is no sweep's, or shards of different sweeps.
MergeResult merge_shards(const MergeRequest& request);

}  // namespace fl
