// libFuzzer target for the Hall log reader (hall_log/hall_log, hall_log/hall_log_reader) and what
// follows it for a log that reads: the rig's estimator and the checks of its periods and geometry
// (lab/logs/log_estimate, lab/logs/geometry_check). Any input is either read and estimated, or
// refused with an InputError; anything else (a crash, a sanitizer report, another exception, a
// hang) is a bug. The first byte picks how the log is read (columns, a rate, a time unit, a
// geometry), as a user's options would; the rest is the log's bytes.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "hall_log/hall_log.hpp"
#include "io/input_error.hpp"
#include "lab/logs/geometry_check.hpp"
#include "lab/logs/log_estimate.hpp"

namespace {

fl::HallLogOptions options_of(std::uint8_t pick) {
  fl::HallLogOptions options;
  switch (pick & 7u) {
    case 1:
      options.columns = "t_us,adc";
      break;
    case 2:
      options.columns = "_,t_ms,adc";
      break;
    case 3:
      options.rate_hz = 1000.0;
      break;
    case 4:
      options.time_unit = "ms";
      break;
    case 5:
      options.columns = "adc";
      options.rate_hz = 500.0;
      break;
    default:
      break;
  }
  return options;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  fl::LogSetUp set_up;
  set_up.geometry = (data[0] >> 3) % 3 == 0   ? fl_estimator::kAutoGeometry
                    : (data[0] >> 3) % 3 == 1 ? fl_estimator::kOnePulse
                                              : fl_estimator::kPulsePair;
  try {
    const fl::HallLog log = fl::parse_hall_log(text, "fuzz.csv", options_of(data[0]));
    const fl::LogEstimate estimate = fl::estimate_log(log, set_up, (data[0] & 0x80u) != 0);
    (void)fl::log_estimate_json(log, estimate).dump();
    if ((data[0] & 0x80u) != 0) (void)fl::hall_plot_data(log, estimate).dump();
    fl::require_periods(log, estimate, "");
    fl::require_geometry(log, estimate, fl::check_geometry(log, estimate), "");
    fl::require_plausible(log, estimate, "");
  } catch (const fl::InputError&) {
    // A refused input: expected.
  }
  return 0;
}
