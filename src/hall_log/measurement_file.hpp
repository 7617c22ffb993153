// What a measurement file is, recognised from its content (its first bytes and first lines), never
// from its name: the rig's Hall-sensor log, or the file of another instrument a student measures
// with: a phyphox export (the zip of one CSV per sensor, one of those CSVs, or its Excel file),
// Tracker's exported data, a position-time table from a spreadsheet or a logger, or a phone's
// video. The Hall-log reader reads the first and names the others, so that a student who hands it
// a phone's file hears what it is rather than a complaint about a header of binary bytes.
#pragma once

#include <string>
#include <string_view>

namespace fl {

enum class MeasurementFile {
  kRigLog,         // anything not recognised below: read as the rig's Hall-sensor log
  kPhyphoxExport,  // a zip holding phyphox's meta/ folder and one CSV per sensor
  kExcel,          // an Office Open XML workbook (.xlsx): phyphox's Excel export, a spreadsheet
  kZip,            // another zip archive
  kPhyphoxCsv,     // one CSV of a phyphox export: "Time (s)" then a sensor's columns
  kTracker,        // Tracker's exported data: a track's name, then "t", "x", ...
  kPositionTable,  // a time column and a position column, units in the header
  kVideo,          // an MP4 or MOV, a WebM or Matroska, an AVI
};

struct RecognisedFile {
  MeasurementFile kind = MeasurementFile::kRigLog;
  // What was read, in words a student knows: "phyphox magnetometer", "Tracker", "video (MP4)";
  // empty for the rig's log.
  std::string instrument;
};

// Recognises a file from its first bytes (any number; the first 64 KiB are enough).
RecognisedFile recognise_measurement_file(std::string_view bytes);

// Why the rig's log reader cannot read a file recognised as another instrument's, and what to
// do instead: the message of the error the reader throws. Empty for MeasurementFile::kRigLog.
std::string not_a_rig_log(const RecognisedFile& file);

}  // namespace fl
