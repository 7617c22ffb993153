#include "hall_log/hall_log_reader.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "hall_log/log_line.hpp"
#include "hall_log/log_reading_error.hpp"
#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

constexpr double kWrap = 4294967296.0;  // a 32-bit clock's readings
constexpr double kHalfWrap = 2147483648.0;
// Samples the unit of a time column without one is inferred from.
constexpr std::size_t kUnitSamples = 64;
// Sample rates a log can have [Hz]: the unit that puts the rate in [low, high) is the one.
constexpr double kLowestRate = 20.0;
constexpr double kHighestRate = 20000.0;
// Headerless logs: lines of numbers in a row that make the first one the start.
constexpr std::size_t kConfirmingLines = 3;

// A field or line for a message: bytes that are not printable ASCII (garbage from a reset, a
// wrong baud rate) as \xNN.
std::string quoted_for_message(std::string_view s) {
  constexpr std::size_t kMax = 60;
  constexpr char kHex[] = "0123456789abcdef";
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size() && i < kMax; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (s.size() > kMax) out += "...";
  out += '"';
  return out;
}

std::string percent(int part, int whole) {
  std::ostringstream s;
  s.precision(part * 1000 >= whole ? 3 : 2);
  s << 100.0 * part / std::max(whole, 1) << " %";
  return s.str();
}

constexpr std::string_view kFirmwareBanner = "# frictionlab rig firmware";

// The request's options with the columns, the rate or the time's unit changed: what an error's
// advice names, for a caller to try on the log before giving it.
ReadingTry try_columns(HallLogOptions options, const std::string& columns) {
  options.columns = columns;
  options.rate_hz = 0.0;
  return {options, field_ref("columns", columns), ""};
}
ReadingTry try_rate(HallLogOptions options, double hz, const std::string& text,
                    const std::string& caveat) {
  options.rate_hz = hz;
  return {options, field_ref("rate", text), caveat};
}
// A guessed rate's caveat: the period scales with it.
const std::string kGuessedRate = "if the sketch samples at 1 kHz; T scales with the rate";
ReadingTry try_time_unit(HallLogOptions options, const std::string& unit) {
  options.time_unit = unit;
  return {options, field_ref("time_unit", unit), ""};
}

// Every way of reading `fields` fields as a time ("t", its unit inferred, or `time` when given)
// and an ADC value ("adc") among the first four, the rest skipped ("_").
std::vector<ReadingTry> column_tries(const HallLogOptions& options, std::size_t fields,
                                     std::optional<std::size_t> time = std::nullopt,
                                     const std::string& time_name = "t") {
  std::vector<ReadingTry> tries;
  if (fields < 2 || fields > 8) return tries;
  const std::size_t most = std::min<std::size_t>(fields, 4);
  for (std::size_t t = 0; t < most; ++t) {
    if (time && t != *time) continue;
    for (std::size_t v = 0; v < most; ++v) {
      if (v == t) continue;
      std::string columns;
      for (std::size_t k = 0; k < fields; ++k)
        columns += std::string(k > 0 ? "," : "") + (k == t ? time_name : k == v ? "adc" : "_");
      tries.push_back(try_columns(options, columns));
    }
  }
  return tries;
}
}  // namespace

void LineTally::add(int line) {
  ++count;
  if (first.size() < kShown) first.push_back(line);
}

HallLogReader::HallLogReader(std::string name, HallLogOptions options)
    : name_(std::move(name)), options_(std::move(options)) {
  if (!options_.columns.empty()) {
    layout_ = columns_from_option(options_.columns);
    reading_.columns_from = "columns";
  }
  if (!options_.time_unit.empty()) {
    const std::optional<std::string> unit = time_unit_name(options_.time_unit);
    if (!unit)
      throw InputError(SourceLocation::of_field("time_unit"),
                       "expected us, ms or s, found " + quoted_for_message(options_.time_unit));
    options_.time_unit = *unit;
  }
  if (!(options_.rate_hz >= 0.0) || !std::isfinite(options_.rate_hz))
    throw InputError(SourceLocation::of_field("rate"),
                     "expected a positive sample rate (for example 1kHz)");
}

