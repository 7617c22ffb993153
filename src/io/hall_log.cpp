#include "io/hall_log.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <sstream>
#include <system_error>

#include "core/micros_clock.hpp"
#include "core/text.hpp"
#include "io/input_error.hpp"
#include "io/text_file.hpp"

namespace fl {
namespace {

struct Field {
  std::string_view text;
  int column = 0;  // 1-based
};

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// Around a field: blanks and quotes.
constexpr std::string_view kPadding = " \t\r\"'";

// Splits a line at `delimiter` (0: runs of spaces or tabs), keeping each field's column.
std::vector<Field> split(std::string_view line, char delimiter) {
  std::vector<Field> out;
  std::size_t i = 0;
  if (delimiter == 0) {
    while (i < line.size()) {
      while (i < line.size() && is_space(line[i])) ++i;
      if (i >= line.size()) break;
      const std::size_t start = i;
      while (i < line.size() && !is_space(line[i])) ++i;
      out.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return out;
  }
  for (;;) {
    const std::size_t end = line.find(delimiter, i);
    const std::string_view raw =
        line.substr(i, end == std::string_view::npos ? line.npos : end - i);
    std::size_t lead = 0;
    while (lead < raw.size() && is_space(raw[lead])) ++lead;
    out.push_back({trim(raw, kPadding), static_cast<int>(i + lead) + 1});
    if (end == std::string_view::npos) break;
    i = end + 1;
  }
  return out;
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) {
    return static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  });
  return out;
}

// The unit of a time column's name ("t_us" -> "us", "time (s)" -> "s", "t" -> "s"), or "" when
// the name is not a time column's.
std::string time_unit_of(std::string_view header) {
  const std::string name = lower(trim(header, kPadding));
  if (name == "micros") return "us";
  if (name == "millis") return "ms";
  for (std::string_view base : {"timestamp", "time", "ts", "t"}) {
    if (name.rfind(base, 0) != 0) continue;
    std::string_view rest = std::string_view(name).substr(base.size());
    while (!rest.empty() && (rest.front() == '_' || rest.front() == '-' || rest.front() == ' ' ||
                             rest.front() == '(' || rest.front() == '[' || rest.front() == '/')) {
      rest.remove_prefix(1);
    }
    while (!rest.empty() && (rest.back() == ')' || rest.back() == ']' || rest.back() == ' ')) {
      rest.remove_suffix(1);
    }
    if (rest.empty() || rest == "s" || rest == "sec" || rest == "secs" || rest == "second" ||
        rest == "seconds")
      return "s";
    if (rest == "ms" || rest == "msec" || rest == "millis" || rest == "milliseconds") return "ms";
    if (rest == "us" || rest == "\xC2\xB5s" || rest == "usec" || rest == "micros" ||
        rest == "microseconds")
      return "us";
  }
  return "";
}

bool is_adc_name(std::string_view header) {
  static constexpr std::array<std::string_view, 14> kNames = {
      "adc", "value",  "val",    "hall",   "hall_adc", "adc_value",  "a0",
      "raw", "analog", "counts", "sensor", "reading",  "analogread", "signal"};
  const std::string name = lower(trim(header, kPadding));
  return std::find(kNames.begin(), kNames.end(), name) != kNames.end();
}

bool parse_number(std::string_view text, double* out) {
  text = trim(text, kPadding);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), *out);
  return ec == std::errc() && end == text.data() + text.size() && std::isfinite(*out);
}

std::string quoted(std::string_view s) {
  constexpr std::size_t kMax = 60;
  std::string out = "\"";
  out += s.size() > kMax ? std::string(s.substr(0, kMax)) + "..." : std::string(s);
  out += '"';
  return out;
}

