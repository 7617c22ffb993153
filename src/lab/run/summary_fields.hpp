// The one declaration of a run's result fields: each field's name in every output that carries
// it (summary.json and `run --json`, timing.json, a sweep's rows, the Python module's RunSummary),
// its type, its unit, what it means and when it is null, and how to read it from a RunSummary.
// summary.json, timing.json and the sweep rows are written from it; the Python attributes of plain
// values are bound from it; docs/cli.md's and docs/sweep-format.md's key tables, the .pyi stub's
// RunSummary and the page's TypeScript type are generated from it (tools/generate-fields) and a
// test fails when one of them is not what it gives. A new field is one entry here plus its
// computation.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab/fields/field_value.hpp"
#include "lab/run/run_summary.hpp"

namespace fl {

struct SummaryField {
  const char* json = nullptr;    // key in summary.json and `run --json`; nullptr: not there
  const char* sweep = nullptr;   // column of a sweep's rows; nullptr: not there
  const char* python = nullptr;  // attribute of the Python RunSummary; nullptr: not there
  // The Python attribute's type where it is not the plain value (an enum or a class the binding
  // makes by hand: "Regime", "DriveReport"); nullptr: the plain value, bound from `get`.
  const char* python_type = nullptr;
  FieldType type = FieldType::kNumber;
  const char* unit = "";     // SI ("s", "m", "rad/s", "kg", "N", "K", "1/s"); "" for none
  const char* meaning = "";  // one sentence for the docs and the stubs
  // When the value is null (JSON) or None (Python); nullptr: never.
  const char* null_when = nullptr;
  FieldValue (*get)(const RunSummary&) = nullptr;
  bool omit_when_null = false;  // summary.json leaves the key out instead of writing null
  bool timing = false;          // this machine's cost: timing.json (and `run --json`), never
                                // summary.json, whose bytes must not depend on the machine
};

// Every field, in the order of a sweep's columns (the summary's keys are written sorted).
const std::vector<SummaryField>& summary_fields();

// summary.json's object: every field with a JSON key but the timing ones.
nlohmann::json summary_json(const RunSummary& summary);

// timing.json's object: the timing fields (wall time, real-time factor, steps per second).
nlohmann::json timing_json(const RunSummary& summary);

// A sweep row's columns from a run: every field with a sweep column.
void fill_sweep_columns(nlohmann::json& row, const RunSummary& summary);

// The sweep columns the table gives, in order.
std::vector<const char*> sweep_summary_columns();

}  // namespace fl