void HallLogReader::add_line(std::string_view line, int number, bool unfinished) {
  while (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  const std::size_t offset = ide_timestamp_prefix(line);
  if (offset != 0) reading_.ide_timestamps = true;
  std::string_view text = line.substr(offset);
  // A board reset in the middle of a line: the firmware's banner follows the cut-off line.
  const std::size_t banner = text.find(kFirmwareBanner);
  if (banner != std::string_view::npos && banner > 0) text.remove_prefix(banner);
  const std::string_view content = trim(text);
  if (content.empty()) return;
  if (content.front() == '#') {
    ++reading_.comment_lines;
    if (content.rfind(kFirmwareBanner, 0) == 0) {
      reading_.format = "firmware";
      // The firmware starts again (the board was reset): a new run of samples.
      if (started_ && segment_samples_ + (pending_ ? 1 : 0) > 0) new_segment();
    }
    return;
  }
  if (!started_ || plotter_) {
    if (const std::optional<PlotterLine> plotter = plotter_line(content)) {
      if (!started_) {
        start(plotter->header, 0, number);
        if (!started_) return;
        plotter_ = true;
        reading_.format = "serial-plotter";
      }
      if (plotter->header != header_text_) {
        data_line(text, offset, number, unfinished);  // other labels: not a sample of this log
        return;
      }
      data_line(plotter->values, 0, number, unfinished);
      return;
    }
  }
  if (!started_) {
    start(text, offset, number);
    return;
  }
  if (is_header_again(content)) {
    if (segment_samples_ + (pending_ ? 1 : 0) > 0) new_segment();
    return;
  }
  data_line(text, offset, number, unfinished);
}

// Before the log starts: is this line the header, or the first of the samples?
bool HallLogReader::start(std::string_view text, std::size_t offset, int number) {
  if (!options_.columns.empty()) {
    const char delimiter = detect_delimiter(text);
    const std::vector<LogField> fields = split_fields(text, delimiter);
    double v = 0.0;
    bool sample = fields.size() >= layout_.fields;
    for (std::size_t i = 0; sample && i < layout_.fields; ++i) {
      const bool used = i == layout_.value || (layout_.time && i == *layout_.time);
      if (used) sample = parse_log_number(fields[i].text, delimiter, &v, nullptr);
    }
    if (!sample) {
      skip(text);
      return false;
    }
    delimiter_ = delimiter;
    started_ = true;
    reading_.first_line = number;
    reading_.time_column = layout_.time && options_.rate_hz == 0.0 ? layout_.time_name : "";
    reading_.adc_column = layout_.value_name;
    set_unit();
    data_line(text, offset, number, false);
    return true;
  }
  if (try_header(text, number)) return true;

  // Without a header: lines of numbers, confirmed by the next few.
  const char delimiter = detect_delimiter(text);
  const std::vector<LogField> fields = split_fields(text, delimiter);
  bool numeric = !fields.empty();
  double v = 0.0;
  for (const LogField& f : fields)
    numeric = numeric && parse_log_number(f.text, delimiter, &v, nullptr);
  if (!candidates_.empty() && (!numeric || fields.size() != candidates_.front().fields ||
                               delimiter != candidates_.front().delimiter)) {
    for (const Candidate& c : candidates_) skip(c.text);
    candidates_.clear();
  }
  if (!numeric) {
    skip(text);
    return false;
  }
  // Lines of the doubtful header's shape: it was the log's header after all, and cannot be used.
  if (doubtful_ && fields.size() == doubtful_->fields && delimiter == doubtful_->delimiter)
    throw_doubtful();
  candidates_.push_back({std::string(text), offset, number, fields.size(), delimiter});
  if (candidates_.size() >= kConfirmingLines) start_by_position();
  return true;
}

bool HallLogReader::try_header(std::string_view text, int number) {
  const char delimiter = detect_delimiter(text);
  std::vector<LogField> fields = split_fields(text, delimiter);
  // A one-column header may hold spaces: "ADC Value".
  if (delimiter == 0 && column_name(trim(text))) fields = {LogField{trim(text), 1}};
  double v = 0.0;
  bool all_numbers = true;
  for (const LogField& f : fields)
    all_numbers = all_numbers && parse_log_number(f.text, delimiter, &v, nullptr);
  if (all_numbers) return false;
  std::optional<std::size_t> time;
  std::optional<std::size_t> value;
  std::string unit;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const std::optional<ColumnName> name = column_name(fields[i].text);
    if (!name) continue;
    if (name->role == ColumnRole::kTime && !time) {
      time = i;
      unit = name->unit;
    } else if (name->role == ColumnRole::kValue && !value) {
      value = i;
    }
  }
  if (!value) {
    // A delimited line naming a time but no value is a header this reader cannot use.
    if (time && delimiter != 0) {
      const std::optional<ColumnName> named = column_name(fields[*time].text);
      throw LogReadingError(SourceLocation{name_, number, 0},
                            "the header " + quoted_for_message(trim(text)) +
                                " names no ADC column: expected one called " +
                                std::string(kValueNames),
                            "or name the log's fields in order with " + field_ref("columns") +
                                " (for example " + field_ref("columns", "t_us,adc") + ")",
                            column_tries(options_, fields.size(), *time,
                                         named && !named->unit.empty() ? "t_" + named->unit : "t"));
    }
    return false;
  }
  if (!time && options_.rate_hz == 0.0) {
    // Held, not thrown: a banner that mentions the sensor ("Hall rig ready") reads like this.
    if (!doubtful_)
      doubtful_ = DoubtfulHeader{
          "the header " + quoted_for_message(trim(text)) +
              " names no time column: expected one called " + std::string(kTimeNames),
          "for a log of values only, give the sample rate with " + field_ref("rate") +
              " (for example " + field_ref("rate", "1kHz") + ")",
          number, fields.size(), delimiter};
    skip(text);
    return true;
  }
  layout_ = ColumnLayout{};
  layout_.value = *value;
  layout_.value_name = std::string(fields[*value].text);
  if (time) {
    layout_.time = *time;
    layout_.time_name = std::string(fields[*time].text);
    layout_.time_unit = unit;
  }
  layout_.fields = std::max(layout_.value, layout_.time.value_or(0)) + 1;
  delimiter_ = delimiter;
  header_text_ = std::string(trim(text));
  started_ = true;
  reading_.columns_from = "header";
  reading_.header_line = number;
  reading_.first_line = number;
  reading_.time_column = layout_.time && options_.rate_hz == 0.0 ? layout_.time_name : "";
  reading_.adc_column = layout_.value_name;
  set_unit();
  return true;
}

