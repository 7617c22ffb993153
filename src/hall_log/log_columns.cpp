#include "hall_log/log_columns.hpp"

#include <algorithm>
#include <array>

#include "io/field_ref.hpp"
#include "io/input_error.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

// Letters and digits only, lower case: "ADC Value" -> "adcvalue", "analogRead(A0)" ->
// "analogreada0".
std::string letters_and_digits(std::string_view s) {
  std::string out;
  for (char c : ascii_lower(s))
    if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) out += c;
  return out;
}

// A unit as a time column's name writes it after its base ("_us", " (ms)", "[s]").
std::optional<std::string> unit_suffix(std::string_view rest) {
  while (!rest.empty() && (rest.front() == '_' || rest.front() == '-' || rest.front() == ' ' ||
                           rest.front() == '(' || rest.front() == '[' || rest.front() == '/')) {
    rest.remove_prefix(1);
  }
  while (!rest.empty() && (rest.back() == ')' || rest.back() == ']' || rest.back() == ' ')) {
    rest.remove_suffix(1);
  }
  if (rest.empty()) return std::string();
  return time_unit_name(rest);
}

std::optional<std::string> time_unit_of(std::string_view header) {
  std::string name = ascii_lower(trim(header, kFieldPadding));
  if (name.size() > 2 && name.compare(name.size() - 2, 2, "()") == 0) name.resize(name.size() - 2);
  if (name == "micros" || name == "us" || name == "\xC2\xB5s") return std::string("us");
  if (name == "millis" || name == "ms") return std::string("ms");
  for (std::string_view base : {"timestamp", "elapsed", "time", "ts", "t"}) {
    if (name.rfind(base, 0) != 0) continue;
    if (auto unit = unit_suffix(std::string_view(name).substr(base.size()))) return unit;
  }
  return std::nullopt;
}

bool is_value_name(std::string_view header) {
  static constexpr std::array<std::string_view, 31> kNames = {
      "adc",     "adcvalue",    "adcval",       "adcreading",    "adccounts",    "value",
      "val",     "sensorvalue", "sensorval",    "sensorreading", "sensor",       "hall",
      "halladc", "hallvalue",   "hallsensor",   "hallsignal",    "a0",           "a1",
      "a2",      "a3",          "analogreada0", "analogreada1",  "analogreada2", "analogread",
      "analog",  "analogvalue", "raw",          "rawvalue",      "counts",       "reading",
      "signal"};
  const std::string name = letters_and_digits(header);
  return std::find(kNames.begin(), kNames.end(), name) != kNames.end();
}

bool is_skip_name(std::string_view name) {
  const std::string n = ascii_lower(trim(name, kFieldPadding));
  return n.empty() || n == "_" || n == "-" || n == "x" || n == "skip";
}

}  // namespace

const std::string_view kTimeNames =
    "t_us, t_ms, t_s, t, time, timestamp, elapsed, millis or micros (a unit may follow, as in "
    "\"time (ms)\")";
const std::string_view kValueNames =
    "adc, value, sensorValue, analogRead(A0), \"ADC Value\", hall, a0, raw, analog, counts, "
    "reading, sensor or signal";

std::optional<std::string> time_unit_name(std::string_view text) {
  const std::string unit = ascii_lower(trim(text));
  if (unit == "s" || unit == "sec" || unit == "secs" || unit == "second" || unit == "seconds")
    return std::string("s");
  if (unit == "ms" || unit == "msec" || unit == "millis" || unit == "milliseconds")
    return std::string("ms");
  if (unit == "us" || unit == "\xC2\xB5s" || unit == "usec" || unit == "micros" ||
      unit == "microseconds")
    return std::string("us");
  return std::nullopt;
}

std::optional<ColumnName> column_name(std::string_view name) {
  if (auto unit = time_unit_of(name)) return ColumnName{ColumnRole::kTime, *unit};
  if (is_value_name(name)) return ColumnName{ColumnRole::kValue, ""};
  return std::nullopt;
}

ColumnLayout columns_from_option(std::string_view spec) {
  const auto fail = [&](const std::string& what) {
    return InputError(SourceLocation::of_field("columns"),
                      what + ", found \"" + std::string(spec) +
                          "\"; name the log's fields in order, for example " +
                          field_ref("columns", "t_us,adc") + ", " +
                          field_ref("columns", "millis,sensorValue") + " or " +
                          field_ref("columns", "_,t_ms,adc"));
  };
  ColumnLayout layout;
  std::size_t index = 0;
  std::size_t start = 0;
  bool have_value = false;
  for (;;) {
    const std::size_t end = spec.find(',', start);
    const std::string_view name =
        trim(spec.substr(start, end == spec.npos ? spec.npos : end - start));
    if (!is_skip_name(name)) {
      const std::optional<ColumnName> role = column_name(name);
      if (!role)
        throw fail("expected each field a time name (" + std::string(kTimeNames) +
                   "), a value name (" + std::string(kValueNames) + ") or _ to skip it; \"" +
                   std::string(name) + "\" is neither");
      if (role->role == ColumnRole::kTime) {
        if (layout.time) throw fail("expected at most one time column");
        layout.time = index;
        layout.time_name = std::string(name);
        layout.time_unit = role->unit;
      } else {
        if (have_value) throw fail("expected one value column");
        have_value = true;
        layout.value = index;
        layout.value_name = std::string(name);
      }
    }
    ++index;
    if (end == spec.npos) break;
    start = end + 1;
  }
  if (!have_value) throw fail("expected a value column (adc, value, ...)");
  layout.fields = std::max(layout.value, layout.time.value_or(0)) + 1;
  return layout;
}

double seconds_per(const std::string& unit) {
  return unit == "us" ? 1e-6 : unit == "ms" ? 1e-3 : 1.0;
}

}  // namespace fl
