// What a measurement file is, from its content: the headers phyphox, Tracker and spreadsheets
// write, as those programs write them, and the magic bytes of zips and videos, each named; every
// rig log the repository holds (tests/data/logs, assets/examples) still read as a rig's log; and
// the Hall-log reader refusing another instrument's file by name rather than reading its bytes.
#include "hall_log/measurement_file.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "hall_log/hall_log.hpp"
#include "hall_log/measurement_zip.hpp"
#include "io/input_error.hpp"
#include "io/text_file.hpp"

namespace fl {
namespace {

struct Case {
  const char* name;
  std::string bytes;
  MeasurementFile kind;
  const char* instrument;
};

std::string zip_with(std::string_view entry) {
  // A zip's local file header: the signature, 26 bytes of fields, then the entry's name.
  return std::string("PK\x03\x04", 4) + std::string(26, '\0') + std::string(entry) + "data";
}

TEST(MeasurementFile, NamesEachInstrumentFromItsContent) {
  const Case cases[] = {
      {"phyphox magnetometer, comma",
       "\"Time (s)\",\"Magnetic field x (\xC2\xB5T)\",\"Magnetic "
       "field y (\xC2\xB5T)\",\"Magnetic field z (\xC2\xB5T)\",\"Absolute field (\xC2\xB5T)\"\n"
       "0.0,12.1,-3.0,40.2,42.1\n",
       MeasurementFile::kPhyphoxMagnetometer, "phyphox magnetometer"},
      {"phyphox magnetometer, semicolon and decimal comma",
       "\"Time (s)\";\"Magnetic field x (\xC2\xB5T)\"\n0,0;12,1\n",
       MeasurementFile::kPhyphoxMagnetometer, "phyphox magnetometer"},
      {"phyphox accelerometer, tab",
       "\"Time (s)\"\t\"Acceleration x (m/s^2)\"\t\"Acceleration y "
       "(m/s^2)\"\n0.0\t0.1\t9.8\n",
       MeasurementFile::kPhyphoxAccelerometer, "phyphox accelerometer"},
      {"phyphox accelerometer without g",
       "\"Time (s)\",\"Linear Acceleration x (m/s^2)\"\n0.0,0.1\n",
       MeasurementFile::kPhyphoxLinearAccelerometer, "phyphox accelerometer (without g)"},
      {"Tracker", "mass A\nt\tx\ty\n0.0\t1.2E-2\t0.0\n", MeasurementFile::kTracker, "Tracker"},
      {"Tracker, several tracks", "#multi:\nmass A\tmass B\nt\tx\ty\tt\tx\ty\n",
       MeasurementFile::kTracker, "Tracker"},
      {"spreadsheet", "Time (s),Position (m)\n0.00,0.012\n", MeasurementFile::kPositionTable,
       "position-time table"},
      {"logger, millimetres", "t_s;x_mm\n0,00;12,0\n", MeasurementFile::kPositionTable,
       "position-time table"},
      {"phyphox export", zip_with("meta/device.csv"), MeasurementFile::kPhyphoxExport,
       "phyphox export (zip)"},
      {"Excel", zip_with("xl/workbook.xml"), MeasurementFile::kExcel, "Excel workbook (.xlsx)"},
      {"zip", zip_with("notes.txt"), MeasurementFile::kZip, "zip archive"},
      {"MP4",
       std::string("\0\0\0\x20"
                   "ftypisom\0\0\x02\0",
                   16),
       MeasurementFile::kVideo, "video (MP4)"},
      {"MOV",
       std::string("\0\0\0\x14"
                   "ftypqt  \0\0\0\0",
                   16),
       MeasurementFile::kVideo, "video (MOV)"},
      {"WebM", std::string("\x1A\x45\xDF\xA3\x9F\x42\x86\x81\x01\x42\x82\x84webm", 16),
       MeasurementFile::kVideo, "video (WebM)"},
      {"AVI",
       std::string("RIFF\x10\0\0\0"
                   "AVI LIST",
                   16),
       MeasurementFile::kVideo, "video (AVI)"},
  };
  for (const Case& c : cases) {
    const RecognisedFile file = recognise_measurement_file(c.bytes);
    EXPECT_EQ(file.kind, c.kind) << c.name;
    EXPECT_EQ(file.instrument, c.instrument) << c.name;
  }
}

TEST(MeasurementFile, RigLogsOfEveryShapeAreRigLogs) {
  for (const char* text : {"t_us,adc\n0,512\n", "Time (s),ADC\n0,512\n", "time (ms)\thall\n",
                           "12:34:56.789 -> 1000,512\n", "millis,sensorValue\n", "512\n513\n",
                           "\"Time (s)\",\"Hall (counts)\"\n0,512\n"}) {
    EXPECT_EQ(recognise_measurement_file(text).kind, MeasurementFile::kRigLog) << text;
  }
  int logs = 0;
  for (const char* folder : {"tests/data/logs", "assets/examples/spacing-series"}) {
    for (const auto& entry : std::filesystem::directory_iterator(
             std::filesystem::path(FRICTIONLAB_TEST_SOURCE_DIR) / folder)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".csv" && ext != ".txt") continue;
      const std::string bytes = read_text_file(entry.path().string());
      EXPECT_EQ(recognise_measurement_file(bytes).kind, MeasurementFile::kRigLog) << entry.path();
      ++logs;
    }
  }
  EXPECT_GE(logs, 15);
}

TEST(MeasurementFile, TheLogReaderRefusesAnotherInstrumentsFileByName) {
  // A phone's video, handed to the log reader as text.
  const std::string video(
      "\0\0\0\x20"
      "ftypisom\0\0\x02\0isomiso2avc1mp41",
      32);
  try {
    parse_hall_log(video, "clip.mp4");
    FAIL() << "a video was read as a rig's log";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("clip.mp4:1:1"), std::string::npos) << what;
    EXPECT_NE(what.find("found a video (MP4)"), std::string::npos) << what;
    EXPECT_NE(what.find("Your measurements against the lab"), std::string::npos) << what;
  }
  // A zip on disk is recognised before it is read as text, which it is not (its entries' names
  // lie past the first 64 KiB, in its end), and opened as a zip: this one's table of entries is
  // garbage, and it is refused as a damaged zip, not as a log of binary bytes.
  const auto path = std::filesystem::temp_directory_path() / "frictionlab-measurement-file.zip";
  {
    std::ofstream out(path, std::ios::binary);
    out << zip_with("Raw Data.csv") << std::string(200000, '\x11') << zip_with("meta/time.csv");
  }
  try {
    read_hall_log(path.string());
    FAIL() << "a damaged zip was read as a rig's log";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(reads_zips() ? "error: the zip is damaged"
                                                      : "a phyphox export (the zip of one CSV"),
              std::string::npos)
        << e.what();
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace fl
