// A synthetic Hall-sensor log with a known truth, for the estimator's tests, the firmware test
// and the benchmark: a point-dipole magnet on the plate oscillating x(t) = A cos(2 pi t/T + phi),
// a sensor fixed near the magnet's largest displacement that reads the field component along its
// axis, a linear sensor into a 10-bit ADC. On top: sample-time jitter, additive noise, baseline
// drift, clipping at the ADC's rails, and jumps of the plate (a pulse blanked out, a spurious
// pulse added).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace fl::test {

struct HallSignal {
  double period_s = 0.79;     // true period T
  double amplitude_m = 0.02;  // plate amplitude A
  double phase_rad = 0.4;     // phi: the magnet is farthest out at t = (2 pi k - phi) T / (2 pi)
  // Sensor position along x minus the magnet's largest x: > 0 the sensor is beyond the turning
  // point (one pulse per period), < 0 the magnet passes over it and back (a pair per period).
  double sensor_offset_m = 0.003;
  double sensor_y_m = 0.0;          // sideways offset of the sensor
  double magnet_height_m = 0.008;   // height of the magnet above the sensor
  bool axis_along_x = false;        // the sensor reads B_x instead of B_z
  double peak_counts = 300.0;       // |field| straight above the sensor, in ADC counts
  int polarity = 1;                 // +1: the field pushes the ADC up; -1: down
  double baseline_counts = 512.0;   // sensor output without field [counts]
  double drift_counts_per_s = 0.0;  // linear drift of the baseline
  double drift_sine_counts = 0.0;   // plus a slow sinusoidal wander of this amplitude
  double drift_sine_period_s = 30.0;
  double noise_counts = 0.0;  // Gaussian noise sigma [counts]
  double sample_rate_hz = 1000.0;
  double jitter_us = 0.0;            // sample instants uniform in +- jitter_us around the nominal
  bool jitter_in_timestamps = true;  // timestamps record the jittered instant (else nominal)
  double duration_s = 20.0;
  uint32_t t0_us = 0;  // clock reading at the first sample (wrap tests)
  uint64_t seed = 1;
  std::vector<std::pair<double, double>> blanks;  // [from, to] [s]: no field (a missing pulse)
  std::vector<double> spurious;                   // extra Gaussian pulses at these times [s]
  double spurious_width_s = 0.01;                 // their sigma
  double spurious_height = 1.0;                   // their height, in units of peak_counts
};

struct HallSamples {
  std::vector<uint32_t> t_us;  // clock readings (wrap at 2^32)
  std::vector<uint16_t> adc;   // 10-bit values
  std::vector<double> t_s;     // true sampling instants since the first nominal one [s]
};

inline constexpr double kPiTest = 3.14159265358979323846;

// Field along the sensor axis of a z-directed point dipole, normalised to 1 straight above.
inline double dipole_field(const HallSignal& s, double t) {
  const double x_mag = s.amplitude_m * std::cos(2.0 * kPiTest * t / s.period_s + s.phase_rad);
  const double x_sensor = s.amplitude_m + s.sensor_offset_m;
  const double dx = x_mag - x_sensor;
  const double dy = -s.sensor_y_m;
  const double dz = s.magnet_height_m;
  const double r2 = dx * dx + dy * dy + dz * dz;
  const double r5 = r2 * r2 * std::sqrt(r2);
  const double h3 = dz * dz * dz;
  // B = (3 (m.r) r - m r^2) / r^5 with m = z: B_z = (3 dz^2 - r^2)/r^5, B_x = 3 dz dx / r^5.
  const double b = s.axis_along_x ? 3.0 * dz * dx / r5 : (3.0 * dz * dz - r2) / r5;
  return b * h3 / 2.0;
}

inline double clean_signal(const HallSignal& s, double t) {
  double field = dipole_field(s, t);
  for (const auto& [from, to] : s.blanks)
    if (t >= from && t <= to) field = 0.0;
  for (double c : s.spurious) {
    const double u = (t - c) / s.spurious_width_s;
    field += s.spurious_height * std::exp(-0.5 * u * u);
  }
  const double drift = s.drift_counts_per_s * t +
                       s.drift_sine_counts * std::sin(2.0 * kPiTest * t / s.drift_sine_period_s);
  return s.baseline_counts + drift + s.polarity * s.peak_counts * field;
}

inline HallSamples generate(const HallSignal& s) {
  HallSamples out;
  std::mt19937_64 rng(s.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::uniform_real_distribution<double> jitter(-1.0, 1.0);
  const auto n = static_cast<std::size_t>(std::floor(s.duration_s * s.sample_rate_hz));
  out.t_us.reserve(n);
  out.adc.reserve(n);
  out.t_s.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double nominal = static_cast<double>(k) / s.sample_rate_hz;
    const double t = nominal + (s.jitter_us > 0.0 ? s.jitter_us * 1e-6 * jitter(rng) : 0.0);
    double v = clean_signal(s, t);
    if (s.noise_counts > 0.0) v += s.noise_counts * noise(rng);
    v = std::clamp(std::round(v), 0.0, 1023.0);
    const double stamp = s.jitter_in_timestamps ? t : nominal;
    out.t_us.push_back(s.t0_us + static_cast<uint32_t>(std::llround(std::max(stamp, 0.0) * 1e6)));
    out.adc.push_back(static_cast<uint16_t>(v));
    out.t_s.push_back(t);
  }
  return out;
}

// Times in [from, to] at which the magnet is farthest out (the plate's turning points).
inline std::vector<double> turning_times(const HallSignal& s, double from, double to) {
  std::vector<double> out;
  const double first = -s.phase_rad / (2.0 * kPiTest) * s.period_s;
  for (double k = std::ceil((from - first) / s.period_s);; k += 1.0) {
    const double t = first + k * s.period_s;
    if (t > to) break;
    out.push_back(t);
  }
  return out;
}

}  // namespace fl::test
