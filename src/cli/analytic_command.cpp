// frictionlab analytic: the analytic model for a set-up given by l, mu_k or T, and h_c.
#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/option_quantity.hpp"
#include "core/analytic_model.hpp"
#include "core/paper_table.hpp"
#include "io/input_error.hpp"
#include "io/paper_table_yaml.hpp"

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
  std::string gravity = "9.81 m/s^2";
  std::string roller_radius = "10 mm";
  std::string roller_speed = "1600 rpm";
  std::string amplitude = "20 mm";
  bool json = false;
};

nlohmann::json optional_number(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

int run_analytic(const AnalyticOptions& o, const GlobalOptions& global) {
  const double spacing = option_quantity(o.spacing, Dimension::kLength, "--spacing");
  const double spacing_err = option_quantity(o.spacing_err, Dimension::kLength, "--spacing-err");
  const double h_c = option_quantity(o.h_c, Dimension::kLength, "--h-c");
  const double gravity = option_quantity(o.gravity, Dimension::kAcceleration, "--gravity");
  const double radius = option_quantity(o.roller_radius, Dimension::kLength, "--roller-radius");
  const double roller_speed =
      option_quantity(o.roller_speed, Dimension::kAngularSpeed, "--roller-speed");
  const double amplitude = option_quantity(o.amplitude, Dimension::kLength, "--amplitude");
  const int given =
      (o.mu_k.empty() ? 0 : 1) + (o.period.empty() ? 0 : 1) + (o.material.empty() ? 0 : 1);
  if (given != 1)
    throw InputError({}, "give exactly one of --mu-k, --period or --material (found " +
                             std::to_string(given) + ")");

  nlohmann::json out;
  out["spacing_m"] = spacing;
  out["spacing_err_m"] = spacing_err;
  out["h_c_m"] = h_c;
  out["gravity_m_s2"] = gravity;

  std::optional<double> mu_k;
  std::string source;
  std::optional<double> period;
  double period_err = 0.0;
  if (!o.mu_k.empty()) {
    mu_k = option_quantity(o.mu_k, Dimension::kDimensionless, "--mu-k");
    source = "given mu_k";
  } else if (!o.period.empty()) {
    period = option_quantity(o.period, Dimension::kTime, "--period");
    period_err = option_quantity(o.period_err, Dimension::kTime, "--period-err");
    source = "given period";
  } else {
    const PaperTable table =
        load_paper_table(paper_table_path(resolve_asset_dir(global.asset_dir)));
    const PaperMaterial* material = table.find(o.material);
    if (material == nullptr) {
      std::string known;
      for (const PaperMaterial& m : table.materials) known += " " + m.key;
      throw InputError({}, "--material: unknown material \"" + o.material +
                               "\"; the paper's materials are:" + known);
    }
    const double temperature =
        option_quantity(o.temperature, Dimension::kTemperature, "--temperature");
    const PaperMeasurement* row = PaperTable::at(*material, temperature);
    if (row == nullptr)
      throw InputError({}, fmt::format("--temperature: the paper measured {} at 300 K{} only",
                                       material->name, material->cold ? " and 77 K" : ""));
    period = row->period.value;
    period_err = row->period.uncertainty;
    source = fmt::format("the paper's {} at {:.0f} K", material->name, row->temperature);
    out["material"] = material->key;
    out["temperature_k"] = row->temperature;
    out["mu_k_paper"] = row->mu_k.value;
    out["mu_k_paper_err"] = row->mu_k.uncertainty;
  }
  out["source"] = source;

  if (period) {
    const MuKUncertainty thin =
        mu_k_with_uncertainty(*period, period_err, spacing, spacing_err, 0.0, gravity);
    const MuKUncertainty thick =
        mu_k_with_uncertainty(*period, period_err, spacing, spacing_err, h_c, gravity);
    out["period_measured_s"] = *period;
    out["period_measured_err_s"] = period_err;
    out["mu_k_thin"] = thin.mu_k;
    out["mu_k_thin_err_worst"] = thin.worst;
    out["mu_k_thin_err_quadrature"] = thin.quadrature;
    out["mu_k_thick"] = thick.mu_k;
    out["mu_k_thick_err_worst"] = thick.worst;
    out["mu_k_thick_err_quadrature"] = thick.quadrature;
    out["condition_period"] = thick.condition_period;
    out["condition_spacing"] = thick.condition_spacing;
    mu_k = thick.mu_k;
  }
  out["mu_k"] = *mu_k;
  const bool restoring = has_restoring_force(spacing, *mu_k, h_c);
  out["restoring_force"] = restoring;
  std::optional<double> t_thin, t_thick, tipping, full_slip, margin;
  t_thin = period_thin(spacing, *mu_k, gravity);
  if (restoring) {
    t_thick = period_thick(spacing, *mu_k, h_c, gravity);
    tipping = tipping_amplitude(spacing, *mu_k, h_c);
    full_slip = roller_speed_for_full_slip(amplitude, radius, spacing, *mu_k, h_c, gravity);
    margin = slip_margin(roller_speed, radius, amplitude, spacing, *mu_k, h_c, gravity);
  }
  out["period_thin_s"] = optional_number(t_thin);
  out["period_thick_s"] = optional_number(t_thick);
  out["tipping_amplitude_m"] = optional_number(tipping);
  out["amplitude_m"] = amplitude;
  out["roller_radius_m"] = radius;
  out["roller_speed_rad_s"] = roller_speed;
  out["roller_speed_for_full_slip_rad_s"] = optional_number(full_slip);
  out["slip_margin"] = optional_number(margin);

  if (o.json) {
    fmt::print("{}\n", out.dump(2));
    return 0;
  }
  constexpr double kRpm = 60.0 / (2.0 * 3.14159265358979323846);
  fmt::print("frictionlab analytic: the friction oscillator for {}\n", source);
  fmt::print("  roller spacing l             {:.1f} +- {:.1f} mm\n", spacing * 1e3,
             spacing_err * 1e3);
  fmt::print("  centre-of-mass height h_c    {:.2f} mm\n", h_c * 1e3);
  if (period) {
    fmt::print("  measured period T            {:.4g} +- {:.2g} s\n", *period, period_err);
    if (out.contains("mu_k_paper"))
      fmt::print("  paper's mu_k                 {} +- {}\n", out["mu_k_paper"].get<double>(),
                 out["mu_k_paper_err"].get<double>());
    fmt::print(
        "  mu_k, thin formula           {:.4f} +- {:.4f} (worst case) +- {:.4f} (quadrature)\n",
        out["mu_k_thin"].get<double>(), out["mu_k_thin_err_worst"].get<double>(),
        out["mu_k_thin_err_quadrature"].get<double>());
    fmt::print(
        "  mu_k, thick formula          {:.4f} +- {:.4f} (worst case) +- {:.4f} (quadrature)\n",
        out["mu_k_thick"].get<double>(), out["mu_k_thick_err_worst"].get<double>(),
        out["mu_k_thick_err_quadrature"].get<double>());
    fmt::print(
        "  condition numbers            d ln mu / d ln T = {:.3f}, d ln mu / d ln l = {:.0f}\n",
        out["condition_period"].get<double>(), out["condition_spacing"].get<double>());
  } else {
    fmt::print("  mu_k                         {:.4g}\n", *mu_k);
  }
  fmt::print("  period, thin formula         {:.5f} s\n", *t_thin);
  if (!restoring) {
    fmt::print(
        "  no restoring force: l = {:.1f} mm <= 2 mu_k h_c = {:.1f} mm; the plate drifts off\n",
        spacing * 1e3, 2.0 * *mu_k * h_c * 1e3);
    return 0;
  }
  fmt::print("  period, thick formula        {:.5f} s ({:+.2f} % against thin)\n", *t_thick,
             100.0 * (*t_thick / *t_thin - 1.0));
  fmt::print("  tipping amplitude            {:.1f} mm (a normal force reaches zero)\n",
             *tipping * 1e3);
  fmt::print(
      "  full slip at amplitude {:.0f} mm needs the rollers above {:.0f} rpm; at {:.0f} rpm the "
      "slip margin is {:.2f}{}\n",
      amplitude * 1e3, *full_slip * kRpm, roller_speed * kRpm, *margin,
      *margin > 1.0 ? "" : " (< 1: the plate sticks to a roller for part of each cycle)");
  return 0;
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
  sub->add_flag("--json", options->json, "Print one JSON object (SI units) instead of the table");
  return Command{sub, [options, &global] { return run_analytic(*options, global); }};
}

}  // namespace fl::cli
