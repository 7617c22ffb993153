#include "cli/estimate_follow.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "cli/estimate_report.hpp"
#include "cli/stop_signals.hpp"
#include "hall_log/hall_log.hpp"
#include "hall_log/serial_port.hpp"
#include "io/appending_file.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "lab/logs/geometry_check.hpp"
#include "lab/logs/live_capture.hpp"
#include "lab/logs/live_log_estimate.hpp"

namespace fl::cli {
namespace {

// The estimator run live on the samples as they come, with what it says printed at once.
class LiveEstimate {
 public:
  LiveEstimate(const LogSetUp& set_up, bool quiet) : set_up_(set_up), quiet_(quiet) { reset(); }

  void reset() {
    live_ = std::make_unique<LiveLogEstimate>(set_up_);
    periods_shown_ = 0;
    doubt_.clear();
  }

  void add(const LogSample& s) {
    const uint8_t events = live_->add(s);
    if (quiet_ || events == fl_estimator::kNoEvent) return;
    const fl_estimator::PeriodEstimator& e = live_->host().estimator();
    if (events & fl_estimator::kSignalLearned)
      say(fmt::format("  {:<20}  polarity {:+d}, baseline {:.1f} counts (line {})",
                      "signal learned", e.polarity(), e.baseline(), s.line));
    if (events & fl_estimator::kGeometryFound) geometry_found();
    if (events & fl_estimator::kRestart)
      say(fmt::format("  {:<20}  learning it again", "signal lost"));
    // The periods judged in this sample; the running statistics after the last of them.
    const std::vector<EstimatedPeriod>& periods = live_->host().periods();
    for (; periods_shown_ < periods.size(); ++periods_shown_) {
      const EstimatedPeriod& p = periods[periods_shown_];
      const fl_estimator::Stats st = e.stats();
      std::string running;
      if (periods_shown_ + 1 == periods.size() && st.periods_used > 0 && doubt_.empty())
        running =
            fmt::format("  T = {:.6f} +- {:.6f} s (N = {}), mu_k = {:.4f} +- {:.4f}", st.period_s,
                        st.period_std_s, st.periods_used, st.mu_k, st.mu_k_err_worst);
      say(fmt::format("  {:<20}  {:.6f} s {}{}", fmt::format("period {}", periods_shown_ + 1),
                      p.period, period_status_name(p.status), running));
    }
  }

 private:
  static void say(const std::string& line) {
    fmt::print("{}\n", line);
    std::fflush(stdout);
  }

  // Evenly spaced pulses read as one per period: are they shaped like a turn? (The periods'
  // alternation needs more of them than there are yet: the summary checks it.)
  void geometry_found() {
    const bool pair = live_->host().estimator().geometry() == fl_estimator::kPulsePair;
    doubt_.clear();
    if (!pair && set_up_.geometry == fl_estimator::kAutoGeometry) {
      const HallLog& samples = live_->samples();
      const GeometryCheck check = check_geometry(samples, estimate_log(samples, set_up_, false));
      if (check.verdict != "turn") doubt_ = check.reason;
    }
    if (doubt_.empty()) {
      say(fmt::format("  {:<20}  {}", "geometry",
                      pair ? "a pair of pulses per period" : "one pulse per period"));
      return;
    }
    say(
        fmt::format("  {:<20}  evenly spaced pulses, one per period or two: {}; T is the "
                    "interval below or twice it (give --geometry one or pair)",
                    "geometry", doubt_));
  }

