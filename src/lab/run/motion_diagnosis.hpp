// What a trajectory shows about a plate that stayed on both rollers (no guard fired, no lift-off,
// a restoring force): the stick episodes the contacts reported and the oscillation's own crossings
// and turning points, read as one of the regimes of core/regime.hpp with its numbers:
//
//   sticks      the last stick episode is still on at the end and has lasted a quarter of the
//               run: the plate stays with the roller (a stalled motor, rollers standing still)
//   stick-slip  stick episodes that last keep coming back: the cycle's period (between sticks to
//               the same roller), its amplitude and its stick duration
//   clipped     one lasting stick (or only grazes: episodes of at most kGrazeSteps steps), then a
//               slipping oscillation at a steady amplitude: when, and the amplitude before/after
//   grows / decays  a slip-dependent law, no lasting stick since the start (or since the last
//               one), and a fit of the turning points' ln |x| against time whose change over the
//               span exceeds kSteadyFraction: the measured e-folding rate
//   oscillates  otherwise: slipping at a steady amplitude
//
// No Bullet, no files: the monitor (lab/run/regime_monitor.hpp) gathers the evidence step by step.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/regime.hpp"

namespace fl {

// One stretch of steps in which the plate was held to a roller's surface.
struct StickEpisode {
  int roller = 0;
  double start = 0.0;  // s, the first stuck step
  double end = 0.0;    // s, the last stuck step
  int steps = 0;
  bool open = false;  // still stuck at the run's last step
};

struct MotionEvidence {
  std::vector<StickEpisode> sticks;
  std::vector<double> crossings;           // s, the plate through the centre, alternating
  std::vector<double> turning_times;       // s
  std::vector<double> turning_amplitudes;  // m, |x| at each turning point
  double amplitude_start = 0.0;            // m, |x| at the start (before any turning point)
  double duration = 0.0;                   // s simulated
  double time_step = 0.0;                  // s
  // Whether the friction law depends on the slip speed. Without that dependence a slipping
  // plate's amplitude is conserved (docs/friction-laws.md): a change is the integrator's, not a
  // growth or decay, and is reported as a measured rate only.
  bool slip_dependent = true;
};

struct MotionFinding {
  Regime regime = Regime::kOscillates;
  double since = 0.0;  // s
  std::string evidence;
  // clipped: when the first stick began, the amplitude before it and the steady one after (the
  // mean of the last four turning points).
  std::optional<double> clip_time;         // s
  std::optional<double> amplitude_before;  // m
  std::optional<double> amplitude_after;   // m
  // stick-slip: the cycle's period, amplitude and one stick phase's mean duration.
  std::optional<double> cycle_period;     // s
  std::optional<double> cycle_amplitude;  // m
  std::optional<double> stick_duration;   // s
  // The amplitude's fitted e-folding rate over the slipping span (grows, decays; also measured for
  // a steady oscillation): d ln A / dt [1/s], and that span's first turning point.
  std::optional<double> growth_rate;
  std::optional<double> slipping_since;  // s
  int stick_count = 0;                   // lasting stick episodes
  int graze_count = 0;                   // episodes of at most kGrazeSteps steps
};

// A stick episode this short is the plate grazing a roller's speed, not a stick phase.
inline constexpr int kGrazeSteps = 2;
// An amplitude that changes by less than this fraction over the slipping span is steady.
inline constexpr double kSteadyFraction = 0.01;

MotionFinding diagnose_motion(const MotionEvidence& evidence);

}  // namespace fl
