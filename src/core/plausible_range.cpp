#include "core/plausible_range.hpp"

#include <cmath>

#include "text/describe.hpp"

namespace fl {

std::optional<std::string> implausible(double value, const PlausibleRange& range) {
  if (std::isfinite(value) && value >= range.least && value <= range.most) return std::nullopt;
  const std::string unit = range.unit.empty() ? "" : " " + std::string(range.unit);
  return describe("expected ", range.what, " from ", range.least / range.per_unit, " to ",
                  range.most / range.per_unit, unit, " (the paper's rig: ", range.paper,
                  "), found ", value / range.per_unit, unit);
}

std::string plain_number_advice(double value, std::string_view text, const PlausibleRange& range) {
  // Lengths the rig measures in millimetres, periods in milliseconds when not in seconds.
  const bool length = range.unit == "mm";
  const bool time = range.unit == "s";
  if (!(length || time) || implausible(value * 1e-3, range)) return "";
  return describe(": a plain number is SI, so ", text, " was read as ", text, length ? " m" : " s",
                  "; write ", text, length ? "mm for millimetres" : "ms for milliseconds");
}

}  // namespace fl
