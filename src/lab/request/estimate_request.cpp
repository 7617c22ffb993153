#include "lab/request/estimate_request.hpp"
#include "hall_log/log_sidecar.hpp"
#include "io/unknown_material.hpp"
#include "lab/request/lab_data.hpp"
#include "lab/request/video_fields.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "hall_log/log_files.hpp"
#include "hall_log/serial_port.hpp"
#include "io/atomic_file.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "lab/logs/checked_reading.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/plot_script.hpp"
#include "text/utf8.hpp"

namespace fl {
namespace {

// The logs named when they are many (a table): more than one, a pattern, or a folder of several
// logs; nothing when they are one (its own report).
std::optional<std::vector<std::string>> many_logs(const std::vector<std::string>& logs) {
  if (logs.empty() || (logs.size() == 1 && logs.front() == "-")) return std::nullopt;
  std::error_code ec;
  if (logs.size() == 1 && !is_log_pattern(logs.front()) &&
      !std::filesystem::is_directory(logs.front(), ec))
    return std::nullopt;
  std::vector<std::string> found = expand_log_arguments(logs);
  if (logs.size() == 1 && !is_log_pattern(logs.front()) && found.size() <= 1) return std::nullopt;
  return found;
}

// The three jobs' own fields, after the fields they share (prepare_estimate).
// Several logs: a table, each log estimated as one, written into out.
PreparedEstimate prepare_log_table(const EstimateRequest& r, const std::vector<std::string>& logs,
                                   FieldChecks& checks, PreparedEstimate& p) {
  const bool follow = !r.follow_port.empty();
  p.job = EstimateJob::kLogTable;
  if (!r.plot.empty())
    checks.problem("plot", field_ref("plot") + " draws one log's signal; with several logs give " +
                               field_ref("out") + " for the table, or estimate one log with " +
                               field_ref("plot"));
  if (follow || !r.follow_raw_log.empty() || r.follow_duration)
    checks.problem(follow                      ? "follow.port"
                   : !r.follow_raw_log.empty() ? "follow.raw_log"
                                               : "follow.duration",
                   field_ref("follow.port") + ", " + field_ref("follow.raw_log") + " and " +
                       field_ref("follow.duration") +
                       " read the rig's serial port, not logs (give one: logs, or " +
                       field_ref("follow.port") + ")");
  if (std::find(r.logs.begin(), r.logs.end(), "-") != r.logs.end())
    checks.problem("logs", "-",
                   "- (standard input) is one log: estimate it alone, not among others");
  p.logs = logs;
  p.table.set_up = p.set_up;
  p.table.reading = p.reading;
  p.table.material = r.material;
  // A material must be one of the paper's (a sidecar's too, checked as each log is read).
  const PaperTable& paper = paper_table_in(asset_dir(r.assets));
  p.table.paper = &paper;
  if (r.material && paper.find(*r.material) == nullptr)
    checks.problem("material", *r.material, unknown_material_message(paper, *r.material));
  if (r.temperature)
    p.table.temperature = checks.quantity(*r.temperature, Dimension::kTemperature, "temperature");
  checks.throw_if_any();
  std::vector<InputFile> inputs;
  for (const std::string& log : p.logs) inputs.push_back({log, "a log"});
  refuse_overwriting_inputs(r.out, {"estimates.csv", "estimates.json"}, "out", inputs);
  if (!r.out.empty()) prepare_output_folder(r.out, "out");
  p.out = r.out;
  p.warnings = checks.warnings();
  return p;
}

// The rig's serial port, estimated as its lines come.
PreparedEstimate prepare_follow(const EstimateRequest& r, FieldChecks& checks,
                                PreparedEstimate& p) {
  p.job = EstimateJob::kFollow;
  if (!r.logs.empty() || r.samples)
    checks.problem("follow.port", r.follow_port,
                   "reads the rig's serial port, not a log file; found both \"" + r.follow_port +
                       "\" and \"" + (r.logs.empty() ? "" : r.logs.front()) +
                       "\" (give one: a log, or " + field_ref("follow.port") + ")");
  p.follow_port = r.follow_port;
  if (r.follow_baud) {
    p.follow_baud = checks.quantity(*r.follow_baud, Dimension::kDimensionless, "follow.baud");
    if (const std::optional<std::string> why = baud_problem(p.follow_baud))
      checks.problem("follow.baud", quantity_input_text(*r.follow_baud),
                     *why + ", found " + quantity_input_text(*r.follow_baud));
  }
  p.follow_raw_log = r.follow_raw_log;
  p.follow_duration = checks.quantity(r.follow_duration, Dimension::kTime, "follow.duration");
  if (p.follow_duration && !(*p.follow_duration > 0.0))
    checks.problem(
        "follow.duration", quantity_input_text(*r.follow_duration),
        "expected a positive time, such as 30s, found " + quantity_input_text(*r.follow_duration));
  checks.throw_if_any();
  refuse_overwriting_inputs(r.plot, "plot", {{r.follow_raw_log, "the log of the lines received"}});
  if (!r.plot.empty()) prepare_output_file(r.plot, "plot");
  if (!r.follow_raw_log.empty()) prepare_output_file(r.follow_raw_log, "follow.raw_log");
  p.plot = r.plot;
  p.warnings = checks.warnings();
  return p;
}

// One log (or samples given as arrays), with its plots and a Monte Carlo of mu_k.
PreparedEstimate prepare_one_log(const EstimateRequest& r, FieldChecks& checks,
                                 PreparedEstimate& p) {
  p.job = EstimateJob::kOneLog;
  if (r.logs.empty() && !r.samples)
    checks.problem("logs",
                   "expected a log (a file, a folder holding one, or - for standard "
                   "input), or " +
                       field_ref("follow.port") + " for the rig's serial port");
  if (!r.follow_raw_log.empty() || r.follow_duration)
    checks.problem(!r.follow_raw_log.empty() ? "follow.raw_log" : "follow.duration",
                   field_ref("follow.raw_log") + " and " + field_ref("follow.duration") +
                       " go with " + field_ref("follow.port"));
  if (r.mc && (*r.mc < 1 || *r.mc > kMaxMonteCarloDraws))
    checks.problem("monte_carlo.draws", std::to_string(*r.mc),
                   fmt::format("expected the number of draws, a whole number from 1 to {}, found "
                               "{}",
                               kMaxMonteCarloDraws, *r.mc));
  if (!r.mc && (r.h_c_err || !r.mc_plot.empty()))
    checks.problem(r.h_c_err ? "h_c_err" : "mc_plot",
                   field_ref("h_c_err") + " and " + field_ref("mc_plot") + " go with " +
                       field_ref("monte_carlo.draws") + " (the Monte Carlo of mu_k); add " +
                       field_ref("monte_carlo.draws", "100000") + ", or drop them");
  if (r.h_c) {
    p.set_up.h_c = checks.not_negative(*r.h_c, Dimension::kLength, "h_c", "a height");
    checks.plausible(*p.set_up.h_c, kHcRange, "h_c", *r.h_c);
  }
  if (r.h_c_err)
    p.h_c_err = checks.not_negative(*r.h_c_err, Dimension::kLength, "h_c_err", "an uncertainty");
  checks.throw_if_any();
  // The plots' places are checked before any work; a plot that fails still leaves the results.
  // Neither may replace the log (or a folder's log) nor the other plot.
  std::vector<InputFile> inputs;
  if (!r.logs.empty()) {
    inputs.push_back({r.logs.front(), "the log"});
    try {
      if (r.logs.front() != "-") inputs.push_back({log_file_of(r.logs.front()), "the log"});
    } catch (const InputError&) {
      // A folder without one log: reading it says so.
    }
  }
  refuse_overwriting_inputs(r.plot, "plot", inputs);
  inputs.push_back({r.plot, "the plot of the signal"});
  refuse_overwriting_inputs(r.mc_plot, "mc_plot", inputs);
  if (!r.plot.empty()) prepare_output_file(r.plot, "plot");
  if (!r.mc_plot.empty()) prepare_output_file(r.mc_plot, "mc_plot");
  if (r.mc)
    p.monte_carlo =
        MonteCarloRequest{.draws = static_cast<int>(*r.mc), .seed = r.seed, .keep_samples = true};
  if (!r.logs.empty()) p.log = r.logs.front();
  p.samples = r.samples;
  p.plot = r.plot;
  p.mc_plot = r.mc_plot;
  p.warnings = checks.warnings();
  return p;
}

}  // namespace

PreparedEstimate prepare_estimate(const EstimateRequest& r) {
  FieldChecks checks;
  PreparedEstimate p;
  p.set_up.spacing =
      checks.positive(r.spacing, Dimension::kLength, "spacing", "the roller spacing");
  p.set_up.spacing_err =
      checks.not_negative(r.spacing_err, Dimension::kLength, "spacing_err", "the uncertainty");
  p.set_up.gravity = checks.positive(r.gravity, Dimension::kAcceleration, "gravity", "g");
  checks.plausible(p.set_up.spacing, kSpacingRange, "spacing", r.spacing);
  checks.plausible(p.set_up.gravity, kGravityRange, "gravity", r.gravity);
  if (const std::optional<fl_estimator::Geometry> g = geometry_from_option(r.geometry))
    p.set_up.geometry = *g;
  else
    checks.problem("geometry", r.geometry,
                   "expected auto, one or pair, found \"" + r.geometry + "\"");
  p.reading.columns = r.columns;
  p.reading.time_unit = r.time_unit;
  p.reading.video = checked_track_options(r.roi, r.scale, r.plate_length, checks);
  if (r.rate) {
    p.reading.rate_hz = checks.quantity(*r.rate, Dimension::kFrequency, "rate");
    if (!checks.has("rate") && (!(p.reading.rate_hz > 0.0) || !std::isfinite(p.reading.rate_hz)))
      checks.problem("rate", quantity_input_text(*r.rate),
                     "expected a positive sample rate (for example 1kHz), found \"" +
                         quantity_input_text(*r.rate) + "\"");
  }
  const bool follow = !r.follow_port.empty();
  if (r.follow_baud && !follow)
    checks.problem("follow.baud", field_ref("follow.baud") + " is the serial port's rate for " +
                                      field_ref("follow.port") +
                                      "; a log file has none: drop it, or add " +
                                      field_ref("follow.port"));
  const bool monte_carlo = r.mc || r.h_c_err || !r.mc_plot.empty();
  const std::optional<std::vector<std::string>> many = r.samples ? std::nullopt : many_logs(r.logs);
  if (r.h_c && !monte_carlo && (many || follow))
    checks.problem("h_c", field_ref("h_c") +
                              " gives one log's mu_k through the thick formula; give one log (not "
                              "several, nor " +
                              field_ref("follow.port") + ")");
  if (monte_carlo && (many || follow))
    checks.problem("monte_carlo.draws",
                   field_ref("monte_carlo.draws") +
                       " and its fields estimate one log's mu_k by Monte Carlo; give one log "
                       "(not several, nor " +
                       field_ref("follow.port") + ")");
  if (many) return prepare_log_table(r, *many, checks, p);
  if (!r.out.empty())
    checks.problem("out", field_ref("out") +
                              " writes the table of several logs; for one log its result is "
                              "the estimate itself (or give " +
                              field_ref("follow.raw_log") + " with " + field_ref("follow.port") +
                              "), or name several logs");
  if (follow && (r.material || r.temperature))
    checks.problem(r.material ? "material" : "temperature",
                   field_ref("material") + " and " + field_ref("temperature") +
                       " go with a log or several; the live rig is estimated without them");
  if (!follow) {
    // One log's material: the paper's value is printed beside its result.
    const PaperTable& paper = paper_table_in(asset_dir(r.assets));
    p.paper = &paper;
    p.material = read_material_fields(checks, paper, r.material, r.temperature);
  }
  if (follow) return prepare_follow(r, checks, p);
  return prepare_one_log(r, checks, p);
}

nlohmann::json OneLogEstimate::json() const {
  nlohmann::json j = log_estimate_json(log, estimate);
  j["plot"] = plot.empty() ? nlohmann::json(nullptr) : nlohmann::json(escape_invalid_utf8(plot));
  j["monte_carlo"] =
      monte_carlo ? monte_carlo_json(*monte_carlo->monte_carlo) : nlohmann::json(nullptr);
  j["paper"] = paper ? paper_comparison_json(*paper) : nlohmann::json(nullptr);
  return j;
}

Outcome OneLogEstimate::outcome() const {
  return plot_failure.empty() ? Outcome::kDone : Outcome::kIncomplete;
}

OneLogEstimate estimate_one_log(const PreparedEstimate& p) {
  OneLogEstimate out;
  out.log = p.samples ? *p.samples : read_hall_log_checked(p.log, p.reading, p.set_up);
  // The log's sidecar over the request's rig (its material checked against the paper's).
  std::optional<LogSidecar> sidecar;
  const LogSetUp set_up =
      p.samples ? p.set_up
                : set_up_for_log(out.log.file, p.set_up, &out.sidecar_note, &sidecar, p.paper);
  out.estimate = estimate_log(out.log, set_up, !p.plot.empty());
  std::string plot_note;
  if (!p.plot.empty()) {
    try {
      run_plot_script_on("plot_hall.py", hall_plot_data(out.log, out.estimate), p.plot);
      out.plot = p.plot;
      plot_note = " (the plot " + p.plot + " shows the signal)";
    } catch (const std::runtime_error& e) {
      out.plot_failure = e.what();
    }
  }
  require_periods(out.log, out.estimate, plot_note);
  out.check = check_geometry(out.log, out.estimate);
  require_geometry(out.log, out.estimate, out.check, plot_note);
  require_plausible(out.log, out.estimate, plot_note);
  // A geometry given that the log contradicts: the log looked at as if none had been given.
  if (set_up.geometry != fl_estimator::kAutoGeometry) {
    LogSetUp open = set_up;
    open.geometry = fl_estimator::kAutoGeometry;
    const LogEstimate seen = estimate_log(out.log, open, false);
    const GeometryCheck look = check_geometry(out.log, seen);
    const bool one_seen = seen.geometry == fl_estimator::kOnePulse && look.verdict == "turn";
    const bool pair_seen =
        seen.geometry == fl_estimator::kPulsePair ||
        (seen.geometry == fl_estimator::kOnePulse && look.verdict == "alternating");
    const bool given_pair = set_up.geometry == fl_estimator::kPulsePair;
    if ((given_pair && one_seen) || (!given_pair && pair_seen))
      out.warnings.push_back(fmt::format(
          "{}: the log shows {}: T = {:.6f} s and mu_k = {:.4f} read so, against {:.6f} s and "
          "{:.4f} as given; drop {} unless you know the rig gives {} a period",
          field_ref("geometry", given_pair ? "pair" : "one"),
          given_pair ? "one pulse per period (evenly spaced pulses shaped like a turn at the "
                       "sensor)"
                     : "a pair of pulses per period",
          seen.stats.period_s, seen.stats.mu_k, out.estimate.stats.period_s,
          out.estimate.stats.mu_k, field_ref("geometry", given_pair ? "pair" : "one"),
          given_pair ? "two pulses" : "one pulse"));
  }
  // The paper's value for the material the request or the log's sidecar names.
  if (p.paper != nullptr) {
    const MaterialChoice from_sidecar =
        sidecar ? MaterialChoice{sidecar->material, sidecar->temperature} : MaterialChoice{};
    out.paper = paper_value_for(*p.paper, p.material, from_sidecar,
                                static_cast<double>(out.estimate.stats.mu_k),
                                static_cast<double>(out.estimate.stats.mu_k_err_quadrature));
  }
  // mu_k by Monte Carlo: T drawn with the periods' standard deviation (the dT of the rules
  // printed), l with dl, h_c with dh_c, through the thick formula (the thin one at h_c = 0).
  if (p.monte_carlo) {
    AnalyticSetUp mc;
    mc.spacing = set_up.spacing;
    mc.spacing_err = set_up.spacing_err;
    mc.gravity = set_up.gravity;
    mc.h_c = set_up.h_c.value_or(0.0);
    mc.h_c_err = p.h_c_err;
    out.monte_carlo = analytic_for_period(mc, static_cast<double>(out.estimate.stats.period_s),
                                          static_cast<double>(out.estimate.stats.period_std_s));
    add_monte_carlo(*out.monte_carlo, *p.monte_carlo);
    if (!p.mc_plot.empty()) {
      try {
        run_plot_script_on("plot_mc.py", monte_carlo_plot_data(*out.monte_carlo), p.mc_plot);
        out.mc_plot = p.mc_plot;
      } catch (const std::runtime_error& e) {
        out.plot_failure += (out.plot_failure.empty() ? "" : "; ") + std::string(e.what());
      }
    }
  }
  return out;
}

nlohmann::json LogTableResult::json() const {
  return {{"logs", log_table_json(rows)}};
}

int LogTableResult::failed() const {
  return static_cast<int>(std::count_if(rows.begin(), rows.end(),
                                        [](const LogTableRow& r) { return r.status != "ok"; }));
}

Outcome LogTableResult::outcome() const {
  return failed() == 0 ? Outcome::kDone : Outcome::kFailed;
}

LogTableResult estimate_log_table(const PreparedEstimate& p) {
  LogTableResult out;
  for (const std::string& log : p.logs) out.rows.push_back(estimate_log_row(log, p.table));
  if (!p.out.empty()) {
    const std::string csv = p.out + "/estimates.csv";
    const std::string json = p.out + "/estimates.json";
    write_file_atomic(csv, log_table_csv(out.rows));
    write_file_atomic(json, out.json().dump(1) + "\n");
    out.written = {csv, json};
  }
  return out;
}

}  // namespace fl
