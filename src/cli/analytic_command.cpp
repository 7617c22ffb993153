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
#include "cli/field_spelling.hpp"
#include "cli/monte_carlo_options.hpp"
#include "cli/monte_carlo_report.hpp"
#include "cli/option_quantity.hpp"
#include "cli/plot_failure.hpp"
#include "core/paper_table.hpp"
#include "core/units.hpp"
#include "io/input_error.hpp"
#include "io/paper_table_yaml.hpp"
#include "io/unknown_material.hpp"
#include "lab/analytic/analytic_report.hpp"
#include "lab/request/analytic_request.hpp"
#include "lab/request/lab_data.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/plot_script.hpp"

namespace fl::cli {
namespace {

// The options' texts; the defaults shown in --help are the request's.
struct AnalyticOptions {
  AnalyticRequest request;
  std::string spacing = quantity_input_text(request.spacing);
  std::string spacing_err = quantity_input_text(request.spacing_err);
  std::string mu_k;
  std::string period;
  std::string period_err = "0 s";
  std::string material;
  std::string temperature = "300 K";
  std::string h_c = quantity_input_text(request.h_c);
  std::string h_c_err = quantity_input_text(request.h_c_err);
  std::string gravity = quantity_input_text(request.gravity);
  std::string roller_radius = quantity_input_text(request.roller_radius);
  std::string roller_speed = quantity_input_text(request.roller_speed);
  std::string amplitude = quantity_input_text(request.amplitude);
  std::string law = request.law;
  std::string mu_s;
  std::string v_s;
  std::string beta;
  bool json = false;
  MonteCarloOptions monte_carlo;
  std::string plot;
};

void print_report(const AnalyticReport& r) {
  const AnalyticSetUp& s = r.set_up;
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
      s.amplitude * 1e3, *r.roller_speed_for_full_slip * kRpmPerRadPerSecond,
      s.roller_speed * kRpmPerRadPerSecond, *r.slip_margin,
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
             a.full_slip_roller_speed * kRpmPerRadPerSecond, s.amplitude * 1e3);
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

// The options as the request's fields: the optional ones only when given.
AnalyticRequest request_of(const AnalyticOptions& o, const CLI::App& sub,
                           const GlobalOptions& global) {
  AnalyticRequest r;
  r.spacing = o.spacing;
  r.spacing_err = o.spacing_err;
  if (!o.mu_k.empty()) r.mu_k = o.mu_k;
  if (!o.period.empty()) r.period = o.period;
  if (!o.material.empty()) r.material = o.material;
  if (sub.count("--period-err") > 0) r.period_err = o.period_err;
  if (sub.count("--temperature") > 0) r.temperature = o.temperature;
  r.h_c = o.h_c;
  r.h_c_err = o.h_c_err;
  r.gravity = o.gravity;
  r.roller_radius = o.roller_radius;
  r.roller_speed = o.roller_speed;
  r.amplitude = o.amplitude;
  r.law = o.law;
  if (!o.mu_s.empty()) r.mu_s = o.mu_s;
  if (!o.v_s.empty()) r.v_s = o.v_s;
  if (!o.beta.empty()) r.beta = o.beta;
  if (const std::optional<MonteCarloRequest> mc = monte_carlo_request(o.monte_carlo)) {
    r.mc = mc->draws;
    r.seed = mc->seed;
  }
  r.plot = o.plot;
  r.assets = global.asset_dir;
  return r;
}

int run_analytic(const AnalyticOptions& o, const CLI::App& sub, const GlobalOptions& global) {
  const AnalyticResult result = analyze(request_of(o, sub, global));
  for (const std::string& w : result.warnings) fmt::print(stderr, "warning: {}\n", spelled(w));
  if (o.json) {
    fmt::print("{}\n", result.json().dump(2));
  } else {
    print_report(result.report);
    if (!result.plot.empty()) fmt::print("  plot: {}\n", result.plot);
  }
  return plot_failure_status(result.plot_failure);
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
  return Command{sub, [options, &global, sub] { return run_analytic(*options, *sub, global); }};
}

}  // namespace fl::cli
