// The one declaration of what `frictionlab estimate --json` says of one log (and the Python
// Estimate's values): each key's name, the Python attribute where the module has one, its unit, its
// meaning and when it is null. log_estimate_json writes the keys from it, the Python module binds
// its plain attributes from it, and docs/cli.md's table of the keys and the stub's Estimate are
// generated from it (tools/generate-fields). A new key is one entry here plus its computation.
#pragma once

#include <vector>

#include "hall_log/hall_log.hpp"
#include "lab/fields/field_value.hpp"
#include "lab/logs/log_estimate.hpp"

namespace fl {

// What a key is computed from: the log as read, and the estimator's verdict on it.
struct EstimateOf {
  const HallLog& log;
  const LogEstimate& estimate;
};

// Where a key comes from, in the order the docs list them.
enum class EstimatePart {
  kReading,  // how the log was read and what was left out of it
  kSignal,   // the signal and the estimator's state
  kVerdict,  // the geometry, the periods' counts, T +- dT and mu_k +- d mu_k (the Hall plot's too)
  kRequest,  // added by the request that ran it (a plot, a Monte Carlo, the paper's value)
};

struct EstimateField {
  const char* json = "";
  const char* python = nullptr;  // the Python Estimate's attribute; nullptr: none
  EstimatePart part = EstimatePart::kSignal;
  FieldType type = FieldType::kNumber;
  const char* unit = "";            // SI; "" for none
  const char* meaning = "";         // for the docs and the stub
  const char* null_when = nullptr;  // nullptr: never
  // The value; nullptr for a key of kRequest, which the request sets.
  FieldValue (*get)(const EstimateOf&) = nullptr;
};

// Every key, in the docs' order.
const std::vector<EstimateField>& estimate_fields();

}  // namespace fl