// A number as the log wrote it, for messages.
std::string shown(double v) {
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

// Microseconds since the first sample on a 32-bit clock, as the firmware counts them.
void stamp_rig_clock(HallLog& log) {
  const double t0 = log.t_s.front();
  log.t_us.reserve(log.t_s.size());
  for (double t : log.t_s) {
    const auto us = static_cast<uint64_t>(std::llround((t - t0) * 1e6));
    log.t_us.push_back(static_cast<uint32_t>(us & 0xFFFFFFFFu));
  }
}

constexpr std::string_view kExpected =
    "a header naming the time and ADC columns (for example \"t_us,adc\", \"t_s,adc\" or "
    "\"time,value\")";

}  // namespace

HallLog parse_hall_log(std::string_view text, const std::string& name) {
  HallLog log;
  log.path = name;
  log.format = "csv";
  auto fail = [&](int line, int column, const std::string& what) -> InputError {
    return InputError(SourceLocation{name, line, column}, what);
  };

  char delimiter = 0;
  std::size_t time_index = 0;
  std::size_t adc_index = 0;
  std::size_t fields_needed = 0;
  double scale = 1.0;  // seconds per unit of the time column
  MicrosClock clock;   // a microsecond column may be the firmware's wrapping clock
  double previous_raw = 0.0;
  int previous_line = 0;
  int line_number = 0;
  bool comments_only = true;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    std::size_t first = 0;
    while (first < line.size() && is_space(line[first])) ++first;
    if (first == line.size()) continue;
    if (line[first] == '#') {
      if (line.substr(first).rfind("# frictionlab rig firmware", 0) == 0) log.format = "firmware";
      continue;
    }
    comments_only = false;

    if (log.header_line == 0) {
      delimiter = line.find(',') != line.npos    ? ','
                  : line.find(';') != line.npos  ? ';'
                  : line.find('\t') != line.npos ? '\t'
                                                 : 0;
      const std::vector<Field> header = split(line, delimiter);
      bool all_numbers = true;
      for (const Field& f : header) {
        double v = 0.0;
        all_numbers = all_numbers && parse_number(f.text, &v);
      }
      if (all_numbers)
        throw fail(line_number, static_cast<int>(first) + 1,
                   "expected " + std::string(kExpected) + ", found numbers: " + quoted(line));
      bool have_time = false;
      bool have_adc = false;
      for (std::size_t i = 0; i < header.size(); ++i) {
        const std::string unit = time_unit_of(header[i].text);
        if (!have_time && !unit.empty()) {
          have_time = true;
          time_index = i;
          log.time_column = std::string(header[i].text);
          log.time_unit = unit;
        } else if (!have_adc && is_adc_name(header[i].text)) {
          have_adc = true;
          adc_index = i;
          log.adc_column = std::string(header[i].text);
        }
      }
      if (!have_time)
        throw fail(line_number, 0,
                   "the header " + quoted(line) +
                       " names no time column: expected one called t_us, t_ms, t_s, time, "
                       "timestamp or micros (a unit may follow, as in \"time (ms)\")");
      if (!have_adc)
        throw fail(line_number, 0,
                   "the header " + quoted(line) +
                       " names no ADC column: expected one called adc, value, hall, a0, raw, "
                       "analog, counts, reading, sensor or signal");
      scale = log.time_unit == "us" ? 1e-6 : log.time_unit == "ms" ? 1e-3 : 1.0;
      fields_needed = std::max(time_index, adc_index) + 1;
      log.header_line = line_number;
      continue;
    }

    const std::vector<Field> fields = split(line, delimiter);
    // A capture stopped in the middle of a line: its unfinished last line is left out.
    const bool unfinished = end == text.size();
    if (unfinished) {
      double v = 0.0;
      const bool complete = fields.size() >= fields_needed &&
                            parse_number(fields[time_index].text, &v) &&
                            parse_number(fields[adc_index].text, &v);
      if (!complete) {
        log.unfinished_last_line = true;
        break;
      }
    }
    if (fields.size() < fields_needed)
      throw fail(line_number, 0,
                 "expected at least " + std::to_string(fields_needed) +
                     " fields, as the header has the time in field " +
                     std::to_string(time_index + 1) + " and the ADC value in field " +
                     std::to_string(adc_index + 1) + ", found " + std::to_string(fields.size()) +
                     ": " + quoted(line));
    const Field& tf = fields[time_index];
    const Field& af = fields[adc_index];
    double t_raw = 0.0;
    double value = 0.0;
    if (!parse_number(tf.text, &t_raw))
      throw fail(
          line_number, tf.column,
          "column " + quoted(log.time_column) + ": expected a number, found " + quoted(tf.text));
    if (!parse_number(af.text, &value))
      throw fail(
          line_number, af.column,
          "column " + quoted(log.adc_column) + ": expected a number, found " + quoted(af.text));
    if (value < 0.0 || value > 65535.0)
      throw fail(line_number, af.column,
                 "column " + quoted(log.adc_column) +
                     ": expected an ADC value from 0 to 65535 counts, found " + shown(value));
    const double t = (log.time_unit == "us" ? clock.advance(t_raw) : t_raw) * scale;
    if (!log.t_s.empty() && !(t > log.t_s.back()))
      throw fail(line_number, tf.column,
                 "time " + shown(t_raw) + " " + log.time_unit + " is not after the previous " +
                     "sample's " + shown(previous_raw) + " " + log.time_unit + " (line " +
                     std::to_string(previous_line) + "): the times must increase");
    log.t_s.push_back(t);
    log.adc.push_back(static_cast<uint16_t>(std::lround(value)));
    log.line.push_back(line_number);
    previous_raw = t_raw;
    previous_line = line_number;
  }

  if (log.header_line == 0) {
    if (comments_only && line_number > 1)
      throw fail(1, 0, "the log has only comment lines: expected " + std::string(kExpected));
    throw fail(1, 0, "the log is empty: expected " + std::string(kExpected));
  }
  log.clock_wraps = clock.wraps();
  if (log.t_s.empty())
    throw fail(log.header_line, 0,
               "no samples after the header: expected lines of " + log.time_column + " and " +
                   log.adc_column + " values");
  stamp_rig_clock(log);
  return log;
}

