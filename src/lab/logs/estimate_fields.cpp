#include "lab/logs/estimate_fields.hpp"

#include <cstdint>
#include <string>

#include "lab/logs/geometry_check.hpp"

namespace fl {
namespace {

using E = const EstimateOf&;
using V = FieldValue;
using T = FieldType;
using P = EstimatePart;

V count(std::int64_t n) {
  return V::whole(n);
}

// A tally's first lines, as a list.
V first_lines(const LineTally& t) {
  return V::object(nlohmann::json(t.first));
}

// Every period judged, on the log's time axis.
V periods(E e) {
  nlohmann::json out = nlohmann::json::array();
  for (const EstimatedPeriod& p : e.estimate.periods)
    out.push_back({{"start_s", p.start},
                   {"end_s", p.end},
                   {"period_s", p.period},
                   {"status", period_status_name(p.status)}});
  return V::object(std::move(out));
}

const fl_estimator::Stats& stats(E e) {
  return e.estimate.stats;
}

// How the log was read: its file, format and columns, and what was left out.
std::vector<EstimateField> reading_fields() {
  // clang-format off
  return {
      {.json = "log",
       .part = P::kReading,
       .type = T::kText,
       .meaning = "the log as given (`<stdin>`, a folder, a port)",
       .get = [](E e) { return escaped_text(e.log.path); }},
      {.json = "file",
       .part = P::kReading,
       .type = T::kText,
       .meaning = "the file read (a folder's log; a followed port's raw log, or the port)",
       .get = [](E e) { return escaped_text(e.log.file); }},
      {.json = "instrument",
       .python = "instrument",
       .part = P::kReading,
       .type = T::kText,
       .meaning = "what measured: `Hall sensor` (the rig's), `phyphox magnetometer` (a phone "
                  "beside the rig), `phyphox accelerometer` or `phyphox accelerometer (without g)` "
                  "(a phone on the plate), `Tracker` (a video's marks), `position-time table`, "
                  "`video` (a phone's video, the plate followed without clicks)",
       .get = [](E e) { return V::text(instrument_words(e.log.instrument)); }},
      {.json = "channel",
       .python = "channel",
       .part = P::kReading,
       .type = T::kText,
       .meaning = "the channel read of the instrument's several, the one that swings clearest: "
                  "a magnetometer's `x`, `y`, `z` or `|B|`, an accelerometer's axis (or, for a "
                  "phone lying between them, its axes combined along the motion: `0.866 x + 0.500 "
                  "y`), a table's position column, a video's `x (px)` or `x (mm)`",
       .null_when = "the instrument has one channel (the rig's Hall sensor)",
       .get = [](E e) { return escaped_text_or_none(e.log.channel); }},
      {.json = "format",
       .part = P::kReading,
       .type = T::kText,
       .meaning = "`firmware` (a capture of the rig firmware, recognised by its banner comment), "
                  "`serial-plotter` (label:value lines), `phyphox`, `tracker`, `table` or `csv`",
       .get = [](E e) { return V::text(e.log.reading.format); }},
      {.json = "encoding",
       .part = P::kReading,
       .type = T::kText,
       .meaning = "`utf-8`, `utf-8 with BOM`, `utf-16le`, `utf-16be`, `utf-16le (no BOM)`, "
                  "`utf-16be (no BOM)`",
       .null_when = "a video was read (frames, no text)",
       .get =
           [](E e) { return e.log.encoding.empty() ? FieldValue() : V::text(e.log.encoding); }},
      {.json = "columns_from",
       .part = P::kReading,
       .type = T::kText,
       .meaning = "`header`, `columns` (the request's field `columns`), `position`, or "
                  "`tracked` (a video's plate followed in its frames)",
       .get = [](E e) { return V::text(e.log.reading.columns_from); }},
      {.json = "time_column",
       .part = P::kReading,
       .type = T::kText,
       .meaning = "the name of the time column used (`field 1` by position)",
       .null_when = "the samples are timed by a rate (the request's field `rate`)",
       .get = [](E e) { return escaped_text_or_none(e.log.reading.time_column); }},
      {.json = "adc_column",
       .part = P::kReading,
       .type = T::kText,
       .meaning = "the name of the value column used (`field 2` by position)",
       .get = [](E e) { return escaped_text(e.log.reading.adc_column); }},
      {.json = "time_unit",
       .part = P::kReading,
       .type = T::kText,
       .meaning = "`us`, `ms` or `s`",
       .null_when = "the samples are timed by a rate (the request's field `rate`)",
       .get = [](E e) { return escaped_text_or_none(e.log.reading.time_unit); }},
      {.json = "time_unit_from",
       .part = P::kReading,
       .type = T::kText,
       .meaning = "`header`, `columns`, `time_unit`, `inferred` or `rate` (the last three the "
                  "request's fields `columns`, `time_unit`, `rate`)",
       .get = [](E e) { return V::text(e.log.reading.time_unit_from); }},
      {.json = "rate_hz",
       .part = P::kReading,
       .unit = "Hz",
       .meaning = "the rate given (the request's field `rate`)",
       .null_when = "no rate was given",
       .get =
           [](E e) {
             const double rate = e.log.reading.rate_hz;
             return rate > 0.0 ? V::number(rate) : V();
           }},
      {.json = "header_line",
       .part = P::kReading,
       .type = T::kInteger,
       .meaning = "the header's line",
       .null_when = "the log has no header",
       .get =
           [](E e) {
             const int line = e.log.reading.header_line;
             return line > 0 ? count(line) : V();
           }},
      {.json = "first_line",
       .part = P::kReading,
       .type = T::kInteger,
       .meaning = "the line the log starts at (its header or first sample)",
       .get = [](E e) { return count(e.log.reading.first_line); }},
      {.json = "lines_skipped",
       .part = P::kReading,
       .type = T::kInteger,
       .meaning = "lines before it (banner, reset garbage)",
       .get = [](E e) { return count(e.log.reading.lines_skipped); }},
      {.json = "comment_lines",
       .part = P::kReading,
       .type = T::kInteger,
       .meaning = "`#` lines",
       .get = [](E e) { return count(e.log.reading.comment_lines); }},
  };
  // clang-format on
}

// The lines and samples left out, and the runs of samples.
std::vector<EstimateField> left_out_fields() {
  // clang-format off
  return {
      {.json = "lines_corrupted",
       .part = P::kReading,
       .type = T::kInteger,
       .meaning = "lines after the start that are not samples",
       .get = [](E e) { return count(e.log.reading.corrupted.count); }},
      {.json = "lines_corrupted_first",
       .part = P::kReading,
       .type = T::kObject,
       .meaning = "the first five of them (line numbers)",
       .get = [](E e) { return first_lines(e.log.reading.corrupted); }},
      {.json = "times_repeated",
       .part = P::kReading,
       .type = T::kInteger,
       .meaning = "samples left out because their time repeats the previous one's",
       .get = [](E e) { return count(e.log.reading.repeated_times.count); }},
      {.json = "times_repeated_first",
       .part = P::kReading,
       .type = T::kObject,
       .meaning = "the first five of them (line numbers)",
       .get = [](E e) { return first_lines(e.log.reading.repeated_times); }},
      {.json = "times_out_of_order",
       .part = P::kReading,
       .type = T::kInteger,
       .meaning = "samples left out because their time is out of order",
       .get = [](E e) { return count(e.log.reading.out_of_order.count); }},
      {.json = "times_out_of_order_first",
       .part = P::kReading,
       .type = T::kObject,
       .meaning = "the first five of them (line numbers)",
       .get = [](E e) { return first_lines(e.log.reading.out_of_order); }},
      {.json = "ide_timestamps",
       .part = P::kReading,
       .type = T::kFlag,
       .meaning = "the Arduino IDE's time prefixes were taken off",
       .get = [](E e) { return V::flag(e.log.reading.ide_timestamps); }},
      {.json = "decimal_comma",
       .part = P::kReading,
       .type = T::kFlag,
       .meaning = "numbers had a decimal comma",
       .get = [](E e) { return V::flag(e.log.reading.decimal_comma); }},
      {.json = "clock_wraps",
       .part = P::kReading,
       .type = T::kInteger,
       .meaning = "times a 32-bit microsecond clock wrapped around",
       .get = [](E e) { return count(e.log.reading.clock_wraps); }},
      {.json = "runs",
       .part = P::kReading,
       .type = T::kInteger,
       .meaning = "runs of samples (a board that restarted begins a new one)",
       .get = [](E e) { return count(e.log.reading.segments); }},
      {.json = "run_used",
       .part = P::kReading,
       .type = T::kInteger,
       .meaning = "the run used (1-based: the longest)",
       .get = [](E e) { return count(e.log.segment + 1); }},
      {.json = "samples_in_other_runs",
       .part = P::kReading,
       .type = T::kInteger,
       .meaning = "samples left in the other runs",
       .get = [](E e) { return count(e.log.segment_samples_left_out); }},
      {.json = "unfinished_last_line",
       .part = P::kReading,
       .type = T::kFlag,
       .meaning = "true when a cut-off last line was left out",
       .get = [](E e) { return V::flag(e.log.reading.unfinished_last_line); }},
  };
  // clang-format on
}

// The signal and the estimator's state.
std::vector<EstimateField> signal_fields() {
  // clang-format off
  return {
      {.json = "samples",
       .part = P::kSignal,
       .type = T::kInteger,
       .meaning = "samples used",
       .get = [](E e) { return V::whole(std::uint64_t{e.log.adc.size()}); }},
      {.json = "duration_s",
       .python = "duration",
       .unit = "s",
       .meaning = "last sample time minus first",
       .get = [](E e) { return V::number(e.estimate.duration); }},
      {.json = "sample_rate_hz",
       .python = "sample_rate",
       .unit = "Hz",
       .meaning = "the mean sample rate",
       .get = [](E e) { return V::number(e.estimate.sample_rate); }},
      {.json = "polarity",
       .python = "polarity",
       .type = T::kInteger,
       .meaning = "+1 when the magnet pushes the ADC up, -1 down",
       .get = [](E e) { return count(e.estimate.polarity); }},
      {.json = "baseline_adc",
       .python = "baseline",
       .meaning = "the estimator's baseline at the end, in ADC counts",
       .null_when = "another instrument was read (its values are no ADC counts)",
       .get =
           [](E e) {
             return e.log.instrument == MeasurementFile::kRigLog ? V::number(e.estimate.baseline)
                                                      : FieldValue();
           }},
      {.json = "pulses",
       .type = T::kInteger,
       .meaning = "pulses detected (after the two the signal is learned from)",
       .get = [](E e) { return V::whole(std::uint64_t{stats(e).pulses}); }},
      {.json = "pulses_distorted",
       .type = T::kInteger,
       .meaning = "pulses whose peak or width was far from the others'",
       .get = [](E e) { return count(e.estimate.distorted); }},
      {.json = "pulses_unused",
       .type = T::kInteger,
       .meaning = "pulses seen before the geometry was recognised and not used",
       .get = [](E e) { return V::whole(std::uint64_t{stats(e).unused_pulses}); }},
      {.json = "restarts",
       .type = T::kInteger,
       .meaning = "times the signal was lost (no pulse for four periods) and learned again",
       .get = [](E e) { return V::whole(std::uint64_t{stats(e).restarts}); }},
  };
  // clang-format on
}

// The estimator's verdict: the geometry, the periods, T and mu_k.
std::vector<EstimateField> verdict_fields() {
  // clang-format off
  return {
      {.json = "geometry",
       .python = "geometry",
       .part = P::kVerdict,
       .type = T::kText,
       .meaning = "`one-pulse` or `pair`: pulses per period",
       .get = [](E e) { return V::text(geometry_name(e.estimate.geometry)); }},
      {.json = "geometry_from",
       .type = T::kText,
       .meaning = "`recognised`, or `geometry` (the request's field `geometry`)",
       .get =
           [](E e) {
             return V::text(e.estimate.set_up.geometry == fl_estimator::kAutoGeometry ? "recognised"
                                                                                      : "geometry");
           }},
      {.json = "geometry_check",
       .type = T::kObject,
       .meaning = "for evenly spaced pulses read as one per period: `verdict` (`turn`), "
                  "`pulse_shape_ratio` (median width at 1/4 over width at 1/2), `shape_pulses`, "
                  "`samples_across_pulse`, `alternation_s` and `alternation_err_s` (each period "
                  "minus its neighbours' mean, by turns, and its standard error; null with fewer "
                  "than 4 independent triples), `alternation_triples`",
       .null_when = "the pulses are not evenly spaced, or are read as a pair",
       .get =
           [](E e) { return V::object(geometry_check_json(check_geometry(e.log, e.estimate))); }},
      {.json = "periods_used",
       .python = "periods_used",
       .part = P::kVerdict,
       .type = T::kInteger,
       .meaning = "N, the accepted periods",
       .get = [](E e) { return V::whole(std::uint64_t{stats(e).periods_used}); }},
      {.json = "periods_discarded",
       .python = "periods_discarded",
       .part = P::kVerdict,
       .type = T::kInteger,
       .meaning = "rejected periods: outliers and periods at broken turning points",
       .get = [](E e) { return V::whole(std::uint64_t{stats(e).periods_discarded}); }},
      {.json = "periods_outliers",
       .python = "outliers",
       .type = T::kInteger,
       .meaning = "of which farther than 20 % from the running median (a missing pulse)",
       .get = [](E e) { return count(e.estimate.outliers); }},
      {.json = "period_s",
       .python = "period",
       .part = P::kVerdict,
       .unit = "s",
       .meaning = "T, the mean accepted period",
       .get = [](E e) { return V::number(static_cast<double>(stats(e).period_s)); }},
      {.json = "period_std_s",
       .python = "period_std",
       .part = P::kVerdict,
       .unit = "s",
       .meaning = "dT, the accepted periods' standard deviation (the paper's)",
       .get = [](E e) { return V::number(static_cast<double>(stats(e).period_std_s)); }},
      {.json = "period_sem_s",
       .python = "period_std_error",
       .part = P::kVerdict,
       .unit = "s",
       .meaning = "the standard error of the mean, dT/sqrt(N)",
       .get = [](E e) { return V::number(static_cast<double>(stats(e).period_sem_s)); }},
      {.json = "mu_k",
       .python = "mu_k",
       .part = P::kVerdict,
       .meaning = "mu_k = 2 pi^2 l / (g T^2), the paper's (thin) formula",
       .get = [](E e) { return V::number(static_cast<double>(stats(e).mu_k)); }},
      {.json = "mu_k_err_worst",
       .python = "mu_k_err_worst",
       .part = P::kVerdict,
       .meaning = "d mu_k, the paper's worst case: mu_k (dl/l + 2 dT/T)",
       .get = [](E e) { return V::number(static_cast<double>(stats(e).mu_k_err_worst)); }},
      {.json = "mu_k_err_quadrature",
       .python = "mu_k_err_quadrature",
       .part = P::kVerdict,
       .meaning = "d mu_k in quadrature: mu_k sqrt((dl/l)^2 + (2 dT/T)^2)",
       .get = [](E e) { return V::number(static_cast<double>(stats(e).mu_k_err_quadrature)); }},
      {.json = "mu_k_thick",
       .python = "mu_k_thick",
       .meaning = "mu_k through the thick formula, 2 pi^2 l / (g T^2 + 4 pi^2 h_c), with the "
                  "request's h_c (the plate's centre of mass above the contact line)",
       .null_when = "no h_c was given, or the log gave no period",
       .get = [](E e) { return V::number(mu_k_thick(e.estimate)); }},
      {.json = "amplitude",
       .python = "amplitude",
       .meaning = "the plate's amplitude in `amplitude_unit`: the least-squares sinusoid's at "
                  "the strongest frequency of the positions read, or of the accelerometer's axis "
                  "over omega^2 = (2 pi / T)^2 (a mean over the record, if the swing changes)",
       .null_when = "the instrument does not follow the plate's motion (the Hall sensor, a "
                    "magnetometer: pulses), or the log gave no period",
       .get = [](E e) { return V::number(plate_amplitude(e.log, e.estimate)); }},
      {.json = "amplitude_unit",
       .python = "amplitude_unit",
       .type = T::kText,
       .meaning = "the amplitude's unit: the position column's (`m`, `mm`, `px`), `m` from an "
                  "accelerometer",
       .null_when = "there is no amplitude, or the column's header names no unit (Tracker's "
                    "data: the unit its video was calibrated in)",
       .get =
           [](E e) {
             std::string unit;
             return plate_amplitude(e.log, e.estimate, &unit) && !unit.empty() ? V::text(unit)
                                                                                 : FieldValue();
           }},
  };
  // clang-format on
}

// The rig the estimate was made for, and what the request adds.
std::vector<EstimateField> request_fields() {
  // clang-format off
  return {
      {.json = "spacing_m",
       .python = "spacing",
       .unit = "m",
       .meaning = "l used",
       .get = [](E e) { return V::number(e.estimate.set_up.spacing); }},
      {.json = "spacing_err_m",
       .python = "spacing_err",
       .unit = "m",
       .meaning = "dl used",
       .get = [](E e) { return V::number(e.estimate.set_up.spacing_err); }},
      {.json = "gravity_m_s2",
       .python = "gravity",
       .unit = "m/s^2",
       .meaning = "g used",
       .get = [](E e) { return V::number(e.estimate.set_up.gravity); }},
      {.json = "periods",
       .type = T::kObject,
       .meaning = "every period judged: `start_s`, `end_s` (its turning points on the log's time "
                  "axis [s]), `period_s`, `status` (`accepted`, `outlier`, `broken`)",
       .get = periods},
      {.json = "plot",
       .part = P::kRequest,
       .type = T::kText,
       .meaning = "the PNG written",
       .null_when = "no plot was asked"},
      {.json = "monte_carlo",
       .part = P::kRequest,
       .type = T::kObject,
       .meaning = "with a Monte Carlo (the request's field `mc`): mu_k's draws from T, l and h_c "
                  "drawn from "
                  "their uncertainties "
                  "(`draws`, `seed`, `accepted`, `skipped`, `mu_k_mean`, `mu_k_sd`, "
                  "`mu_k_quantile_025`, `mu_k_quantile_975`)",
       .null_when = "no Monte Carlo was asked"},
      {.json = "paper",
       .part = P::kRequest,
       .type = T::kObject,
       .meaning = "the paper's Table I value for the log's material, beside the log's",
       .null_when = "no material was named (the request's field `material`, or the log's sidecar)"},
      {.json = "raw_log",
       .part = P::kRequest,
       .type = T::kText,
       .meaning = "following a port: the file its raw log was written to",
       .null_when = "no file was given for the raw log"},
  };
  // clang-format on
}

}  // namespace

const std::vector<EstimateField>& estimate_fields() {
  static const std::vector<EstimateField> fields = [] {
    std::vector<EstimateField> all;
    for (auto* group :
         {&reading_fields, &left_out_fields, &signal_fields, &verdict_fields, &request_fields}) {
      std::vector<EstimateField> part = group();
      all.insert(all.end(), part.begin(), part.end());
    }
    return all;
  }();
  return fields;
}

}  // namespace fl
