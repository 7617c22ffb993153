#include "hall_log/measurement_file.hpp"

#include <cctype>
#include <optional>
#include <vector>

#include "hall_log/log_columns.hpp"
#include "hall_log/log_line.hpp"
#include "hall_log/measurement_table.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

bool starts_with(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

bool contains(std::string_view s, std::string_view part) {
  return s.find(part) != std::string_view::npos;
}

// A container format from its magic bytes: true, and `file` set, for one.
// A kind the lab names in its own words.
RecognisedFile recognised(MeasurementFile kind) {
  return {kind, instrument_words(kind)};
}

bool recognise_container(std::string_view bytes, RecognisedFile* file) {
  if (starts_with(bytes, "PK\x03\x04") || starts_with(bytes, "PK\x05\x06")) {
    // A zip stores its entries' names as they are, in each entry's header and at its end.
    *file = recognised(contains(bytes, "xl/workbook.xml") ? MeasurementFile::kExcel
                       : contains(bytes, "meta/")         ? MeasurementFile::kPhyphoxExport
                                                          : MeasurementFile::kZip);
    return true;
  }
  if (bytes.size() >= 12 && bytes.substr(4, 4) == "ftyp") {
    *file = {MeasurementFile::kVideo, bytes.substr(8, 2) == "qt" ? "video (MOV)" : "video (MP4)"};
    return true;
  }
  if (starts_with(bytes, "\x1A\x45\xDF\xA3")) {
    *file = {MeasurementFile::kVideo,
             contains(bytes.substr(0, 64), "webm") ? "video (WebM)" : "video (Matroska)"};
    return true;
  }
  if (starts_with(bytes, "RIFF") && bytes.size() >= 12 && bytes.substr(8, 4) == "AVI ") {
    *file = {MeasurementFile::kVideo, "video (AVI)"};
    return true;
  }
  return false;
}

// The first few lines that hold anything but a comment, without a UTF-8 byte-order mark.
std::vector<std::string_view> first_lines(std::string_view text, std::size_t most) {
  if (starts_with(text, "\xEF\xBB\xBF")) text.remove_prefix(3);
  std::vector<std::string_view> lines;
  std::size_t pos = 0;
  while (pos < text.size() && lines.size() < most) {
    std::size_t end = text.find_first_of("\r\n", pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = trim(text.substr(pos, end - pos));
    // A comment line ("# simulated, not measured") says nothing of the format; Tracker's
    // "#multi:" does.
    const bool comment = line.substr(0, 1) == "#" && ascii_lower(line).rfind("#multi:", 0) != 0;
    if (!line.empty() && !comment) lines.push_back(line);
    pos = end + 1;
  }
  return lines;
}

// A header's fields, as a log's line is split.
std::vector<std::string> header_fields(std::string_view line) {
  std::vector<std::string> fields;
  for (const LogField& f : split_fields(line, detect_delimiter(line))) fields.emplace_back(f.text);
  return fields;
}

bool recognise_text(std::string_view bytes, RecognisedFile* file) {
  const std::vector<std::string_view> lines = first_lines(bytes.substr(0, 1 << 16), 3);
  if (lines.empty()) return false;
  const std::string first = ascii_lower(lines[0]);
  if (starts_with(first, "#multi:")) {
    *file = recognised(MeasurementFile::kTracker);
    return true;
  }
  if (contains(first, "time (s)")) {
    if (contains(first, "latitude") || contains(first, "longitude")) {
      *file = recognised(MeasurementFile::kPhyphoxLocation);
      return true;
    }
    if (contains(first, "sound pressure") || contains(first, "frequency (hz)") ||
        contains(first, "\"amplitude") || contains(first, "audio")) {
      *file = recognised(MeasurementFile::kPhyphoxAudio);
      return true;
    }
    if (contains(first, "gyroscope") || contains(first, "illuminance") ||
        contains(first, "pressure (hpa)") || contains(first, "proximity")) {
      *file = recognised(MeasurementFile::kPhyphoxOtherSensor);
      return true;
    }
    const bool field = contains(first, "magnetic field");
    const bool linear = contains(first, "linear acceleration");
    if (field || linear || contains(first, "acceleration")) {
      *file = recognised(field    ? MeasurementFile::kPhyphoxMagnetometer
                         : linear ? MeasurementFile::kPhyphoxLinearAccelerometer
                                  : MeasurementFile::kPhyphoxAccelerometer);
      return true;
    }
  }
  // Tracker's data: the track's name on a line of its own, then "t", "x", ... (tab-separated); a
  // table: a time column and a position column, and no column a rig's log names its value by.
  for (std::size_t i = 0; i < lines.size() && i < 2; ++i) {
    const std::vector<std::string> fields = header_fields(lines[i]);
    if (fields.size() < 2 || !is_time_column(bare_column_name(fields[0]))) continue;
    bool position = false;
    bool rig_value = false;
    for (std::size_t k = 1; k < fields.size(); ++k) {
      position = position || is_position_column(bare_column_name(fields[k]));
      const std::optional<ColumnName> column = column_name(fields[k]);
      rig_value = rig_value || (column && column->role == ColumnRole::kValue);
    }
    if (!position || rig_value) continue;
    *file = recognised(i == 1 ? MeasurementFile::kTracker : MeasurementFile::kPositionTable);
    return true;
  }
  return false;
}

}  // namespace

RecognisedFile recognise_measurement_file(std::string_view bytes) {
  RecognisedFile file;
  if (recognise_container(bytes, &file) || recognise_text(bytes, &file)) return file;
  return {};
}

Said instrument_said(MeasurementFile kind) {
  switch (kind) {
    case MeasurementFile::kRigLog:
      return said("instrument-hall-sensor");
    case MeasurementFile::kPhyphoxMagnetometer:
      return said("instrument-phyphox-magnetometer");
    case MeasurementFile::kPhyphoxAccelerometer:
      return said("instrument-phyphox-accelerometer");
    case MeasurementFile::kPhyphoxLinearAccelerometer:
      return said("instrument-phyphox-linear-accelerometer");
    case MeasurementFile::kTracker:
      return said("instrument-tracker");
    case MeasurementFile::kPositionTable:
      return said("instrument-position-table");
    case MeasurementFile::kPhyphoxLocation:
      return said("instrument-phyphox-location");
    case MeasurementFile::kPhyphoxAudio:
      return said("instrument-phyphox-audio");
    case MeasurementFile::kPhyphoxOtherSensor:
      return said("instrument-phyphox-other");
    case MeasurementFile::kPhyphoxExport:
      return said("instrument-phyphox-export");
    case MeasurementFile::kExcel:
      return said("instrument-excel");
    case MeasurementFile::kZip:
      return said("instrument-zip");
    case MeasurementFile::kVideo:
      break;
  }
  return said("instrument-video");
}

std::string instrument_words(MeasurementFile kind) {
  return english(instrument_said(kind));
}

bool is_accelerometer(MeasurementFile kind) {
  return kind == MeasurementFile::kPhyphoxAccelerometer ||
         kind == MeasurementFile::kPhyphoxLinearAccelerometer;
}

bool records_no_oscillation(MeasurementFile kind) {
  return kind == MeasurementFile::kPhyphoxLocation || kind == MeasurementFile::kPhyphoxAudio ||
         kind == MeasurementFile::kPhyphoxOtherSensor;
}

std::string no_oscillation_recorded(const RecognisedFile& file) {
  const std::string why =
      file.kind == MeasurementFile::kPhyphoxLocation
          ? "GPS follows a phone across the ground to a few metres, not a plate's centimetres"
      : file.kind == MeasurementFile::kPhyphoxAudio
          ? "a microphone hears the rollers' motor, not the plate's swing"
          : "that sensor does not follow the plate's swing";
  return "expected a recording of the plate's oscillation, found a " + file.instrument +
         " export: " + why +
         "; record with phyphox's \"Magnetometer\" beside the rig or its \"Acceleration\" "
         "with the phone on the plate, or film the rig (frictionlab track)";
}

bool is_container(MeasurementFile kind) {
  return kind == MeasurementFile::kPhyphoxExport || kind == MeasurementFile::kExcel ||
         kind == MeasurementFile::kZip || kind == MeasurementFile::kVideo;
}

std::string not_a_rig_log(const RecognisedFile& file) {
  const std::string what = file.kind == MeasurementFile::kPhyphoxExport
                               ? "a phyphox export (the zip of one CSV per sensor)"
                           : file.kind == MeasurementFile::kExcel ? "an Excel workbook (.xlsx)"
                                                                  : "a " + file.instrument;
  return "expected a log of the rig's Hall sensor (a time and an ADC column), found " + what +
         ", which the lab does not read; save or export it as CSV (phyphox exports CSV too), "
         "which the lab reads, or read the period off it yourself and give it with its error as a "
         "measured period: the lab compares it with the rig and fits mu_k from several spacings "
         "(docs/students.md, \"Your measurements against the lab\")";
}

}  // namespace fl