// The lines of numbers seen so far begin the log: their fields are, in order, the time and the
// value (or the value alone).
void HallLogReader::start_by_position() {
  const Candidate& first = candidates_.front();
  const SourceLocation at{name_, first.number, 0};
  if (first.fields == 1 && options_.rate_hz == 0.0)
    throw LogReadingError(at, "one number per line and no header: ADC values without times",
                          "give the sample rate with " + field_ref("rate") + " (for example " +
                              field_ref("rate", "1kHz") +
                              ": the sketch's delay between samples) or, if the numbers are "
                              "times, name the fields with " +
                              field_ref("columns"),
                          {try_rate(options_, 1000.0, "1kHz", kGuessedRate)});
  if (first.fields > 2)
    throw LogReadingError(at, std::to_string(first.fields) + " numbers per line and no header",
                          "say which field is the time and which the ADC value with " +
                              field_ref("columns") + " (for example " +
                              field_ref("columns", "t_ms,adc,_") + " for the first two)",
                          column_tries(options_, first.fields));
  layout_ = ColumnLayout{};
  if (first.fields == 1) {
    layout_.value = 0;
    layout_.fields = 1;
    layout_.value_name = "field 1";
  } else {
    // The time is the field that increases (the first, unless only the second does).
    std::vector<std::vector<double>> columns(2);
    for (const Candidate& c : candidates_) {
      const std::vector<LogField> fields = split_fields(c.text, c.delimiter);
      for (std::size_t i = 0; i < 2; ++i) {
        double v = 0.0;
        parse_log_number(fields[i].text, c.delimiter, &v, nullptr);
        columns[i].push_back(v);
      }
    }
    const auto increasing = [](const std::vector<double>& v) {
      return std::adjacent_find(v.begin(), v.end(), std::greater_equal<>()) == v.end();
    };
    const std::size_t time = !increasing(columns[0]) && increasing(columns[1]) ? 1 : 0;
    layout_.time = time;
    layout_.value = 1 - time;
    layout_.fields = 2;
    layout_.time_name = "field " + std::to_string(time + 1);
    layout_.value_name = "field " + std::to_string(2 - time);
  }
  delimiter_ = first.delimiter;
  started_ = true;
  reading_.columns_from = "position";
  reading_.first_line = first.number;
  reading_.time_column = layout_.time && options_.rate_hz == 0.0 ? layout_.time_name : "";
  reading_.adc_column = layout_.value_name;
  set_unit();
  const std::vector<Candidate> lines = std::exchange(candidates_, {});
  for (const Candidate& c : lines) data_line(c.text, c.offset, c.number, false);
}

