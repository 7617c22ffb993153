// A report's parts from what the lab made: a run's files (its summary.json, trajectory.csv,
// hall.csv and periods.csv, from a folder `run --out` wrote or a session's run), or a
// measurement's estimate (a Hall log, a phone's file, a video). Their numbers are the files' and
// the estimate's own, never computed again.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "core/paper_table.hpp"
#include "hall_log/hall_log.hpp"
#include "lab/logs/log_estimate.hpp"
#include "lab/logs/paper_comparison.hpp"
#include "lab/report/report_content.hpp"

namespace fl {

// A run's file by name ("summary.json"), or nullopt where the run kept none.
using RunFiles = std::function<std::optional<std::string>(const std::string& name)>;

// Throws std::invalid_argument naming the file when summary.json is missing or not a run's
// summary, or a table is not the run's. `source` names the run (its folder, or its scene).
ReportPart simulation_part(const RunFiles& files, const std::string& source,
                           const PaperTable& table);

ReportPart measurement_part(const HallLog& log, const LogEstimate& estimate,
                            const std::optional<PaperComparison>& paper);

// A measurement's part from its estimate's numbers alone (no samples, no periods' table), marked
// with the estimate's own field names.
ReportPart measurement_part(const MeasuredSummary& measured);

}  // namespace fl