  LogSetUp set_up_;
  bool quiet_ = false;
  std::unique_ptr<LiveLogEstimate> live_;
  std::size_t periods_shown_ = 0;
  std::string doubt_;  // why evenly spaced pulses may be two per period ("" : no doubt)
};

}  // namespace

int follow_rig(const FollowRequest& request) {
  SerialPort port(request.port, static_cast<int>(request.baud));
  // The lines received, each written whole as it comes (io/appending_file.hpp).
  std::optional<AppendingFile> raw;
  if (!request.raw_log.empty()) raw.emplace(request.raw_log, "the raw log (--log)");
  // Messages locate lines in the raw log, which holds them as received.
  LiveCapture capture(request.raw_log.empty() ? request.port : request.raw_log, request.reading);
  LiveEstimate live(request.set_up, request.json);
  // Ctrl-C (or SIGTERM) ends the capture, and the summary follows: the normal end, exit 0.
  const StopSignals stop;

  if (!request.json) {
    fmt::print("frictionlab estimate --follow {} at {:.0f} baud{}: Ctrl-C ends it\n", request.port,
               request.baud, request.raw_log.empty() ? "" : ", raw log " + request.raw_log);
    std::fflush(stdout);
  }
  const LiveCapture::LineSink keep = [&raw](std::string_view line) {
    if (raw) raw->write(line);
    return true;
  };
  const LiveCapture::SampleSink estimate = [&](const LogSample& s, bool new_run) {
    if (new_run) {
      live.reset();
      if (!request.json)
        fmt::print("  {:<20}  a new run from line {}\n", "board restarted", s.line);
    }
    live.add(s);
  };

  const auto start = std::chrono::steady_clock::now();
  std::string bytes;
  std::size_t received = 0;
  bool open = true;
  while (open && !stop_requested()) {
    if (request.duration_s) {
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (elapsed >= *request.duration_s) break;
    }
    bytes.clear();
    open = port.read_some(&bytes, 100);
    received += bytes.size();
    capture.add(bytes, false, keep, estimate);
  }
  capture.add("", true, keep, estimate);
  if (received == 0)
    throw InputError(
        SourceLocation{request.port, 0, 0},
        fmt::format("nothing came from the port in {:.1f} s: is the rig's firmware "
                    "running, and sending at {:.0f} baud ({})?",
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                    request.baud, field_ref("follow.baud")));
  if (!request.json) {
    fmt::print("  {:<20}  {} lines received\n",
               stop_requested() ? "stopped"
               : open           ? "time up"
                                : "port closed",
               capture.lines());
    std::fflush(stdout);
  }
  capture.finish(estimate);
  const std::vector<LogSample>& samples = capture.samples();

  // The summary: the same as `estimate LOG` on the lines received.
  // Messages locate lines in the raw log, which holds them as received.
  HallLog log;
  log.path = request.raw_log.empty() ? request.port : request.raw_log;
  log.file = log.path;
  log.encoding = "utf-8";
  log.reading = capture.reading();
  log.segment = capture.run();
  for (const LogSample& s : samples) {
    log.t_s.push_back(s.t_s);
    log.adc.push_back(s.adc);
    log.line.push_back(s.line);
  }
  if (log.t_s.empty())
    throw InputError(SourceLocation{request.port, 0, 0},
                     "no samples received: expected the rig firmware's lines of t_us and adc");
  const double t0 = log.t_s.front();
  for (double t : log.t_s)
    log.t_us.push_back(
        static_cast<uint32_t>(static_cast<uint64_t>(std::llround((t - t0) * 1e6)) & 0xFFFFFFFFu));
  const LogEstimate est = estimate_log(log, request.set_up, !request.plot.empty());
  std::string note;
  if (!request.plot.empty()) {
    request.draw_plot(log, est, request.plot);
    note = " (the plot " + request.plot + " shows the signal)";
  }
  require_periods(log, est, note);
  const GeometryCheck check = check_geometry(log, est);
  require_geometry(log, est, check, note);
  require_plausible(log, est, note);
  if (request.json) {
    nlohmann::json out = estimate_json(log, est, request.plot);
    out["raw_log"] =
        request.raw_log.empty() ? nlohmann::json(nullptr) : nlohmann::json(request.raw_log);
    fmt::print("{}\n", out.dump(2));
  } else {
    print_estimate(log, est, check, request.plot);
  }
  return 0;
}

}  // namespace fl::cli