void HallLogReader::skip(std::string_view text) {
  if (reading_.lines_skipped++ == 0) first_skipped_ = std::string(trim(text));
}

void HallLogReader::set_unit() {
  if (options_.rate_hz > 0.0) {
    scale_ = 1.0;
    reading_.time_unit = "";
    reading_.time_unit_from = "rate";
    reading_.rate_hz = options_.rate_hz;
  } else if (!options_.time_unit.empty()) {
    scale_ = seconds_per(options_.time_unit);
    reading_.time_unit = options_.time_unit;
    reading_.time_unit_from = "time_unit";
  } else if (!layout_.time_unit.empty()) {
    scale_ = seconds_per(layout_.time_unit);
    reading_.time_unit = layout_.time_unit;
    reading_.time_unit_from = reading_.columns_from;
  } else {
    scale_ = 0.0;  // inferred from the first samples
  }
}

bool HallLogReader::is_header_again(std::string_view content) const {
  return !header_text_.empty() && content == header_text_;
}

void HallLogReader::data_line(std::string_view text, std::size_t offset, int number,
                              bool unfinished) {
  const std::vector<LogField> fields = split_fields(text, delimiter_, offset);
  const bool timed_by_rate = options_.rate_hz > 0.0;
  // What is wrong with the line, if anything; its message is written for the first one only (a
  // log of garbage has millions).
  enum class Fault { kNone, kFields, kValueNotNumber, kValueRange, kTimeNotNumber };
  Fault fault = Fault::kNone;
  double t = 0.0;
  double value = 0.0;
  int time_column = 0;
  if (fields.size() < layout_.fields) {
    fault = Fault::kFields;
  } else {
    const LogField& vf = fields[layout_.value];
    if (!parse_log_number(vf.text, delimiter_, &value, &reading_.decimal_comma)) {
      fault = Fault::kValueNotNumber;
    } else if (value < 0.0 || value > 65535.0) {
      fault = Fault::kValueRange;
    } else if (layout_.time && !timed_by_rate) {
      const LogField& tf = fields[*layout_.time];
      time_column = tf.column;
      if (!parse_log_number(tf.text, delimiter_, &t, &reading_.decimal_comma))
        fault = Fault::kTimeNotNumber;
    }
  }
  if (fault != Fault::kNone) {
    // A capture stopped in the middle of a line: its unfinished last line is left out.
    if (unfinished) {
      reading_.unfinished_last_line = true;
      return;
    }
    ++reading_.data_lines;
    reading_.corrupted.add(number);
    if (first_corrupted_.line == 0) {
      const LogField* vf = fields.size() > layout_.value ? &fields[layout_.value] : nullptr;
      switch (fault) {
        case Fault::kFields:
          first_corrupted_ = {
              number, 0,
              "expected at least " + std::to_string(layout_.fields) + " fields (the " +
                  (layout_.time ? "time in field " + std::to_string(*layout_.time + 1) + " and the "
                                : std::string()) +
                  "ADC value in field " + std::to_string(layout_.value + 1) + "), found " +
                  std::to_string(fields.size()) + ": " + quoted_for_message(trim(text))};
          break;
        case Fault::kValueNotNumber:
          first_corrupted_ = {number, vf->column,
                              "column " + quoted_for_message(layout_.value_name) +
                                  ": expected a number, found " + quoted_for_message(vf->text)};
          break;
        case Fault::kValueRange:
          first_corrupted_ = {number, vf->column,
                              "column " + quoted_for_message(layout_.value_name) +
                                  ": expected an ADC value from 0 to 65535 counts, found " +
                                  shown_number(value)};
          break;
        case Fault::kTimeNotNumber: {
          const LogField& tf = fields[*layout_.time];
          first_corrupted_ = {number, tf.column,
                              "column " + quoted_for_message(layout_.time_name) +
                                  ": expected a number, found " + quoted_for_message(tf.text)};
          break;
        }
        case Fault::kNone:
          break;
      }
    }
    if (timed_by_rate) ++rate_index_;  // the sample was taken, its line garbled
    return;
  }
  ++reading_.data_lines;
  const auto adc = static_cast<std::uint16_t>(std::lround(value));
  if (timed_by_rate) {
    const double at = static_cast<double>(rate_index_++) / options_.rate_hz;
    ++segment_samples_;
    emit(at, adc, number);
    return;
  }
  timed(t, adc, number, time_column);
}

