#include "hall_log/hall_log.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "hall_log/measurement_file.hpp"
#include "hall_log/measurement_zip.hpp"
#include "hall_log/oscillation_log.hpp"
#include "hall_log/phyphox_log.hpp"
#include "hall_log/video_log.hpp"
#include "io/input_error.hpp"
#include "io/text_file.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

// UTF-16 text of a spreadsheet's "Unicode text" export: the log's characters are ASCII, so each
// is kept from its code unit (any other becomes '?').
std::string from_utf16(std::string_view bytes, bool little_endian) {
  std::string out;
  out.reserve(bytes.size() / 2);
  for (std::size_t i = 0; i + 1 < bytes.size(); i += 2) {
    const auto lo = static_cast<unsigned char>(bytes[little_endian ? i : i + 1]);
    const auto hi = static_cast<unsigned char>(bytes[little_endian ? i + 1 : i]);
    out += hi == 0 && lo < 0x80 ? static_cast<char>(lo) : '?';
  }
  return out;
}

// The log a folder holds: hall.csv (a simulated run's outputs), or its only .csv, .txt, .log or
// .tsv file.
std::string log_in_folder(const std::string& folder) {
  namespace fs = std::filesystem;
  const fs::path dir(folder);
  if (fs::is_regular_file(dir / "hall.csv")) return (dir / "hall.csv").string();
  std::vector<std::string> logs;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".csv" || ext == ".txt" || ext == ".log" || ext == ".tsv"))
      logs.push_back(e.path().string());
  }
  std::sort(logs.begin(), logs.end());
  if (logs.size() == 1) return logs.front();
  if (logs.empty())
    throw InputError(SourceLocation{folder, 0, 0},
                     "expected a folder holding a log (hall.csv, or one .csv, .txt, .log or .tsv "
                     "file), found none: give the log's file");
  std::string names;
  for (std::size_t i = 0; i < logs.size() && i < 4; ++i)
    names += (i > 0 ? ", " : "") + fs::path(logs[i]).filename().string();
  if (logs.size() > 4) names += ", ...";
  throw InputError(SourceLocation{folder, 0, 0},
                   "expected a folder holding one log, found " + std::to_string(logs.size()) +
                       " (" + names + "): give the log's file, for example " + logs.front());
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

// The text as UTF-8 without a byte-order mark: a view into `bytes` for UTF-8 (no copy of a large
// log), else into `storage`, which holds the text decoded from UTF-16.
std::string_view decoded_text(std::string_view bytes, std::string* encoding, std::string* storage) {
  const auto starts = [&](std::string_view mark) { return bytes.substr(0, mark.size()) == mark; };
  if (starts("\xEF\xBB\xBF")) {
    *encoding = "utf-8 with BOM";
    return bytes.substr(3);
  }
  if (starts("\xFF\xFE")) {
    *encoding = "utf-16le";
    *storage = from_utf16(bytes.substr(2), true);
    return *storage;
  }
  if (starts("\xFE\xFF")) {
    *encoding = "utf-16be";
    *storage = from_utf16(bytes.substr(2), false);
    return *storage;
  }
  // UTF-16 without a byte-order mark (a Windows tool's "Unicode" text): the ASCII of a log puts a
  // zero in every other byte, the high one (the second in little-endian order).
  if (bytes.size() >= 4) {
    const std::size_t pairs = std::min<std::size_t>(bytes.size() / 2, 512);
    std::size_t zero_high = 0;
    std::size_t zero_low = 0;
    for (std::size_t i = 0; i < pairs; ++i) {
      zero_high += bytes[2 * i + 1] == '\0' && bytes[2 * i] != '\0' ? 1 : 0;
      zero_low += bytes[2 * i] == '\0' && bytes[2 * i + 1] != '\0' ? 1 : 0;
    }
    if (10 * zero_high >= 9 * pairs) {
      *encoding = "utf-16le (no BOM)";
      *storage = from_utf16(bytes, true);
      return *storage;
    }
    if (10 * zero_low >= 9 * pairs) {
      *encoding = "utf-16be (no BOM)";
      *storage = from_utf16(bytes, false);
      return *storage;
    }
  }
  *encoding = "utf-8";
  return bytes;
}

}  // namespace

