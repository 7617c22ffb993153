// Measured periods to compare with the lab: a CSV with one row per measurement, whose header names
// `period` and `period_err` (or a period written "0.79 +- 0.03 s"), optionally `label`, `mu_k` and
// `mu_k_err` (the mu_k the measurement reports, as the paper's Table I does) and `spacing_err`,
// `status` (rows other than "ok" are skipped), the columns of `frictionlab estimate`'s table that
// say how a row was measured (read past), and any scene keys (`plate.material`,
// `friction.temperature`, `rollers.spacing`, ...) that set the row's rig. Values carry units as in
// scene files; a plain number is SI. An empty cell under a scene key leaves that key to the scene.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/units.hpp"
#include "io/input_error.hpp"
#include "scene/scene_yaml.hpp"

namespace fl {

struct MeasuredRow {
  std::string label;
  std::vector<SceneOverride> keys;        // the row's scene keys, in the file's column order
  std::vector<SourceLocation> key_cells;  // where each key's value is written
  Measured period;                        // T +- dT [s]
  std::optional<Measured> mu_k;           // the mu_k the measurement reports
  std::optional<double> spacing_err;      // dl [m]
  SourceLocation where;                   // the row's line
  SourceLocation period_cell;             // where its period is written
};

// A row left out: `frictionlab estimate`'s table has a status column, and a log that gave no
// period is a row without one.
struct SkippedRow {
  std::string label;
  SourceLocation where;
  std::string reason;
};

struct MeasuredRows {
  std::string file;
  std::vector<MeasuredRow> rows;
  std::vector<SkippedRow> skipped;
};

// Keys a row may not set: the comparison sets them itself (mu_k for the refit, the run's length).
bool compare_sets_key(std::string_view scene_key);

// Throws InputError located at the cell at fault, saying what was expected and what to do.
MeasuredRows parse_measured_rows(std::string_view text, const std::string& file);

// The file's rows (read_text_file, then parse_measured_rows).
MeasuredRows read_measured_rows(const std::string& path);

}  // namespace fl
