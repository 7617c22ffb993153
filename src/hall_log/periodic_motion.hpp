// Whether another instrument's channel shows a periodic motion at all, before the rig's estimator
// times it: a phone lying still, an export of another experiment, a video of something else give
// pulses of noise that the estimator would discard one by one, and a student would hear about a
// Hall sensor they never had. The channel's spectrum says it first: a swinging plate's strongest
// frequency stands hundreds of times above the spectrum's median (between 0.2 Hz and 25 Hz, or
// half the sample rate when that is lower: periods from 40 ms to 5 s, every rig's); noise's
// strongest stands a few times above it.
#pragma once

#include <string>

#include "hall_log/measurement_table.hpp"
#include "io/input_error.hpp"
#include "text/said.hpp"

namespace fl {

// The strongest frequency's power over the spectrum's median at which a channel is periodic.
inline constexpr double kLeastPeakOverMedian = 50.0;

struct Periodicity {
  double strongest_hz = 0.0;  // the strongest frequency in the band
  double peak_over_median = 0.0;
  double noise = 0.0;  // the sample-to-sample noise, as a standard deviation (the channel's unit)
  double swing = 0.0;  // the channel's 0.5th to 99.5th percentile
  bool periodic() const { return peak_over_median >= kLeastPeakOverMedian; }
};

// The channel's spectrum, less its straight line (its samples taken as evenly spaced at their mean
// interval, at most 20 000 of them, every k-th of a longer one). Needs 16 samples or more.
Periodicity periodicity_of(const Series& channel);

// The channel's strongest oscillation: its frequency (the spectrum's peak, `periodicity` of the
// same channel, refined to a small fraction of the record's resolution) and its amplitude there
// (the least-squares sinusoid's, so the noise averages out rather than widening the swing). Zeros
// for a channel with no spectrum.
struct Oscillation {
  double frequency_hz = 0.0;
  double amplitude = 0.0;  // in the channel's unit
};
Oscillation strongest_oscillation(const Series& channel, const Periodicity& periodicity);

// Throws InputError at `where` when the channel shows no periodic motion, saying what was found:
// the strongest frequency and how far it stands above the rest, the noise and the swing (in the
// channel's unit, which `column` names), and what to check. Returns the channel's periodicity.
Periodicity require_periodic_motion(const Series& channel, const SourceLocation& where,
                                    const Said& instrument, const Said& column);

}  // namespace fl
