// A comparison of measurements with simulations of the rig, as every front end asks for it
// (`frictionlab compare`): every row of a measurements file (the paper's Table I when none is
// named) simulated and refitted, or one Hall log held against its simulation. The request owns
// its defaults, reads and checks its fields before any simulation (problems by field), runs,
// writes its files and plots, and says how it ended: a row of your own measurements that gives no
// result fails it (lab/request/outcome.hpp).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab/compare/compare.hpp"
#include "lab/compare/log_against_rig.hpp"
#include "lab/compare/measured_rows.hpp"
#include "lab/logs/paper_comparison.hpp"
#include "lab/request/field_checks.hpp"
#include "lab/request/outcome.hpp"

namespace fl {

struct CompareRequest {
  std::string scene;                      // "scene": the rig (scenes/paper-rig.yaml)
  std::string measured;                   // "measured": your rows (the paper's Table I)
  std::string log;                        // "log": a Hall log instead of rows
  std::string geometry;                   // "geometry", with log: auto, one or pair
  std::string columns;                    // "columns", with log
  std::optional<QuantityInput> rate;      // "rate", with log
  std::string time_unit;                  // "time_unit", with log
  std::vector<std::string> set;           // "set": the scene's keys compare leaves to it
  std::optional<QuantityInput> duration;  // "duration": per run (15 measured periods)
  int jobs = 0;                           // "jobs": rows at once (every core)
  std::string out = "out/compare";        // "out"
  bool plot = false;                      // "plot"
  bool refit = true;                      // "refit": refit mu_k (no_refit on the command line)
  std::string assets;                     // "assets"
  // "material", "temperature", with log: the plate's (else the log's sidecar's), for the paper's
  // value beside the refitted mu_k.
  std::optional<std::string> material;
  std::optional<QuantityInput> temperature;
};

struct CompareRequestResult {
  bool paper = false;  // the rows are the paper's Table I
  bool refit_asked = true;
  std::optional<CompareResult> table;  // rows compared
  std::vector<SkippedRow> skipped;     // rows of a table of logs left out (no period)
  std::optional<LogAgainstRig> log;    // or the log against its simulation
  // With a log: the paper's value for its material beside the refitted mu_k, when both are known.
  std::optional<PaperComparison> paper_value;
  // Asked to stop: the rows finished are kept (the others "interrupted"); a log's comparison
  // not finished leaves nothing written.
  bool interrupted = false;
  nlohmann::json json;  // compare.json's or compare-log.json's object
  std::vector<std::string> written;
  std::string plot_failure;

  // Rows of your own measurements without a result (no period, or no refit when asked).
  int rows_without_result() const;
  Outcome outcome() const;
};

// `progress` (rows done, rows in all) as the comparison's options have it; may be empty.
// `control` may ask it to stop (CompareOptions::control).
CompareRequestResult compare_measurements(const CompareRequest& request,
                                          std::function<void(std::size_t, std::size_t)> progress,
                                          const JobControl& control = {});

}  // namespace fl
