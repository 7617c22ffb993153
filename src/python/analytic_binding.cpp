// frictionlab.analytic: the analytic model for one set-up (lab/analytic/analytic_report.hpp), as
// `frictionlab analytic` computes it from a mu_k, a measured period or a material of the paper's
// Table I: the thin and thick periods, mu_k +- d mu_k through both formulas, the tipping
// amplitude, the rollers' slip and a friction law's closed forms.
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "core/paper_table.hpp"
#include "io/input_error.hpp"
#include "io/unknown_material.hpp"
#include "lab/analytic/analytic_report.hpp"
#include "lab/request/analytic_request.hpp"
#include "python/arguments.hpp"
#include "python/bindings.hpp"
#include "python/field_spelling.hpp"
#include "python/json_values.hpp"
#include "python/lab_data.hpp"

namespace fl::python {
namespace {

AnalyticReport analytic(const Quantity& spacing, const Quantity& spacing_err,
                        const std::optional<Quantity>& mu_k, const std::optional<Quantity>& period,
                        const std::optional<Quantity>& period_err,
                        const std::optional<std::string>& material,
                        const std::optional<Quantity>& temperature, const Quantity& h_c,
                        const Quantity& gravity, const Quantity& roller_radius,
                        const Quantity& roller_speed, const Quantity& amplitude,
                        const std::string& law, const std::optional<Quantity>& mu_s,
                        const std::optional<Quantity>& v_s, const std::optional<Quantity>& beta,
                        const std::optional<Path>& assets) {
  AnalyticRequest r;
  r.spacing = spacing;
  r.spacing_err = spacing_err;
  r.mu_k = mu_k;
  r.period = period;
  r.period_err = period_err;
  r.material = material;
  r.temperature = temperature;
  r.h_c = h_c;
  r.gravity = gravity;
  r.roller_radius = roller_radius;
  r.roller_speed = roller_speed;
  r.amplitude = amplitude;
  r.law = law;
  r.mu_s = mu_s;
  r.v_s = v_s;
  r.beta = beta;
  if (assets) r.assets = assets->string();
  AnalyticResult result = analyze(r);
  for (const std::string& warning : result.warnings)
    PyErr_WarnEx(PyExc_UserWarning, spelled(warning).c_str(), 1);
  return std::move(result.report);
}

void bind_law_types(py::module_& m) {
  py::class_<FrictionLaw>(m, "FrictionLaw", "A friction law (core/friction_law.hpp).")
      .def_property_readonly(
          "kind", [](const FrictionLaw& l) { return std::string(friction_law_kind_name(l.kind)); },
          "\"coulomb\" or \"stribeck\"")
      .def_readonly("mu_k", &FrictionLaw::mu_k)
      .def_readonly("mu_s", &FrictionLaw::mu_s)
      .def_readonly("v_s", &FrictionLaw::v_s, "m/s (stribeck)")
      .def_readonly("beta", &FrictionLaw::beta, "s/m (stribeck)");
  py::class_<MuKUncertainty>(m, "MuKUncertainty", "mu_k and how errors in T and l carry into it.")
      .def_readonly("mu_k", &MuKUncertainty::mu_k)
      .def_readonly("worst", &MuKUncertainty::worst, "mu (dl/l kappa_l + dT/T kappa_T)")
      .def_readonly("quadrature", &MuKUncertainty::quadrature,
                    "mu sqrt((kappa_l dl/l)^2 + (kappa_T dT/T)^2)")
      .def_readonly("condition_period", &MuKUncertainty::condition_period, "|d ln mu / d ln T|")
      .def_readonly("condition_spacing", &MuKUncertainty::condition_spacing, "|d ln mu / d ln l|")
      .def_readonly("condition_h_c", &MuKUncertainty::condition_h_c, "|d ln mu / d ln h_c|");
  py::class_<StickSlipCycle>(m, "StickSlipCycle", "The stick-slip (or clipped) cycle (SI).")
      .def_readonly("omega", &StickSlipCycle::omega, "rad/s, of the slip arcs")
      .def_readonly("break_offset", &StickSlipCycle::break_offset, "x_b [m]")
      .def_readonly("amplitude", &StickSlipCycle::amplitude, "m")
      .def_readonly("stick_duration", &StickSlipCycle::stick_duration, "s, one stick")
      .def_readonly("slip_duration", &StickSlipCycle::slip_duration, "s, one slip arc")
      .def_readonly("period", &StickSlipCycle::period, "s")
      .def_readonly("clipped", &StickSlipCycle::clipped, "no stick phase (mu_s == mu_k)");
  py::class_<LinearisedMotion>(m, "LinearisedMotion", "The motion linearised about v_r (SI).")
      .def_readonly("mu", &LinearisedMotion::mu, "mu(v_r)")
      .def_readonly("slope", &LinearisedMotion::slope, "mu'(v_r) [s/m]")
      .def_readonly("omega", &LinearisedMotion::omega, "rad/s")
      .def_readonly("gamma", &LinearisedMotion::gamma, "1/s, the amplitude's e-folding rate")
      .def_readonly("period", &LinearisedMotion::period, "s")
      .def_readonly("period_0", &LinearisedMotion::period_0, "s, 2 pi / Omega");
  py::class_<FrictionRegimePrediction>(m, "FrictionRegimePrediction",
                                       "Where the motion from amplitude A goes (SI).")
      .def_readonly("regime", &FrictionRegimePrediction::regime)
      .def_readonly("motion", &FrictionRegimePrediction::motion)
      .def_readonly("margin", &FrictionRegimePrediction::margin, "v_r / (A Omega)")
      .def_readonly("break_offset", &FrictionRegimePrediction::break_offset, "x_b [m]")
      .def_readonly("tipping_offset", &FrictionRegimePrediction::tipping_offset, "m")
      .def_readonly("growth_rate", &FrictionRegimePrediction::growth_rate, "1/s at A")
      .def_readonly("settled_amplitude", &FrictionRegimePrediction::settled_amplitude, "m")
      .def_readonly("stick_time", &FrictionRegimePrediction::stick_time, "s")
      .def_readonly("tip_time", &FrictionRegimePrediction::tip_time, "s")
      .def_readonly("cycle", &FrictionRegimePrediction::cycle);
  py::class_<AnalyticLaw>(m, "AnalyticLaw", "A friction law's closed forms at the rollers' speed.")
      .def_readonly("law", &AnalyticLaw::law)
      .def_readonly("surface_speed", &AnalyticLaw::surface_speed, "v_r [m/s]")
      .def_readonly("mu_at_surface_speed", &AnalyticLaw::mu_at_surface_speed, "mu(v_r)")
      .def_readonly("full_slip_roller_speed", &AnalyticLaw::full_slip_roller_speed,
                    "rad/s, the slip threshold for A")
      .def_readonly("break_offset", &AnalyticLaw::break_offset, "x_b [m]")
      .def_readonly("cycle", &AnalyticLaw::cycle, "the stick-slip cycle, or None")
      .def_readonly("linearised", &AnalyticLaw::linearised, "growth rate and period, or None")
      .def_readonly("prediction", &AnalyticLaw::prediction);
}

}  // namespace

void bind_analytic(py::module_& m) {
  bind_law_types(m);
  using R = AnalyticReport;
  const auto with_period = [](auto member) {
    return [member](const R& r) {
      return r.period_measured ? std::optional(r.*member) : std::nullopt;
    };
  };
  py::class_<R>(m, "AnalyticReport", R"(The analytic model for one set-up (SI).

json() is the object `frictionlab analytic --json` prints. Values that need a period
(mu_k_thin, mu_k_thick) are None when the report was made from mu_k; those that need a
restoring force (period_thick, tipping_amplitude, ...) are None without one.)")
      .def_property_readonly(
          "spacing", [](const R& r) { return r.set_up.spacing; }, "l [m]")
      .def_property_readonly(
          "spacing_err", [](const R& r) { return r.set_up.spacing_err; }, "dl [m]")
      .def_property_readonly(
          "h_c", [](const R& r) { return r.set_up.h_c; }, "m")
      .def_property_readonly(
          "gravity", [](const R& r) { return r.set_up.gravity; }, "m/s^2")
      .def_property_readonly(
          "roller_speed", [](const R& r) { return r.set_up.roller_speed; }, "rad/s")
      .def_property_readonly(
          "amplitude", [](const R& r) { return r.set_up.amplitude; }, "m")
      .def_readonly("source", &R::source, "\"given mu_k\", \"given period\" or the material")
      .def_readonly("material", &R::material, "the Table I key, or None")
      .def_property_readonly(
          "temperature",
          [](const R& r) { return r.material ? std::optional(r.temperature) : std::nullopt; },
          "K, with a material")
      .def_property_readonly(
          "paper_mu_k",
          [](const R& r) { return r.material ? std::optional(r.paper_mu_k) : std::nullopt; },
          "what the paper printed, with a material")
      .def_readonly("period_measured", &R::period_measured, "T [s], given or the paper's")
      .def_property_readonly("period_measured_err", with_period(&R::period_measured_err), "dT [s]")
      .def_property_readonly("mu_k_thin", with_period(&R::mu_k_thin),
                             "mu_k +- d mu_k from the period, thin formula (the paper's)")
      .def_property_readonly("mu_k_thick", with_period(&R::mu_k_thick),
                             "mu_k +- d mu_k from the period, thick formula for h_c")
      .def_readonly("mu_k", &R::mu_k, "given, or the thick formula's from the period")
      .def_readonly("restoring_force", &R::restoring_force, "l > 2 mu_k h_c")
      .def_readonly("period_thin", &R::period_thin, "s, pi sqrt(2 l / (mu_k g))")
      .def_readonly("period_thick", &R::period_thick, "s")
      .def_readonly("tipping_amplitude", &R::tipping_amplitude, "m")
      .def_readonly("roller_speed_for_full_slip", &R::roller_speed_for_full_slip, "rad/s")
      .def_readonly("slip_margin", &R::slip_margin)
      .def_readonly("friction_law", &R::friction_law, "the law's closed forms, or None")
      .def_readonly("friction_law_refused", &R::friction_law_refused,
                    "why the law has no closed forms here, or None")
      .def(
          "json", [](const R& r) { return python_value(analytic_json(r)); },
          "The object `frictionlab analytic --json` prints.");

  // The defaults are the request's (lab/request/analytic_request.hpp), shown as text.
  const AnalyticRequest d;
  m.def("analytic", &analytic, py::kw_only(), py::arg("spacing") = quantity_input_text(d.spacing),
        py::arg("spacing_err") = quantity_input_text(d.spacing_err), py::arg("mu_k") = py::none(),
        py::arg("period") = py::none(), py::arg("period_err") = py::none(),
        py::arg("material") = py::none(), py::arg("temperature") = py::none(),
        py::arg("h_c") = quantity_input_text(d.h_c),
        py::arg("gravity") = quantity_input_text(d.gravity),
        py::arg("roller_radius") = quantity_input_text(d.roller_radius),
        py::arg("roller_speed") = quantity_input_text(d.roller_speed),
        py::arg("amplitude") = quantity_input_text(d.amplitude), py::arg("law") = d.law,
        py::arg("mu_s") = py::none(), py::arg("v_s") = py::none(), py::arg("beta") = py::none(),
        py::arg("assets") = py::none(),
        R"(The analytic model for a set-up, as `frictionlab analytic`; returns an AnalyticReport.

Give exactly one of mu_k, period (with period_err, default 0 s) or material (a key of the
paper's Table I, with temperature "300K" or "77K", default 300 K); period_err without period
and temperature without material are refused, as the command refuses them. Quantities are text with units ("3.6mm", "200rpm") or SI
numbers; the defaults are the command's. law: "coulomb" (with mu_s) or "stribeck" (mu_s,
v_s, beta). Raises InputError for bad input.)");
}

}  // namespace fl::python
