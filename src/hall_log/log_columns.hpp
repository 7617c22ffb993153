// The names of a Hall-sensor log's columns, as loggers and Arduino sketches write them: the time
// (t_us, t_ms, t_s, time, timestamp, millis, micros, "time (ms)", ...) with the unit its name
// gives, if any, and the ADC value (adc, value, sensorValue, analogRead(A0), "ADC Value", hall,
// ...). The same names say which field is which in `--columns` for a log without a header.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl {

enum class ColumnRole { kTime, kValue, kSkip };

struct ColumnName {
  ColumnRole role = ColumnRole::kSkip;
  std::string unit;  // a time's unit from its name: "s", "ms", "us", or "" when it gives none
};

// What a header's name stands for; nullopt for a name that is neither a time nor a value.
std::optional<ColumnName> column_name(std::string_view name);

// The names, for messages: "t_us, t_ms, t_s, time, timestamp, millis or micros ...".
extern const std::string_view kTimeNames;
extern const std::string_view kValueNames;

// Which field holds what (0-based), and the names that said so.
struct ColumnLayout {
  std::optional<std::size_t> time;  // none: the samples are timed by --rate
  std::size_t value = 0;
  std::size_t fields = 0;  // fields a data line needs
  std::string time_name;
  std::string value_name;
  std::string time_unit;  // from the time's name ("" when it gives none)
};

// `--columns`: the log's fields in order, each a time name, a value name, or "_" (or "-", "x",
// "skip") for a field to ignore: "t_us,adc", "adc,millis", "_,time,value", "sensorValue". Throws
// InputError (located at the option) for a list without exactly one value and at most one time.
ColumnLayout columns_from_option(std::string_view spec);

// "s", "ms", "us" from what `--time-unit` or a user may write ("us", "µs", "micros", "ms",
// "millis", "s", "sec"), nullopt otherwise.
std::optional<std::string> time_unit_name(std::string_view text);

// Seconds per unit of time: 1e-6 for "us", 1e-3 for "ms", 1 for "s".
double seconds_per(const std::string& unit);

}  // namespace fl
