#include "lab/logs/geometry_check.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "core/sample_summary.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "io/json_value.hpp"

namespace fl {
namespace {

// The periods' alternation over independent triples of consecutive accepted periods.
void measure_alternation(const LogEstimate& est, GeometryCheck* check) {
  const std::vector<EstimatedPeriod>& p = est.periods;
  if (p.empty()) return;
  const double t = static_cast<double>(est.stats.period_s);
  if (!(t > 0.0)) return;
  std::vector<double> e;
  for (std::size_t i = 0; i + 2 < p.size();) {
    const bool run = p[i].status == fl_estimator::kAccepted &&
                     p[i + 1].status == fl_estimator::kAccepted &&
                     p[i + 2].status == fl_estimator::kAccepted &&
                     std::fabs(p[i + 1].start - p[i].end) < 0.25 * t &&
                     std::fabs(p[i + 2].start - p[i + 1].end) < 0.25 * t;
    if (!run) {
      ++i;
      continue;
    }
    // The parity of the middle period on the log's time axis (a discarded period keeps it).
    const long k = std::lround((p[i + 1].start - p.front().start) / t);
    const double sign = k % 2 == 0 ? 1.0 : -1.0;
    e.push_back(sign * (p[i + 1].period - 0.5 * (p[i].period + p[i + 2].period)));
    i += 3;
  }
  check->alternation_triples = static_cast<int>(e.size());
  if (e.size() < 4) return;
  double mean = 0.0;
  for (double x : e) mean += x;
  mean /= static_cast<double>(e.size());
  double var = 0.0;
  for (double x : e) var += (x - mean) * (x - mean);
  var /= static_cast<double>(e.size() - 1);
  const double err = std::sqrt(var / static_cast<double>(e.size()));
  check->alternation_s = mean;
  check->alternation_err_s = err;
  check->alternates = std::fabs(mean) > 5.0 * err && std::fabs(mean) > 5e-4 * t;
}

bool at_a_rail(int value) {
  for (int bits : {8, 10, 12, 14, 16})
    if (value == (1 << bits) - 1) return true;
  return value == 0;
}

// One pulse's (width at 1/4) / (width at 1/2) of its own height above the baseline, and the
// samples within its half-height width; false when the pulse cannot be measured.
bool pulse_shape(const HallLog& log, const EstimatedPulse& pulse, double baseline, int polarity,
                 double* ratio, int* across, bool* clipped) {
  const double width = pulse.fall - pulse.rise;
  if (!(width > 0.0)) return false;
  const auto begin = std::lower_bound(log.t_s.begin(), log.t_s.end(), pulse.rise - 2.0 * width);
  const auto end = std::upper_bound(log.t_s.begin(), log.t_s.end(), pulse.fall + 2.0 * width);
  const auto lo = static_cast<std::size_t>(begin - log.t_s.begin());
  const auto hi = static_cast<std::size_t>(end - log.t_s.begin());
  if (hi <= lo + 2) return false;
  const auto dev = [&](std::size_t i) {
    return polarity * (static_cast<double>(log.adc[i]) - baseline);
  };
  std::size_t top = lo;
  for (std::size_t i = lo; i < hi; ++i) {
    if (log.t_s[i] < pulse.rise || log.t_s[i] > pulse.fall) continue;
    if (top == lo || dev(i) > dev(top)) top = i;
  }
  const double peak = dev(top);
  if (!(peak > 0.0)) return false;
  *clipped = at_a_rail(log.adc[top]);
  // The crossings of `level` nearest the top on either side, interpolated.
  const auto crossing = [&](double level, int step, double* at) {
    std::size_t i = top;
    for (;;) {
      if ((step < 0 && i == lo) || (step > 0 && i + 1 >= hi)) return false;
      const std::size_t j = step < 0 ? i - 1 : i + 1;
      if (dev(j) < level) {
        const double f = (dev(i) - level) / (dev(i) - dev(j));
        *at = log.t_s[i] + f * (log.t_s[j] - log.t_s[i]);
        return true;
      }
      i = j;
    }
  };
  double l50 = 0.0, r50 = 0.0, l25 = 0.0, r25 = 0.0;
  if (!crossing(0.5 * peak, -1, &l50) || !crossing(0.5 * peak, 1, &r50) ||
      !crossing(0.25 * peak, -1, &l25) || !crossing(0.25 * peak, 1, &r25))
    return false;
  if (!(r50 > l50)) return false;
  *ratio = (r25 - l25) / (r50 - l50);
  *across = static_cast<int>(std::upper_bound(log.t_s.begin(), log.t_s.end(), r50) -
                             std::lower_bound(log.t_s.begin(), log.t_s.end(), l50));
  return true;
}

void measure_shape(const HallLog& log, const LogEstimate& est, GeometryCheck* check) {
  std::vector<double> ratios;
  std::vector<double> across;
  int clipped = 0;
  for (std::size_t i = 0; i < est.pulses.size() && i < est.pulse_baseline.size(); ++i) {
    if (est.pulses[i].distorted) continue;
    double r = 0.0;
    int n = 0;
    bool rail = false;
    if (!pulse_shape(log, est.pulses[i], static_cast<double>(est.pulse_baseline[i]), est.polarity,
                     &r, &n, &rail))
      continue;
    ratios.push_back(r);
    across.push_back(n);
    clipped += rail ? 1 : 0;
  }
  check->shape_pulses = static_cast<int>(ratios.size());
  if (ratios.empty()) return;
  check->shape_ratio = median_of(ratios);
  check->samples_across = median_of(across);
  check->clipped = 2 * clipped > static_cast<int>(ratios.size());
}

}  // namespace

GeometryCheck check_geometry(const HallLog& log, const LogEstimate& est) {
  GeometryCheck check;
  check.needed =
      est.set_up.geometry == fl_estimator::kAutoGeometry && est.geometry == fl_estimator::kOnePulse;
  if (!check.needed) return check;
  measure_alternation(est, &check);
  measure_shape(log, est, &check);
  if (check.alternates) {
    check.verdict = "alternating";
    check.reason = fmt::format(
        "the periods alternate short and long: each is {:+.3f} ms off the mean of its two "
        "neighbours, by turns ({:.1f} standard errors over {} independent triples), as two pulses "
        "per period give when the sensor is near, not at, the middle of the travel",
        *check.alternation_s * 1e3, std::fabs(*check.alternation_s / *check.alternation_err_s),
        check.alternation_triples);
  } else if (check.shape_pulses < 3) {
    check.verdict = "unknown";
    check.reason = fmt::format(
        "the shape of fewer than three pulses ({}) could be measured to tell a turn from a pass",
        check.shape_pulses);
  } else if (check.clipped) {
    check.verdict = "unknown";
    check.reason =
        "the pulses are clipped at the ADC's rail, so their shape cannot tell a turn from a pass";
  } else if (*check.samples_across < 5.0) {
    check.verdict = "unknown";
    check.reason = fmt::format(
        "a pulse spans {:.0f} samples at half its height, too few to tell a turn from a pass by "
        "its shape (5 are needed: a higher sample rate would do)",
        *check.samples_across);
  } else if (*check.shape_ratio > kPassShapeRatio) {
    check.verdict = "pass";
    check.reason = fmt::format(
        "their shape is a pass's: a pulse's width at a quarter of its height is {:.2f} times its "
        "width at half height (median of {} pulses), where a magnet turning at the sensor gives "
        "at most about 1.39 and a small one passing it at speed 1.44 to 1.48",
        *check.shape_ratio, check.shape_pulses);
  } else {
    check.verdict = "turn";
  }
  return check;
}

nlohmann::json geometry_check_json(const GeometryCheck& check) {
  if (!check.needed) return nullptr;
  return {{"verdict", check.verdict},
          {"pulse_shape_ratio", json_or_null(check.shape_ratio)},
          {"shape_pulses", check.shape_pulses},
          {"samples_across_pulse", json_or_null(check.samples_across)},
          {"alternation_s", json_or_null(check.alternation_s)},
          {"alternation_err_s", json_or_null(check.alternation_err_s)},
          {"alternation_triples", check.alternation_triples}};
}

void require_geometry(const HallLog& log, const LogEstimate& est, const GeometryCheck& check,
                      const std::string& note) {
  if (!check.needed || check.verdict == "turn") return;
  const double tau = static_cast<double>(est.stats.period_s);
  const auto it = std::lower_bound(log.t_s.begin(), log.t_s.end(),
                                   est.pulses.empty() ? log.t_s.front() : est.pulses.front().time);
  const std::size_t i = it == log.t_s.end() ? log.t_s.size() - 1 : it - log.t_s.begin();
  const SourceLocation at{log.path, log.line[i], 0};
  throw InputError(
      at, fmt::format(
              "{} pulses at even intervals of {:.4f} s: one pulse per period gives them (a magnet "
              "turning at a sensor beyond its turning point: T = {:.4f} s, mu_k = {:.4f}) and so "
              "do two (a magnet passing a sensor at the middle of its travel: T = {:.4f} s, mu_k "
              "= {:.4f}); {}. Say which: {} for a sensor at the end of the travel, {} for one at "
              "the middle{}",
              est.pulses.size(), tau, tau, static_cast<double>(est.stats.mu_k), 2.0 * tau,
              static_cast<double>(est.stats.mu_k) / 4.0, check.reason, field_ref("geometry", "one"),
              field_ref("geometry", "pair"), note));
}

}  // namespace fl