// Keeps the samples in time order: a sample waits until the next one confirms it.
void HallLogReader::timed(double reading, std::uint16_t adc, int line, int column) {
  const Raw* last = pending_ ? &*pending_ : confirmed_ ? &*confirmed_ : nullptr;
  const auto unwrap = [&](const Raw* before, double offset) {
    // A reading more than half a wrap below a 32-bit clock's previous one: the clock wrapped.
    if (before != nullptr && reading + kHalfWrap < before->reading && before->reading < kWrap)
      return offset + kWrap;
    return offset;
  };
  double offset = unwrap(last, wrap_offset_);
  Raw s{reading + offset, reading, wrap_offset_, adc, line, column};
  if (!pending_) {
    pending_ = s;
    lines_at_time_ = 1;
    if (offset != wrap_offset_) ++reading_.clock_wraps;
    wrap_offset_ = offset;
    return;
  }
  const std::string unit = reading_.time_unit.empty() ? "" : " " + reading_.time_unit;
  if (s.t > pending_->t) {
    confirm(*pending_);
    pending_ = s;
    lines_at_time_ = 1;
    if (offset != wrap_offset_) ++reading_.clock_wraps;
    wrap_offset_ = offset;
  } else if (s.t == pending_->t) {
    ++lines_at_time_;
    reading_.repeated_times.add(line);
    if (first_repeated_.line == 0)
      first_repeated_ = {line, column,
                         "time " + shown_number(reading) + unit +
                             " repeats the previous sample's (line " +
                             std::to_string(pending_->line) + ")"};
  } else if (!confirmed_ || s.t > confirmed_->t) {
    // The sample held back jumped ahead of its neighbours (a garbled time): it goes.
    reading_.out_of_order.add(pending_->line);
    if (first_out_of_order_.line == 0)
      first_out_of_order_ = {pending_->line, pending_->column,
                             "time " + shown_number(pending_->reading) + unit +
                                 " is ahead of the next sample's " + shown_number(reading) + unit +
                                 " (line " + std::to_string(line) + ")"};
    if (pending_->offset != wrap_offset_) --reading_.clock_wraps;
    wrap_offset_ = pending_->offset;
    offset = unwrap(confirmed_ ? &*confirmed_ : nullptr, wrap_offset_);
    s = Raw{reading + offset, reading, wrap_offset_, adc, line, column};
    pending_ = s;
    if (offset != wrap_offset_) ++reading_.clock_wraps;
    wrap_offset_ = offset;
  } else {
    reading_.out_of_order.add(line);
    if (first_out_of_order_.line == 0)
      first_out_of_order_ = {line, column,
                             "time " + shown_number(reading) + unit +
                                 " is not after the previous " + "sample's " +
                                 shown_number(pending_->reading) + unit + " (line " +
                                 std::to_string(pending_->line) + ")"};
  }
}

void HallLogReader::confirm(const Raw& sample) {
  confirmed_ = sample;
  ++segment_samples_;
  if (scale_ > 0.0) {
    emit(sample.t * scale_, sample.adc, sample.line);
    return;
  }
  held_.push_back(sample);
  if (held_.size() >= kUnitSamples) infer_unit();
}

