// A Hall-sensor log of the real rig (hall_log/hall_log) run through the rig's estimator: T +- dT
// and mu_k +- d mu_k, every pulse and period on the log's time axis, what the log lacks when it
// gives no period, and the data tools/plot_hall.py draws.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "estimator/host_estimator.hpp"
#include "estimator/period_estimator.h"
#include "hall_log/hall_log.hpp"

namespace fl {

// What the estimate needs besides the log: l +- dl and g for mu_k, and the pulses per period
// when they are known.
struct LogSetUp {
  double spacing = 0.089;      // l [m]
  double spacing_err = 0.002;  // dl [m]
  double gravity = 9.81;       // g [m/s^2]
  fl_estimator::Geometry geometry = fl_estimator::kAutoGeometry;
  // The plate's centre of mass above the rollers' contact line, when given [m]: mu_k through the
  // thick formula beside the paper's (a phone lying on the plate raises it).
  std::optional<double> h_c;

  // The estimator's configuration (single precision, as the rig's Arduino holds it).
  fl_estimator::Config config() const;
};

struct LogEstimate {
  LogSetUp set_up;
  fl_estimator::Stats stats{};
  fl_estimator::Geometry geometry = fl_estimator::kAutoGeometry;
  int polarity = 0;
  double baseline = 0.0;  // at the end [counts]
  bool learned = false;   // the signal was learned at least once
  std::vector<EstimatedPulse> pulses;
  std::vector<float> pulse_baseline;  // the baseline each pulse was measured from [counts]
  std::vector<EstimatedPeriod> periods;
  int outliers = 0;       // periods rejected as farther than the tolerance from the running median
  int distorted = 0;      // pulses bent out of shape
  double duration = 0.0;  // last sample time minus first [s]
  double sample_rate = 0.0;  // mean [Hz]
  // Per sample, for the plot: the baseline and the timing level [counts], NaN while learning.
  std::vector<float> baseline_trace;
  std::vector<float> level_trace;
};

// mu_k through the thick formula, 2 pi^2 l / (g T^2 + 4 pi^2 h_c), with the set-up's h_c; nullopt
// without an h_c or a period.
std::optional<double> mu_k_thick(const LogEstimate& estimate);

// The plate's amplitude from an instrument that follows its motion: the amplitude of its
// positions' oscillation, or of an accelerometer's axis over omega^2 (a = -omega^2 x, omega = 2 pi
// / T: metres from m/s^2). `unit` is set to the amplitude's ("" when the file names none: Tracker's
// calibration). nullopt for the Hall sensor and a magnetometer, or without a period.
std::optional<double> plate_amplitude(const HallLog& log, const LogEstimate& estimate,
                                      std::string* unit = nullptr);

// Runs the estimator over the log; `traces` keeps the per-sample levels for a plot.
LogEstimate estimate_log(const HallLog& log, const LogSetUp& set_up, bool traces);

// What a log's periods must show to be a rig's oscillation (docs/estimator.md, "Periods that are
// no rig's"): at least kLeastPeriods accepted, no more discarded than accepted, and a scatter
// dT/T of at most kMostPeriodScatter. The paper averaged 10 to 100 periods and its dT/T is 0.5
// to 8 % (Table I); the estimator accepts a period within 20 % of the running median, and periods
// spread evenly over that window scatter by 0.2 / sqrt(3) = 11.5 %.
inline constexpr int kLeastPeriods = 5;
inline constexpr double kMostPeriodScatter = 0.10;

// Throws InputError, located at the log's line, saying what was found when the log gives no
// T +- dT (no pulse and why, one pulse, too few to recognise the geometry, intervals that fit
// neither geometry) or periods that are no rig's (fewer than kLeastPeriods accepted, more
// discarded than accepted, a scatter beyond kMostPeriodScatter): never a made-up period. `note`
// ends the message (e.g. where a plot shows the signal).
void require_periods(const HallLog& log, const LogEstimate& estimate, const std::string& note);

// Throws InputError when the estimate's T or mu_k is beyond any bench (core/plausible_range.hpp):
// a time read in the wrong unit (the unit that would make it a rig's said), never a number to
// print.
void require_plausible(const HallLog& log, const LogEstimate& estimate, const std::string& note);

// "; if its time is in ms, give ⟦time_unit=ms⟧" when the log's time, read in the unit its header
// or the request names, makes its sample rate no rig's (20 Hz to 20 kHz) and another unit would
// not; "" otherwise.
std::string time_unit_hint(const HallLog& log, const LogEstimate& estimate);

// "accepted", "outlier", "broken"; "one-pulse", "pair", "unknown".
const char* period_status_name(std::uint8_t status);
const char* geometry_name(fl_estimator::Geometry geometry);
// The pulses per period as a user names them (--geometry, a sidecar's geometry): "auto", "one" or
// "pair"; nothing for any other text.
std::optional<fl_estimator::Geometry> geometry_from_option(std::string_view text);

// The result as `frictionlab estimate --json` prints it (docs/cli.md), without "plot".
nlohmann::json log_estimate_json(const HallLog& log, const LogEstimate& estimate);

// What tools/plot_hall.py draws: the samples (long logs thinned to the lowest and highest of each
// bucket, so no peak is lost), the baseline and timing level, the pulses, the periods and the
// summary. Needs an estimate made with traces.
nlohmann::json hall_plot_data(const HallLog& log, const LogEstimate& estimate);

}  // namespace fl
