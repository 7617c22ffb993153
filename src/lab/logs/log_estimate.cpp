#include "lab/logs/log_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string_view>

#include <fmt/format.h>

#include "core/analytic_model.hpp"
#include "core/plausible_range.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "io/json_value.hpp"
#include "lab/logs/estimate_fields.hpp"
#include "lab/logs/geometry_check.hpp"
#include "text/said.hpp"
#include "text/utf8.hpp"

namespace fl {
namespace {

// The log's line nearest to a time.
int line_at(const HallLog& log, double t) {
  const auto it = std::lower_bound(log.t_s.begin(), log.t_s.end(), t);
  const std::size_t i = it == log.t_s.end() ? log.t_s.size() - 1 : it - log.t_s.begin();
  return log.line[i];
}

// Refuses the log, saying why: in the catalogues' words, or in English only where a note in
// English only (a unit's hint, a plot's place) goes with it.
[[noreturn]] void refuse(const SourceLocation& where, const Said& why, const std::string& note) {
  if (note.empty()) throw InputError(where, why);
  throw InputError(where, english(why) + note);
}

// The keys of one part of the declaration (lab/logs/estimate_fields.hpp).
nlohmann::json part_json(const HallLog& log, const LogEstimate& estimate, EstimatePart part) {
  nlohmann::json out = nlohmann::json::object();
  for (const EstimateField& f : estimate_fields())
    if (f.part == part && f.get != nullptr) out[f.json] = f.get({log, estimate}).json();
  return out;
}

// Enough accepted periods, no more discarded, scattering as a rig's do (require_periods' checks).
bool periods_of_a_rig(const fl_estimator::Stats& s) {
  return s.periods_used >= static_cast<std::uint32_t>(kLeastPeriods) &&
         s.periods_discarded <= s.periods_used &&
         static_cast<double>(s.period_std_s) <=
             kMostPeriodScatter * static_cast<double>(s.period_s);
}

}  // namespace

fl_estimator::Config LogSetUp::config() const {
  fl_estimator::Config config;
  config.spacing_m = static_cast<float>(spacing);
  config.spacing_err_m = static_cast<float>(spacing_err);
  config.gravity_m_s2 = static_cast<float>(gravity);
  config.geometry = geometry;
  return config;
}

const char* period_status_name(std::uint8_t status) {
  return status == fl_estimator::kAccepted          ? "accepted"
         : status == fl_estimator::kRejectedOutlier ? "outlier"
                                                    : "broken";
}

const char* geometry_name(fl_estimator::Geometry geometry) {
  return geometry == fl_estimator::kOnePulse    ? "one-pulse"
         : geometry == fl_estimator::kPulsePair ? "pair"
                                                : "unknown";
}

std::optional<fl_estimator::Geometry> geometry_from_option(std::string_view text) {
  if (text == "auto") return fl_estimator::kAutoGeometry;
  if (text == "one") return fl_estimator::kOnePulse;
  if (text == "pair") return fl_estimator::kPulsePair;
  return std::nullopt;
}

LogEstimate estimate_log(const HallLog& log, const LogSetUp& set_up, bool traces) {
  HostEstimator host(set_up.config(), log.t_s.front());
  LogEstimate out;
  out.set_up = set_up;
  if (traces) {
    out.baseline_trace.reserve(log.adc.size());
    out.level_trace.reserve(log.adc.size());
  }
  const fl_estimator::PeriodEstimator& e = host.estimator();
  for (std::size_t i = 0; i < log.adc.size(); ++i) {
    if (host.add(log.t_us[i], log.adc[i]) & fl_estimator::kSignalLearned) out.learned = true;
    // The baseline is frozen during a pulse: the one after it is the one it was timed from.
    while (out.pulse_baseline.size() < host.pulses().size())
      out.pulse_baseline.push_back(e.baseline());
    if (traces) {
      const bool known = e.phase() != fl_estimator::kLearning;
      const float nan = std::numeric_limits<float>::quiet_NaN();
      out.baseline_trace.push_back(known ? e.baseline() : nan);
      out.level_trace.push_back(known ? e.timing_level() : nan);
    }
  }
  host.finish();
  out.stats = e.stats();
  out.geometry = e.geometry();
  out.polarity = e.polarity();
  out.baseline = static_cast<double>(e.baseline());
  out.pulses = host.pulses();
  out.periods = host.periods();
  for (const EstimatedPeriod& p : out.periods)
    out.outliers += p.status == fl_estimator::kRejectedOutlier ? 1 : 0;
  for (const EstimatedPulse& p : out.pulses) out.distorted += p.distorted ? 1 : 0;
  out.duration = log.t_s.back() - log.t_s.front();
  out.sample_rate = log.adc.size() > 1 ? static_cast<double>(log.adc.size() - 1) / out.duration : 0;
  return out;
}

std::string time_unit_hint(const HallLog& log, const LogEstimate& est) {
  const HallLogReading& r = log.reading;
  if (r.time_unit.empty() || r.time_unit_from == "inferred" || !(est.sample_rate > 0.0)) return "";
  constexpr double kLeast = 20.0;  // Hz: the slowest a rig's Arduino samples a Hall sensor
  constexpr double kMost = 2e4;    // Hz: the fastest an Uno's ADC goes
  if (est.sample_rate >= kLeast && est.sample_rate <= kMost) return "";
  const auto seconds = [](const std::string& unit) {
    return unit == "us" ? 1e-6 : unit == "ms" ? 1e-3 : 1.0;
  };
  for (const char* unit : {"us", "ms", "s"}) {
    if (unit == r.time_unit) continue;
    const double factor = seconds(unit) / seconds(r.time_unit);
    const double rate = est.sample_rate / factor;
    if (rate < kLeast || rate > kMost) continue;
    // Checked before it is given: the log read in that unit gives a rig's T and mu_k.
    std::vector<double> t_s(log.t_s);
    for (double& t : t_s) t *= factor;
    const HallLog read_so = hall_log_from_samples(
        std::move(t_s), std::vector<double>(log.adc.begin(), log.adc.end()), log.path);
    const fl_estimator::Stats s = estimate_log(read_so, est.set_up, false).stats;
    if (!periods_of_a_rig(s) || implausible(static_cast<double>(s.period_s), kPeriodRange) ||
        implausible(static_cast<double>(s.mu_k), kMuKRange))
      continue;
    return fmt::format(
        "; the samples come {:.4g} a second read in {} ({}), where a rig samples 20 to 20000 a "
        "second: if its time is in {}, give {}, which reads it as T = {:.4f} s, mu_k {:.3f} from "
        "{} periods",
        est.sample_rate, r.time_unit,
        r.time_unit_from == "header" ? "as the header names it" : "as given", unit,
        field_ref("time_unit", unit), static_cast<double>(s.period_s), static_cast<double>(s.mu_k),
        s.periods_used);
  }
  return "";
}

void require_plausible(const HallLog& log, const LogEstimate& est, const std::string& note) {
  const fl_estimator::Stats& s = est.stats;
  std::optional<Said> why = implausible_said(static_cast<double>(s.period_s), kPeriodRange);
  if (!why) why = implausible_said(static_cast<double>(s.mu_k), kMuKRange);
  if (!why) return;
  refuse({log.path, log.line.front(), 0},
         said("estimate-no-rig", {arg("period_s", static_cast<double>(s.period_s)),
                                  arg("mu_k", static_cast<double>(s.mu_k)), arg("why", *why)}),
         time_unit_hint(log, est) + note);
}

void require_periods(const HallLog& log, const LogEstimate& est, const std::string& note_given) {
  const fl_estimator::Stats& s = est.stats;
  // A time read in the wrong unit makes pulses look absent or a period absurd: say which unit
  // would make the log a rig's.
  const std::string note = time_unit_hint(log, est) + note_given;
  const SourceLocation first{log.path, log.line.front(), 0};
  const double duration = est.duration;
  if (est.pulses.empty()) {
    const int min_amplitude = est.set_up.config().min_amplitude;
    const auto [lo, hi] = std::minmax_element(log.adc.begin(), log.adc.end());
    const int swing = *hi - *lo;
    const Said why =
        swing < min_amplitude
            ? said("estimate-swing-too-small", {arg("swing", swing), arg("needed", min_amplitude)})
        : !est.learned ? said("estimate-not-learned", {arg("swing", swing)})
                       : said("estimate-no-timing-level", {arg("swing", swing)});
    refuse(first,
           said("estimate-no-pulse",
                {arg("samples", log.adc.size()), arg("duration_s", to_decimal_places(duration, 3)),
                 arg("first_line", log.line.front()), arg("last_line", log.line.back()),
                 arg("low", static_cast<int>(*lo)), arg("high", static_cast<int>(*hi)),
                 arg("why", why)}),
           note);
  }
  const SourceLocation at_pulse{log.path, line_at(log, est.pulses.front().time), 0};
  if (est.pulses.size() == 1)
    refuse(at_pulse,
           said("estimate-one-pulse", {arg("duration_s", to_decimal_places(duration, 3)),
                                       arg("at_s", to_decimal_places(est.pulses.front().time, 4))}),
           note);
  if (est.periods.empty()) {
    std::string intervals;
    for (std::size_t i = 1; i < est.pulses.size() && i <= 8; ++i)
      intervals +=
          fmt::format("{}{:.4f}", i > 1 ? ", " : "", est.pulses[i].time - est.pulses[i - 1].time);
    if (est.pulses.size() > 9) intervals += ", ...";
    if (est.pulses.size() < 5)
      refuse(at_pulse,
             said("estimate-few-pulses",
                  {arg("pulses", est.pulses.size()), arg("intervals", intervals)}),
             note);
    // Do the intervals alternate (the 1st and 3rd of each four both shorter, or both longer,
    // than the 2nd and 4th)? Then the pulses are two per period, too wide a pair to recognise.
    int alternating = 0;
    int windows = 0;
    for (std::size_t i = 4; i < est.pulses.size(); ++i, ++windows) {
      double iv[4];
      for (std::size_t k = 0; k < 4; ++k)
        iv[k] = est.pulses[i - 3 + k].time - est.pulses[i - 4 + k].time;
      const bool ordered = std::max(iv[0], iv[2]) < std::min(iv[1], iv[3]) ||
                           std::max(iv[1], iv[3]) < std::min(iv[0], iv[2]);
      alternating += ordered ? 1 : 0;
    }
    const Said advice =
        2 * alternating > windows
            ? said("estimate-pulses-alternate", {arg("geometry", field_ref("geometry", "pair"))})
            : said("estimate-pulses-irregular", {arg("plot", field_ref("plot", "FILE.png"))});
    refuse(at_pulse,
           said("estimate-no-turning-points", {arg("pulses", est.pulses.size()),
                                               arg("intervals", intervals), arg("advice", advice)}),
           note);
  }
  // Periods that are a rig's oscillation: most of them kept, enough of them, and scattering as a
  // rig's do (docs/estimator.md, "Periods that are no rig's").
  const Said counts =
      said(est.periods.size() == 1 ? "estimate-counts-one" : "estimate-counts",
           {arg("pulses", static_cast<std::size_t>(s.pulses)), arg("periods", est.periods.size()),
            arg("accepted", static_cast<std::size_t>(s.periods_used)),
            arg("discarded", static_cast<std::size_t>(s.periods_discarded))});
  const Said look = said("estimate-look", {arg("plot", field_ref("plot", "FILE.png"))});
  const double tolerance_percent = 100.0 * static_cast<double>(est.set_up.config().tolerance);
  if (s.periods_discarded > s.periods_used)
    refuse(
        at_pulse,
        s.periods_used == 0
            ? said("estimate-more-discarded-none",
                   {arg("counts", counts),
                    arg("tolerance_percent", to_decimal_places(tolerance_percent, 0)),
                    arg("look", look)})
            : said("estimate-more-discarded",
                   {arg("counts", counts),
                    arg("tolerance_percent", to_decimal_places(tolerance_percent, 0)),
                    arg("accepted", static_cast<std::size_t>(s.periods_used)), arg("look", look)}),
        note);
  if (s.periods_used < static_cast<std::uint32_t>(kLeastPeriods))
    refuse(at_pulse,
           said("estimate-too-few-accepted", {arg("counts", counts), arg("least", kLeastPeriods)}),
           note);
  const double scatter = static_cast<double>(s.period_std_s) / static_cast<double>(s.period_s);
  if (scatter > kMostPeriodScatter)
    refuse(
        at_pulse,
        said(
            "estimate-scatter",
            {arg("counts", counts), arg("scatter_percent", to_decimal_places(100.0 * scatter, 1)),
             arg("spread_s", to_decimal_places(static_cast<double>(s.period_std_s), 4)),
             arg("period_s", to_decimal_places(static_cast<double>(s.period_s), 4)),
             arg("most_percent", to_decimal_places(100.0 * kMostPeriodScatter, 0)),
             arg("tolerance_percent", to_decimal_places(tolerance_percent, 0)), arg("look", look)}),
        note);
}

nlohmann::json log_estimate_json(const HallLog& log, const LogEstimate& est) {
  nlohmann::json out = nlohmann::json::object();
  for (const EstimateField& f : estimate_fields())
    if (f.get != nullptr) out[f.json] = f.get({log, est}).json();
  return out;
}

nlohmann::json hall_plot_data(const HallLog& log, const LogEstimate& est) {
  // Long logs keep the lowest and highest sample of each bucket, so no peak is lost.
  const std::size_t n = log.adc.size();
  const std::size_t kMaxPoints = 200000;
  const std::size_t bucket = std::max<std::size_t>(1, (2 * n + kMaxPoints - 1) / kMaxPoints);
  std::vector<std::size_t> keep;
  for (std::size_t start = 0; start < n; start += bucket) {
    const std::size_t stop = std::min(n, start + bucket);
    if (bucket == 1) {
      keep.push_back(start);
      continue;
    }
    std::size_t lo = start;
    std::size_t hi = start;
    for (std::size_t i = start; i < stop; ++i) {
      if (log.adc[i] < log.adc[lo]) lo = i;
      if (log.adc[i] > log.adc[hi]) hi = i;
    }
    keep.push_back(std::min(lo, hi));
    if (lo != hi) keep.push_back(std::max(lo, hi));
  }
  nlohmann::json data = part_json(log, est, EstimatePart::kVerdict);
  nlohmann::json t = nlohmann::json::array();
  nlohmann::json adc = nlohmann::json::array();
  nlohmann::json baseline = nlohmann::json::array();
  nlohmann::json level = nlohmann::json::array();
  for (std::size_t i : keep) {
    t.push_back(log.t_s[i]);
    adc.push_back(log.adc[i]);
    baseline.push_back(json_or_null(static_cast<double>(est.baseline_trace[i])));
    level.push_back(json_or_null(static_cast<double>(est.level_trace[i])));
  }
  data["log"] = escape_invalid_utf8(log.path);
  data["t_s"] = std::move(t);
  data["adc"] = std::move(adc);
  data["baseline"] = std::move(baseline);
  data["timing_level"] = std::move(level);
  nlohmann::json pulses = nlohmann::json::array();
  for (const EstimatedPulse& p : est.pulses)
    pulses.push_back({{"time_s", p.time},
                      {"rise_s", p.rise},
                      {"fall_s", p.fall},
                      {"peak", p.peak},
                      {"distorted", p.distorted}});
  data["pulses"] = std::move(pulses);
  for (const EstimateField& f : estimate_fields())
    if (std::string_view(f.json) == "periods") data["periods"] = f.get({log, est}).json();
  data["spacing_m"] = static_cast<double>(est.set_up.config().spacing_m);
  return data;
}

std::optional<double> plate_amplitude(const HallLog& log, const LogEstimate& estimate,
                                      std::string* unit) {
  const double period = static_cast<double>(estimate.stats.period_s);
  if (!log.half_swing || !(period > 0.0)) return std::nullopt;
  if (is_accelerometer(log.instrument)) {
    const double omega = 2.0 * std::numbers::pi / period;
    if (unit != nullptr) *unit = log.swing_unit == "m/s^2" ? "m" : log.swing_unit + " s^2";
    return *log.half_swing / (omega * omega);
  }
  if (unit != nullptr) *unit = log.swing_unit;
  return log.half_swing;
}

std::optional<double> mu_k_thick(const LogEstimate& estimate) {
  const LogSetUp& s = estimate.set_up;
  const double period = static_cast<double>(estimate.stats.period_s);
  if (!s.h_c || !(period > 0.0)) return std::nullopt;
  return mu_k_from_period_thick(period, s.spacing, *s.h_c, s.gravity);
}

}  // namespace fl
