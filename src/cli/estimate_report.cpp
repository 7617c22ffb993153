#include "cli/estimate_report.hpp"

#include <optional>
#include <vector>

#include <fmt/format.h>

#include "io/json_value.hpp"
#include "text/utf8.hpp"

namespace fl::cli {
namespace {

std::string plural(int n, const char* one, const char* many) {
  return fmt::format("{} {}", n, n == 1 ? one : many);
}

// Where the columns and the time's unit came from.
std::string columns_text(const HallLogReading& r) {
  std::string names = escape_invalid_utf8(
      r.time_column.empty() ? r.adc_column : r.time_column + ", " + r.adc_column);
  std::string from = r.columns_from == "header"
                         ? fmt::format("from the header, line {}", r.header_line)
                     : r.columns_from == "columns" ? std::string("from --columns")
                     : r.columns_from == "tracked"
                         ? std::string(
                               "the plate tracked in each frame: frictionlab track draws "
                               "what was followed")
                         : std::string("by position: no header");
  std::string unit;
  if (r.time_unit_from == "rate")
    unit = fmt::format("; timed by --rate {:g} Hz", r.rate_hz);
  else if (r.time_unit_from == "inferred")
    unit = fmt::format("; time in {}, inferred from the interval (--time-unit says otherwise)",
                       r.time_unit);
  else if (r.time_unit_from == "time_unit")
    unit = fmt::format("; time in {} (--time-unit)", r.time_unit);
  return fmt::format("columns {} ({}){}", names, from, unit);
}

// What was skipped before the log and left out of it; empty when nothing was.
std::vector<std::string> left_out_text(const HallLog& log) {
  const HallLogReading& r = log.reading;
  std::vector<std::string> out;
  if (r.lines_skipped > 0)
    out.push_back(fmt::format("{} before line {} skipped (a banner, reset garbage)",
                              plural(r.lines_skipped, "line", "lines"), r.first_line));
  if (r.corrupted.count > 0)
    out.push_back(fmt::format("{} left out ({})",
                              plural(r.corrupted.count, "corrupted line", "corrupted lines"),
                              line_list(r.corrupted)));
  if (r.repeated_times.count > 0)
    out.push_back(fmt::format("{} left out ({})",
                              plural(r.repeated_times.count, "repeated time", "repeated times"),
                              line_list(r.repeated_times)));
  if (r.out_of_order.count > 0)
    out.push_back(fmt::format(
        "{} left out ({})", plural(r.out_of_order.count, "time out of order", "times out of order"),
        line_list(r.out_of_order)));
  if (r.segments > 1)
    out.push_back(
        fmt::format("the board restarted: {} runs, the longest (lines {}-{}) used, {} of "
                    "the others left out",
                    r.segments, log.line.front(), log.line.back(),
                    plural(log.segment_samples_left_out, "sample", "samples")));
  if (r.unfinished_last_line) out.push_back("its last line, cut off without a newline, left out");
  return out;
}

// Another instrument, and the channel of it read.
std::string instrument_text(const HallLog& log) {
  const std::string words = instrument_words(log.instrument);
  if (log.instrument == MeasurementFile::kVideo)
    return fmt::format(
        "{} (the plate's position along its motion, in {}, timed at its upper "
        "turns)",
        words, log.reading.adc_column == "x (mm)" ? "mm" : "the video's pixels");
  if (log.instrument == MeasurementFile::kPhyphoxMagnetometer)
    return fmt::format("{} ({} {}, the clearest pulses)", words,
                       log.channel == "|B|" ? "the field's magnitude" : "component", log.channel);
  // An accelerometer lying between its axes is read along the motion, its axes combined.
  if (log.channel.find(' ') != std::string::npos)
    return fmt::format("{} (along {}, the direction of the swing, timed at its upper turns)", words,
                       log.channel);
  return fmt::format("{} (column {}, the clearest swing, timed at its upper turns)", words,
                     log.channel);
}

std::string format_text(const HallLog& log) {
  std::vector<std::string> parts;
  parts.push_back(log.reading.format == "firmware" ? "the rig firmware's serial output"
                  : log.reading.format == "serial-plotter"
                      ? "the Serial Plotter's label:value lines"
                  : log.instrument == MeasurementFile::kRigLog ? "CSV"
                                                               : instrument_text(log));
  if (!log.encoding.empty() && log.encoding != "utf-8") parts.push_back(log.encoding);
  if (log.reading.ide_timestamps) parts.push_back("the Arduino IDE's timestamps taken off");
  if (log.reading.decimal_comma) parts.push_back("decimal commas");
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i > 0 ? ", " : "") + parts[i];
  return out;
}

std::string geometry_text(const LogEstimate& est, const GeometryCheck& check) {
  const std::string name = est.geometry == fl_estimator::kPulsePair ? "a pair of pulses per period"
                                                                    : "one pulse per period";
  if (est.set_up.geometry != fl_estimator::kAutoGeometry) return name + " (--geometry)";
  if (check.needed && check.verdict == "turn" && check.shape_ratio)
    return fmt::format(
        "{} (pulses evenly spaced and shaped like a turn at the sensor: width at 1/4 of the "
        "height {:.2f} x that at 1/2)",
        name, *check.shape_ratio);
  return name;
}

}  // namespace

