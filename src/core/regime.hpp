// The physical regimes of the friction oscillator: what the analytic model expects for a set-up
// (lab/regime_theory.hpp) and what a run's trajectory shows (lab/regime_monitor.hpp) are told in
// the same terms, so the two can be held against each other.
#pragma once

#include <optional>
#include <ostream>
#include <string_view>

namespace fl {

enum class Regime {
  kOscillates,         // harmonic oscillation: both rollers slip all the time
  kSticks,             // stick-slip: the plate reached a roller's surface speed
  kTips,               // tipping or lift-off: a normal force reached zero
  kNoRestoringForce,   // the plate drifts off (l <= 2 mu_k h_c, or rollers turning outward)
  kLost,               // the plate fell off or left the rig's bounds
  kNumericallyFailed,  // NaN, infinity, energy blow-up or penetration beyond a bound
};

// "oscillates", "sticks", "tips", "no restoring force", "lost", "numerically failed".
const char* regime_name(Regime regime);

// The regime a name stands for (the names above), or nullopt.
std::optional<Regime> regime_from_name(std::string_view name);

inline std::ostream& operator<<(std::ostream& out, Regime regime) {
  return out << regime_name(regime);
}

}  // namespace fl
