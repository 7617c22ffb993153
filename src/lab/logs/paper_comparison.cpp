#include "lab/logs/paper_comparison.hpp"

#include <cmath>

namespace fl {

std::optional<PaperComparison> compare_with_paper(const PaperTable& table,
                                                  const std::string& material, double temperature,
                                                  double mu_k, double mu_k_err) {
  const PaperMaterial* row = table.find(material);
  if (row == nullptr) return std::nullopt;
  const PaperMeasurement* m = PaperTable::at(*row, temperature);
  if (m == nullptr) return std::nullopt;
  PaperComparison out;
  out.key = row->key;
  out.name = row->name;
  out.temperature = m->temperature;
  out.period = m->period;
  out.mu_k = m->mu_k;
  const double combined = std::hypot(mu_k_err, m->mu_k.uncertainty);
  if (combined > 0.0 && std::isfinite(combined))
    out.standard_errors = (mu_k - m->mu_k.value) / combined;
  return out;
}

nlohmann::json paper_comparison_json(const PaperComparison& c) {
  return {{"material", c.name},
          {"key", c.key},
          {"temperature_k", c.temperature},
          {"period_s", c.period.value},
          {"period_err_s", c.period.uncertainty},
          {"mu_k", c.mu_k.value},
          {"mu_k_err", c.mu_k.uncertainty},
          {"difference_standard_errors",
           c.standard_errors ? nlohmann::json(*c.standard_errors) : nlohmann::json(nullptr)}};
}

}  // namespace fl
