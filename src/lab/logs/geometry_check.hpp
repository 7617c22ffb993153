// Which geometry a log shows, beyond what the estimator's look at five pulses can tell. Evenly
// spaced pulses come from one pulse per period (a magnet turning at a sensor beyond its turning
// point) and from two (a magnet passing a sensor at the exact middle of its travel, going and
// coming back): the estimator reads them as one. frictionlab estimate then looks at the whole
// log:
//  - do the periods alternate short and long, beyond their noise? Then there are two pulses per
//    period (a sensor near, not at, the middle of the travel);
//  - are the pulses shaped like a turn or like a pass? A magnet that turns at the sensor stays
//    near it longest at the top of the pulse (the distance it is from its turning point grows as
//    the square of the time), so the pulse's width at a quarter of its height is at most 1.37
//    times its width at half height (1.39 in noise); a magnet passing at full speed draws the
//    field's own profile, 1.44 to 1.48 for a magnet small beside its distance to the sensor (a
//    point dipole), less for a wide magnet close to it (docs/estimator.md). Above 1.42, a pass.
// When either says "two", or the shape cannot be measured, the log does not say which: the
// estimate asks for --geometry rather than give a period that may be half the true one.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "hall_log/hall_log.hpp"
#include "lab/logs/log_estimate.hpp"

namespace fl {

// A pulse's width at a quarter of its height over its width at half height, above which the
// pulses are a pass's, not a turn's.
inline constexpr double kPassShapeRatio = 1.42;

struct GeometryCheck {
  bool needed = false;  // the estimator recognised one pulse per period on its own
  // The periods' alternation: the mean of each period minus the mean of its two neighbours,
  // signed by its parity, over independent triples of consecutive accepted periods.
  int alternation_triples = 0;
  std::optional<double> alternation_s;      // [s]
  std::optional<double> alternation_err_s;  // its standard error [s]
  bool alternates = false;                  // beyond 5 standard errors and 0.05 % of T
  // The pulses' shape: the median over the clean pulses of (width at 1/4) / (width at 1/2).
  int shape_pulses = 0;
  std::optional<double> shape_ratio;
  std::optional<double> samples_across;  // median samples within a pulse's half-height width
  bool clipped = false;                  // the pulses' peaks sit at the ADC's rail
  // "turn", "pass", "alternating", "unknown" (needed), or "" (not needed).
  std::string verdict;
  std::string reason;  // why the log does not say which, for the message
};

// Looks at the log when the estimator recognised one pulse per period on its own.
GeometryCheck check_geometry(const HallLog& log, const LogEstimate& estimate);

// The check as `frictionlab estimate --json` gives it: null when it was not needed.
nlohmann::json geometry_check_json(const GeometryCheck& check);

// Throws InputError (at the first pulse's line) when the check leaves the geometry in doubt,
// saying what it found and which --geometry to give. `note` ends the message.
void require_geometry(const HallLog& log, const LogEstimate& estimate, const GeometryCheck& check,
                      const std::string& note);

}  // namespace fl
