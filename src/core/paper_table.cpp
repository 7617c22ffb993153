#include "core/paper_table.hpp"

#include <cctype>
#include <cmath>

namespace fl {
namespace {

bool same_text(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  }
  return true;
}

}  // namespace

const PaperMaterial* PaperTable::find(std::string_view key_or_name) const {
  for (const PaperMaterial& material : materials) {
    if (same_text(material.key, key_or_name) || same_text(material.name, key_or_name))
      return &material;
  }
  return nullptr;
}

const PaperMeasurement* PaperTable::at(const PaperMaterial& material, double temperature) {
  if (std::fabs(material.room.temperature - temperature) < 1.0) return &material.room;
  if (material.cold && std::fabs(material.cold->temperature - temperature) < 1.0)
    return &*material.cold;
  return nullptr;
}

double round_to_decimals(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(value * scale) / scale;
}

RecomputedRow recompute(const PaperMeasurement& row, const Measured& spacing, double gravity) {
  RecomputedRow out;
  out.mu = mu_k_with_uncertainty(row.period.value, row.period.uncertainty, spacing.value,
                                 spacing.uncertainty, 0.0, gravity);
  out.mu_k_rounded = round_to_decimals(out.mu.mu_k, row.mu_k.decimals);
  out.worst_rounded = round_to_decimals(out.mu.worst, row.mu_k.uncertainty_decimals);
  // Compare at the printed precision: half a unit of the last printed digit.
  const double half_unit_mu = 0.5 * std::pow(10.0, -row.mu_k.decimals);
  const double half_unit_err = 0.5 * std::pow(10.0, -row.mu_k.uncertainty_decimals);
  out.mu_k_agrees = std::fabs(out.mu_k_rounded - row.mu_k.value) < half_unit_mu;
  out.uncertainty_agrees = std::fabs(out.worst_rounded - row.mu_k.uncertainty) < half_unit_err;
  return out;
}

}  // namespace fl
