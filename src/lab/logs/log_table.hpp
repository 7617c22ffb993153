// Many Hall-sensor logs at once: each log estimated as `frictionlab estimate` estimates one (its
// rig from its sidecar, hall_log/log_sidecar, else from the command line), one row per log. A log
// that gives no period is a row with its error; the others go on. The table's columns are those a
// measurements file takes (lab/measured_rows), so it feeds `frictionlab compare --measured` and
// `frictionlab fit` as it is.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/paper_table.hpp"
#include "hall_log/hall_log.hpp"
#include "hall_log/log_sidecar.hpp"
#include "lab/logs/log_estimate.hpp"

namespace fl {

struct LogTableRow {
  std::string log;      // the file read
  std::string sidecar;  // the sidecar read, "" for none
  std::string label;
  LogSetUp set_up;
  std::optional<std::string> material;
  std::optional<double> temperature;  // K
  std::string status;                 // "ok" or "failed"
  std::string error;                  // why, when failed
  std::string geometry;               // "one-pulse", "pair"
  std::optional<int> periods_used;
  std::optional<int> periods_discarded;
  std::optional<double> period;               // s, the mean of the accepted periods
  std::optional<double> period_err;           // s, its standard error
  std::optional<double> period_std;           // s, the periods' standard deviation
  std::optional<double> mu_k;                 // thin formula, as the rig computes it
  std::optional<double> mu_k_err_worst;       // from dT = the standard deviation and dl
  std::optional<double> mu_k_err_quadrature;  // the same in quadrature
};

// What the command line gives every log without a sidecar (or whose sidecar leaves a key out).
struct LogTableDefaults {
  LogSetUp set_up;
  std::optional<std::string> material;
  // The paper's Table I, which a sidecar's material must name (none: not checked).
  const PaperTable* paper = nullptr;
  std::optional<double> temperature;  // K
  HallLogOptions reading;
};

// What a sidecar says of the rig (spacing, dl, g, geometry) over `set_up`.
void apply_log_sidecar(const LogSidecar& sidecar, LogSetUp& set_up);

// The rig one log was taken on, for every front end alike: `set_up` with the log's sidecar over
// it, when the log has one. `note`, when given, is set to what the sidecar set ("the rig from
// x.yaml: l = 75.0 +- 2.0 mm, g = 9.81 m/s^2"), or left empty; `sidecar`, when given, to the
// sidecar read (its material checked against `materials`, when given).
LogSetUp set_up_for_log(const std::string& log_file, const LogSetUp& set_up, std::string* note,
                        std::optional<LogSidecar>* sidecar = nullptr,
                        const PaperTable* materials = nullptr);

// One log's row; never throws for what is wrong with the log or its sidecar (the row says it).
LogTableRow estimate_log_row(const std::string& log, const LogTableDefaults& defaults);

// The rows as a measurements table: CSV (the columns docs/cli.md lists) and JSON.
std::string log_table_csv(const std::vector<LogTableRow>& rows);
nlohmann::json log_table_json(const std::vector<LogTableRow>& rows);

}  // namespace fl
