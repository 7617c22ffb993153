#include "lab/analytic/analytic_report.hpp"

#include <fmt/format.h>

#include "core/friction_oscillator.hpp"
#include "core/stick_slip_cycle.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "io/json_value.hpp"

namespace fl {
namespace {

// Everything that follows from mu_k.
void complete(AnalyticReport& r) {
  const AnalyticSetUp& s = r.set_up;
  // A static coefficient below the kinetic one is no friction law: refused at the field.
  if (s.mu_s && !(*s.mu_s >= r.mu_k))
    throw InputError(SourceLocation::of_field("mu_s", fmt::format("{:g}", *s.mu_s)),
                     fmt::format("expected mu_s >= mu_k = {:.4g} (a plate at rest holds at least "
                                 "the friction it slides with), found {:g}; raise it, or drop it "
                                 "for mu_s = mu_k",
                                 r.mu_k, *s.mu_s));
  r.restoring_force = has_restoring_force(s.spacing, r.mu_k, s.h_c);
  r.period_thin = period_thin(s.spacing, r.mu_k, s.gravity);
  if (!r.restoring_force) return;
  r.period_thick = period_thick(s.spacing, r.mu_k, s.h_c, s.gravity);
  r.tipping_amplitude = tipping_amplitude(s.spacing, r.mu_k, s.h_c);
  r.roller_speed_for_full_slip = fl::roller_speed_for_full_slip(
      s.amplitude, s.roller_radius, s.spacing, r.mu_k, s.h_c, s.gravity);
  r.slip_margin = fl::slip_margin(s.roller_speed, s.roller_radius, s.amplitude, s.spacing, r.mu_k,
                                  s.h_c, s.gravity);
  // The law's closed forms; a law they refuse here is said, not guessed.
  AnalyticLaw a;
  a.law.kind = s.law;
  a.law.mu_k = r.mu_k;
  a.law.mu_s = s.mu_s.value_or(r.mu_k);
  a.law.v_s = s.v_s.value_or(0.0);
  a.law.beta = s.beta;
  a.surface_speed = s.roller_speed * s.roller_radius;
  const PlateOnRollers plate{s.spacing, s.h_c, s.gravity};
  try {
    a.mu_at_surface_speed = effective_mu(a.law, a.surface_speed);
    a.full_slip_roller_speed =
        fl::full_slip_roller_speed(a.law, plate, s.amplitude, s.roller_radius);
    a.break_offset = stick_break_offset(a.law, plate, a.surface_speed);
    if (a.law.depends_on_slip())
      a.linearised = linearised_motion(a.law, plate, a.surface_speed);
    else if (a.surface_speed <
             s.amplitude * sliding_angular_frequency(a.law, plate, a.surface_speed))
      a.cycle = stick_slip_cycle(a.law, plate, a.surface_speed);
    a.prediction = predict_friction_regime(a.law, plate, a.surface_speed, s.amplitude);
    r.friction_law = a;
  } catch (const DomainError& e) {
    r.friction_law_refused = e.what();
  }
}

// mu_k from a measured period, through both formulas; the thick one's is the report's.
void from_period(AnalyticReport& r, double period, double period_err) {
  const AnalyticSetUp& s = r.set_up;
  r.period_measured = period;
  r.period_measured_err = period_err;
  r.mu_k_thin = mu_k_with_uncertainty(period, period_err, s.spacing, s.spacing_err, 0.0, s.gravity);
  r.mu_k_thick =
      mu_k_with_uncertainty(period, period_err, s.spacing, s.spacing_err, s.h_c, s.gravity);
  r.mu_k = r.mu_k_thick.mu_k;
  complete(r);
}

}  // namespace

AnalyticReport analytic_for_mu_k(const AnalyticSetUp& set_up, double mu_k) {
  AnalyticReport r;
  r.set_up = set_up;
  r.source = "given mu_k";
  r.mu_k = mu_k;
  complete(r);
  return r;
}

AnalyticReport analytic_for_period(const AnalyticSetUp& set_up, double period, double period_err) {
  AnalyticReport r;
  r.set_up = set_up;
  r.source = "given period";
  from_period(r, period, period_err);
  return r;
}

AnalyticReport analytic_for_material(const AnalyticSetUp& set_up, const PaperMaterial& material,
                                     const PaperMeasurement& row) {
  AnalyticReport r;
  r.set_up = set_up;
  r.source = fmt::format("the paper's {} at {:.0f} K", material.name, row.temperature);
  r.material = material.key;
  r.temperature = row.temperature;
  r.paper_mu_k = row.mu_k;
  from_period(r, row.period.value, row.period.uncertainty);
  return r;
}

void add_monte_carlo(AnalyticReport& r, const MonteCarloRequest& request) {
  if (!r.period_measured)
    throw DomainError("a Monte Carlo of mu_k needs a measured period (" + field_ref("period") +
                      " or " + field_ref("material") + ")");
  const AnalyticSetUp& s = r.set_up;
  r.monte_carlo = mu_k_monte_carlo(MuKMeasurement{.period = *r.period_measured,
                                                  .period_err = r.period_measured_err,
                                                  .spacing = s.spacing,
                                                  .spacing_err = s.spacing_err,
                                                  .h_c = s.h_c,
                                                  .h_c_err = s.h_c_err,
                                                  .gravity = s.gravity},
                                   request);
}

nlohmann::json monte_carlo_json(const MuKMonteCarlo& mc) {
  const std::optional<SampleSummary>& m = mc.mu_k;
  return {{"draws", mc.draws},
          {"seed", mc.seed},
          {"accepted", mc.accepted},
          {"skipped", mc.skipped},
          {"mu_k_mean", m ? nlohmann::json(m->mean) : nlohmann::json(nullptr)},
          {"mu_k_sd", m ? json_or_null(m->sd) : nlohmann::json(nullptr)},
          {"mu_k_quantile_025", m ? nlohmann::json(m->quantile_025) : nlohmann::json(nullptr)},
          {"mu_k_quantile_975", m ? nlohmann::json(m->quantile_975) : nlohmann::json(nullptr)}};
}

nlohmann::json monte_carlo_plot_data(const AnalyticReport& r) {
  nlohmann::json out = r.monte_carlo ? monte_carlo_json(*r.monte_carlo) : nlohmann::json::object();
  out["samples"] = r.monte_carlo ? r.monte_carlo->samples : std::vector<double>{};
  out["mu_k_thick"] = r.mu_k_thick.mu_k;
  out["mu_k_err_worst"] = r.mu_k_thick.worst;
  out["mu_k_err_quadrature"] = r.mu_k_thick.quadrature;
  out["period_s"] = json_or_null(r.period_measured);
  out["period_err_s"] = r.period_measured_err;
  out["spacing_m"] = r.set_up.spacing;
  out["spacing_err_m"] = r.set_up.spacing_err;
  out["h_c_m"] = r.set_up.h_c;
  out["h_c_err_m"] = r.set_up.h_c_err;
  return out;
}

nlohmann::json analytic_json(const AnalyticReport& r) {
  const AnalyticSetUp& s = r.set_up;
  nlohmann::json out;
  out["spacing_m"] = s.spacing;
  out["spacing_err_m"] = s.spacing_err;
  out["h_c_m"] = s.h_c;
  out["h_c_err_m"] = s.h_c_err;
  out["gravity_m_s2"] = s.gravity;
  out["source"] = r.source;
  if (r.material) {
    out["material"] = *r.material;
    out["temperature_k"] = r.temperature;
    out["mu_k_paper"] = r.paper_mu_k.value;
    out["mu_k_paper_err"] = r.paper_mu_k.uncertainty;
  }
  if (r.period_measured) {
    out["period_measured_s"] = *r.period_measured;
    out["period_measured_err_s"] = r.period_measured_err;
    out["mu_k_thin"] = r.mu_k_thin.mu_k;
    out["mu_k_thin_err_worst"] = r.mu_k_thin.worst;
    out["mu_k_thin_err_quadrature"] = r.mu_k_thin.quadrature;
    out["mu_k_thick"] = r.mu_k_thick.mu_k;
    out["mu_k_thick_err_worst"] = r.mu_k_thick.worst;
    out["mu_k_thick_err_quadrature"] = r.mu_k_thick.quadrature;
    out["condition_period"] = r.mu_k_thick.condition_period;
    out["condition_spacing"] = r.mu_k_thick.condition_spacing;
  }
  out["mu_k"] = r.mu_k;
  out["restoring_force"] = r.restoring_force;
  out["period_thin_s"] = json_or_null(r.period_thin);
  out["period_thick_s"] = json_or_null(r.period_thick);
  out["tipping_amplitude_m"] = json_or_null(r.tipping_amplitude);
  out["amplitude_m"] = s.amplitude;
  out["roller_radius_m"] = s.roller_radius;
  out["roller_speed_rad_s"] = s.roller_speed;
  out["roller_speed_for_full_slip_rad_s"] = json_or_null(r.roller_speed_for_full_slip);
  out["slip_margin"] = json_or_null(r.slip_margin);
  if (r.friction_law) {
    const AnalyticLaw& a = *r.friction_law;
    nlohmann::json law{
        {"law", friction_law_kind_name(a.law.kind)},
        {"mu_k", a.law.mu_k},
        {"mu_s", a.law.mu_s},
        {"v_s_m_s", a.law.kind == FrictionLawKind::kStribeck && a.law.mu_s != a.law.mu_k
                        ? nlohmann::json(a.law.v_s)
                        : nlohmann::json(nullptr)},
        {"beta_s_m", a.law.beta},
        {"surface_speed_m_s", a.surface_speed},
        {"mu_at_surface_speed", a.mu_at_surface_speed},
        {"full_slip_roller_speed_rad_s", a.full_slip_roller_speed},
        {"stick_break_offset_m", a.break_offset},
        {"regime", regime_name(a.prediction.regime)},
        {"stick_time_s", json_or_null(a.prediction.stick_time)},
        {"tip_time_s", json_or_null(a.prediction.tip_time)},
        {"settled_amplitude_m", json_or_null(a.prediction.settled_amplitude)}};
    law["stick_slip_cycle"] = a.cycle
                                  ? nlohmann::json{{"clipped", a.cycle->clipped},
                                                   {"period_s", a.cycle->period},
                                                   {"amplitude_m", a.cycle->amplitude},
                                                   {"stick_duration_s", a.cycle->stick_duration},
                                                   {"slip_duration_s", a.cycle->slip_duration}}
                                  : nlohmann::json(nullptr);
    law["growth_rate_per_s"] =
        a.linearised ? nlohmann::json(a.linearised->gamma) : nlohmann::json(nullptr);
    law["linearised_period_s"] =
        a.linearised ? nlohmann::json(a.linearised->period) : nlohmann::json(nullptr);
    out["friction_law"] = law;
  } else {
    out["friction_law"] = nullptr;
  }
  out["friction_law_refused"] = json_or_null(r.friction_law_refused);
  out["monte_carlo"] = r.monte_carlo ? monte_carlo_json(*r.monte_carlo) : nlohmann::json(nullptr);
  return out;
}

}  // namespace fl