void HallLogReader::emit(double t, std::uint16_t adc, int line) {
  // The time the samples span, run by run (a restarted board's clock starts again).
  if (emitted_ > 0 && last_segment_ == segment_) span_s_ += t - last_t_s_;
  ++emitted_;
  last_t_s_ = t;
  last_segment_ = segment_;
  out_.push_back({t, adc, line, segment_});
}

// The unit that makes the median interval a sample rate of 20 Hz to 20 kHz.
void HallLogReader::infer_unit() {
  if (held_.empty()) return;
  std::vector<double> steps;
  for (std::size_t i = 1; i < held_.size(); ++i) steps.push_back(held_[i].t - held_[i - 1].t);
  std::string unit = "s";
  if (!steps.empty()) {
    std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
    const double step = steps[steps.size() / 2];
    std::string found;
    for (const char* u : {"s", "ms", "us"}) {
      const double rate = 1.0 / (step * seconds_per(u));
      if (rate >= kLowestRate && rate < kHighestRate) found = u;
    }
    if (found.empty()) {
      std::ostringstream rates;
      rates.precision(3);
      rates << 1.0 / step << " Hz in seconds, " << 1e3 / step << " Hz in milliseconds, "
            << 1e6 / step << " Hz in microseconds";
      throw LogReadingError(
          SourceLocation{name_, held_.front().line, 0},
          "the time column " + quoted_for_message(layout_.time_name) +
              " names no unit, and its step of " + shown_number(step) +
              " per sample fits none: expected a sample rate from 20 Hz to 20 kHz, found " +
              rates.str(),
          "give the unit with " + field_ref("time_unit") +
              " (us, ms or s), or the sample rate with " + field_ref("rate"),
          {try_time_unit(options_, "us"), try_time_unit(options_, "ms"),
           try_time_unit(options_, "s")});
    }
    unit = found;
  }
  scale_ = seconds_per(unit);
  reading_.time_unit = unit;
  reading_.time_unit_from = "inferred";
  for (const Raw& r : std::exchange(held_, {})) emit(r.t * scale_, r.adc, r.line);
}

void HallLogReader::new_segment() {
  if (pending_) confirm(*pending_);
  pending_.reset();
  confirmed_.reset();
  if (scale_ == 0.0) infer_unit();
  wrap_offset_ = 0.0;
  rate_index_ = 0;
  ++segment_;
  segment_samples_ = 0;
}

std::optional<HallLogReader::PlotterLine> HallLogReader::plotter_line(std::string_view content) {
  PlotterLine out;
  std::size_t pos = 0;
  int pairs = 0;
  while (pos < content.size()) {
    const std::size_t end = content.find_first_of("\t ,", pos);
    const std::string_view token =
        content.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
    pos = end == std::string_view::npos ? content.size() : end + 1;
    if (token.empty()) continue;
    const std::size_t colon = token.find(':');
    if (colon == 0 || colon == std::string_view::npos) return std::nullopt;
    const std::string_view label = token.substr(0, colon);
    const std::string_view value = token.substr(colon + 1);
    for (const char c : label)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return std::nullopt;
    double v = 0.0;
    if (!parse_log_number(value, ',', &v, nullptr)) return std::nullopt;
    out.header += (pairs == 0 ? "" : ",") + std::string(label);
    out.values += (pairs == 0 ? "" : ",") + std::string(value);
    ++pairs;
  }
  if (pairs < 1) return std::nullopt;
  return out;
}

void HallLogReader::throw_doubtful() const {
  throw LogReadingError(SourceLocation{name_, doubtful_->number, 0}, doubtful_->problem,
                        doubtful_->advice, {try_rate(options_, 1000.0, "1kHz", kGuessedRate)});
}

void HallLogReader::finish() {
  if (!started_ && !candidates_.empty()) start_by_position();
  if (pending_) confirm(*pending_);
  pending_.reset();
  if (scale_ == 0.0) infer_unit();
  reading_.segments = segment_ + 1;
  if (!started_ && doubtful_) throw_doubtful();
  if (!started_) {
    const SourceLocation top{name_, 1, 0};
    if (reading_.lines_skipped == 0 && reading_.comment_lines == 0)
      throw InputError(top, said("reading-empty", {arg("expected", said("reading-expected"))}));
    if (reading_.lines_skipped == 0)
      throw InputError(top,
                       said("reading-only-comments", {arg("expected", said("reading-expected"))}));
    throw LogReadingError(
        top,
        said("reading-no-sample-line",
             {arg("lines", reading_.lines_skipped), arg("expected", said("reading-expected")),
              arg("example", quoted_for_message(first_skipped_))}),
        "for a log without a header, name its fields in order with " + field_ref("columns") +
            " (for example " + field_ref("columns", "t,adc") + ")",
        {try_columns(options_, "t,adc")});
  }
  check_shares();
}

