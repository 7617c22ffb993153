// The plate's material and the rollers' temperature a request names so that its result can stand
// beside the paper's value (its Table I): one reading for every request that takes them (one
// log's estimate, a spacing series' fit, a log against its simulation).
#pragma once

#include <optional>
#include <string>

#include "core/paper_table.hpp"
#include "lab/logs/paper_comparison.hpp"
#include "lab/request/field_checks.hpp"

namespace fl {

struct MaterialChoice {
  std::optional<std::string> material;  // a key or name of the paper's table
  std::optional<double> temperature;    // K
};

// Reads "material" and "temperature": a material the table does not have is a problem with the
// nearest names; a temperature goes with a material, at one the paper measured it at.
MaterialChoice read_material_fields(FieldChecks& checks, const PaperTable& paper,
                                    const std::optional<std::string>& material,
                                    const std::optional<QuantityInput>& temperature);

// The paper's value beside a measured mu_k +- mu_k_err for the material `choice` names, else the
// one `fallback` names (a log's sidecar), its temperature likewise (300 K when neither names one);
// nothing when neither names a material or the table lacks it at that temperature.
std::optional<PaperComparison> paper_value_for(const PaperTable& paper,
                                               const MaterialChoice& choice,
                                               const MaterialChoice& fallback, double mu_k,
                                               double mu_k_err);

}  // namespace fl
