// frictionlab compare: every row of a measurements file (the paper's Table I unless --measured
// names another) simulated in the rig, residuals in units of the row's dT, and mu_k refitted
// through the simulation.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/log_options.hpp"
#include "cli/option_quantity.hpp"
#include "cli/paper_value_text.hpp"
#include "cli/plot_failure.hpp"
#include "cli/scene_options.hpp"
#include "cli/stop_signals.hpp"
#include "hall_log/hall_log.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/plus_minus.hpp"
#include "lab/compare/compare.hpp"
#include "lab/compare/log_against_rig.hpp"
#include "lab/request/compare_request.hpp"
#include "lab/request/lab_data.hpp"
#include "lab/request/outcome.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/plot_script.hpp"

namespace fl::cli {
namespace {

struct CompareCommandOptions {
  std::string scene;
  std::string measured;
  std::string log;
  std::string geometry;
  LogReadingOptions reading;
  std::vector<std::string> overrides;
  std::string duration;
  int workers = 0;
  std::string out = CompareRequest{}.out;
  bool plot = false;
  bool json = false;
  bool no_refit = false;
  std::optional<std::string> material;
  std::optional<std::string> temperature;
};

// As the row wrote it, to at most 6 decimals (a table written by frictionlab estimate carries
// every digit of a float).
std::string measured_text(const Measured& m) {
  return fmt::format("{:.{}f} +- {:.{}f}", m.value, std::min(m.decimals, 6), m.uncertainty,
                     std::min(m.uncertainty_decimals, 6));
}

void print_table(const CompareResult& r, bool paper) {
  fmt::print(
      "frictionlab compare: {} in the scene {} (l = {:.1f}{} mm, h_c = {:.2f} mm, g = {} "
      "m/s^2)\n",
      paper ? std::string("the paper's Table I") : r.measurements, r.scene, r.spacing * 1e3,
      r.spacing_err ? fmt::format(" +- {:.1f}", *r.spacing_err * 1e3) : std::string(), r.h_c * 1e3,
      r.gravity);
  fmt::print(
      "  residual = (T_sim - T_measured) / dT; thin bias = how much the paper's formula "
      "overestimates mu_k for this h_c\n\n");
  // The rows' own rigs, where their keys change the scene's spacing or plate.
  for (const CompareRow& row : r.rows)
    if (!row.keys.empty() &&
        (std::fabs(row.spacing - r.spacing) > 1e-12 || std::fabs(row.h_c - r.h_c) > 1e-12))
      fmt::print("  {}: l = {:.1f} mm, h_c = {:.2f} mm\n", row.label, row.spacing * 1e3,
                 row.h_c * 1e3);
  fmt::print("  {:<28} {:>5}  {:>15} {:>10} {:>9} {:>9}  {:>14}  {:>27} {:>9}\n",
             paper ? "material" : "row", "temp", "T measured [s]", "T sim [s]", "residual",
             "thin bias", paper ? "mu_k paper" : "mu_k reported", "mu_k refit (worst) (quad.)",
             "T at fit");
  for (const CompareRow& row : r.rows) {
    const std::string head = fmt::format("  {:<28} {:>3} K  {:>15}", row.label, row.temperature,
                                         measured_text(row.period_measured));
    if (row.status != "compared") {
      fmt::print("{}  {}: {}\n", head, row.status, row.reason);
      continue;
    }
    const std::string refit = row.mu_k_refit
                                  ? fmt::format("{:.4f} +- {:.4f} ({:.4f})", *row.mu_k_refit,
                                                row.mu_k_refit_err_worst.value_or(0.0),
                                                row.mu_k_refit_err_quadrature.value_or(0.0))
                                  : std::string("-");
    const std::string at_fit =
        row.period_at_refit
            ? fmt::format("{:+.4f}%",
                          100.0 * (*row.period_at_refit / row.period_measured.value - 1))
            : std::string("-");
    const bool from_trajectory = row.period_simulated_source.starts_with("trajectory");
    fmt::print("{} {:>10.5f} {:>7.2f} sd {:>+8.2f}%  {:>14}  {:>27} {:>9}{}{}\n", head,
               row.period_simulated.value_or(NAN), row.residual_sigma.value_or(NAN),
               100.0 * row.thin_bias_mu_k.value_or(NAN),
               row.mu_k_reported ? measured_text(*row.mu_k_reported) : std::string("-"), refit,
               at_fit, row.refit_note.empty() ? "" : "  (" + row.refit_note + ")",
               from_trajectory ? "  (T sim from the trajectory: the rig's estimator accepted no "
                                 "period; simulate longer)"
                               : "");
  }
}

void print_log_report(const LogAgainstRig& r, const std::optional<PaperComparison>& paper,
                      const std::string& written) {
  const CompareRow& row = r.fit.rows.front();
  fmt::print(
      "frictionlab compare --log: {} against the scene {} (l = {:.1f} mm, h_c = {:.2f} mm)\n\n",
      r.log, r.fit.scene, row.spacing * 1e3, row.h_c * 1e3);
  fmt::print(
      "  the log                T = {:.6f} +- {:.6f} s (standard error, N = {}, {} "
      "discarded)\n",
      row.period_measured.value, row.period_measured.uncertainty, r.measured.periods_used,
      r.measured.periods_discarded);
  fmt::print(
      "  the scene's mu_k       {:.4f}: T = {}\n", row.mu_k_simulated,
      row.period_simulated ? fmt::format("{:.6f} s", *row.period_simulated) : std::string("-"));
  if (row.mu_k_refit)
    fmt::print(
        "  mu_k refitted          {} (quadrature, from dT and dl = {:.1f} mm): T = {:.6f} s{}\n",
        plus_minus(*row.mu_k_refit, row.mu_k_refit_err_quadrature.value_or(NAN), 4),
        row.spacing_err.value_or(0.0) * 1e3, row.period_at_refit.value_or(NAN),
        row.refit_note.empty() ? "" : " (" + row.refit_note + ")");
  else
    fmt::print("  mu_k refitted          none{}\n",
               row.refit_note.empty() ? "" : ": " + row.refit_note);
  if (paper) print_paper_value(*paper, "the refitted", 22);
  fmt::print("  simulated at mu_k      {:.4f}: T = {:.6f} +- {:.6f} s (sd), {} periods\n", r.mu_k,
             r.simulated.period, r.simulated.period_std, r.simulated.periods_used);
  fmt::print(
      "  aligned                on the first pulse (the log's time = simulated time {:+.4f} s)\n",
      r.shift);
  fmt::print(
      "  residual               {:.1f} counts rms (first three periods {:.1f}, last three "
      "{:.1f})\n",
      r.residual_rms, r.residual_rms_first_periods, r.residual_rms_last_periods);
  fmt::print("  {:<22} {:>12} {:>12}\n", "", "log", "simulated");
  fmt::print("  {:<22} {:>11.3f}% {:>11.3f}%\n", "period scatter (sd/T)",
             100 * r.measured.period_std / r.measured.period,
             100 * r.simulated.period_std / r.simulated.period);
  fmt::print("  {:<22} {:>12} {:>12}\n", "periods discarded", r.measured.periods_discarded,
             r.simulated.periods_discarded);
  const auto drift = [](const TraceFacts& f) {
    return f.period_drift ? fmt::format("{:+.2f}", 60e3 * *f.period_drift) : std::string("-");
  };
  fmt::print("  {:<22} {:>12} {:>12}\n", "drift [ms/min]", drift(r.measured), drift(r.simulated));
  fmt::print("  {:<22} {:>12.2f} {:>12.2f}\n", "pulse width [ms]", 1e3 * r.measured.pulse_width,
             1e3 * r.simulated.pulse_width);
  fmt::print("  {:<22} {:>12.0f} {:>12.0f}\n", "pulse height [counts]", r.measured.pulse_height,
             r.simulated.pulse_height);
  fmt::print("  {:<22} {:>+12.1f} {:>+12.1f}\n", "baseline drift [counts]",
             r.measured.baseline_last - r.measured.baseline_first,
             r.simulated.baseline_last - r.simulated.baseline_first);
  if (r.disagreements.empty())
    fmt::print("\n  the log and its simulation agree in every test above\n");
  else
    fmt::print("\n  where they disagree:\n");
  for (const std::string& d : r.disagreements) fmt::print("  - {}\n", d);
  if (!written.empty()) fmt::print("\n  written: {}\n", written);
}

int run_compare_command(const CompareCommandOptions& o, const GlobalOptions& global) {
  CompareRequest request;
  request.scene = o.scene;
  request.measured = o.measured;
  request.log = o.log;
  request.geometry = o.geometry;
  request.columns = o.reading.columns;
  if (!o.reading.rate.empty()) request.rate = o.reading.rate;
  request.time_unit = o.reading.time_unit;
  request.set = o.overrides;
  if (!o.duration.empty()) request.duration = o.duration;
  request.jobs = o.workers;
  request.out = o.out;
  request.plot = o.plot;
  request.refit = !o.no_refit;
  request.assets = global.asset_dir;
  request.material = o.material;
  if (o.temperature) request.temperature = *o.temperature;
  const bool tty = isatty(2) == 1;
  const StopSignals signals;
  const CompareRequestResult result = compare_measurements(
      request,
      [tty](std::size_t done, std::size_t total) {
        if (tty) {
          fmt::print(stderr, "\r\033[Kcompare: {}/{} rows", done, total);
          if (done == total) fmt::print(stderr, "\n");
        }
      },
      JobControl{&stop_requested(), {}});
  std::string written;
  for (const std::string& w : result.written) written += (written.empty() ? "" : ", ") + w;
  if (result.log && result.log->interrupted) {
    fmt::print(stderr,
               "frictionlab compare: interrupted before the log's comparison was done; "
               "nothing written\n");
    return stop_exit_status();
  }
  if (result.log) {
    if (o.json)
      fmt::print("{}\n", result.json.dump(2));
    else
      print_log_report(*result.log, result.paper_value, written);
    return plot_failure_status(result.plot_failure);
  }
  const CompareResult& table = *result.table;
  const int without = result.rows_without_result();
  if (without > 0 && !result.interrupted)
    fmt::print(stderr, "error: {} of {} rows gave no {} (their rows say why)\n", without,
               table.rows.size(), request.refit ? "refitted mu_k" : "simulated period");
  if (o.json) {
    fmt::print("{}\n", result.json.dump(2));
  } else {
    print_table(table, result.paper);
    for (const SkippedRow& row : result.skipped)
      fmt::print("  left out: {} (line {}, {}: no period to compare)\n", row.label, row.where.line,
                 row.reason);
    fmt::print("\n  {} simulations in {:.1f} s on {} worker{}\n", table.simulations, table.wall_s,
               table.workers, table.workers == 1 ? "" : "s");
    fmt::print("  written: {}\n", written);
  }
  if (!result.plot_failure.empty())
    fmt::print(stderr, "error: no plot: {}; the results above are complete\n", result.plot_failure);
  if (result.interrupted)
    fmt::print(stderr,
               "frictionlab compare: interrupted; kept: the {} rows done above and in {} ({} "
               "marked interrupted)\n",
               table.rows.size() - static_cast<std::size_t>(table.rows_interrupted()), written,
               table.rows_interrupted());
  return exit_status(result.outcome(), stop_signal());
}

}  // namespace

Command add_compare_command(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<CompareCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "compare",
      "Simulate every row of your measurements (or the paper's Table I) and refit mu_k through "
      "the model");
  sub->add_option("--scene", options->scene, "The rig's scene (default scenes/paper-rig.yaml)");
  sub->add_option("--measured", options->measured,
                  "Your measurements: a CSV of label, scene keys, period, period_err (default: "
                  "the paper's Table I, assets/paper/table1-measured.csv)");
  sub->add_option("--log", options->log,
                  "A Hall log of your rig: refit mu_k so the simulated signal has its period, "
                  "and set the two signals side by side (compare-log.json, --plot)");
  sub->add_option("--geometry", options->geometry,
                  "With --log: pulses per period, auto, one or pair (as for estimate)");
  add_log_reading_options(*sub, options->reading, "With --log: ");
  sub->add_option("--material", options->material,
                  "With --log: the plate's material (the paper's Table I), for a log whose sidecar "
                  "names none: its value is printed beside the refitted mu_k");
  sub->add_option("--temperature", options->temperature,
                  "With --material: the rollers' temperature (300 K, or 77 K)");
  sub->add_option("--set", options->overrides,
                  "Override a scene key, e.g. --set plate.thickness=5mm (repeatable)");
  sub->add_option("--duration", options->duration,
                  "Simulated time per run, e.g. 20s (default: 15 measured periods, at least the "
                  "scene's duration)");
  sub->add_option("-j,--jobs", options->workers, "Rows simulated in parallel (default: every core)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--out", options->out, "Folder for compare.csv, compare.json, compare.png");
  sub->add_flag("--plot", options->plot, "Draw compare.png (python3 + matplotlib)");
  sub->add_flag("--json", options->json, "Print one JSON object instead of the table");
  sub->add_flag("--no-refit", options->no_refit, "Only simulate the paper's mu_k");
  return Command{sub, [options, &global] { return run_compare_command(*options, global); }};
}

}  // namespace fl::cli
