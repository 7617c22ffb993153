// What a measurement file is, recognised from its content (its first bytes and first lines), never
// from its name: the rig's Hall-sensor log, or the file of another instrument a student measures
// with: a phyphox export (the zip of one CSV per sensor, one of those CSVs, or its Excel file),
// Tracker's exported data, a position-time table from a spreadsheet or a logger, or a phone's
// video. The Hall-log reader reads the first and names the others, so that a student who hands it
// a phone's file hears what it is rather than a complaint about a header of binary bytes.
#pragma once

#include <string>
#include <string_view>

#include "text/said.hpp"

namespace fl {

enum class MeasurementFile {
  kRigLog,                      // anything not recognised below: read as the rig's Hall log
  kPhyphoxMagnetometer,         // phyphox's CSV: "Time (s)", "Magnetic field x (µT)", ...
  kPhyphoxAccelerometer,        // phyphox's CSV: "Time (s)", "Acceleration x (m/s^2)", ...
  kPhyphoxLinearAccelerometer,  // the same without g: "Linear Acceleration x (m/s^2)", ...
  kTracker,                     // Tracker's exported data: a track's name, then "t", "x", ...
  kPositionTable,               // a time column and a position column, units in the header
  kPhyphoxLocation,             // phyphox's CSV of GPS: "Latitude (°)", ... (no oscillation)
  kPhyphoxAudio,                // phyphox's CSV of sound: "Amplitude", "Frequency (Hz)", ...
  kPhyphoxOtherSensor,          // phyphox's CSV of a gyroscope, light, pressure, proximity
  kPhyphoxExport,               // a zip holding phyphox's meta/ folder and one CSV per sensor
  kExcel,                       // an Office Open XML workbook (.xlsx): phyphox's, a spreadsheet's
  kZip,                         // another zip archive
  kVideo,                       // an MP4 or MOV, a WebM or Matroska, an AVI
};

// What measured, in words a student knows: "Hall sensor" (the rig's), "phyphox magnetometer",
// "Tracker", "video"; the key `instrument` of an estimate.
std::string instrument_words(MeasurementFile kind);
// The same, as the catalogues say it (instrument-*).
Said instrument_said(MeasurementFile kind);

// A phone's accelerometer, with or without g.
bool is_accelerometer(MeasurementFile kind);

// Files that are no text of lines: a zip and a video (read through hall_log/measurement_zip.hpp
// and tracking/), a workbook (named and refused).
bool is_container(MeasurementFile kind);

struct RecognisedFile {
  MeasurementFile kind = MeasurementFile::kRigLog;
  // instrument_words(kind), and a video's container in words: "video (MP4)".
  std::string instrument = instrument_words(MeasurementFile::kRigLog);
};

// A phone's recording of something other than the plate's motion (GPS, sound, another sensor):
// named and refused.
bool records_no_oscillation(MeasurementFile kind);

// Why such a recording gives no period, and what to record instead.
std::string no_oscillation_recorded(const RecognisedFile& file);

// Recognises a file from its first bytes (any number; the first 64 KiB are enough).
RecognisedFile recognise_measurement_file(std::string_view bytes);

// Why the rig's log reader cannot read a file recognised as a container (is_container) it does not
// open (a workbook; a zip or a video in a build without minizip or libav), and what to do
// instead: the message of the error the reader throws.
std::string not_a_rig_log(const RecognisedFile& file);

}  // namespace fl
