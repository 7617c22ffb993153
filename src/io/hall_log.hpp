// A Hall-sensor log of the real rig: the rig firmware's serial output (comment lines starting
// with '#', a "t_us,adc" header, one line per raw sample), or any CSV of time and ADC value. The
// columns are found by the header's names; the time may be in seconds, milliseconds or
// microseconds. Problems are reported as InputError located at the line (and column); only an
// unfinished last line (a capture stopped mid-line, with no newline after it) is left out.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace fl {

struct HallLog {
  std::string path;         // as given
  std::string format;       // "firmware" (the rig firmware's capture), "csv" or "samples"
  std::string time_column;  // the header's names of the two columns used
  std::string adc_column;
  std::string time_unit;       // "s", "ms" or "us"
  int header_line = 0;         // 1-based line of the header
  std::vector<double> t_s;     // sample times [s] on the log's own axis (wraps of a
                               // microsecond clock undone)
  std::vector<uint32_t> t_us;  // the same in microseconds since the first sample, on a 32-bit
                               // clock that wraps like the firmware's (for the estimator)
  std::vector<uint16_t> adc;   // ADC values [counts]
  std::vector<int> line;       // 1-based line of each sample
  int clock_wraps = 0;         // times a microsecond column wrapped around 2^32
  bool unfinished_last_line = false;  // the last line, cut off without a newline, was left out
};

// Reads and checks a log file; throws InputError ("file:line:col: error: ...") for a log that
// cannot be used: no header, no time or ADC column, a field that is not a number, times that do
// not increase, no samples.
HallLog read_hall_log(const std::string& path);

// The same from text in memory; `name` stands for the file in messages.
HallLog parse_hall_log(std::string_view text, const std::string& name);

// A log of samples already in memory (times in seconds on any axis, ADC values in counts),
// checked as a file's are: `name` stands for the file in messages and each sample's 1-based index
// for its line. Throws InputError for no samples, a length mismatch, times that are not finite or
// do not increase, or an ADC value outside 0 to 65535 (others are rounded, as a file's are).
HallLog hall_log_from_samples(std::vector<double> t_s, const std::vector<double>& adc,
                              const std::string& name);

}  // namespace fl
