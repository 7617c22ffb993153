// The physical regimes of the friction oscillator: what the analytic model expects for a set-up
// (lab/run/regime_theory.hpp, core/friction_regime.hpp) and what a run's trajectory shows
// (lab/run/regime_monitor.hpp) are told in the same terms, so the two can be held against each
// other.
#pragma once

#include <optional>
#include <ostream>
#include <string_view>

namespace fl {

enum class Regime {
  kOscillates,        // harmonic oscillation at a steady amplitude: both rollers slip throughout
  kClipped,           // one stick clipped the amplitude to v_r / Omega; then a harmonic cycle that
                      // grazes the rollers' surface speed, with the period unchanged
  kStickSlip,         // a periodic cycle whose stick phases (moving with a roller) last
  kGrows,             // both rollers slip; the amplitude grows exponentially (a slip-dependent law)
  kDecays,            // both rollers slip; the amplitude decays exponentially
  kSticks,            // the plate stays stuck to a roller (or the rollers stand still) for good
  kTips,              // tipping or lift-off: a normal force reached zero
  kNoRestoringForce,  // the plate drifts off (l <= 2 mu_k h_c, or rollers turning outward)
  kLost,              // the plate fell off or left the rig's bounds
  kNumericallyFailed,  // NaN, infinity, energy blow-up or penetration beyond a bound
};

// "oscillates", "clipped", "stick-slip", "grows", "decays", "sticks", "tips",
// "no restoring force", "lost", "numerically failed".
const char* regime_name(Regime regime);

// The regime a name stands for (the names above), or nullopt.
std::optional<Regime> regime_from_name(std::string_view name);

// An oscillation the period estimator can measure: both rollers slip for all but instants of
// each cycle (oscillates, clipped, grows, decays); the paper's formula gives mu at the rollers'
// surface speed from its period.
bool regime_is_harmonic(Regime regime);

inline std::ostream& operator<<(std::ostream& out, Regime regime) {
  return out << regime_name(regime);
}

}  // namespace fl
