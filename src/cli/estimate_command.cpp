// frictionlab estimate LOG: T +- dT and mu_k +- d mu_k from a log of the real rig's Hall sensor,
// by the very estimator the rig's Arduino runs (src/estimator/period_estimator.h).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/option_quantity.hpp"
#include "cli/plot_script.hpp"
#include "estimator/period_estimator.h"
#include "io/hall_log.hpp"
#include "io/input_error.hpp"

namespace fl::cli {
namespace {

struct EstimateOptions {
  std::string log;
  std::string spacing = "89 mm";
  std::string spacing_err = "2 mm";
  std::string gravity = "9.81 m/s^2";
  std::string geometry = "auto";
  std::string plot;
  bool json = false;
};

struct PulseRecord {
  double time = 0.0;  // [s] on the log's time axis
  double rise = 0.0;
  double fall = 0.0;
  int peak = 0;  // [counts]
  bool distorted = false;
};

struct PeriodRecord {
  double start = 0.0;  // turning points [s] on the log's time axis
  double end = 0.0;
  double period = 0.0;  // [s]
  std::string status;   // accepted, outlier, broken
};

struct Estimate {
  fl_estimator::Stats stats{};
  fl_estimator::Geometry geometry = fl_estimator::kAutoGeometry;
  int polarity = 0;
  double baseline = 0.0;  // at the end [counts]
  bool learned = false;   // the signal was learned at least once
  std::vector<PulseRecord> pulses;
  std::vector<PeriodRecord> periods;
  // Per sample, for the plot: baseline and timing level [counts], NaN while learning.
  std::vector<float> baseline_trace;
  std::vector<float> level_trace;
};

const char* status_name(uint8_t status) {
  return status == fl_estimator::kAccepted          ? "accepted"
         : status == fl_estimator::kRejectedOutlier ? "outlier"
                                                    : "broken";
}

const char* geometry_name(fl_estimator::Geometry g) {
  return g == fl_estimator::kOnePulse    ? "one-pulse"
         : g == fl_estimator::kPulsePair ? "pair"
                                         : "unknown";
}

fl_estimator::Geometry parse_geometry(const std::string& text) {
  if (text == "auto") return fl_estimator::kAutoGeometry;
  if (text == "one") return fl_estimator::kOnePulse;
  if (text == "pair") return fl_estimator::kPulsePair;
  throw InputError({}, "--geometry: expected auto, one or pair, found \"" + text + "\"");
}

Estimate run_estimator(const HallLog& log, const fl_estimator::Config& config, bool traces) {
  fl_estimator::PeriodEstimator e(config);
  Estimate out;
  const double t0 = log.t_s.front();
  uint64_t epoch = 0;  // wraps of the 32-bit microsecond clock so far
  uint32_t now = 0;
  // An instant the estimator reports lies at or before the latest sample.
  auto seconds = [&](const fl_estimator::Instant& t) {
    const uint64_t e_of_t = t.us > now && epoch > 0 ? epoch - 1 : epoch;
    return t0 + (static_cast<double>(e_of_t) * 4294967296.0 + static_cast<double>(t.us) +
                 static_cast<double>(t.frac) / 256.0) *
                    1e-6;
  };
  uint32_t pulses_seen = 0;
  uint32_t periods_seen = 0;
  auto collect = [&] {
    for (; pulses_seen < e.pulse_count(); ++pulses_seen) {
      if (!e.has_pulse(pulses_seen)) continue;
      const fl_estimator::Pulse& p = e.pulse(pulses_seen);
      out.pulses.push_back(
          {seconds(p.time), seconds(p.rise), seconds(p.fall), p.peak, p.distorted});
    }
    for (; periods_seen < e.period_count(); ++periods_seen) {
      if (!e.has_period(periods_seen)) continue;
      const fl_estimator::Period& p = e.period(periods_seen);
      out.periods.push_back({seconds(p.start), seconds(p.end),
                             static_cast<double>(p.period_us) * 1e-6, status_name(p.status)});
    }
  };
  if (traces) {
    out.baseline_trace.reserve(log.adc.size());
    out.level_trace.reserve(log.adc.size());
  }
  for (std::size_t i = 0; i < log.adc.size(); ++i) {
    if (i > 0 && log.t_us[i] < now) ++epoch;
    now = log.t_us[i];
    const uint8_t events = e.add_sample(log.t_us[i], log.adc[i]);
    if (events & fl_estimator::kSignalLearned) out.learned = true;
    if (events != 0) collect();
    if (traces) {
      const bool known = e.phase() != fl_estimator::kLearning;
      const float nan = std::numeric_limits<float>::quiet_NaN();
      out.baseline_trace.push_back(known ? e.baseline() : nan);
      out.level_trace.push_back(known ? e.timing_level() : nan);
    }
  }
  e.finish();
  collect();
  out.stats = e.stats();
  out.geometry = e.geometry();
  out.polarity = e.polarity();
  out.baseline = static_cast<double>(e.baseline());
  return out;
}

// The log's line nearest to a time.
int line_at(const HallLog& log, double t) {
  const auto it = std::lower_bound(log.t_s.begin(), log.t_s.end(), t);
  const std::size_t i = it == log.t_s.end() ? log.t_s.size() - 1 : it - log.t_s.begin();
  return log.line[i];
}

nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

// The data the plotting script draws, as JSON in a temporary file; then the script.
void draw_plot(const HallLog& log, const Estimate& est, const fl_estimator::Config& config,
               const std::string& png) {
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
  nlohmann::json data;
  nlohmann::json t = nlohmann::json::array();
  nlohmann::json adc = nlohmann::json::array();
  nlohmann::json baseline = nlohmann::json::array();
  nlohmann::json level = nlohmann::json::array();
  for (std::size_t i : keep) {
    t.push_back(log.t_s[i]);
    adc.push_back(log.adc[i]);
    baseline.push_back(number_or_null(static_cast<double>(est.baseline_trace[i])));
    level.push_back(number_or_null(static_cast<double>(est.level_trace[i])));
  }
  data["log"] = log.path;
  data["t_s"] = std::move(t);
  data["adc"] = std::move(adc);
  data["baseline"] = std::move(baseline);
  data["timing_level"] = std::move(level);
  nlohmann::json pulses = nlohmann::json::array();
  for (const PulseRecord& p : est.pulses)
    pulses.push_back({{"time_s", p.time},
                      {"rise_s", p.rise},
                      {"fall_s", p.fall},
                      {"peak", p.peak},
                      {"distorted", p.distorted}});
  data["pulses"] = std::move(pulses);
  nlohmann::json periods = nlohmann::json::array();
  for (const PeriodRecord& p : est.periods)
    periods.push_back(
        {{"start_s", p.start}, {"end_s", p.end}, {"period_s", p.period}, {"status", p.status}});
  data["periods"] = std::move(periods);
  const fl_estimator::Stats& s = est.stats;
  data["geometry"] = geometry_name(est.geometry);
  data["periods_used"] = s.periods_used;
  data["periods_discarded"] = s.periods_discarded;
  data["period_s"] = static_cast<double>(s.period_s);
  data["period_std_s"] = static_cast<double>(s.period_std_s);
  data["mu_k"] = static_cast<double>(s.mu_k);
  data["mu_k_err_worst"] = static_cast<double>(s.mu_k_err_worst);
  data["spacing_m"] = static_cast<double>(config.spacing_m);

  const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
  const std::filesystem::path json_path =
      std::filesystem::temp_directory_path() /
      fmt::format("frictionlab-hall-{}-{}.json", getpid(), stamp);
  {
    std::ofstream f(json_path);
    f << data.dump();
    if (!f) throw std::runtime_error("cannot write " + json_path.string());
  }
  struct Remove {
    std::filesystem::path path;
    ~Remove() {
      std::error_code ignored;
      std::filesystem::remove(path, ignored);
    }
  } remove_json{json_path};
  run_plot_script("plot_hall.py", {json_path.string(), png});
}

// Says what was found when the log gives no T +- dT; never a made-up period.
void check_enough(const HallLog& log, const Estimate& est, const fl_estimator::Config& config,
                  const std::string& plot_note) {
  const fl_estimator::Stats& s = est.stats;
  const SourceLocation first{log.path, log.line.front(), 0};
  const double duration = log.t_s.back() - log.t_s.front();
  if (est.pulses.empty()) {
    const auto [lo, hi] = std::minmax_element(log.adc.begin(), log.adc.end());
    const int swing = *hi - *lo;
    std::string why;
    if (swing < config.min_amplitude)
      why = fmt::format(
          "a swing of {} counts is below the {} counts a pulse needs: does the magnet pass the "
          "sensor?",
          swing, config.min_amplitude);
    else if (!est.learned)
      why = fmt::format(
          "the signal swings {} counts, but the estimator learns the baseline and polarity from "
          "the first two pulses and did not see two (between pulses the signal must rest at its "
          "baseline, more than half of the time)",
          swing);
    else
      why =
          fmt::format("the signal swings {} counts but no pulse rose past the timing level", swing);
    throw InputError(first, fmt::format("no pulse in {} samples over {:.3f} s (lines {}-{}): the "
                                        "ADC values stay within {}..{} counts; {}{}",
                                        log.adc.size(), duration, log.line.front(), log.line.back(),
                                        *lo, *hi, why, plot_note));
  }
  const SourceLocation at_pulse{log.path, line_at(log, est.pulses.front().time), 0};
  if (est.pulses.size() == 1)
    throw InputError(at_pulse, fmt::format("only one pulse in {:.3f} s of log (at t = {:.4f} s, "
                                           "after the two the signal was learned from): a period "
                                           "needs at least two{}",
                                           duration, est.pulses.front().time, plot_note));
  if (est.periods.empty()) {
    std::string intervals;
    for (std::size_t i = 1; i < est.pulses.size() && i <= 8; ++i)
      intervals +=
          fmt::format("{}{:.4f}", i > 1 ? ", " : "", est.pulses[i].time - est.pulses[i - 1].time);
    if (est.pulses.size() > 9) intervals += ", ...";
    if (est.pulses.size() < 5)
      throw InputError(at_pulse,
                       fmt::format("only {} pulses (intervals {} s): the estimator needs five in a "
                                   "row to tell one pulse per period from a pair; record more "
                                   "periods{}",
                                   est.pulses.size(), intervals, plot_note));
    throw InputError(
        at_pulse,
        fmt::format("{} pulses, but no two turning points: the intervals between pulses ({} s) fit "
                    "neither one pulse per period (equal intervals) nor a close pair per period "
                    "(alternating short and long, the short under 0.6 of the long); with the "
                    "sensor near the middle of the motion give --geometry pair{}",
                    est.pulses.size(), intervals, plot_note));
  }
  if (s.periods_used < 2)
    throw InputError(
        at_pulse,
        fmt::format("{} pulses and {} periods, of which {} accepted and {} discarded: T +- dT "
                    "needs at least two accepted periods{}",
                    s.pulses, est.periods.size(), s.periods_used, s.periods_discarded, plot_note));
}

int run_estimate(const EstimateOptions& o) {
  const double spacing = option_quantity(o.spacing, Dimension::kLength, "--spacing");
  const double spacing_err = option_quantity(o.spacing_err, Dimension::kLength, "--spacing-err");
  const double gravity = option_quantity(o.gravity, Dimension::kAcceleration, "--gravity");
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw InputError({}, "--spacing: the roller spacing must be a finite positive length");
  if (!(spacing_err >= 0.0) || !std::isfinite(spacing_err))
    throw InputError({}, "--spacing-err: the uncertainty must be a finite length, not negative");
  if (!(gravity > 0.0) || !std::isfinite(gravity))
    throw InputError({}, "--gravity: g must be a finite positive acceleration");
  fl_estimator::Config config;
  config.spacing_m = static_cast<float>(spacing);
  config.spacing_err_m = static_cast<float>(spacing_err);
  config.gravity_m_s2 = static_cast<float>(gravity);
  config.geometry = parse_geometry(o.geometry);

  const HallLog log = read_hall_log(o.log);
  const Estimate est = run_estimator(log, config, !o.plot.empty());
  std::string plot_note;
  if (!o.plot.empty()) {
    draw_plot(log, est, config, o.plot);
    plot_note = " (the plot " + o.plot + " shows the signal)";
  }
  check_enough(log, est, config, plot_note);

  const fl_estimator::Stats& s = est.stats;
  const double duration = log.t_s.back() - log.t_s.front();
  const double rate = log.adc.size() > 1 ? static_cast<double>(log.adc.size() - 1) / duration : 0;
  int outliers = 0;
  for (const PeriodRecord& p : est.periods) outliers += p.status == "outlier" ? 1 : 0;
  int distorted = 0;
  for (const PulseRecord& p : est.pulses) distorted += p.distorted ? 1 : 0;

  if (o.json) {
    nlohmann::json out;
    out["log"] = log.path;
    out["format"] = log.format;
    out["time_column"] = log.time_column;
    out["adc_column"] = log.adc_column;
    out["samples"] = log.adc.size();
    out["duration_s"] = duration;
    out["sample_rate_hz"] = rate;
    out["geometry"] = geometry_name(est.geometry);
    out["polarity"] = est.polarity;
    out["baseline_adc"] = est.baseline;
    out["pulses"] = s.pulses;
    out["pulses_distorted"] = distorted;
    out["pulses_unused"] = s.unused_pulses;
    out["restarts"] = s.restarts;
    out["periods_used"] = s.periods_used;
    out["periods_discarded"] = s.periods_discarded;
    out["periods_outliers"] = outliers;
    out["period_s"] = static_cast<double>(s.period_s);
    out["period_std_s"] = static_cast<double>(s.period_std_s);
    out["period_sem_s"] = static_cast<double>(s.period_sem_s);
    out["mu_k"] = static_cast<double>(s.mu_k);
    out["mu_k_err_worst"] = static_cast<double>(s.mu_k_err_worst);
    out["mu_k_err_quadrature"] = static_cast<double>(s.mu_k_err_quadrature);
    out["spacing_m"] = spacing;
    out["spacing_err_m"] = spacing_err;
    out["gravity_m_s2"] = gravity;
    out["unfinished_last_line"] = log.unfinished_last_line;
    nlohmann::json periods = nlohmann::json::array();
    for (const PeriodRecord& p : est.periods)
      periods.push_back(
          {{"start_s", p.start}, {"end_s", p.end}, {"period_s", p.period}, {"status", p.status}});
    out["periods"] = std::move(periods);
    out["plot"] = o.plot.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.plot);
    fmt::print("{}\n", out.dump(2));
    return 0;
  }

