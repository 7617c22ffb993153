// frictionlab fit SERIES.csv: mu_k and h_c from periods measured at several roller spacings, by
// the thick-plate line T^2 = (2 pi^2 / (mu_k g)) l - 4 pi^2 h_c / g (core/thick_plate_fit); with
// --mc, its Monte Carlo; with --through-rig, refitted through simulations of a scene
// (lab/fit_through_rig). Reading the series is io/spacing_series_csv, the report
// lab/spacing_fit_report; this command reads the options, checks what the fit says, and prints.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/field_spelling.hpp"
#include "cli/monte_carlo_options.hpp"
#include "cli/paper_value_text.hpp"
#include "cli/plot_failure.hpp"
#include "io/plus_minus.hpp"
#include "lab/compare/spacing_fit_report.hpp"
#include "lab/request/fit_request.hpp"

namespace fl::cli {
namespace {

struct FitOptions {
  std::string file;
  std::string gravity = quantity_input_text(FitRequest{}.gravity);
  bool json = false;
  std::string out;
  std::string plot;
  CLI::Option* plot_option = nullptr;
  MonteCarloOptions monte_carlo;
  bool through_rig = false;
  std::string scene;
  std::vector<std::string> overrides;
  int workers = 0;
  std::optional<std::string> material;
  std::optional<std::string> temperature;
};

std::string pm(std::optional<double> value, std::optional<double> err, double scale, int digits) {
  if (!value) return "-";
  return err ? plus_minus(*value * scale, *err * scale, digits)
             : fmt::format("{:.{}f}", *value * scale, digits);
}

std::string interval(const SampleSummary& s, double scale, int digits, const char* unit) {
  return fmt::format("{:.{}f} +- {}{} (95 % in [{:.{}f}, {:.{}f}]{})", s.mean * scale, digits,
                     s.sd ? fmt::format("{:.{}f}", *s.sd * scale, digits) : std::string("-"), unit,
                     s.quantile_025 * scale, digits, s.quantile_975 * scale, digits, unit);
}

void print_report(const SpacingFitReport& r) {
  const ThickPlateFit& f = r.fit;
  fmt::print("frictionlab fit: {} ({} rows, g = {} m/s^2)\n", r.series.file, r.series.rows.size(),
             r.gravity);
  fmt::print("  line T^2 = s l + c     s = {:.5g} +- {:.2g} s^2/m, c = {:.5g} +- {:.2g} s^2{}\n",
             f.slope, f.slope_err, f.intercept, f.intercept_err,
             f.iterations > 1 ? fmt::format(" (effective variance: {} iterations{})", f.iterations,
                                            f.converged ? "" : ", not converged")
                              : std::string());
  fmt::print("  mu_k                   {}\n", pm(f.mu_k, f.mu_k_err, 1.0, 4));
  fmt::print("  h_c                    {} mm{}\n", pm(f.h_c, f.h_c_err, 1e3, 2),
             *f.h_c < 0.0
                 ? fmt::format(" (below the contact line: {:.1f} sd from 0)", -*f.h_c / *f.h_c_err)
                 : std::string());
  fmt::print(
      "                         (the intercept reads h_c - delta / mu_k for rollers with rolling "
      "resistance delta: a spacing series alone cannot tell delta from h_c)\n");
  if (f.correlation)
    fmt::print(
        "  correlation            {:+.3f} (of mu_k and h_c: a larger h_c goes with a {} mu_k)\n",
        *f.correlation, *f.correlation < 0.0 ? "smaller" : "larger");
  fmt::print("  chi^2                  {:.3f} for {} degree{} of freedom{}\n", f.chi2,
             f.degrees_of_freedom, f.degrees_of_freedom == 1 ? "" : "s",
             f.chi2_per_dof ? fmt::format(" (chi^2/dof {:.3f})", *f.chi2_per_dof)
                            : std::string(" (two rows: the line goes through both; no check)"));
  fmt::print(
      "  thin formula           mu_k = {} from a line through the origin (chi^2/dof {:.3g}): the "
      "paper's formula, h_c = 0\n",
      plus_minus(f.mu_k_thin_line, f.mu_k_thin_line_err, 4),
      f.rows.size() > 1 ? f.thin_chi2 / static_cast<double>(f.rows.size() - 1)
                        : std::numeric_limits<double>::quiet_NaN());
  fmt::print("\n  {:>4} {:<14} {:>16} {:>20} {:>10} {:>9} {:>10}", "line", "label", "l [mm]",
             "T [s]", "T fit [s]", "residual", "mu_k thin");
  if (r.rig) fmt::print(" {:>11} {:>11}", "T sim [s]", "correction");
  fmt::print("\n");
  for (std::size_t i = 0; i < f.rows.size(); ++i) {
    const SpacingSeriesRow& in = r.series.rows[i];
    const FitRow& out = f.rows[i];
    fmt::print("  {:>4} {:<14} {:>16} {:>20} {:>10.5f} {:>+6.2f} sd {:>10.4f}", in.line,
               in.label.substr(0, 14),
               pm(in.measurement.spacing, in.measurement.spacing_err, 1e3, 1),
               pm(in.measurement.period, in.measurement.period_err, 1.0, 4),
               out.period_fit.value_or(std::numeric_limits<double>::quiet_NaN()),
               out.residual_sigma, out.mu_k_thin);
    if (r.rig)
      fmt::print(" {:>11.5f} {:>+10.2e}", r.rig->rows[i].period_simulated,
                 r.rig->rows[i].correction - 1.0);
    fmt::print("\n");
  }
  if (r.monte_carlo) {
    const ThickPlateFitMonteCarlo& mc = *r.monte_carlo;
    fmt::print("\n  Monte Carlo            {} draws of every row (seed {}), each refitted{}\n",
               mc.draws, mc.seed,
               mc.skipped > 0 ? fmt::format("; {} skipped (a period or spacing drawn <= 0, or a "
                                            "falling line)",
                                            mc.skipped)
                              : std::string());
    if (mc.mu_k) {
      fmt::print("    mu_k                 {}  (fit: +- {:.4f})\n", interval(*mc.mu_k, 1.0, 4, ""),
                 *f.mu_k_err);
      fmt::print("    h_c                  {}  (fit: +- {:.2f} mm)\n",
                 interval(*mc.h_c, 1e3, 2, " mm"), *f.h_c_err * 1e3);
      if (mc.correlation)
        fmt::print("    correlation          {:+.3f}  (fit: {:+.3f})\n", *mc.correlation,
                   *f.correlation);
    }
  }
  if (r.rig) {
    const FitThroughRig& rig = *r.rig;
    const ThickPlateFit& g = rig.fit;
    fmt::print(
        "\n  through the rig        scene {}: every row simulated at its spacing ({} simulations, "
        "{} iteration{}{})\n",
        rig.scene, rig.simulations, rig.iterations, rig.iterations == 1 ? "" : "s",
        rig.converged
            ? fmt::format(", mu_k settled within {:.1e}{}", std::max(rig.tolerance, rig.resolution),
                          rig.resolution > rig.tolerance ? ", what the simulations resolve" : "")
            : ", NOT converged");
    fmt::print("    mu_k                 {} (closed form {:.4f}; {:+.2e} relative)\n",
               pm(g.mu_k, g.mu_k_err, 1.0, 4), *rig.closed_form.mu_k,
               *g.mu_k / *rig.closed_form.mu_k - 1.0);
    fmt::print(
        "    h_c                  {} mm fitted; the scene's plate has {:.2f} mm ({:+.1f} sd)\n",
        pm(g.h_c, g.h_c_err, 1e3, 2), rig.h_c_scene * 1e3, (*g.h_c - rig.h_c_scene) / *g.h_c_err);
    if (g.chi2_per_dof) fmt::print("    chi^2/dof            {:.3f}\n", *g.chi2_per_dof);
  }
}

int run_fit(const FitOptions& o, const GlobalOptions& global) {
  FitRequest request;
  request.series = o.file;
  request.gravity = o.gravity;
  request.out = o.out;
  if (o.plot_option->count() > 0) request.plot = o.plot;
  if (const std::optional<MonteCarloRequest> mc = monte_carlo_request(o.monte_carlo)) {
    request.mc = mc->draws;
    request.seed = mc->seed;
  }
  request.through_rig = o.through_rig;
  if (!o.scene.empty()) request.scene.file = o.scene;
  request.scene.asset_dir = global.asset_dir;
  request.set = o.overrides;
  request.jobs = o.workers;
  request.material = o.material;
  if (o.temperature) request.temperature = *o.temperature;
  request.assets = global.asset_dir;
  const FitResult result = fit_series(request);
  for (const std::string& w : result.warnings) fmt::print(stderr, "{}\n", spelled(w));
  if (!result.rig_failure.empty()) {
    fmt::print(stderr,
               "error: --through-rig: {}; the closed-form fit stands (run without "
               "--through-rig), or simulate a scene that oscillates there\n",
               spelled(result.rig_failure));
    return exit_status(result.outcome());
  }
  if (o.json) {
    nlohmann::json out = result.json;
    out["plot"] = result.plot.empty() ? nlohmann::json(nullptr) : nlohmann::json(result.plot);
    fmt::print("{}\n", out.dump(2));
  } else {
    print_report(result.report);
    if (result.paper) {
      fmt::print("\n");
      print_paper_value(*result.paper, "the fitted", 22);
    }
    if (!result.written.empty()) {
      std::string list;
      for (const std::string& w : result.written) list += (list.empty() ? "" : ", ") + w;
      fmt::print("\n  written: {}\n", list);
    }
  }
  return plot_failure_status(result.plot_failure);
}

}  // namespace

Command add_fit_command(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<FitOptions>();
  CLI::App* sub = app.add_subcommand(
      "fit",
      "mu_k and h_c from periods measured at several roller spacings (a CSV of spacing, period, "
      "period_err[, spacing_err, label]): the thick-plate line T^2 against l");
  sub->add_option("SERIES", options->file,
                  "The series: a CSV whose header names spacing, period, period_err and "
                  "optionally spacing_err and label; values with units (89 mm, 0.79 s, 5 ms)")
      ->required();
  sub->add_option("--gravity", options->gravity, "Gravity g")->capture_default_str();
  sub->add_option("--out", options->out, "Folder for fit.csv and fit.json (and fit.png)");
  options->plot_option =
      sub->add_option("--plot", options->plot,
                      "Draw T^2 against l with the fit, its 1-sigma band and the thin formula's "
                      "line: to this PNG, or to DIR/fit.png with --out DIR")
          ->expected(0, 1);
  add_monte_carlo_options(*sub, options->monte_carlo);
  sub->add_flag("--through-rig", options->through_rig,
                "Refit through simulations of a scene at every row's spacing, for what the "
                "closed form leaves out");
  sub->add_option("--scene", options->scene,
                  "With --through-rig: the rig's scene (default scenes/minimal.yaml)");
  sub->add_option("--set", options->overrides,
                  "With --through-rig: override a scene key, e.g. --set world.time_step=0.5ms");
  sub->add_option("-j,--jobs", options->workers,
                  "With --through-rig: rows simulated in parallel (default: every core)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--material", options->material,
                  "The plate's material (the paper's Table I): its value is printed beside the "
                  "fitted mu_k, with the difference in standard errors");
  sub->add_option("--temperature", options->temperature,
                  "With --material: the rollers' temperature (300 K, or 77 K)");
  sub->add_flag("--json", options->json, "Print one JSON object (SI units) instead of the table");
  return Command{sub, [options, &global] { return run_fit(*options, global); }};
}

}  // namespace fl::cli
