#include "core/regime.hpp"

namespace fl {

const char* regime_name(Regime regime) {
  switch (regime) {
    case Regime::kOscillates:
      return "oscillates";
    case Regime::kClipped:
      return "clipped";
    case Regime::kStickSlip:
      return "stick-slip";
    case Regime::kGrows:
      return "grows";
    case Regime::kDecays:
      return "decays";
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
  for (const Regime r : {Regime::kOscillates, Regime::kClipped, Regime::kStickSlip, Regime::kGrows,
                         Regime::kDecays, Regime::kSticks, Regime::kTips, Regime::kNoRestoringForce,
                         Regime::kLost, Regime::kNumericallyFailed})
    if (name == regime_name(r)) return r;
  return std::nullopt;
}

bool regime_is_harmonic(Regime regime) {
  return regime == Regime::kOscillates || regime == Regime::kClipped || regime == Regime::kGrows ||
         regime == Regime::kDecays;
}

}  // namespace fl