std::string decode_log_text(std::string_view bytes, std::string* encoding) {
  std::string storage;
  return std::string(decoded_text(bytes, encoding, &storage));
}

HallLog parse_hall_log(std::string_view bytes, const std::string& name,
                       const HallLogOptions& options) {
  const RecognisedFile recognised = recognise_measurement_file(bytes);
  if (recognised.kind == MeasurementFile::kPhyphoxExport ||
      recognised.kind == MeasurementFile::kZip) {
    // The instrument's CSV inside, read as that file would be, named as the zip's entry.
    const ZipMeasurement inside = measurement_in_zip(bytes, name);
    return parse_hall_log(inside.text, name + "/" + inside.entry, options);
  }
  if (is_container(recognised.kind))
    throw InputError(SourceLocation(name, 1, 1), not_a_rig_log(recognised));
  if (records_no_oscillation(recognised.kind))
    throw InputError(SourceLocation(name, 1, 1), no_oscillation_recorded(recognised));
  if (recognised.kind != MeasurementFile::kRigLog) {
    // Another instrument's table, one channel of it read as a log.
    std::string decoded_table;
    std::string encoding;
    const std::string_view table = decoded_text(bytes, &encoding, &decoded_table);
    HallLog log = recognised.kind == MeasurementFile::kPhyphoxMagnetometer
                      ? read_phyphox_magnetometer(table, name)
                      : read_oscillation_log(table, name, recognised.kind);
    log.encoding = encoding;
    return log;
  }
  HallLog log;
  log.path = name;
  log.file = name;
  std::string decoded;
  const std::string_view text = decoded_text(bytes, &log.encoding, &decoded);
  HallLogReader reader(name, options);
  // Lines end in "\n" (or "\r\n"); a text without any "\n" may end its lines in "\r" alone.
  const char end_of_line = text.find('\n') == std::string_view::npos ? '\r' : '\n';
  // The samples straight into the log, each with its run (a restarted board starts another).
  std::vector<int> segment_of;
  std::vector<LogSample> ready;
  const auto keep = [&] {
    reader.take(ready);
    for (const LogSample& s : ready) {
      log.t_s.push_back(s.t_s);
      log.adc.push_back(s.adc);
      log.line.push_back(s.line);
      segment_of.push_back(s.segment);
    }
    ready.clear();
  };
  int number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find(end_of_line, pos);
    const bool unfinished = end == std::string_view::npos;
    if (unfinished) end = text.size();
    ++number;
    // A line no log has (a file without line ends), refused as reading a file refuses it.
    const std::string_view line = text.substr(pos, end - pos);
    if (line.size() > kMostLogLineBytes + 1)  // + 1: a "\r" before the "\n"
      throw line_too_long(name, number, "the log", kMostLogLineBytes);
    reader.add_line(line, number, unfinished);
    pos = end + 1;
    keep();
  }
  reader.finish();
  keep();
  log.reading = reader.reading();

  // Several runs (the board restarted): the longest is used.
  std::map<int, int> per_segment;
  for (const int segment : segment_of) ++per_segment[segment];
  int longest = 0;
  int most = -1;
  for (const auto& [segment, count] : per_segment) {
    if (count > most) {
      most = count;
      longest = segment;
    }
  }
  log.segment = longest;
  if (per_segment.size() > 1) {
    // The others' samples left out, the longest run's kept in order.
    std::size_t kept = 0;
    for (std::size_t i = 0; i < segment_of.size(); ++i) {
      if (segment_of[i] != longest) {
        ++log.segment_samples_left_out;
        continue;
      }
      log.t_s[kept] = log.t_s[i];
      log.adc[kept] = log.adc[i];
      log.line[kept] = log.line[i];
      ++kept;
    }
    log.t_s.resize(kept);
    log.adc.resize(kept);
    log.line.resize(kept);
  }
  if (log.t_s.empty())
    throw InputError(SourceLocation{name, log.reading.first_line, 0},
                     "no samples after the header: expected lines of time and ADC values");
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
                            shown_number(adc[i]));
    log.adc.push_back(static_cast<uint16_t>(std::lround(adc[i])));
    if (!std::isfinite(t_s[i]))
      throw fail(i + 1, "sample " + std::to_string(i + 1) + ": time " + shown_number(t_s[i]) +
                            " s is not a finite number");
    if (i > 0 && !(t_s[i] > t_s[i - 1]))
      throw fail(i + 1, "sample " + std::to_string(i + 1) + ": time " + shown_number(t_s[i]) +
                            " s is not after the previous sample's " + shown_number(t_s[i - 1]) +
                            " s: the times must increase");
  }
  log.path = name;
  log.file = name;
  log.reading.format = "samples";
  log.reading.columns_from = "samples";
  log.reading.time_column = "t";
  log.reading.adc_column = "adc";
  log.reading.time_unit = "s";
  log.reading.time_unit_from = "samples";
  log.reading.first_line = 1;
  log.reading.data_lines = static_cast<int>(t_s.size());
  log.reading.segments = 1;
  log.t_s = std::move(t_s);
  log.line.resize(log.t_s.size());
  for (std::size_t i = 0; i < log.line.size(); ++i) log.line[i] = static_cast<int>(i + 1);
  stamp_rig_clock(log);
  return log;
}

