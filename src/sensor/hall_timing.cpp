#include "sensor/hall_timing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "sensor/hall_signal.hpp"

namespace fl {

std::optional<HallTiming> predict_hall_timing(const CompiledRig& rig, double least_swing) {
  if (!rig.sensor || !rig.omega || !rig.period_thick) return std::nullopt;
  const SensorDesc& sensor = *rig.sensor;
  const HallSignal hall(rig);
  const double omega = *rig.omega;
  const double period = *rig.period_thick;
  const double centre = rig.oscillation_centre.value_or(0.0);
  const double amplitude = rig.amplitude_initial;
  const double counts_per_volt = std::ldexp(1.0, sensor.adc_bits) / sensor.supply;

  // The noiseless signal in counts (before the ADC's rounding) over one period, evenly in time.
  constexpr int kPoints = 20000;
  const double dt = period / kPoints;
  std::vector<double> counts(kPoints);
  for (int i = 0; i < kPoints; ++i) {
    const double phase = omega * dt * i;
    PlatePose pose;
    pose.t = dt * i;
    pose.x = centre + amplitude * std::cos(phase);
    pose.vx = -amplitude * omega * std::sin(phase);
    pose.z = rig.plate.h_c;  // the contact line is at z = 0
    counts[i] = hall.voltage(hall.field_along_axis(pose)) * counts_per_volt;
  }
  // The baseline is where the signal rests most of the time (the estimator's resting side); the
  // pulse is the larger excursion from it.
  std::vector<double> sorted = counts;
  std::nth_element(sorted.begin(), sorted.begin() + kPoints / 2, sorted.end());
  const double baseline = sorted[kPoints / 2];
  const auto [lo, hi] = std::minmax_element(counts.begin(), counts.end());
  const double polarity = (*hi - baseline) >= (baseline - *lo) ? 1.0 : -1.0;
  const double height = polarity > 0 ? *hi - baseline : baseline - *lo;
  if (!(height >= least_swing)) return std::nullopt;

  // Every crossing of the timing level (half the height), its slope and curvature there.
  const double level = 0.5 * height;
  const auto deviation = [&](int i) {
    return polarity * (counts[(i + kPoints) % kPoints] - baseline);
  };
  // The side of the travel the pulses are on: the turning point there (t = 0 on the side the
  // plate is released from, T / 2 on the other) times the estimator's turning point.
  const int peak = static_cast<int>(polarity > 0 ? hi - counts.begin() : lo - counts.begin());
  const double side = std::cos(omega * dt * peak) * (amplitude > 0.0 ? 1.0 : 0.0);
  const double turning = side >= 0.0 ? 0.0 : 0.5 * period;
  double half_span = 0.0;  // s, from the turning point to its group's farthest crossing
  double slowest = std::numeric_limits<double>::infinity();
  double bias = 0.0;
  const double h = 1.0 / sensor.sample_rate;
  for (int i = 0; i < kPoints; ++i) {
    const double a = deviation(i) - level, b = deviation(i + 1) - level;
    if ((a < 0.0) == (b < 0.0)) continue;
    const double slope = std::fabs(deviation(i + 1) - deviation(i)) / dt;
    const double curvature =
        std::fabs(deviation(i + 2) - deviation(i + 1) - deviation(i) + deviation(i - 1)) /
        (2.0 * dt * dt);
    if (!(slope > 0.0)) continue;
    const double from_turning = std::remainder(dt * i - turning, period);
    half_span = std::max(half_span, std::fabs(from_turning));
    slowest = std::min(slowest, slope);
    bias = std::max(bias, h * h * curvature / (8.0 * slope));
  }
  if (!std::isfinite(slowest)) return std::nullopt;

  HallTiming out;
  out.pulse_height = height;
  out.slope = slowest;
  // Each sample's error in counts: the noise, the ADC's step, and the jitter times the slope. A
  // crossing interpolated a fraction f of the way between two samples carries (1 - f)^2 + f^2 of
  // their variance: 2/3 on average over f.
  const double noise_counts = sensor.noise * counts_per_volt;
  const double jitter_counts = sensor.jitter * slowest;
  const double sample_variance =
      noise_counts * noise_counts + 1.0 / 12.0 + jitter_counts * jitter_counts;
  out.crossing_sd = std::sqrt(2.0 / 3.0 * sample_variance) / slowest;
  out.interpolation_bias = bias;
  // The groups whose last crossing falls within the run; the estimator learns the signal from
  // the first two and times periods between the rest.
  const int groups =
      static_cast<int>(std::floor((rig.world.duration - turning - half_span) / period)) + 1;
  out.periods = groups - 3;
  out.period_error = out.periods >= 2 ? (3.0 * out.crossing_sd + 2.0 * out.interpolation_bias) /
                                            (out.periods * period)
                                      : std::numeric_limits<double>::infinity();
  return out;
}

}  // namespace fl
