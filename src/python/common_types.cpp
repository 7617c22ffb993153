// Types that scenes, runs, the analytic model and the paper's table share: the regimes
// (core/regime.hpp), where a run's mu_k comes from, and a measured value with its uncertainty.
#include <string>

#include "core/regime.hpp"
#include "core/units.hpp"
#include "lab/run/run_summary.hpp"
#include "python/bindings.hpp"

namespace fl::python {

void bind_common_types(py::module_& m) {
  py::enum_<Regime>(m, "Regime",
                    "The physical regime of the friction oscillator, as theory expects it and as a "
                    "run's trajectory shows it\n(core/regime.hpp). `label` is the name the "
                    "command and the JSON outputs use (\"stick-slip\").")
      .value("OSCILLATES", Regime::kOscillates,
             "harmonic oscillation at a steady amplitude: both rollers slip throughout")
      .value("CLIPPED", Regime::kClipped,
             "one stick clipped the amplitude to v_r / Omega; then a harmonic cycle")
      .value("STICK_SLIP", Regime::kStickSlip,
             "a periodic cycle whose stick phases (moving with a roller) last")
      .value("GROWS", Regime::kGrows, "both rollers slip; the amplitude grows exponentially")
      .value("DECAYS", Regime::kDecays, "both rollers slip; the amplitude decays exponentially")
      .value("STICKS", Regime::kSticks, "the plate stays stuck to a roller for good")
      .value("TIPS", Regime::kTips, "tipping or lift-off: a normal force reached zero")
      .value("NO_RESTORING_FORCE", Regime::kNoRestoringForce,
             "the plate drifts off (l <= 2 mu_k h_c, or rollers turning outward)")
      .value("LOST", Regime::kLost, "the plate fell off or left the rig's bounds")
      .value("NUMERICALLY_FAILED", Regime::kNumericallyFailed,
             "NaN, infinity, energy blow-up or penetration beyond a bound")
      .def_property_readonly(
          "label", [](Regime r) { return std::string(regime_name(r)); },
          "The regime's name in the command's output and the JSON files, e.g. \"stick-slip\".")
      .def_property_readonly("harmonic", &regime_is_harmonic,
                             "An oscillation whose period the paper's formula reads (oscillates, "
                             "clipped, grows, decays).")
      .def_static(
          "from_label",
          [](const std::string& label) {
            const std::optional<Regime> r = regime_from_name(label);
            if (!r) throw py::value_error("no regime is called \"" + label + "\"");
            return *r;
          },
          py::arg("label"), "The regime whose label is `label` (\"no restoring force\").");

  py::enum_<PeriodSource>(m, "PeriodSource", "Where a run's mu_k comes from.")
      .value("HALL_ESTIMATOR", PeriodSource::kHallEstimator,
             "the rig's estimator on the simulated Hall signal")
      .value("TRAJECTORY", PeriodSource::kTrajectory,
             "the trajectory's own period (a scene without a sensor, or no accepted period)");

  py::class_<Measured>(m, "Measured", "A measured value and its uncertainty, as printed (SI).")
      .def_readonly("value", &Measured::value, "The value (SI).")
      .def_readonly("uncertainty", &Measured::uncertainty, "Its uncertainty (SI, >= 0).")
      .def("__repr__", [](const Measured& v) {
        return "Measured(" + py::repr(py::float_(v.value)).cast<std::string>() + " +- " +
               py::repr(py::float_(v.uncertainty)).cast<std::string>() + ")";
      });
}

}  // namespace fl::python
