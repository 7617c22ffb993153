#include "lab/run/motion_diagnosis.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <fmt/format.h>

#include "core/oscillation_tracker.hpp"

namespace fl {
namespace {

bool lasting(const StickEpisode& e) {
  return e.steps > kGrazeSteps;
}

double mean(const std::vector<double>& v) {
  double sum = 0.0;
  for (const double x : v) sum += x;
  return v.empty() ? 0.0 : sum / static_cast<double>(v.size());
}

// The turning points at or after time `from`.
struct Span {
  std::vector<double> times;
  std::vector<double> amplitudes;
};
Span turning_points_after(const MotionEvidence& e, double from) {
  Span s;
  for (std::size_t i = 0; i < e.turning_times.size(); ++i) {
    if (e.turning_times[i] < from) continue;
    s.times.push_back(e.turning_times[i]);
    s.amplitudes.push_back(e.turning_amplitudes[i]);
  }
  return s;
}

// The e-folding rate d ln A / dt of a span's turning points (at least four), and whether the
// amplitude changes by more than kSteadyFraction over the span.
struct Trend {
  double rate = 0.0;  // 1/s
  double change = 0.0;
};
std::optional<Trend> trend_of(const Span& s) {
  if (s.times.size() < 4) return std::nullopt;
  std::vector<double> log_amplitude;
  for (const double a : s.amplitudes) {
    if (!(a > 0.0)) return std::nullopt;
    log_amplitude.push_back(std::log(a));
  }
  const LinearFit fit = fit_line(s.times, log_amplitude);
  return Trend{fit.slope, std::expm1(fit.slope * (s.times.back() - s.times.front()))};
}

std::string millimetres(double metres) {
  return fmt::format("{:.2f} mm", metres * 1e3);
}

// Stick phases that keep coming back: a stick-slip cycle. The first stick brings the plate onto
// the cycle; the cycle is read from the later ones. Whether `held` (the lasting sticks) shows one,
// written into `f`.
bool stick_slip(const MotionEvidence& e, const std::vector<StickEpisode>& held, MotionFinding& f) {
  if (held.size() >= 3) {
    std::vector<double> intervals;  // between sticks to the same roller
    std::vector<double> durations;
    for (std::size_t i = 1; i < held.size(); ++i) {
      for (std::size_t j = i + 1; j < held.size(); ++j) {
        if (held[j].roller == held[i].roller) {
          intervals.push_back(held[j].start - held[i].start);
          break;
        }
      }
      if (!held[i].open) durations.push_back(held[i].end - held[i].start + e.time_step);
    }
    const double gap =
        intervals.empty() ? e.duration : *std::max_element(intervals.begin(), intervals.end());
    if (e.duration - held.back().start <= 1.5 * gap) {
      f.regime = Regime::kStickSlip;
      f.since = held.front().start;
      if (!intervals.empty()) f.cycle_period = mean(intervals);
      if (!durations.empty()) f.stick_duration = mean(durations);
      const Span cycle = turning_points_after(e, held[1].start);
      if (!cycle.amplitudes.empty()) f.cycle_amplitude = mean(cycle.amplitudes);
      f.evidence = fmt::format(
          "the plate stuck to a roller {} times from t = {:.4f} s on{}{}{}", held.size(),
          held.front().start,
          f.cycle_period ? fmt::format(", a cycle of {:.5f} s", *f.cycle_period) : std::string(),
          f.stick_duration ? fmt::format(" with sticks of {:.4f} s", *f.stick_duration)
                           : std::string(),
          f.cycle_amplitude ? ", amplitude " + millimetres(*f.cycle_amplitude) : std::string());
      return true;
    }
  }
  return false;
}

// A stick (or a graze) that clipped the amplitude, then a steady slipping oscillation, written
// into `f`.
void clipped(const MotionEvidence& e, const std::vector<StickEpisode>& held, MotionFinding& f) {
  const StickEpisode& first = e.sticks.front();
  f.regime = Regime::kClipped;
  f.since = first.start;
  f.clip_time = first.start;
  const Span before = [&] {
    Span s;
    for (std::size_t i = 0; i < e.turning_times.size() && e.turning_times[i] < first.start; ++i) {
      s.times.push_back(e.turning_times[i]);
      s.amplitudes.push_back(e.turning_amplitudes[i]);
    }
    return s;
  }();
  f.amplitude_before = before.amplitudes.empty() ? e.amplitude_start : before.amplitudes.back();
  const Span after = turning_points_after(e, held.empty() ? first.end : held.back().end);
  if (!after.amplitudes.empty()) {
    const std::size_t n = after.amplitudes.size();
    f.amplitude_after = mean(
        {after.amplitudes.begin() + static_cast<std::ptrdiff_t>(n - std::min<std::size_t>(n, 4)),
         after.amplitudes.end()});
  }
  f.evidence = fmt::format(
      "the plate reached roller {}'s surface speed at t = {:.4f} s and moved with it for {:.4f} s; "
      "then both rollers slipped{}, at an amplitude of {}{}",
      first.roller, first.start, first.end - first.start + e.time_step,
      f.graze_count > (lasting(first) ? 0 : 1)
          ? fmt::format(" (grazing a roller's speed {} times)",
                        f.graze_count - (lasting(first) ? 0 : 1))
          : std::string(),
      f.amplitude_after ? millimetres(*f.amplitude_after) : std::string("(not measured)"),
      f.amplitude_before ? " (" + millimetres(*f.amplitude_before) + " before)" : std::string());
}

}  // namespace

MotionFinding diagnose_motion(const MotionEvidence& e) {
  MotionFinding f;
  std::vector<StickEpisode> held;  // the lasting ones
  for (const StickEpisode& s : e.sticks) {
    if (lasting(s))
      held.push_back(s);
    else
      ++f.graze_count;
  }
  f.stick_count = static_cast<int>(held.size());

  // Stuck for good: the last episode is still on and has lasted a quarter of the run.
  if (!e.sticks.empty() && e.sticks.back().open &&
      e.duration - e.sticks.back().start >= 0.25 * e.duration) {
    const StickEpisode& s = e.sticks.back();
    f.regime = Regime::kSticks;
    f.since = s.start;
    f.evidence = fmt::format(
        "the plate moved with roller {}'s surface from t = {:.4f} s to the end of the run ({:.3f} "
        "s): it stays stuck",
        s.roller, s.start, e.duration - s.start);
    return f;
  }

  if (stick_slip(e, held, f)) return f;

  // Slipping since the last lasting stick (grazes do not interrupt it).
  const double slipping_from = held.empty() ? 0.0 : held.back().end;
  const Span span = turning_points_after(e, slipping_from);
  const std::optional<Trend> trend = trend_of(span);
  if (trend) {
    f.growth_rate = trend->rate;
    f.slipping_since = span.times.front();
  }
  const bool steady = !trend || !e.slip_dependent || std::fabs(trend->change) <= kSteadyFraction;

  if (!steady) {
    f.regime = trend->rate > 0.0 ? Regime::kGrows : Regime::kDecays;
    f.since = held.empty() ? 0.0 : span.times.front();
    f.evidence = fmt::format(
        "both rollers slipped{}; the amplitude went from {} to {} between t = {:.3f} s and {:.3f} "
        "s, an e-folding rate of {:+.5f} /s ({} {:.3f} s)",
        held.empty() ? " throughout"
                     : fmt::format(" after the plate's last stick at t = {:.4f} s", slipping_from),
        millimetres(span.amplitudes.front()), millimetres(span.amplitudes.back()),
        span.times.front(), span.times.back(), trend->rate,
        trend->rate > 0.0 ? "doubling every" : "halving every",
        std::log(2.0) / std::fabs(trend->rate));
    return f;
  }

  if (e.sticks.empty()) {
    f.regime = Regime::kOscillates;
    f.evidence = fmt::format("both rollers slipped throughout at a steady amplitude{}",
                             trend ? fmt::format(" ({:+.2e} /s)", trend->rate) : std::string());
    return f;
  }

  clipped(e, held, f);
  return f;
}

}  // namespace fl
