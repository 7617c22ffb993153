// frictionlab analytic: the analytic model for a set-up given by l, mu_k or T, and h_c. The
// model's report is lab/analytic_report; this command reads the options and prints.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>

#include <unistd.h>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/monte_carlo_options.hpp"
#include "cli/monte_carlo_report.hpp"
#include "cli/option_quantity.hpp"
#include "cli/plot_failure.hpp"
#include "core/paper_table.hpp"
#include "io/input_error.hpp"
#include "io/paper_table_yaml.hpp"
#include "io/unknown_material.hpp"
#include "lab/analytic/analytic_report.hpp"
#include "lab/request/lab_data.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/plot_script.hpp"

namespace fl::cli {
namespace {

struct AnalyticOptions {
  std::string spacing = "89 mm";
  std::string spacing_err = "2 mm";
  std::string mu_k;
  std::string period;
  std::string period_err = "0 s";
  std::string material;
  std::string temperature = "300 K";
  std::string h_c = "0 mm";
  std::string h_c_err = "0 mm";
  std::string gravity = "9.81 m/s^2";
  std::string roller_radius = "10 mm";
  std::string roller_speed = "1600 rpm";
  std::string amplitude = "20 mm";
  std::string law = "coulomb";
  std::string mu_s;
  std::string v_s;
  std::string beta;
  bool json = false;
  MonteCarloOptions monte_carlo;
  std::string plot;
};

// The material and its row of Table I that --material and --temperature name.
std::pair<const PaperMaterial*, const PaperMeasurement*> paper_row(const PaperTable& table,
                                                                   const AnalyticOptions& o) {
  const PaperMaterial* material = table.find(o.material);
  if (material == nullptr)
    throw InputError({}, "--material: unknown material \"" + o.material + "\"; " +
                             unknown_material_note(table, o.material));
  const double temperature =
      option_quantity(o.temperature, Dimension::kTemperature, "--temperature");
  const PaperMeasurement* row = PaperTable::at(*material, temperature);
  if (row == nullptr)
    throw InputError({}, fmt::format("--temperature: the paper measured {} at 300 K{} only",
                                     material->name, material->cold ? " and 77 K" : ""));
  return {material, row};
}

void print_report(const AnalyticReport& r) {
  const AnalyticSetUp& s = r.set_up;
  constexpr double kRpm = 60.0 / (2.0 * 3.14159265358979323846);
  fmt::print("frictionlab analytic: the friction oscillator for {}\n", r.source);
  fmt::print("  roller spacing l             {:.1f} +- {:.1f} mm\n", s.spacing * 1e3,
             s.spacing_err * 1e3);
  fmt::print("  centre-of-mass height h_c    {:.2f}{} mm\n", s.h_c * 1e3,
             s.h_c_err > 0.0 ? fmt::format(" +- {:.2f}", s.h_c_err * 1e3) : std::string());
  if (r.period_measured) {
    fmt::print("  measured period T            {:.4g} +- {:.2g} s\n", *r.period_measured,
               r.period_measured_err);
    if (r.material)
      fmt::print("  paper's mu_k                 {} +- {}\n", r.paper_mu_k.value,
                 r.paper_mu_k.uncertainty);
    fmt::print(
        "  mu_k, thin formula           {:.4f} +- {:.4f} (worst case) +- {:.4f} (quadrature)\n",
        r.mu_k_thin.mu_k, r.mu_k_thin.worst, r.mu_k_thin.quadrature);
    fmt::print(
        "  mu_k, thick formula          {:.4f} +- {:.4f} (worst case) +- {:.4f} (quadrature)\n",
        r.mu_k_thick.mu_k, r.mu_k_thick.worst, r.mu_k_thick.quadrature);
    fmt::print(
        "  condition numbers            d ln mu / d ln T = {:.3f}, d ln mu / d ln l = {:.0f}\n",
        r.mu_k_thick.condition_period, r.mu_k_thick.condition_spacing);
    if (r.monte_carlo) print_mu_k_monte_carlo(r, 29, "");
  } else {
    fmt::print("  mu_k                         {:.4g}\n", r.mu_k);
  }
  fmt::print("  period, thin formula         {:.5f} s\n", r.period_thin);
  if (!r.restoring_force) {
    fmt::print(
        "  no restoring force: l = {:.1f} mm <= 2 mu_k h_c = {:.1f} mm; the plate drifts off\n",
        s.spacing * 1e3, 2.0 * r.mu_k * s.h_c * 1e3);
    return;
  }
  fmt::print("  period, thick formula        {:.5f} s ({:+.2f} % against thin)\n", *r.period_thick,
             100.0 * (*r.period_thick / r.period_thin - 1.0));
  fmt::print("  tipping amplitude            {:.1f} mm (a normal force reaches zero)\n",
             *r.tipping_amplitude * 1e3);
  fmt::print(
      "  full slip at amplitude {:.0f} mm needs the rollers above {:.0f} rpm; at {:.0f} rpm the "
      "slip margin is {:.2f}{}\n",
      s.amplitude * 1e3, *r.roller_speed_for_full_slip * kRpm, s.roller_speed * kRpm,
      *r.slip_margin,
      *r.slip_margin > 1.0 ? "" : " (< 1: the plate sticks to a roller for part of each cycle)");
  if (r.friction_law_refused)
    fmt::print("  friction law                 no closed forms here: {}\n",
               *r.friction_law_refused);
  if (!r.friction_law) return;
  const AnalyticLaw& a = *r.friction_law;
  fmt::print(
      "  friction law                 {}, mu_k {:.4g}, mu_s {:.4g}{}\n",
      friction_law_kind_name(a.law.kind), a.law.mu_k, a.law.mu_s,
      a.law.kind == FrictionLawKind::kStribeck
          ? fmt::format("{}, beta {:+.4g} s/m",
                        a.law.mu_s != a.law.mu_k ? fmt::format(", v_s {:.4g} mm/s", a.law.v_s * 1e3)
                                                 : std::string(),
                        a.law.beta)
          : std::string());
  fmt::print("  mu at the rollers' speed     {:.4f} (v_r = {:.4g} m/s)\n", a.mu_at_surface_speed,
             a.surface_speed);
  fmt::print("  slip threshold (this law)    {:.1f} rpm for A = {:.0f} mm\n",
             a.full_slip_roller_speed * kRpm, s.amplitude * 1e3);
  fmt::print(
      "  stick condition              a plate stuck to a roller breaks free at |x| = x_b = "
      "{:.3f} mm\n",
      a.break_offset * 1e3);
  if (a.cycle) {
    if (a.cycle->clipped)
      fmt::print(
          "  clipped cycle                amplitude v_r / Omega = {:.3f} mm, period {:.5f} s\n",
          a.cycle->amplitude * 1e3, a.cycle->period);
    else
      fmt::print(
          "  stick-slip cycle             period {:.5f} s, amplitude {:.3f} mm, sticks of {:.5f} "
          "s, slip arcs of {:.5f} s\n",
          a.cycle->period, a.cycle->amplitude * 1e3, a.cycle->stick_duration,
          a.cycle->slip_duration);
  }
  if (a.linearised)
    fmt::print(
        "  growth rate (linearised)     {:+.5g} /s ({}), period {:.5f} s\n", a.linearised->gamma,
        a.linearised->gamma > 0.0 ? fmt::format("e-folds every {:.4g} s", 1.0 / a.linearised->gamma)
        : a.linearised->gamma < 0.0
            ? fmt::format("decays by e every {:.4g} s", -1.0 / a.linearised->gamma)
            : std::string("steady"),
        a.linearised->period);
  fmt::print("  where the motion goes        {} (from A = {:.0f} mm){}\n",
             regime_name(a.prediction.regime), s.amplitude * 1e3,
             a.prediction.settled_amplitude
                 ? fmt::format(", settling at {:.3f} mm", *a.prediction.settled_amplitude * 1e3)
                 : std::string());
}

void draw_histogram(const AnalyticReport& report, const std::string& png) {
  run_plot_script_on("plot_mc.py", monte_carlo_plot_data(report), png);
}

int run_analytic(const AnalyticOptions& o, const GlobalOptions& global) {
  AnalyticSetUp set_up;
  set_up.spacing = option_quantity(o.spacing, Dimension::kLength, "--spacing");
  set_up.spacing_err = option_quantity(o.spacing_err, Dimension::kLength, "--spacing-err");
  set_up.h_c = option_quantity(o.h_c, Dimension::kLength, "--h-c");
  set_up.h_c_err = option_quantity(o.h_c_err, Dimension::kLength, "--h-c-err");
  if (!(set_up.h_c_err >= 0.0) || !std::isfinite(set_up.h_c_err))
    throw InputError(
        {}, "--h-c-err: expected an uncertainty of 0 or more, found \"" + o.h_c_err + "\"");
  set_up.gravity = option_quantity(o.gravity, Dimension::kAcceleration, "--gravity");
  set_up.roller_radius = option_quantity(o.roller_radius, Dimension::kLength, "--roller-radius");
  set_up.roller_speed = option_quantity(o.roller_speed, Dimension::kAngularSpeed, "--roller-speed");
  set_up.amplitude = option_quantity(o.amplitude, Dimension::kLength, "--amplitude");
  const std::optional<FrictionLawKind> law = friction_law_kind_from_name(o.law);
  if (!law) throw InputError({}, "--law: expected coulomb or stribeck, found \"" + o.law + "\"");
  set_up.law = *law;
  if (!o.mu_s.empty()) set_up.mu_s = option_quantity(o.mu_s, Dimension::kDimensionless, "--mu-s");
  if (!o.v_s.empty()) set_up.v_s = option_quantity(o.v_s, Dimension::kSpeed, "--v-s");
  if (!o.beta.empty()) set_up.beta = option_quantity(o.beta, Dimension::kInverseSpeed, "--beta");
  if (set_up.law == FrictionLawKind::kCoulomb && (set_up.v_s || !o.beta.empty()))
    throw InputError({}, "--v-s and --beta belong to the stribeck law; add --law stribeck");
  const int given =
      (o.mu_k.empty() ? 0 : 1) + (o.period.empty() ? 0 : 1) + (o.material.empty() ? 0 : 1);
  if (given != 1)
    throw InputError({}, "give exactly one of --mu-k, --period or --material (found " +
                             std::to_string(given) + ")");

  const std::optional<MonteCarloRequest> mc = monte_carlo_request(o.monte_carlo);
  if (mc && !o.mu_k.empty())
    throw InputError({},
                     "--mc: carries a measured period's uncertainty into mu_k; a given mu_k "
                     "has none: give --period T --period-err dT (or --material) instead of "
                     "--mu-k");
  if (!o.plot.empty() && !mc)
    throw InputError({},
                     "--plot: draws the Monte Carlo's histogram of mu_k; add --mc N (e.g. "
                     "--mc 100000)");
  // The plot's place is checked before any work; a plot that fails still leaves the results.
  if (!o.plot.empty()) prepare_output_file(o.plot, "plot");

  AnalyticReport report;
  if (!o.mu_k.empty()) {
    report =
        analytic_for_mu_k(set_up, option_quantity(o.mu_k, Dimension::kDimensionless, "--mu-k"));
  } else if (!o.period.empty()) {
    const double period = option_quantity(o.period, Dimension::kTime, "--period");
    const double period_err = option_quantity(o.period_err, Dimension::kTime, "--period-err");
    report = analytic_for_period(set_up, period, period_err);
  } else {
    const PaperTable table = load_paper_table(paper_table_path(asset_dir(global.asset_dir)));
    const auto [material, row] = paper_row(table, o);
    report = analytic_for_material(set_up, *material, *row);
  }
  if (mc) add_monte_carlo(report, *mc);
  std::string plot_failure;
  if (!o.plot.empty()) {
    try {
      draw_histogram(report, o.plot);
    } catch (const std::runtime_error& e) {
      plot_failure = e.what();
    }
  }
  if (o.json) {
    nlohmann::json j = analytic_json(report);
    if (mc)
      j["plot"] = o.plot.empty() || !plot_failure.empty() ? nlohmann::json(nullptr)
                                                          : nlohmann::json(o.plot);
    fmt::print("{}\n", j.dump(2));
  } else {
    print_report(report);
    if (!o.plot.empty() && plot_failure.empty()) fmt::print("  plot: {}\n", o.plot);
  }
  return plot_failure_status(plot_failure);
}

}  // namespace

Command add_analytic_command(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<AnalyticOptions>();
  CLI::App* sub = app.add_subcommand(
      "analytic",
      "Period and mu_k of the analytic model (thin and thick plate), with uncertainties");
  sub->add_option("--spacing", options->spacing, "Roller spacing l")->capture_default_str();
  sub->add_option("--spacing-err", options->spacing_err, "Uncertainty dl of the spacing")
      ->capture_default_str();
  sub->add_option("--mu-k", options->mu_k, "Coefficient of kinetic friction");
  sub->add_option("--period", options->period, "A measured period T, e.g. 0.79s");
  sub->add_option("--period-err", options->period_err, "Uncertainty dT of the period")
      ->capture_default_str();
  sub->add_option("--material", options->material,
                  "One of the paper's materials (its measured T +- dT), e.g. lego");
  sub->add_option("--temperature", options->temperature, "300 K or 77 K, with --material")
      ->capture_default_str();
  sub->add_option("--h-c", options->h_c, "Height of the centre of mass above the contact line")
      ->capture_default_str();
  sub->add_option("--gravity", options->gravity, "Gravity g")->capture_default_str();
  sub->add_option("--roller-radius", options->roller_radius, "Roller radius a")
      ->capture_default_str();
  sub->add_option("--roller-speed", options->roller_speed, "Roller angular speed")
      ->capture_default_str();
  sub->add_option("--amplitude", options->amplitude,
                  "Oscillation amplitude A (for the slip margin)")
      ->capture_default_str();
  sub->add_option("--law", options->law, "Friction law: coulomb or stribeck")
      ->capture_default_str();
  sub->add_option("--mu-s", options->mu_s, "Static limit mu_s (default mu_k)");
  sub->add_option("--v-s", options->v_s, "Stribeck speed v_s, e.g. 1mm/s (stribeck)");
  sub->add_option("--beta", options->beta, "Slope of mu with slip speed, e.g. -0.01s/m (stribeck)");
  sub->add_option("--h-c-err", options->h_c_err,
                  "Uncertainty of h_c, drawn by the Monte Carlo (--mc)")
      ->capture_default_str();
  add_monte_carlo_options(*sub, options->monte_carlo);
  sub->add_option("--plot", options->plot,
                  "With --mc: draw the histogram of mu_k's draws to this PNG");
  sub->add_flag("--json", options->json, "Print one JSON object (SI units) instead of the table");
  return Command{sub, [options, &global, sub] {
                   // Options the report would ignore are refused.
                   if (sub->count("--period-err") > 0 && options->period.empty())
                     throw InputError({},
                                      "--period-err is the uncertainty of --period (with "
                                      "--material the paper's dT is used); give --period, or "
                                      "drop --period-err");
                   if (sub->count("--temperature") > 0 && options->material.empty())
                     throw InputError({},
                                      "--temperature picks the row of --material in the "
                                      "paper's table; give --material, or drop "
                                      "--temperature");
                   return run_analytic(*options, global);
                 }};
}

}  // namespace fl::cli
