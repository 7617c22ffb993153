#include "lab/request/material_fields.hpp"

#include <fmt/format.h>

#include "io/field_ref.hpp"
#include "io/unknown_material.hpp"

namespace fl {

MaterialChoice read_material_fields(FieldChecks& checks, const PaperTable& paper,
                                    const std::optional<std::string>& material,
                                    const std::optional<QuantityInput>& temperature) {
  MaterialChoice out;
  if (temperature) {
    out.temperature = checks.quantity(*temperature, Dimension::kTemperature, "temperature");
    if (!material)
      checks.problem("temperature", field_ref("temperature") + " goes with " +
                                        field_ref("material") + "; add the plate's material");
  }
  if (!material) return out;
  const PaperMaterial* row = paper.find(*material);
  if (row == nullptr)
    checks.problem("material", *material, unknown_material_message(paper, *material));
  else if (out.temperature && PaperTable::at(*row, *out.temperature) == nullptr)
    checks.problem("temperature", fmt::format("the paper measured {} at 300 K only", row->name));
  out.material = material;
  return out;
}

std::optional<PaperComparison> paper_value_for(const PaperTable& paper,
                                               const MaterialChoice& choice,
                                               const MaterialChoice& fallback, double mu_k,
                                               double mu_k_err) {
  const std::optional<std::string> material = choice.material ? choice.material : fallback.material;
  if (!material) return std::nullopt;
  const std::optional<double> temperature =
      choice.temperature ? choice.temperature : fallback.temperature;
  return compare_with_paper(paper, *material, temperature.value_or(300.0), mu_k, mu_k_err);
}

}  // namespace fl
