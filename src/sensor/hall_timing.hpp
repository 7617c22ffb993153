// How finely the rig's estimator can time the plate's turning points from the Hall signal,
// predicted before a run from the sensor and the plate's harmonic motion (docs/physics.md, the
// sensor's error budget).
//
// The estimator (src/estimator/period_estimator.h) places each pulse at the midpoint of two
// crossings of its timing level, half the pulse's height from the baseline, each crossing
// interpolated linearly between two samples. A crossing moves by the signal's error over its
// slope there: the sensor's noise, the ADC's step (1/sqrt(12) count rms) and the samples' jitter
// (times the slope) in counts, over the slope in counts per second, with 2/3 of the samples'
// variance left by the interpolation between two of them. The straight line between two samples
// also misses a curved signal by at most h^2 |c''| / 8 (h the sample interval), a bias of the
// sampling's phase. The mean of N successive periods is (last turning point - first) / N, so its
// error is the two end pulses' errors over N T: the one-sigma crossing error sigma over N T, and
// at most 2 h^2 |c''| / (8 |c'|) over N T from the interpolation.
#pragma once

#include <optional>

#include "scene/compiled_rig.hpp"

namespace fl {

struct HallTiming {
  double pulse_height = 0.0;        // counts, from the baseline to the pulse's peak
  double slope = 0.0;               // counts/s at the timing level, the slowest of its crossings
  double crossing_sd = 0.0;         // s, one sigma of one crossing's time (noise, ADC step, jitter)
  double interpolation_bias = 0.0;  // s, the most linear interpolation misses one crossing by
  // Periods the estimator times in the run: between the pulses (or pairs) at the sensor's turning
  // point that end within it, less the first two, which it learns the signal from.
  int periods = 0;
  // Relative error of the mean period the estimator reports: three sigma of the end pulses'
  // difference plus twice the interpolation's bias, over N T. Infinite below two periods.
  double period_error = 0.0;
};

// The signal the rig's sensor gives for the plate oscillating harmonically about its centre at
// the thick-plate frequency and its initial amplitude, level, over one period. Nothing when the
// rig has no sensor or no oscillation, or when the signal swings less than `least_swing` counts
// (the estimator then finds no pulse).
std::optional<HallTiming> predict_hall_timing(const CompiledRig& rig, double least_swing);

}  // namespace fl
