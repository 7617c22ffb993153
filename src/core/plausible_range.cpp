#include "core/plausible_range.hpp"

#include <cmath>

#include "text/describe.hpp"

namespace fl {

std::optional<Said> implausible_said(double value, const PlausibleRange& range) {
  if (std::isfinite(value) && value >= range.least && value <= range.most) return std::nullopt;
  const std::string unit = range.unit.empty() ? "" : " " + std::string(range.unit);
  return said(
      "check-implausible",
      {arg("what", said(std::string(range.what))), arg("least", range.least / range.per_unit),
       arg("most", range.most / range.per_unit), arg("unit", unit),
       arg("paper", said(std::string(range.paper))), arg("value", value / range.per_unit)});
}

std::optional<std::string> implausible(double value, const PlausibleRange& range) {
  if (const std::optional<Said> why = implausible_said(value, range)) return english(*why);
  return std::nullopt;
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
