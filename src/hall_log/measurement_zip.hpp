// A measurement inside a zip archive: phyphox's export (one CSV per sensor, and its meta/ folder),
// or any zip holding an instrument's CSV. The archive is read from memory (minizip, zlib's); each
// entry's text is read only up to kMostTextFileBytes, so a zip that would inflate to gigabytes is
// refused at that size rather than filling memory.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "hall_log/measurement_file.hpp"

namespace fl {

struct ZipMeasurement {
  std::string entry;  // the entry read ("Raw Data.csv")
  std::string text;   // its bytes
  RecognisedFile kind;
};

// The entry holding an instrument the lab reads (a phyphox magnetometer first, then an
// accelerometer, then Tracker's data or a position table), of the zip's CSV and text entries
// outside meta/. `name` stands for the file in messages. Throws InputError, located at the file,
// for a zip that is damaged (where), holds none of those (what it holds: each entry and what it
// is, GPS and audio named), or, in a build without minizip, for any zip (what to do instead).
ZipMeasurement measurement_in_zip(std::string_view bytes, const std::string& name);

// Whether this build reads zips.
bool reads_zips();

}  // namespace fl
