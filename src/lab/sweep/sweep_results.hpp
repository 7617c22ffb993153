// One sweep point run on its own, and the sweep's results as rows: a row per point with its
// parameters, seed, status, regime, T +- dT, mu_k recovered, the analytic periods and errors. Rows
// are deterministic (the same point gives the same bytes); wall time is kept apart.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab/sweep/sweep_spec.hpp"

namespace fl {

// What running one point gave: its row, and what it cost on this machine.
struct PointResult {
  std::size_t index = 0;
  nlohmann::json row;  // deterministic; keys as in sweep_result_columns
  double wall_s = 0.0;
  // The point's cycles (lab/run/cycle_report.hpp) when the sweep asks for them (`cycles: true`) and
  // the point ran; empty otherwise. Deterministic.
  std::string cycles_csv;
};

// Runs one point: loads the base scene with the point's overrides and simulates it. Never throws
// for the point's own trouble: an invalid override or scene gives status "invalid", a run that a
// guard stopped or that threw gives "failed", each with its error; both still give a row.
// Thread-safe (each call builds its own scene and world) if `inputs` are.
PointResult run_sweep_point(const SweepSpec& spec, const SweepPoint& point,
                            const SceneInputs& inputs);

// The results' columns in order: index, one per axis of the plan (sweep_plan), then the fixed
// ones.
std::vector<std::string> sweep_result_columns(const nlohmann::json& plan);

// The final files' text, from the plan and the rows in point order (rows[i] is point i).
std::string sweep_results_csv(const nlohmann::json& plan, const std::vector<nlohmann::json>& rows);
nlohmann::json sweep_results_json(const nlohmann::json& plan,
                                  const std::vector<nlohmann::json>& rows);

// A point file (points/NNNNNNNN.json under a sweep's folder): its row, the plan it belongs to and
// its wall time, as one line of JSON.
std::string point_file_text(const PointResult& result, const std::string& plan_digest);
// Reads one back; nullopt if it is not a point file of this plan (or is damaged).
std::optional<PointResult> parse_point_file(const std::string& text,
                                            const std::string& plan_digest);

}  // namespace fl
