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

Oscillation strongest_oscillation(const Series& channel, const Periodicity& p) {
  if (!(p.strongest_hz > 0.0)) return {};
  const std::size_t n = channel.values.size();
  const std::size_t every = (n + kMostSamples - 1) / kMostSamples;
  std::vector<double> t, v;
  double mean = 0.0;
  for (std::size_t k = 0; k < n; k += every) {
    t.push_back(channel.t_s[k]);
    v.push_back(channel.values[k]);
    mean += channel.values[k];
  }
  mean /= static_cast<double>(v.size());
  // The least-squares sinusoid at f: its cosine and sine parts solved from the 2x2 normal
  // equations (the samples need not span whole periods).
  const auto fit = [&](double f) {
    double cc = 0.0, ss = 0.0, cs = 0.0, xc = 0.0, xs = 0.0;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const double phase = 2.0 * std::numbers::pi * f * t[k];
      const double c = std::cos(phase), s = std::sin(phase), x = v[k] - mean;
      cc += c * c, ss += s * s, cs += c * s, xc += x * c, xs += x * s;
    }
    const double det = cc * ss - cs * cs;
    if (!(std::abs(det) > 0.0)) return 0.0;
    const double a = (xc * ss - xs * cs) / det, b = (xs * cc - xc * cs) / det;
    return std::hypot(a, b);
  };
  // Golden-section search for the largest amplitude within a resolution step of the peak.
  const double span_s = channel.t_s.back() - channel.t_s.front();
  double lo = p.strongest_hz - 0.5 / span_s, hi = p.strongest_hz + 0.5 / span_s;
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
  double f1 = fit(x1), f2 = fit(x2);
  for (int i = 0; i < 40; ++i) {
    if (f1 < f2) {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + golden * (hi - lo), f2 = fit(x2);
    } else {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - golden * (hi - lo), f1 = fit(x1);
    }
  }
  return f1 > f2 ? Oscillation{x1, f1} : Oscillation{x2, f2};
}

Periodicity require_periodic_motion(const Series& channel, const SourceLocation& where,
                                    const Said& instrument, const Said& column) {
  const Periodicity p = periodicity_of(channel);
  if (p.periodic()) return p;
  throw InputError(where, said("reading-not-periodic",
                               {arg("instrument", instrument), arg("column", column),
                                arg("frequency_hz", to_significant_digits(p.strongest_hz, 3)),
                                arg("period_s", to_significant_digits(1.0 / p.strongest_hz, 3)),
                                arg("ratio", to_decimal_places(p.peak_over_median, 1)),
                                arg("least_ratio", kLeastPeakOverMedian),
                                arg("noise", to_significant_digits(p.noise, 3)),
                                arg("swing", to_significant_digits(p.swing, 3))}));
}

}  // namespace fl
