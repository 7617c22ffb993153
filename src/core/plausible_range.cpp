#include "core/plausible_range.hpp"

#include <cmath>

#include "core/describe.hpp"

namespace fl {

std::optional<std::string> implausible(double value, const PlausibleRange& range) {
  if (std::isfinite(value) && value >= range.least && value <= range.most) return std::nullopt;
  const std::string unit = range.unit.empty() ? "" : " " + std::string(range.unit);
  return describe("expected ", range.what, " from ", range.least / range.per_unit, " to ",
                  range.most / range.per_unit, unit, " (the paper's rig: ", range.paper,
                  "), found ", value / range.per_unit, unit);
}

}  // namespace fl