HallLog hall_log_from_samples(std::vector<double> t_s, const std::vector<double>& adc,
                              const std::string& name) {
  const auto fail = [&](std::size_t sample, const std::string& what) -> InputError {
    return InputError(SourceLocation{name, static_cast<int>(sample), 0}, what);
  };
  if (t_s.size() != adc.size())
    throw fail(0, "expected as many ADC values as times, found " + std::to_string(adc.size()) +
                      " and " + std::to_string(t_s.size()));
  if (t_s.empty()) throw fail(0, "no samples");
  HallLog log;
  log.adc.reserve(adc.size());
  for (std::size_t i = 0; i < t_s.size(); ++i) {
    if (!(adc[i] >= 0.0 && adc[i] <= 65535.0))
      throw fail(i + 1, "sample " + std::to_string(i + 1) +
                            ": expected an ADC value from 0 to 65535 counts, found " +
                            shown(adc[i]));
    log.adc.push_back(static_cast<uint16_t>(std::lround(adc[i])));
    if (!std::isfinite(t_s[i]))
      throw fail(i + 1, "sample " + std::to_string(i + 1) + ": time " + shown(t_s[i]) +
                            " s is not a finite number");
    if (i > 0 && !(t_s[i] > t_s[i - 1]))
      throw fail(i + 1, "sample " + std::to_string(i + 1) + ": time " + shown(t_s[i]) +
                            " s is not after the previous sample's " + shown(t_s[i - 1]) +
                            " s: the times must increase");
  }
  log.path = name;
  log.format = "samples";
  log.time_column = "t";
  log.adc_column = "adc";
  log.time_unit = "s";
  log.t_s = std::move(t_s);
  log.line.resize(log.t_s.size());
  for (std::size_t i = 0; i < log.line.size(); ++i) log.line[i] = static_cast<int>(i + 1);
  stamp_rig_clock(log);
  return log;
}

HallLog read_hall_log(const std::string& path) {
  return parse_hall_log(read_text_file(path, "the log"), path);
}

}  // namespace fl