  fmt::print("frictionlab estimate: {}\n", log.path);
  fmt::print("  log                  {}, {} samples over {:.3f} s at {:.0f} Hz (columns {}, {})\n",
             log.format == "firmware" ? "the rig firmware's serial output" : "CSV", log.adc.size(),
             duration, rate, log.time_column, log.adc_column);
  if (log.unfinished_last_line)
    fmt::print("                       (its last line, cut off without a newline, left out)\n");
  fmt::print("  signal               polarity {:+d}, baseline {:.1f} counts, {} pulses{}\n",
             est.polarity, est.baseline, s.pulses,
             distorted > 0 ? fmt::format(" ({} distorted)", distorted) : std::string());
  fmt::print("  geometry             {}\n", est.geometry == fl_estimator::kPulsePair
                                                ? "a pair of pulses per period"
                                                : "one pulse per period");
  const int broken = static_cast<int>(s.periods_discarded) - outliers;
  fmt::print("  periods              {} used, {} discarded ({} {}, {} at broken turning points)\n",
             s.periods_used, s.periods_discarded, outliers, outliers == 1 ? "outlier" : "outliers",
             broken);
  fmt::print("  period T             {:.6f} +- {:.6f} s (N = {}, standard error {:.6f} s)\n",
             s.period_s, s.period_std_s, s.periods_used, s.period_sem_s);
  fmt::print("  mu_k                 {:.4f} +- {:.4f} (worst case) +- {:.4f} (quadrature)\n",
             s.mu_k, s.mu_k_err_worst, s.mu_k_err_quadrature);
  fmt::print(
      "                       for l = {:.1f} +- {:.1f} mm, g = {:.3f} m/s^2, dT the "
      "standard deviation\n",
      spacing * 1e3, spacing_err * 1e3, gravity);
  if (!o.plot.empty()) fmt::print("  plot                 {}\n", o.plot);
  return 0;
}

}  // namespace

Command add_estimate_command(CLI::App& app, const GlobalOptions& /*global*/) {
  auto options = std::make_shared<EstimateOptions>();
  CLI::App* sub = app.add_subcommand(
      "estimate",
      "T +- dT and mu_k +- d mu_k from a Hall-sensor log of the real rig (the rig firmware's "
      "serial output, or a CSV of time and ADC value), by the estimator the rig's Arduino runs");
  sub->add_option("LOG", options->log, "The log: the firmware's serial capture or a CSV")
      ->required();
  sub->add_option("--spacing", options->spacing, "Roller spacing l")->capture_default_str();
  sub->add_option("--spacing-err", options->spacing_err, "Uncertainty dl of the spacing")
      ->capture_default_str();
  sub->add_option("--gravity", options->gravity, "Gravity g")->capture_default_str();
  sub->add_option("--geometry", options->geometry,
                  "Pulses per period: auto (recognise), one, or pair")
      ->capture_default_str();
  sub->add_option("--plot", options->plot,
                  "Draw the signal with the pulses and the rejected periods to this PNG");
  sub->add_flag("--json", options->json, "Print one JSON object (SI units) instead of the table");
  return Command{sub, [options] { return run_estimate(*options); }};
}

}  // namespace fl::cli
