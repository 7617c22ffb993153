#include "cli/log_options.hpp"

#include <cmath>

#include "cli/option_quantity.hpp"
#include "io/input_error.hpp"

namespace fl::cli {

fl_estimator::Geometry parse_geometry(const std::string& text) {
  if (text == "auto") return fl_estimator::kAutoGeometry;
  if (text == "one") return fl_estimator::kOnePulse;
  if (text == "pair") return fl_estimator::kPulsePair;
  throw InputError({}, "--geometry: expected auto, one or pair, found \"" + text + "\"");
}

HallLogOptions log_reading(const std::string& columns, const std::string& rate,
                           const std::string& time_unit) {
  HallLogOptions reading;
  reading.columns = columns;
  reading.time_unit = time_unit;
  if (!rate.empty()) {
    reading.rate_hz = option_quantity(rate, Dimension::kFrequency, "--rate");
    if (!(reading.rate_hz > 0.0) || !std::isfinite(reading.rate_hz))
      throw InputError(
          {}, "--rate: expected a positive sample rate (for example 1kHz), found \"" + rate + "\"");
  }
  return reading;
}

}  // namespace fl::cli
