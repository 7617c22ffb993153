// frictionlab estimate LOG: T +- dT and mu_k +- d mu_k from a log of the real rig's Hall sensor,
// by the very estimator the rig's Arduino runs (src/estimator/period_estimator.h). The estimate
// itself is lab/log_estimate; this command reads the options and prints.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/option_quantity.hpp"
#include "cli/plot_script.hpp"
#include "io/hall_log.hpp"
#include "io/input_error.hpp"
#include "io/json_value.hpp"
#include "lab/log_estimate.hpp"

namespace fl::cli {
namespace {

struct EstimateOptions {
  std::string log;
  std::string spacing = "89 mm";
  std::string spacing_err = "2 mm";
  std::string gravity = "9.81 m/s^2";
  std::string geometry = "auto";
  std::string plot;
  bool json = false;
};

fl_estimator::Geometry parse_geometry(const std::string& text) {
  if (text == "auto") return fl_estimator::kAutoGeometry;
  if (text == "one") return fl_estimator::kOnePulse;
  if (text == "pair") return fl_estimator::kPulsePair;
  throw InputError({}, "--geometry: expected auto, one or pair, found \"" + text + "\"");
}

// The plot's data as JSON in a temporary file, then the script.
void draw_plot(const HallLog& log, const LogEstimate& est, const std::string& png) {
  const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
  const std::filesystem::path json_path =
      std::filesystem::temp_directory_path() /
      fmt::format("frictionlab-hall-{}-{}.json", getpid(), stamp);
  {
    std::ofstream f(json_path);
    f << hall_plot_data(log, est).dump();
    if (!f) throw std::runtime_error("cannot write " + json_path.string());
  }
  struct Remove {
    std::filesystem::path path;
    ~Remove() {
      std::error_code ignored;
      std::filesystem::remove(path, ignored);
    }
  } remove_json{json_path};
  run_plot_script("plot_hall.py", {json_path.string(), png});
}

int run_estimate(const EstimateOptions& o) {
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

  const HallLog log = read_hall_log(o.log);
  const LogEstimate est = estimate_log(log, set_up, !o.plot.empty());
  std::string plot_note;
  if (!o.plot.empty()) {
    draw_plot(log, est, o.plot);
    plot_note = " (the plot " + o.plot + " shows the signal)";
  }
  require_periods(log, est, plot_note);

  if (o.json) {
    nlohmann::json out = log_estimate_json(log, est);
    out["plot"] = json_or_null(o.plot.empty() ? std::nullopt : std::optional<std::string>(o.plot));
    fmt::print("{}\n", out.dump(2));
    return 0;
  }

  const fl_estimator::Stats& s = est.stats;
  fmt::print("frictionlab estimate: {}\n", log.path);
  fmt::print("  log                  {}, {} samples over {:.3f} s at {:.0f} Hz (columns {}, {})\n",
             log.reading.format == "firmware" ? "the rig firmware's serial output" : "CSV", log.adc.size(),
             est.duration, est.sample_rate, log.reading.time_column, log.reading.adc_column);
  if (log.reading.unfinished_last_line)
    fmt::print("                       (its last line, cut off without a newline, left out)\n");
  fmt::print("  signal               polarity {:+d}, baseline {:.1f} counts, {} pulses{}\n",
             est.polarity, est.baseline, s.pulses,
             est.distorted > 0 ? fmt::format(" ({} distorted)", est.distorted) : std::string());
  fmt::print("  geometry             {}\n", est.geometry == fl_estimator::kPulsePair
                                                ? "a pair of pulses per period"
                                                : "one pulse per period");
  const int broken = static_cast<int>(s.periods_discarded) - est.outliers;
  fmt::print("  periods              {} used, {} discarded ({} {}, {} at broken turning points)\n",
             s.periods_used, s.periods_discarded, est.outliers,
             est.outliers == 1 ? "outlier" : "outliers", broken);
  fmt::print("  period T             {:.6f} +- {:.6f} s (N = {}, standard error {:.6f} s)\n",
             s.period_s, s.period_std_s, s.periods_used, s.period_sem_s);
  fmt::print("  mu_k                 {:.4f} +- {:.4f} (worst case) +- {:.4f} (quadrature)\n",
             s.mu_k, s.mu_k_err_worst, s.mu_k_err_quadrature);
  fmt::print(
      "                       for l = {:.1f} +- {:.1f} mm, g = {:.3f} m/s^2, dT the "
      "standard deviation\n",
      set_up.spacing * 1e3, set_up.spacing_err * 1e3, set_up.gravity);
  if (!o.plot.empty()) fmt::print("  plot                 {}\n", o.plot);
  return 0;
}

}  // namespace

Command add_estimate_command(CLI::App& app, const GlobalOptions& /*global*/) {
  auto options = std::make_shared<EstimateOptions>();
  CLI::App* sub = app.add_subcommand(
      "estimate",
      "T +- dT and mu_k +- d mu_k from a Hall-sensor log of the real rig (the rig firmware's "
      "serial output, or a CSV of time and ADC value), by the estimator the rig's Arduino runs");
  sub->add_option("LOG", options->log, "The log: the firmware's serial capture or a CSV")
      ->required();
  sub->add_option("--spacing", options->spacing, "Roller spacing l")->capture_default_str();
  sub->add_option("--spacing-err", options->spacing_err, "Uncertainty dl of the spacing")
      ->capture_default_str();
  sub->add_option("--gravity", options->gravity, "Gravity g")->capture_default_str();
  sub->add_option("--geometry", options->geometry,
                  "Pulses per period: auto (recognise), one, or pair")
      ->capture_default_str();
  sub->add_option("--plot", options->plot,
                  "Draw the signal with the pulses and the rejected periods to this PNG");
  sub->add_flag("--json", options->json, "Print one JSON object (SI units) instead of the table");
  return Command{sub, [options] { return run_estimate(*options); }};
}

}  // namespace fl::cli
