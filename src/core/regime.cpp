#include "core/regime.hpp"

namespace fl {

const char* regime_name(Regime regime) {
  switch (regime) {
    case Regime::kOscillates:
      return "oscillates";
    case Regime::kSticks:
      return "sticks";
    case Regime::kTips:
      return "tips";
    case Regime::kNoRestoringForce:
      return "no restoring force";
    case Regime::kLost:
      return "lost";
    case Regime::kNumericallyFailed:
      return "numerically failed";
  }
  return "unknown";
}

std::optional<Regime> regime_from_name(std::string_view name) {
  for (const Regime r : {Regime::kOscillates, Regime::kSticks, Regime::kTips,
                         Regime::kNoRestoringForce, Regime::kLost, Regime::kNumericallyFailed})
    if (name == regime_name(r)) return r;
  return std::nullopt;
}

}  // namespace fl
