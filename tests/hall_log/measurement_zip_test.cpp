// phyphox's zip export read as the CSV it holds: the same text inside a zip gives the same log and
// the same period to the last bit, whichever other entries are beside it; the magnetometer is read
// first of several sensors; a zip of GPS alone, a zip cut short and a zip with no entry are refused
// with what they hold, located at the file. The zips are written here with minizip's writer.
#include "hall_log/measurement_zip.hpp"

#include <zip.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "hall_log/hall_log.hpp"
#include "io/input_error.hpp"
#include "lab/logs/log_estimate.hpp"
#include "support/temp_folder.hpp"

namespace fl {
namespace {

const std::string kExamples =
    std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/assets/examples/instruments/";

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class MeasurementZip : public test::TempFolderTest {
 protected:
  MeasurementZip() : TempFolderTest("fl-zip") {}

  std::string zip(const std::string& name,
                  const std::vector<std::pair<std::string, std::string>>& entries) {
    const std::string path = (dir_ / name).string();
    zipFile z = zipOpen64(path.c_str(), APPEND_STATUS_CREATE);
    EXPECT_NE(z, nullptr);
    for (const auto& [entry, text] : entries) {
      zip_fileinfo info{};
      EXPECT_EQ(zipOpenNewFileInZip64(z, entry.c_str(), &info, nullptr, 0, nullptr, 0, nullptr,
                                      Z_DEFLATED, Z_DEFAULT_COMPRESSION, 0),
                ZIP_OK);
      EXPECT_EQ(zipWriteInFileInZip(z, text.data(), static_cast<unsigned>(text.size())), ZIP_OK);
      zipCloseFileInZip(z);
    }
    zipClose(z, nullptr);
    return path;
  }
};

const std::vector<std::pair<std::string, std::string>> kMeta = {
    {"meta/device.csv", "\"property\",\"value\"\n\"deviceModel\",\"Pixel 7\"\n"},
    {"meta/time.csv", "\"event\",\"experiment time\",\"system time\"\n\"START\",0,0\n"}};

TEST_F(MeasurementZip, ThePhyphoxExportGivesItsCsvsPeriodToTheBit) {
  const std::string csv = file_text(kExamples + "phone-magnetometer.csv");
  auto entries = kMeta;
  entries.emplace_back("Raw Data.csv", csv);
  const std::string path = zip("export.zip", entries);
  const HallLog inside = read_hall_log(path);
  const HallLog bare = parse_hall_log(csv, "Raw Data.csv");
  EXPECT_EQ(inside.instrument, MeasurementFile::kPhyphoxMagnetometer);
  EXPECT_EQ(inside.file, path + "/Raw Data.csv");
  EXPECT_EQ(inside.t_s, bare.t_s);
  EXPECT_EQ(inside.adc, bare.adc);
  const float t_inside = estimate_log(inside, LogSetUp{}, false).stats.period_s;
  EXPECT_EQ(t_inside, estimate_log(bare, LogSetUp{}, false).stats.period_s);
  EXPECT_NEAR(t_inside, 0.7766, 5e-4);
}

TEST_F(MeasurementZip, OfSeveralSensorsTheMagnetometerIsRead) {
  auto entries = kMeta;
  entries.emplace_back("Accelerometer.csv", file_text(kExamples + "phone-accelerometer.csv"));
  entries.emplace_back("Magnetometer.csv", file_text(kExamples + "phone-magnetometer.csv"));
  entries.emplace_back("Location.csv",
                       "\"Time (s)\",\"Latitude (°)\",\"Longitude (°)\"\n0,48,11\n");
  const HallLog log = read_hall_log(zip("three.zip", entries));
  EXPECT_EQ(log.instrument, MeasurementFile::kPhyphoxMagnetometer);
  EXPECT_NE(log.file.find("Magnetometer.csv"), std::string::npos);
}

TEST_F(MeasurementZip, AZipOfGpsIsRefusedSayingWhatItHolds) {
  auto entries = kMeta;
  entries.emplace_back("Location.csv",
                       "\"Time (s)\",\"Latitude (°)\",\"Longitude (°)\"\n0,48,11\n");
  entries.emplace_back("photo.jpg", "\xFF\xD8\xFF");
  const std::string path = zip("gps.zip", entries);
  try {
    read_hall_log(path);
    FAIL() << "a zip of GPS was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, path);
    const std::string what = e.what();
    EXPECT_NE(what.find("\"Location.csv\" (phyphox location (GPS)), \"photo.jpg\""),
              std::string::npos)
        << what;
  }
}

TEST_F(MeasurementZip, AZipCutShortIsRefused) {
  auto entries = kMeta;
  entries.emplace_back("Raw Data.csv", file_text(kExamples + "phone-magnetometer.csv"));
  const std::string path = zip("export.zip", entries);
  const std::string bytes = file_text(path);
  for (const std::size_t keep : {bytes.size() / 2, bytes.size() - 30}) {
    try {
      measurement_in_zip(std::string_view(bytes).substr(0, keep), "cut.zip");
      FAIL() << "a zip cut to " << keep << " bytes was read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("cut.zip: error: the zip is damaged"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace fl
