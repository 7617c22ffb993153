// frictionlab estimate LOG: T +- dT and mu_k +- d mu_k from a log of the real rig's Hall sensor,
// by the very estimator the rig's Arduino runs (src/estimator/period_estimator.h); with --follow
// PORT, live from the rig's serial port (cli/estimate_follow). Reading the log is io/hall_log,
// the estimate lab/log_estimate, the geometry's check lab/geometry_check; this command reads the
// options and prints (cli/estimate_report).
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
#include "cli/log_options.hpp"
#include "cli/monte_carlo_options.hpp"
#include "cli/monte_carlo_report.hpp"
#include "cli/option_quantity.hpp"
#include "cli/plot_failure.hpp"
#include "io/atomic_file.hpp"
#include "io/hall_log.hpp"
#include "io/input_error.hpp"
#include "io/log_files.hpp"
#include "lab/analytic/analytic_report.hpp"
#include "lab/logs/geometry_check.hpp"
#include "lab/logs/log_estimate.hpp"
#include "lab/logs/log_table.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/plot_script.hpp"

namespace fl::cli {
namespace {

// The exit status when some of several logs gave no period (docs/cli.md).
constexpr int kSomeLogsFailed = 3;

struct EstimateOptions {
  std::vector<std::string> logs;
  std::string log;  // the one log, when one is named
  std::string spacing = "89 mm";
  std::string spacing_err = "2 mm";
  std::string gravity = "9.81 m/s^2";
  std::string geometry = "auto";
  LogReadingOptions reading;
  std::string plot;
  bool json = false;
  std::string follow;
  std::string baud = "250000";
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

LogSetUp set_up_from(const EstimateOptions& o) {
  LogSetUp set_up;
  set_up.spacing = option_quantity(o.spacing, Dimension::kLength, "--spacing");
  set_up.spacing_err = option_quantity(o.spacing_err, Dimension::kLength, "--spacing-err");
  set_up.gravity = option_quantity(o.gravity, Dimension::kAcceleration, "--gravity");
  if (!(set_up.spacing > 0.0) || !std::isfinite(set_up.spacing))
    throw InputError({}, "--spacing: the roller spacing must be a finite positive length");
  if (!(set_up.spacing_err >= 0.0) || !std::isfinite(set_up.spacing_err))
    throw InputError({}, "--spacing-err: the uncertainty must be a finite length, not negative");
  if (!(set_up.gravity > 0.0) || !std::isfinite(set_up.gravity))
    throw InputError({}, "--gravity: g must be a finite positive acceleration");
  set_up.geometry = parse_geometry(o.geometry);
  return set_up;
}

void draw_plot(const HallLog& log, const LogEstimate& est, const std::string& png) {
  run_plot_script_on("plot_hall.py", hall_plot_data(log, est), png);
}

void draw_histogram(const AnalyticReport& report, const std::string& png) {
  run_plot_script_on("plot_mc.py", monte_carlo_plot_data(report), png);
}

// The logs named when they are many (a table): more than one argument, a pattern, or a folder of
// several logs; nothing when they are one (its own report).
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

void print_log_table(const std::vector<LogTableRow>& rows) {
  fmt::print("frictionlab estimate: {} logs\n\n", rows.size());
  fmt::print("  {:<24} {:>7}  {:>20}  {:>9}  {:>18}  {}\n", "log", "l [mm]", "T +- dT [s]",
             "N (disc.)", "mu_k +- worst", "material");
  for (const LogTableRow& r : rows) {
    const std::string label = r.label.size() > 24 ? r.label.substr(0, 21) + "..." : r.label;
    if (r.status != "ok") {
      fmt::print("  {:<24} {:>7.1f}  failed: {}\n", label, r.set_up.spacing * 1e3, r.error);
      continue;
    }
    fmt::print(
        "  {:<24} {:>7.1f}  {:>9.6f} +- {:>8.6f}  {:>4} ({:>2})  {:>8.4f} +- {:>6.4f}  {}{}\n",
        label, r.set_up.spacing * 1e3, *r.period, *r.period_err, *r.periods_used,
        *r.periods_discarded, *r.mu_k, *r.mu_k_err_worst, r.material.value_or("-"),
        r.temperature ? fmt::format(" at {:g} K", *r.temperature) : std::string());
  }
  fmt::print(
      "\n  dT is the standard error of the mean period; mu_k is the paper's thin formula and its "
      "worst-case error\n  (from the periods' standard deviation and dl), as the rig computes "
      "them\n");
}

int run_many_logs(const EstimateOptions& o, const std::vector<std::string>& logs,
                  const LogSetUp& set_up, const HallLogOptions& reading) {
  if (!o.plot.empty())
    throw InputError({},
                     "--plot draws one log's signal; with several logs give --out DIR for "
                     "the table, or estimate one log with --plot");
  if (!o.follow.empty() || !o.raw_log.empty() || !o.duration.empty())
    throw InputError({},
                     "--follow, --log and --duration read the rig's serial port, not logs "
                     "(give one: estimate LOG..., or estimate --follow PORT)");
  if (std::find(o.logs.begin(), o.logs.end(), "-") != o.logs.end())
    throw InputError({}, "- (standard input) is one log: estimate it alone, not among others");
  if (!o.out.empty()) prepare_output_folder(o.out, "out");
  LogTableDefaults defaults;
  defaults.set_up = set_up;
  defaults.reading = reading;
  if (!o.material.empty()) defaults.material = o.material;
  if (!o.temperature.empty())
    defaults.temperature = option_quantity(o.temperature, Dimension::kTemperature, "--temperature");
  std::vector<LogTableRow> rows;
  for (const std::string& log : logs) rows.push_back(estimate_log_row(log, defaults));
  const nlohmann::json j = log_table_json(rows);
  std::string written;
  if (!o.out.empty()) {
    const std::string csv = o.out + "/estimates.csv";
    const std::string json = o.out + "/estimates.json";
    write_file_atomic(csv, log_table_csv(rows));
    write_file_atomic(json, nlohmann::json{{"logs", j}}.dump(1) + "\n");
    written = csv + ", " + json;
  }
  if (o.json) {
    fmt::print("{}\n", nlohmann::json{{"logs", j}}.dump(2));
  } else {
    print_log_table(rows);
    if (!written.empty()) fmt::print("  written: {}\n", written);
  }
  const auto failed = std::count_if(rows.begin(), rows.end(),
                                    [](const LogTableRow& r) { return r.status != "ok"; });
  if (failed == 0) return 0;
  fmt::print(stderr, "error: {} of {} logs gave no period (their rows say why)\n", failed,
             rows.size());
  return kSomeLogsFailed;
}

int run_estimate(const EstimateOptions& o) {
  const LogSetUp set_up = set_up_from(o);
  const HallLogOptions reading = log_reading(o.reading);
  const bool monte_carlo =
      !o.monte_carlo.draws.empty() || !o.h_c.empty() || !o.h_c_err.empty() || !o.mc_plot.empty();
  const std::optional<std::vector<std::string>> many = many_logs(o.logs);
  if (monte_carlo && (many || !o.follow.empty()))
    throw InputError({},
                     "--mc and its options estimate one log's mu_k by Monte Carlo; give one "
                     "log (not several, nor --follow)");
  if (many) return run_many_logs(o, *many, set_up, reading);
  if (!o.out.empty())
    throw InputError({},
                     "--out writes the table of several logs; for one log use --json (or "
                     "--log with --follow), or name several logs");
  if (!o.material.empty() || !o.temperature.empty())
    throw InputError({},
                     "--material and --temperature go into the table of several logs; one "
                     "log's estimate does not use them");
  if (!o.follow.empty()) {
    if (!o.log.empty())
      throw InputError({}, "--follow: reads the rig's serial port, not a log file; found both \"" +
                               o.follow + "\" and \"" + o.log +
                               "\" (give one: estimate LOG, or estimate --follow PORT)");
    if (!o.plot.empty()) prepare_output_file(o.plot, "plot");
    if (!o.raw_log.empty()) prepare_output_file(o.raw_log, "follow.raw_log");
    FollowRequest request;
    request.port = o.follow;
    request.baud = option_quantity(o.baud, Dimension::kDimensionless, "--baud");
    request.raw_log = o.raw_log;
    if (!o.duration.empty())
      request.duration_s = option_quantity(o.duration, Dimension::kTime, "--duration");
    request.set_up = set_up;
    request.reading = reading;
    request.json = o.json;
    request.plot = o.plot;
    request.draw_plot = draw_plot;
    return follow_rig(request);
  }
  if (o.log.empty())
    throw InputError({},
                     "estimate: expected a log (a file, a folder holding one, or - for "
                     "standard input), or --follow PORT for the rig's serial port");
  if (!o.raw_log.empty() || !o.duration.empty())
    throw InputError({}, "--log and --duration go with --follow PORT");

  const std::optional<MonteCarloRequest> mc = monte_carlo_request(o.monte_carlo);
  if (!mc && (!o.h_c.empty() || !o.h_c_err.empty() || !o.mc_plot.empty()))
    throw InputError({},
                     "--h-c, --h-c-err and --mc-plot go with --mc N (the Monte Carlo of "
                     "mu_k); add --mc 100000, or drop them");
  const double h_c = o.h_c.empty() ? 0.0 : option_quantity(o.h_c, Dimension::kLength, "--h-c");
  const double h_c_err =
      o.h_c_err.empty() ? 0.0 : option_quantity(o.h_c_err, Dimension::kLength, "--h-c-err");
  if (!(h_c >= 0.0) || !std::isfinite(h_c) || !(h_c_err >= 0.0) || !std::isfinite(h_c_err))
    throw InputError({}, "--h-c and --h-c-err: expected finite lengths, not negative");
  // The plots' places are checked before any work; a plot that fails still leaves the results.
  if (!o.plot.empty()) prepare_output_file(o.plot, "plot");
  if (!o.mc_plot.empty()) prepare_output_file(o.mc_plot, "mc_plot");
  const HallLog log = read_hall_log(o.log, reading);
  // The log's sidecar, as for a table of logs: its rig over the command line's.
  std::string sidecar_note;
  const LogSetUp log_set_up = set_up_for_log(log.file, set_up, &sidecar_note);
  if (!sidecar_note.empty()) fmt::print(stderr, "note: {}\n", sidecar_note);
  const LogEstimate est = estimate_log(log, log_set_up, !o.plot.empty());
  std::string plot_note;
  std::string plot_failure;
  if (!o.plot.empty()) {
    try {
      draw_plot(log, est, o.plot);
      plot_note = " (the plot " + o.plot + " shows the signal)";
    } catch (const std::runtime_error& e) {
      plot_failure = e.what();
    }
  }
  require_periods(log, est, plot_note);
  const GeometryCheck check = check_geometry(log, est);
  require_geometry(log, est, check, plot_note);

  // mu_k by Monte Carlo: T drawn with the periods' standard deviation (the dT of the rules
  // printed), l with dl, h_c with dh_c, through the thick formula (the thin one at h_c = 0).
  std::optional<AnalyticReport> mc_report;
  if (mc) {
    AnalyticSetUp mc_set_up;
    mc_set_up.spacing = log_set_up.spacing;
    mc_set_up.spacing_err = log_set_up.spacing_err;
    mc_set_up.gravity = log_set_up.gravity;
    mc_set_up.h_c = h_c;
    mc_set_up.h_c_err = h_c_err;
    mc_report = analytic_for_period(mc_set_up, est.stats.period_s, est.stats.period_std_s);
    add_monte_carlo(*mc_report, *mc);
    if (!o.mc_plot.empty()) {
      try {
        draw_histogram(*mc_report, o.mc_plot);
      } catch (const std::runtime_error& e) {
        plot_failure += (plot_failure.empty() ? "" : "; ") + std::string(e.what());
      }
    }
  }
  if (o.json) {
    nlohmann::json j = estimate_json(log, est, plot_failure.empty() ? o.plot : "");
    j["monte_carlo"] =
        mc_report ? monte_carlo_json(*mc_report->monte_carlo) : nlohmann::json(nullptr);
    fmt::print("{}\n", j.dump(2));
    return plot_failure_status(plot_failure);
  }
  print_estimate(log, est, check, plot_failure.empty() ? o.plot : "");
  if (mc_report) print_mu_k_monte_carlo(*mc_report, 19, o.mc_plot);
  return plot_failure_status(plot_failure);
}

}  // namespace

Command add_estimate_command(CLI::App& app, const GlobalOptions& /*global*/) {
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
                  "Read the rig live from this serial port (/dev/ttyACM0): each period as it "
                  "comes, the summary at Ctrl-C");
  sub->add_option("--baud", options->baud, "With --follow: the port's baud rate (the firmware's)")
      ->capture_default_str();
  sub->add_option("--log", options->raw_log,
                  "With --follow: write the lines received to this file, line by line as they "
                  "come");
  sub->add_option("--duration", options->duration,
                  "With --follow: stop after this long (30s) instead of at Ctrl-C");
  sub->add_option("--material", options->material,
                  "With several logs: the plate's material, for logs whose sidecar names none");
  sub->add_option("--temperature", options->temperature,
                  "With several logs: the rollers' temperature (300 K), for logs whose sidecar "
                  "names none");
  sub->add_option("--out", options->out,
                  "With several logs: the folder for estimates.csv and estimates.json");
  add_monte_carlo_options(*sub, options->monte_carlo);
  sub->add_option("--h-c", options->h_c,
                  "With --mc: the plate's centre of mass above the contact line (thick formula)");
  sub->add_option("--h-c-err", options->h_c_err, "With --mc: the uncertainty of --h-c");
  sub->add_option("--mc-plot", options->mc_plot,
                  "With --mc: draw the histogram of mu_k's draws to this PNG");
  return Command{sub, [options, sub] {
                   if (sub->count("--baud") > 0 && options->follow.empty())
                     throw InputError({},
                                      "--baud is the serial port's rate for --follow PORT; "
                                      "a log file has none: drop it, or add --follow");
                   if (options->logs.size() == 1) options->log = options->logs.front();
                   return run_estimate(*options);
                 }};
}

}  // namespace fl::cli
