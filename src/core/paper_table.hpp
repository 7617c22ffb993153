// The paper's Table I as plain data: periods and mu_k measured for materials sliding on PVC
// rollers at 300 K and, for some, at 77 K; and the recomputation of mu_k from each period.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/analytic_model.hpp"
#include "core/units.hpp"

namespace fl {

struct PaperMeasurement {
  double temperature = 300.0;  // K
  Measured period;             // T +- dT [s], as printed
  Measured mu_k;               // mu_k +- d mu_k, as printed
};

struct LiteratureRange {
  double low = 0.0;
  double high = 0.0;
};

struct PaperMaterial {
  std::string key;   // "lego", "polished-wood", ...
  std::string name;  // "LEGO blocks"
  std::string note;
  PaperMeasurement room;                 // 300 K
  std::optional<PaperMeasurement> cold;  // 77 K, where measured
  std::optional<LiteratureRange> literature;
};

struct PaperTable {
  std::string source;
  Measured spacing;  // l +- dl [m]
  std::vector<PaperMaterial> materials;

  // The material with this key or name (case-insensitive), or nullptr.
  const PaperMaterial* find(std::string_view key_or_name) const;
  // The measurement at a temperature (300 or 77 K, within 1 K), or nullptr.
  static const PaperMeasurement* at(const PaperMaterial& material, double temperature);
};

// mu_k recomputed from a row's T +- dT and the table's l +- dl (thin formula, as the paper did),
// and whether the recomputed values round to the printed ones at the printed precision.
struct RecomputedRow {
  MuKUncertainty mu;
  double mu_k_rounded = 0.0;
  double worst_rounded = 0.0;
  bool mu_k_agrees = false;
  bool uncertainty_agrees = false;
};

RecomputedRow recompute(const PaperMeasurement& row, const Measured& spacing,
                        double gravity = kDefaultGravity);

// value rounded to `decimals` digits after the point (half away from zero).
double round_to_decimals(double value, int decimals);

}  // namespace fl
