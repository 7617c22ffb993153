// What `frictionlab estimate` prints for a log, read from a file or followed live from the rig:
// the table (how the log was read and what was left out of it, the signal, the geometry and why,
// the periods, T +- dT and mu_k +- d mu_k) and the JSON object (docs/cli.md).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "hall_log/hall_log.hpp"
#include "lab/logs/geometry_check.hpp"
#include "lab/logs/log_estimate.hpp"

namespace fl::cli {

// The table on stdout; `plot` is the PNG drawn ("" for none).
void print_estimate(const HallLog& log, const LogEstimate& est, const GeometryCheck& check,
                    const std::string& plot);

// The JSON object: lab's log_estimate_json with "plot".
nlohmann::json estimate_json(const HallLog& log, const LogEstimate& est, const std::string& plot);

// "lines 12, 40, 977, ..." for the first lines of a kind.
std::string line_list(const LineTally& tally);

}  // namespace fl::cli
