// frictionlab estimate LOG: T +- dT and mu_k +- d mu_k from a log of the real rig's Hall sensor,
// by the very estimator the rig's Arduino runs (src/estimator/period_estimator.h); with --follow
// PORT, live from the rig's serial port (cli/estimate_follow). Reading the log is
// hall_log/hall_log, the estimate lab/log_estimate, the geometry's check lab/geometry_check; this
// command reads the options and prints (cli/estimate_report).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/estimate_follow.hpp"
#include "cli/estimate_report.hpp"
#include "cli/field_spelling.hpp"
#include "cli/log_options.hpp"
#include "cli/monte_carlo_options.hpp"
#include "cli/monte_carlo_report.hpp"
#include "cli/option_quantity.hpp"
#include "cli/paper_value_text.hpp"
#include "cli/plot_failure.hpp"
#include "hall_log/hall_log.hpp"
#include "hall_log/log_files.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "lab/analytic/analytic_report.hpp"
#include "lab/logs/geometry_check.hpp"
#include "lab/logs/log_estimate.hpp"
#include "lab/logs/log_table.hpp"
#include "lab/request/estimate_request.hpp"
#include "lab/request/outcome.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/plot_script.hpp"
#include "text/utf8.hpp"

namespace fl::cli {
namespace {

// The options' texts; the defaults shown in --help are the request's.
struct EstimateOptions {
  std::vector<std::string> logs;
  std::string spacing = quantity_input_text(EstimateRequest{}.spacing);
  std::string spacing_err = quantity_input_text(EstimateRequest{}.spacing_err);
  std::string gravity = quantity_input_text(EstimateRequest{}.gravity);
  std::string geometry = EstimateRequest{}.geometry;
  LogReadingOptions reading;
  std::string roi;  // a video's
  std::optional<double> scale;
  std::string plate_length;
  std::string plot;
  bool json = false;
  std::string follow;
  std::string baud = std::to_string(kFirmwareBaud);
  std::string raw_log;
  std::string duration;
  std::string material;
  std::string temperature;
  std::string out;
  MonteCarloOptions monte_carlo;
  std::string h_c;
  std::string h_c_err;
  std::string mc_plot;
};

void draw_plot(const HallLog& log, const LogEstimate& est, const std::string& png) {
  run_plot_script_on("plot_hall.py", hall_plot_data(log, est), png);
}

void print_log_table(const std::vector<LogTableRow>& rows) {
  fmt::print("frictionlab estimate: {} logs\n\n", rows.size());
  fmt::print("  {:<24} {:>7}  {:>20}  {:>8}  {:>9}  {:>18}  {}\n", "log", "l [mm]", "T +- sd [s]",
             "se [s]", "N (disc.)", "mu_k +- worst", "material");
  for (const LogTableRow& r : rows) {
    const std::string label = r.label.size() > 24 ? r.label.substr(0, 21) + "..." : r.label;
    if (r.status != "ok") {
      fmt::print("  {:<24} {:>7.1f}  failed: {}\n", label, r.set_up.spacing * 1e3,
                 spelled(r.error));
      continue;
    }
    fmt::print(
        "  {:<24} {:>7.1f}  {:>9.6f} +- {:>8.6f}  {:>8.6f}  {:>4} ({:>2})  {:>8.4f} +- {:>6.4f}  "
        "{}{}\n",
        label, r.set_up.spacing * 1e3, *r.period, *r.period_std, *r.period_err, *r.periods_used,
        *r.periods_discarded, *r.mu_k, *r.mu_k_err_worst, r.material.value_or("-"),
        r.temperature ? fmt::format(" at {:g} K", *r.temperature) : std::string());
  }
  fmt::print(
      "\n  sd is the standard deviation of a log's periods (the paper's dT), se the standard error "
      "of their mean;\n  mu_k is the paper's thin formula and its worst-case error (from sd and "
      "dl), as the rig computes them\n");
}

// The options as the request's fields: what was given.
EstimateRequest request_of(const EstimateOptions& o, const CLI::App& sub,
                           const GlobalOptions& global) {
  EstimateRequest r;
  r.logs = o.logs;
  r.spacing = o.spacing;
  r.spacing_err = o.spacing_err;
  r.gravity = o.gravity;
  r.geometry = o.geometry;
  r.columns = o.reading.columns;
  if (!o.reading.rate.empty()) r.rate = o.reading.rate;
  r.time_unit = o.reading.time_unit;
  r.roi = o.roi;
  r.scale = o.scale;
  if (!o.plate_length.empty()) r.plate_length = o.plate_length;
  r.plot = o.plot;
  r.out = o.out;
  if (!o.material.empty()) r.material = o.material;
  r.assets = global.asset_dir;
  if (!o.temperature.empty()) r.temperature = o.temperature;
  r.follow_port = o.follow;
  if (sub.count("--baud") > 0) r.follow_baud = o.baud;
  r.follow_raw_log = o.raw_log;
  if (!o.duration.empty()) r.follow_duration = o.duration;
  if (const std::optional<MonteCarloRequest> mc = monte_carlo_request(o.monte_carlo)) {
    r.mc = mc->draws;
    r.seed = mc->seed;
  }
  if (!o.h_c.empty()) r.h_c = o.h_c;
  if (!o.h_c_err.empty()) r.h_c_err = o.h_c_err;
  r.mc_plot = o.mc_plot;
  return r;
}

int run_log_table(const EstimateOptions& o, const PreparedEstimate& p) {
  const LogTableResult result = estimate_log_table(p);
  std::string written;
  for (const std::string& w : result.written) written += (written.empty() ? "" : ", ") + w;
  if (o.json) {
    fmt::print("{}\n", result.json().dump(2));
  } else {
    print_log_table(result.rows);
    if (!written.empty()) fmt::print("  written: {}\n", escape_invalid_utf8(written));
  }
  if (result.failed() > 0)
    fmt::print(stderr, "error: {} of {} logs gave no period (their rows say why)\n",
               result.failed(), result.rows.size());
  return exit_status(result.outcome());
}

int run_estimate(const EstimateOptions& o, const CLI::App& sub, const GlobalOptions& global) {
  const PreparedEstimate p = prepare_estimate(request_of(o, sub, global));
  for (const std::string& w : p.warnings) fmt::print(stderr, "warning: {}\n", spelled(w));
  if (p.job == EstimateJob::kLogTable) return run_log_table(o, p);
  if (p.job == EstimateJob::kFollow) {
    FollowRequest request;
    request.port = p.follow_port;
    request.baud = p.follow_baud;
    request.raw_log = p.follow_raw_log;
    request.duration_s = p.follow_duration;
    request.set_up = p.set_up;
    request.reading = p.reading;
    request.json = o.json;
    request.plot = p.plot;
    request.draw_plot = draw_plot;
    return follow_rig(request);
  }
  const OneLogEstimate result = estimate_one_log(p);
  if (!result.sidecar_note.empty()) fmt::print(stderr, "note: {}\n", result.sidecar_note);
  for (const std::string& w : result.warnings) fmt::print(stderr, "warning: {}\n", spelled(w));
  if (o.json) {
    fmt::print("{}\n", result.json().dump(2));
    return plot_failure_status(result.plot_failure);
  }
  print_estimate(result.log, result.estimate, result.check, result.plot);
  if (result.paper) print_paper_value(*result.paper, "this log's", 20);
  if (result.monte_carlo) print_mu_k_monte_carlo(*result.monte_carlo, 19, result.mc_plot);
  return plot_failure_status(result.plot_failure);
}

}  // namespace

Command add_estimate_command(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<EstimateOptions>();
  CLI::App* sub = app.add_subcommand(
      "estimate",
      "T +- dT and mu_k +- d mu_k from a Hall-sensor log of the real rig (the rig firmware's "
      "serial output, a serial monitor's capture, or a CSV of time and ADC value), or live from "
      "the rig's serial port, by the estimator the rig's Arduino runs");
  sub->add_option("LOG", options->logs,
                  "The log: a file, a folder holding one (a run's hall.csv), or - for standard "
                  "input. Several logs, a folder of logs or a pattern (logs/*.csv) give a table, "
                  "one row per log");
  add_log_reading_options(*sub, options->reading, "");
  sub->add_option("--roi", options->roi,
                  "A video's region where the plate is, X,Y,W,H in its pixels (default: the "
                  "whole picture; frictionlab track shows what was followed)");
  sub->add_option("--scale", options->scale,
                  "A video's millimetres per pixel, for the amplitude in mm");
  sub->add_option("--plate-length", options->plate_length,
                  "Or the plate's length (200mm), both its ends in view");
  sub->add_option("--spacing", options->spacing, "Roller spacing l")->capture_default_str();
  sub->add_option("--spacing-err", options->spacing_err, "Uncertainty dl of the spacing")
      ->capture_default_str();
  sub->add_option("--gravity", options->gravity, "Gravity g")->capture_default_str();
  sub->add_option("--geometry", options->geometry,
                  "Pulses per period: auto (recognise), one (the sensor beyond the turning "
                  "point), or pair (the magnet passes the sensor and back: a sensor inside the "
                  "turning point or at the middle of the travel)")
      ->capture_default_str();
  sub->add_option("--plot", options->plot,
                  "Draw the signal with the pulses and the rejected periods to this PNG");
  sub->add_flag("--json", options->json, "Print one JSON object (SI units) instead of the table");
  sub->add_option("--follow", options->follow,
                  "Read the live rig from this serial port (/dev/ttyACM0): each period as it "
                  "comes, the summary at Ctrl-C");
  sub->add_option("--baud", options->baud, "With --follow: the port's baud rate (the firmware's)")
      ->capture_default_str();
  sub->add_option("--log", options->raw_log,
                  "With --follow: write the lines received to this file, line by line as they "
                  "come");
  sub->add_option("--duration", options->duration,
                  "With --follow: stop after this long (30s) instead of at Ctrl-C");
  sub->add_option("--material", options->material,
                  "The plate's material (the paper's Table I), for logs whose sidecar names none: "
                  "one log's result prints the paper's value beside it");
  sub->add_option("--temperature", options->temperature,
                  "With --material: the rollers' temperature (300 K, or 77 K), for logs whose "
                  "sidecar names none");
  sub->add_option("--out", options->out,
                  "With several logs: the folder for estimates.csv and estimates.json");
  add_monte_carlo_options(*sub, options->monte_carlo);
  sub->add_option("--h-c", options->h_c,
                  "The plate's centre of mass above the contact line (a phone on it raises it): "
                  "mu_k through the thick formula too, and with --mc in its draws");
  sub->add_option("--h-c-err", options->h_c_err, "With --mc: the uncertainty of --h-c");
  sub->add_option("--mc-plot", options->mc_plot,
                  "With --mc: draw the histogram of mu_k's draws to this PNG");
  return Command{sub, [options, sub, &global] { return run_estimate(*options, *sub, global); }};
}

}  // namespace fl::cli
