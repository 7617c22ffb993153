// A Hall-sensor log of the real rig, read whole: the rig firmware's serial output (comment lines
// starting with '#', a "t_us,adc" header, one line per raw sample), a serial monitor's capture of
// any sketch (the Arduino IDE's, with or without its timestamps; arduino-cli's, with its banner),
// or any CSV of time and ADC value, from a file, a folder holding one, or standard input. The
// lines are read by HallLogReader (hall_log/hall_log_reader.hpp): what it skips and leaves out is
// counted in `reading`. The text may start with a byte-order mark (UTF-8, or UTF-16 from a
// spreadsheet's "Unicode text"), and its lines may end in "\n", "\r\n" or "\r".
// Another instrument's file is recognised by its content (hall_log/measurement_file.hpp) and read
// into the same log, one channel of it as counts the rig's estimator times: a phone's
// magnetometer (hall_log/phyphox_log.hpp), positions or a phone's accelerometer
// (hall_log/oscillation_log.hpp); `instrument` and `channel` say what was read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hall_log/hall_log_reader.hpp"
#include "hall_log/measurement_file.hpp"

namespace fl {

// The longest line a log may have [bytes]: its lines are a few dozen (a time and a value; a header
// of many columns, a Serial Plotter line of many labels: a few hundred). A longer one (a file
// without line ends, one number of megabytes) is refused as soon as it is read.
inline constexpr std::size_t kMostLogLineBytes = 8192;

struct HallLog {
  std::string path;        // as given ("<stdin>" for standard input)
  std::string file;        // the file read (a folder's log inside it)
  std::string encoding;    // "utf-8", "utf-8 with BOM", "utf-16le", "utf-16be"; "" for a video
  HallLogReading reading;  // columns, unit, and what was skipped or left out
  // What measured: the rig's Hall sensor (kRigLog), or another instrument read as one
  // (instrument_words names it).
  MeasurementFile instrument = MeasurementFile::kRigLog;
  std::string channel;  // the channel read of several ("x", "|B|"); "" for one
  // The amplitude of the channel read (its strongest oscillation's, hall_log/periodic_motion.hpp)
  // in `swing_unit`, for an instrument that follows the plate's position or its acceleration;
  // none for the Hall sensor and a magnetometer, whose pulses are no measure of the motion.
  std::optional<double> half_swing;
  std::string swing_unit;   // the column's ("m", "mm", "px", "m/s^2"); "" when its header says none
  std::vector<double> t_s;  // sample times [s] on the log's own axis (wraps of a
                            // microsecond clock undone)
  std::vector<uint32_t> t_us;        // the same in microseconds since the first sample, on a 32-bit
                                     // clock that wraps like the firmware's (for the estimator)
  std::vector<uint16_t> adc;         // ADC values [counts]
  std::vector<int> line;             // 1-based line of each sample
  int segment = 0;                   // the run of samples used (of reading.segments: the longest)
  int segment_samples_left_out = 0;  // samples in the other runs
};

// Reads and checks a log: a file, a folder (its hall.csv, or its only log), or "-" for standard
// input. Throws InputError ("file:line:col: error: ...") for a log that cannot be used.
HallLog read_hall_log(const std::string& path, const HallLogOptions& options = {});

// A log's bytes as read, not yet decoded: `file` is the file read (a folder's log inside it) or
// "<stdin>" for "-". Throws InputError as read_hall_log does for what cannot be read. A file that
// is no text is read_if_not_text's: every reader asks it first, and this reads what it declined.
struct LogText {
  std::string bytes;
  std::string file;
};
LogText read_log_text(const std::string& path);

// The file read for `path`: a folder's log (its hall.csv, or its only log), else the path itself
// ("-" as it is). Throws InputError, as reading does, for a folder without exactly one log.
std::string log_file_of(const std::string& path);

// The file recognised from its first and last bytes when it is no text (a zip, a workbook, a
// video: is_container); the rig's log (kRigLog) for any other, and for "-" or what cannot be read.
RecognisedFile recognise_file(const std::string& file);

// A file that is no text (a file, or a folder's only log) read as a log: a video, its plate
// tracked with `options.video`; a zip (phyphox's export), the instrument's CSV inside it. Nothing
// for a text file. Throws InputError as read_video_log and measurement_in_zip do, and for another
// container (a workbook), saying what to do instead (not_a_rig_log).
std::optional<HallLog> read_if_not_text(const std::string& path,
                                        const HallLogOptions& options = {});

// The same from text in memory; `name` stands for the file in messages.
HallLog parse_hall_log(std::string_view text, const std::string& name,
                       const HallLogOptions& options = {});

// A log of samples already in memory (times in seconds on any axis, ADC values in counts),
// checked as a file's are: `name` stands for the file in messages and each sample's 1-based index
// for its line. Throws InputError for no samples, a length mismatch, times that are not finite or
// do not increase, or an ADC value outside 0 to 65535 (others are rounded, as a file's are).
HallLog hall_log_from_samples(std::vector<double> t_s, const std::vector<double>& adc,
                              const std::string& name);

// The text as UTF-8 without a byte-order mark; `encoding` says what it was.
std::string decode_log_text(std::string_view bytes, std::string* encoding);

}  // namespace fl