std::string log_file_of(const std::string& path) {
  std::error_code ec;
  return path != "-" && std::filesystem::is_directory(path, ec) ? log_in_folder(path) : path;
}

RecognisedFile recognise_file(const std::string& file) {
  constexpr std::streamoff kPeekBytes = std::streamoff{1} << 16;
  std::error_code error;
  if (file == "-" || !std::filesystem::is_regular_file(file, error)) return {};
  std::ifstream in(file, std::ios::binary);
  if (!in) return {};
  std::string bytes(static_cast<std::size_t>(kPeekBytes), '\0');
  in.read(bytes.data(), kPeekBytes);
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  const auto size = static_cast<std::streamoff>(std::filesystem::file_size(file, error));
  if (!error && size > 2 * kPeekBytes && bytes.rfind("PK", 0) == 0) {
    std::string tail(static_cast<std::size_t>(kPeekBytes), '\0');
    in.clear();
    in.seekg(size - kPeekBytes);
    in.read(tail.data(), kPeekBytes);
    bytes += tail.substr(0, static_cast<std::size_t>(in.gcount()));
  }
  // Text (a phone's CSV, Tracker's data) is recognised as it is parsed: only what has no lines
  // here.
  const RecognisedFile recognised = recognise_measurement_file(bytes);
  return is_container(recognised.kind) ? recognised : RecognisedFile{};
}

LogText read_log_text(const std::string& path) {
  if (path == "-")
    return {read_text_stream(std::cin, "<stdin>", "the log", kMostTextFileBytes, kMostLogLineBytes),
            "<stdin>"};
  const std::string file = log_file_of(path);
  return {read_text_file(file, "the log", kMostTextFileBytes, kMostLogLineBytes), file};
}

std::optional<HallLog> read_if_not_text(const std::string& path, const HallLogOptions& options) {
  const std::string file = log_file_of(path);
  const RecognisedFile recognised = recognise_file(file);
  const MeasurementFile kind = recognised.kind;
  std::optional<HallLog> log;
  if (kind == MeasurementFile::kVideo) {
    log = read_video_log(file, options.video).log;
  } else if (kind == MeasurementFile::kPhyphoxExport || kind == MeasurementFile::kZip) {
    std::error_code error;
    const auto size = std::filesystem::file_size(file, error);
    if (!error && size > kMostTextFileBytes)
      throw InputError(SourceLocation(file),
                       fmt::format("the zip is {} MiB; a phone's export is a few MiB", size >> 20));
    std::ifstream in(file, std::ios::binary);
    std::string bytes(error ? 0 : static_cast<std::size_t>(size), '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(0, in.gcount())));
    log = parse_hall_log(bytes, file, options);
  } else if (is_container(kind)) {
    throw InputError(SourceLocation(file), not_a_rig_log(recognised));
  }
  if (log) log->path = path;
  return log;
}

HallLog read_hall_log(const std::string& path, const HallLogOptions& options) {
  if (std::optional<HallLog> other = read_if_not_text(path, options)) return std::move(*other);
  const LogText text = read_log_text(path);
  HallLog log = parse_hall_log(text.bytes, text.file, options);
  if (path != "-") log.path = path;
  return log;
}

}  // namespace fl