// Lines left out beyond 10 % of the log: the log is not what the reader takes it for.
void HallLogReader::check_shares() const {
  const int bad =
      reading_.corrupted.count + reading_.repeated_times.count + reading_.out_of_order.count;
  const int lines = reading_.data_lines;
  if (lines == 0)
    throw InputError(SourceLocation{name_, reading_.first_line, 0},
                     layout_.time
                         ? said("reading-no-samples-timed",
                                {arg("time", layout_.time_name), arg("value", layout_.value_name)})
                         : said("reading-no-samples", {arg("value", layout_.value_name)}));
  if (bad * 10 <= lines) return;
  const std::string share =
      std::to_string(bad) + " of the " + std::to_string(lines) + " lines after the " +
      (reading_.header_line != 0 ? "header" : "first sample") + " (" + percent(bad, lines) +
      ") are left out, more than the 10 % the reader "
      "skips: ";
  const int corrupted = reading_.corrupted.count;
  const int repeated = reading_.repeated_times.count;
  const int back = reading_.out_of_order.count;
  if (corrupted >= repeated && corrupted >= back) {
    const Problem& p = first_corrupted_;
    throw LogReadingError(
        SourceLocation{name_, p.line, p.column},
        p.what + "; " + share + std::to_string(corrupted) +
            " are not samples. Is the log what it seems? A serial capture at the wrong baud rate "
            "gives garbled lines (the rig firmware's is 250000)",
        "a log whose fields are not (time, value) needs " + field_ref("columns") +
            " (for example " + field_ref("columns", "_,t,adc") + ")",
        {try_columns(options_, "_,t,adc")});
  }
  if (repeated >= back) {
    const Problem& p = first_repeated_;
    // The rate the log's own clock gives: its lines over its span.
    std::vector<ReadingTry> tries;
    std::string example = "1kHz";
    if (emitted_ >= 2 && span_s_ > 0.0 && lines > lines_at_time_) {
      // The log's lines over the time its samples span, from the first time to the last (the
      // lines at the last time come after it): the rate that gives the log's own clock's
      // period. To three significant digits: 500Hz, 2000Hz.
      const double hz = static_cast<double>(lines - lines_at_time_) / span_s_;
      const double digit = std::pow(10.0, std::floor(std::log10(hz)) - 2.0);
      const double rounded = std::round(hz / digit) * digit;
      std::ostringstream rate;
      rate << rounded << "Hz";
      example = rate.str();
      tries.push_back(try_rate(options_, rounded, example,
                               "the rate its clock gives, its lines over its span"));
    }
    throw LogReadingError(
        SourceLocation{name_, p.line, p.column},
        p.what + "; " + share + std::to_string(repeated) +
            " repeat the time before them: the log's clock ticks more slowly than it samples "
            "(millis() counts whole milliseconds)",
        "give the sample rate with " + field_ref("rate") + " (for example " +
            field_ref("rate", example) + ") to time the samples by their count, or log micros()",
        std::move(tries));
  }
  const Problem& p = first_out_of_order_;
  throw LogReadingError(SourceLocation{name_, p.line, p.column},
                        p.what + ": the times must increase; " + share + std::to_string(back) +
                            " are out of order: the log mixes captures or its clock went back",
                        "take one capture, or give the sample rate with " + field_ref("rate") +
                            " (for example " + field_ref("rate", "1kHz") +
                            ") to time the samples by their count",
                        {try_rate(options_, 1000.0, "1kHz", kGuessedRate)});
}

std::vector<LogSample> HallLogReader::take() {
  return std::exchange(out_, {});
}

void HallLogReader::take(std::vector<LogSample>& into) {
  into.insert(into.end(), out_.begin(), out_.end());
  out_.clear();
}

}  // namespace fl
