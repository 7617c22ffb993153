#include "lab/request/analytic_request.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/analytic_model.hpp"
#include "core/paper_table.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "io/unknown_material.hpp"
#include "lab/request/lab_data.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/plot_script.hpp"

namespace fl {
namespace {

// The set-up's fields, each problem by field.
AnalyticSetUp set_up_of(const AnalyticRequest& r, FieldChecks& checks) {
  AnalyticSetUp s;
  s.spacing = checks.quantity(r.spacing, Dimension::kLength, "spacing");
  s.spacing_err = checks.quantity(r.spacing_err, Dimension::kLength, "spacing_err");
  s.h_c = checks.quantity(r.h_c, Dimension::kLength, "h_c");
  s.h_c_err = checks.not_negative(r.h_c_err, Dimension::kLength, "h_c_err", "an uncertainty");
  s.gravity = checks.quantity(r.gravity, Dimension::kAcceleration, "gravity");
  s.roller_radius = checks.quantity(r.roller_radius, Dimension::kLength, "roller_radius");
  s.roller_speed = checks.quantity(r.roller_speed, Dimension::kAngularSpeed, "roller_speed");
  s.amplitude = checks.quantity(r.amplitude, Dimension::kLength, "amplitude");
  checks.plausible(s.spacing, kSpacingRange, "spacing", r.spacing);
  checks.plausible(s.h_c, kHcRange, "h_c", r.h_c);
  checks.plausible(s.gravity, kGravityRange, "gravity", r.gravity);
  checks.plausible(s.roller_radius, kRollerRadiusRange, "roller_radius", r.roller_radius);
  checks.plausible(s.roller_speed, kRollerSpeedRange, "roller_speed", r.roller_speed);
  checks.plausible(s.amplitude, kAmplitudeRange, "amplitude", r.amplitude);
  if (!checks.has("amplitude") && !(std::isfinite(s.amplitude) && s.amplitude >= 0.0))
    checks.problem("amplitude", quantity_input_text(r.amplitude),
                   "expected the plate's amplitude as a length of 0 or more, found " +
                       quantity_input_text(r.amplitude));
  if (const std::optional<FrictionLawKind> law = friction_law_kind_from_name(r.law))
    s.law = *law;
  else
    checks.problem("law", r.law, "expected coulomb or stribeck, found \"" + r.law + "\"");
  s.mu_s = checks.quantity(r.mu_s, Dimension::kDimensionless, "mu_s");
  s.v_s = checks.quantity(r.v_s, Dimension::kSpeed, "v_s");
  if (r.beta) s.beta = checks.quantity(*r.beta, Dimension::kInverseSpeed, "beta");
  if (s.law == FrictionLawKind::kCoulomb && (r.v_s || r.beta))
    checks.problem(r.v_s ? "v_s" : "beta", field_ref("v_s") + " and " + field_ref("beta") +
                                               " belong to the stribeck law; add " +
                                               field_ref("law", "stribeck"));
  return s;
}

}  // namespace

nlohmann::json AnalyticResult::json() const {
  nlohmann::json j = analytic_json(report);
  if (report.monte_carlo) j["plot"] = plot.empty() ? nlohmann::json(nullptr) : nlohmann::json(plot);
  return j;
}

Outcome AnalyticResult::outcome() const {
  return plot_failure.empty() ? Outcome::kDone : Outcome::kIncomplete;
}

AnalyticResult analyze(const AnalyticRequest& r) {
  FieldChecks checks;
  const AnalyticSetUp set_up = set_up_of(r, checks);
  const int given = (r.mu_k ? 1 : 0) + (r.period ? 1 : 0) + (r.material ? 1 : 0);
  if (given != 1)
    checks.problem(r.mu_k     ? "mu_k"
                   : r.period ? "period"
                              : "material",
                   "give exactly one of " + field_ref("mu_k") + ", " + field_ref("period") +
                       " or " + field_ref("material") + " (found " + std::to_string(given) + ")");
  // What the report would ignore is refused.
  if (r.period_err && !r.period)
    checks.problem("period_err", field_ref("period_err") + " is the uncertainty of " +
                                     field_ref("period") + " (with " + field_ref("material") +
                                     " the paper's dT is used); give " + field_ref("period") +
                                     ", or drop " + field_ref("period_err"));
  if (r.temperature && !r.material)
    checks.problem("temperature", field_ref("temperature") + " picks the row of " +
                                      field_ref("material") + " in the paper's table; give " +
                                      field_ref("material") + ", or drop " +
                                      field_ref("temperature"));
  if (r.mc && (*r.mc < 1 || *r.mc > kMaxMonteCarloDraws))
    checks.problem("monte_carlo.draws", std::to_string(*r.mc),
                   fmt::format("expected the number of draws, a whole number from 1 to {}, found "
                               "{}",
                               kMaxMonteCarloDraws, *r.mc));
  if (r.mc && r.mu_k)
    checks.problem("monte_carlo.draws",
                   "carries a measured period's uncertainty into mu_k; a given mu_k has none: "
                   "give " +
                       field_ref("period") + " and " + field_ref("period_err") + " (or " +
                       field_ref("material") + ") instead of " + field_ref("mu_k"));
  if (!r.plot.empty() && !r.mc)
    checks.problem("plot", "draws the Monte Carlo's histogram of mu_k; add " +
                               field_ref("monte_carlo.draws", "100000"));
  const std::optional<double> mu_k = checks.quantity(r.mu_k, Dimension::kDimensionless, "mu_k");
  const std::optional<double> period = checks.quantity(r.period, Dimension::kTime, "period");
  checks.plausible(mu_k, kMuKRange, "mu_k", r.mu_k);
  checks.plausible(period, kPeriodRange, "period", r.period);
  // mu_k from the period, at the request's l, h_c and g: within a rig's too (a period of a rig
  // at another spacing or g is none at these).
  if (period && !checks.has("period") && !checks.has("spacing") && !checks.has("gravity") &&
      !checks.has("h_c") && *period > 0.0) {
    const double thin = mu_k_from_period_thin(*period, set_up.spacing, set_up.gravity);
    const double thick =
        mu_k_from_period_thick(*period, set_up.spacing, set_up.h_c, set_up.gravity);
    for (const double derived : {thin, thick}) {
      const std::optional<std::string> why = implausible(derived, kMuKRange);
      if (!why) continue;
      checks.problem(
          "period", quantity_input_text(*r.period),
          fmt::format("T = {:g} s at l = {:g} mm, h_c = {:g} mm and g = {:g} m/s^2 "
                      "gives a mu_k no rig has, so it is no rig's period at this "
                      "spacing: {}; check the period and its unit, and the spacing",
                      *period, set_up.spacing * 1e3, set_up.h_c * 1e3, set_up.gravity, *why));
      break;
    }
  }
  const double period_err =
      checks.quantity(r.period_err.value_or(std::string("0 s")), Dimension::kTime, "period_err");
  const double temperature = checks.quantity(r.temperature.value_or(std::string("300 K")),
                                             Dimension::kTemperature, "temperature");
  checks.throw_if_any();
  // The plot's place is checked before any work; a plot that fails still leaves the results.
  if (!r.plot.empty()) prepare_output_file(r.plot, "plot");

  AnalyticResult result;
  result.warnings = checks.warnings();
  if (mu_k) {
    result.report = analytic_for_mu_k(set_up, *mu_k);
  } else if (period) {
    result.report = analytic_for_period(set_up, *period, period_err);
  } else {
    const PaperTable& table = paper_table_in(asset_dir(r.assets));
    const PaperMaterial* material = table.find(*r.material);
    if (material == nullptr)
      throw InputError(SourceLocation::of_field("material", *r.material),
                       unknown_material_message(table, *r.material));
    const PaperMeasurement* row = PaperTable::at(*material, temperature);
    if (row == nullptr)
      throw InputError(SourceLocation::of_field("temperature"),
                       fmt::format("the paper measured {} at 300 K{} only", material->name,
                                   material->cold ? " and 77 K" : ""));
    result.report = analytic_for_material(set_up, *material, *row);
  }
  if (r.mc)
    add_monte_carlo(
        result.report,
        MonteCarloRequest{.draws = static_cast<int>(*r.mc), .seed = r.seed, .keep_samples = true});
  if (!r.plot.empty()) {
    try {
      run_plot_script_on("plot_mc.py", monte_carlo_plot_data(result.report), r.plot);
      result.plot = r.plot;
    } catch (const std::runtime_error& e) {
      result.plot_failure = e.what();
    }
  }
  return result;
}

}  // namespace fl
