#include "hall_log/periodic_motion.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "hall_log/instrument_signal.hpp"

namespace fl {
namespace {

constexpr double kLowestHz = 0.2;
constexpr double kHighestHz = 25.0;
constexpr std::size_t kMostSamples = 20000;
constexpr std::size_t kMostFrequencies = 4000;

}  // namespace

Periodicity periodicity_of(const Series& channel) {
  Periodicity out;
  const std::size_t n = channel.values.size();
  if (n < 16 || channel.t_s.back() <= channel.t_s.front()) return out;
  const std::size_t every = (n + kMostSamples - 1) / kMostSamples;
  std::vector<double> v;
  for (std::size_t k = 0; k < n; k += every) v.push_back(channel.values[k]);
  const double span_s = channel.t_s.back() - channel.t_s.front();
  const double step_s = span_s / static_cast<double>(n - 1) * static_cast<double>(every);
  // Less its straight line (a sensor's slow drift is no motion).
  const auto m = static_cast<double>(v.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const auto x = static_cast<double>(k);
    sx += x, sy += v[k], sxx += x * x, sxy += x * v[k];
  }
  const double slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
  const double offset = (sy - slope * sx) / m;
  for (std::size_t k = 0; k < v.size(); ++k) v[k] -= offset + slope * static_cast<double>(k);

  std::vector<double> changes;
  for (std::size_t k = 1; k < n; ++k)
    changes.push_back(std::abs(channel.values[k] - channel.values[k - 1]));
  std::nth_element(changes.begin(), changes.begin() + changes.size() / 2, changes.end());
  out.noise = 1.4826 * changes[changes.size() / 2] / std::numbers::sqrt2;
  if (const std::optional<Spread> s = spread_of(channel.values)) out.swing = s->high - s->low;

  // Frequencies from kLowestHz to the band's top, at half the record's resolution.
  const double top = std::min(kHighestHz, 0.5 / step_s);
  const double resolution = std::max(0.5 / span_s, (top - kLowestHz) / kMostFrequencies);
  std::vector<double> power;
  double strongest = -1.0;
  for (double f = kLowestHz; f <= top; f += resolution) {
    const std::complex<double> turn = std::polar(1.0, -2.0 * std::numbers::pi * f * step_s);
    std::complex<double> phase = 1.0, sum = 0.0;
    for (double x : v) {
      sum += x * phase;
      phase *= turn;
    }
    power.push_back(std::norm(sum));
    if (power.back() > strongest) {
      strongest = power.back();
      out.strongest_hz = f;
    }
  }
  if (power.size() < 8) return out;
  std::nth_element(power.begin(), power.begin() + power.size() / 2, power.end());
  const double median = power[power.size() / 2];
  out.peak_over_median = median > 0.0 ? strongest / median : (strongest > 0.0 ? 1e300 : 0.0);
  return out;
}

void require_periodic_motion(const Series& channel, const SourceLocation& where,
                             const std::string& instrument, const std::string& column) {
  const Periodicity p = periodicity_of(channel);
  if (p.periodic()) return;
  throw InputError(
      where,
      fmt::format("expected a periodic motion, found none in the {}'s {}: its strongest "
                  "frequency, {:.3g} Hz (a period of {:.3g} s), stands {:.1f} times above its "
                  "spectrum's median, where a swinging plate's stands {:.0f} times or more; its "
                  "noise is {:.3g} and it swings by {:.3g} (in that column's unit). Is it a "
                  "recording of the rig oscillating, not of a phone lying still or of another "
                  "experiment?",
                  instrument, column, p.strongest_hz, 1.0 / p.strongest_hz, p.peak_over_median,
                  kLeastPeakOverMedian, p.noise, p.swing));
}

}  // namespace fl
