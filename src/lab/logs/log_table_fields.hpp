// The one declaration of a log table's columns (lab/logs/log_table.hpp): each field's column in
// estimates.csv (a measurements file's, which `compare --measured` and `fit` read), its key in
// estimates.json and `estimate --json` with several logs, its unit, its meaning and when it is
// empty or null. Both files are written from it; docs/cli.md's table of them is generated from it
// (tools/generate-fields). A new column is one entry here plus its computation.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab/fields/field_value.hpp"
#include "lab/logs/log_table.hpp"

namespace fl {

struct LogTableField {
  const char* json = nullptr;  // key in estimates.json; nullptr: not there
  const char* csv = nullptr;   // column of estimates.csv; nullptr: not there
  FieldType type = FieldType::kNumber;
  const char* unit = "";            // SI; "" for none
  const char* meaning = "";         // one sentence for the docs
  const char* null_when = nullptr;  // when the value is empty (CSV) or null (JSON); nullptr: never
  FieldValue (*get)(const LogTableRow&) = nullptr;
  // The unit the CSV writes after a number, as a measurements file takes it (" m", " K"); "" for
  // none.
  const char* csv_unit = "";
};

// Every field, in the order of estimates.csv's columns (JSON-only ones where they belong).
const std::vector<LogTableField>& log_table_fields();

}  // namespace fl