std::string line_list(const LineTally& tally) {
  std::string out = tally.first.size() == 1 ? "line " : "lines ";
  for (std::size_t i = 0; i < tally.first.size(); ++i)
    out += (i > 0 ? ", " : "") + std::to_string(tally.first[i]);
  if (tally.count > static_cast<int>(tally.first.size())) out += ", ...";
  return out;
}

void print_estimate(const HallLog& log, const LogEstimate& est, const GeometryCheck& check,
                    const std::string& plot) {
  const fl_estimator::Stats& s = est.stats;
  const LogSetUp& set_up = est.set_up;
  fmt::print("frictionlab estimate: {}\n", escape_invalid_utf8(log.path));
  // The file read, when it is not the one named: a folder's log, a zip's entry.
  if (!log.file.empty() && log.file != log.path)
    fmt::print("  file                 {}\n", escape_invalid_utf8(log.file));
  fmt::print("  log                  {}, {} samples over {:.3f} s at {:.0f} Hz\n", format_text(log),
             log.adc.size(), est.duration, est.sample_rate);
  fmt::print("                       {}\n", columns_text(log.reading));
  for (const std::string& line : left_out_text(log))
    fmt::print("                       {}\n", line);
  // Another instrument's values are no ADC counts: its baseline in counts means nothing.
  const std::string baseline = log.instrument == MeasurementFile::kRigLog
                                   ? fmt::format(", baseline {:.1f} counts", est.baseline)
                                   : std::string();
  fmt::print("  signal               polarity {:+d}{}, {} pulses{}\n", est.polarity, baseline,
             s.pulses,
             est.distorted > 0 ? fmt::format(" ({} distorted)", est.distorted) : std::string());
  fmt::print("  geometry             {}\n", geometry_text(est, check));
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
  std::string unit;
  if (const std::optional<double> amplitude = plate_amplitude(log, est, &unit))
    fmt::print("  amplitude            {:.4g} {}{}\n", *amplitude,
               unit.empty() ? "(the file's unit)" : unit,
               is_accelerometer(log.instrument)
                   ? fmt::format(" (the swing's {:.4g} {} over (2 pi / T)^2)", *log.half_swing,
                                 log.swing_unit)
                   : std::string(""));
  if (const std::optional<double> thick = mu_k_thick(est))
    fmt::print("  mu_k thick           {:.4f} (the thick formula, h_c = {:.2f} mm)\n", *thick,
               *set_up.h_c * 1e3);
  else if (is_accelerometer(log.instrument))
    fmt::print(
        "  note                 a phone lying on the plate raises its centre of mass: --h-c "
        "(the plate's with the phone, above the rollers' contact line) gives mu_k through the "
        "thick formula\n");
  if (!plot.empty()) fmt::print("  plot                 {}\n", escape_invalid_utf8(plot));
}

nlohmann::json estimate_json(const HallLog& log, const LogEstimate& est, const std::string& plot) {
  nlohmann::json out = log_estimate_json(log, est);
  out["plot"] = json_or_null(plot.empty() ? std::nullopt
                                          : std::optional<std::string>(escape_invalid_utf8(plot)));
  return out;
}

}  // namespace fl::cli
