// A measured mu_k beside the paper's for the same material (its Table I): the paper's T and mu_k
// with their uncertainties, and how many combined standard errors apart the two are, the one
// comparison a student's lab report asks for.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/paper_table.hpp"

namespace fl {

struct PaperComparison {
  std::string key;             // "lego"
  std::string name;            // "LEGO blocks"
  double temperature = 300.0;  // K
  Measured period;             // the paper's T +- dT [s]
  Measured mu_k;               // the paper's mu_k +- d mu_k
  // (mu_k measured - mu_k paper) / sqrt(d_measured^2 + d_paper^2); none when both are 0.
  std::optional<double> standard_errors;
};

// The paper's row for `material` (a key or name it has) at `temperature` [K] beside a measured
// mu_k +- `mu_k_err`; nothing when the material or its measurement at that temperature is not in
// the table.
std::optional<PaperComparison> compare_with_paper(const PaperTable& table,
                                                  const std::string& material, double temperature,
                                                  double mu_k, double mu_k_err);

// {"material", "key", "temperature_k", "period_s", "period_err_s", "mu_k", "mu_k_err",
//  "difference_standard_errors"} (the last null when it has none).
nlohmann::json paper_comparison_json(const PaperComparison& c);

}  // namespace fl
