// The one table of a run's result fields: each field's name in summary.json, its column in a
// sweep's rows (results.csv and results.json), and how to read it from a RunSummary. The JSON
// summary and the sweep rows are both generated from it, so a new field is added here, once.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "lab/run/run_summary.hpp"

namespace fl {

struct SummaryField {
  const char* summary_key;                   // in summary.json; nullptr: not there
  const char* sweep_column;                  // in a sweep's rows; nullptr: not there
  nlohmann::json (*get)(const RunSummary&);  // null where the run has no such value
  bool omit_when_null = false;               // summary.json leaves the key out instead
};

// In the order of a sweep's columns (the summary's keys are written sorted).
const std::vector<SummaryField>& summary_fields();

// summary.json's object: every field with a summary key.
nlohmann::json summary_json(const RunSummary& summary);

// A sweep row's columns from a run: every field with a sweep column.
void fill_sweep_columns(nlohmann::json& row, const RunSummary& summary);

// The sweep columns the table gives, in order.
std::vector<const char*> sweep_summary_columns();

}  // namespace fl
