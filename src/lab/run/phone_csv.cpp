#include "lab/run/phone_csv.hpp"

#include <cmath>
#include <iterator>

#include <fmt/compile.h>
#include <fmt/format.h>

namespace fl {

std::string phone_csv_name(const CompiledRig& rig, std::size_t phone) {
  const PhoneSensor sensor = rig.phones.at(phone).sensor;
  int nth = 0;
  for (std::size_t i = 0; i <= phone; ++i) nth += rig.phones[i].sensor == sensor ? 1 : 0;
  const char* kind = sensor == PhoneSensor::kMagnetometer ? "magnetometer" : "accelerometer";
  return nth == 1 ? fmt::format("phone-{}.csv", kind) : fmt::format("phone-{}-{}.csv", kind, nth);
}

std::string phone_csv_header(const PhoneDesc& phone) {
  if (phone.sensor == PhoneSensor::kMagnetometer)
    return "\"Time (s)\",\"Magnetic field x (\xC2\xB5T)\",\"Magnetic field y (\xC2\xB5T)\","
           "\"Magnetic field z (\xC2\xB5T)\",\"Absolute field (\xC2\xB5T)\"\n";
  const char* name = phone.gravity ? "Acceleration" : "Linear Acceleration";
  return fmt::format(
      "\"Time (s)\",\"{0} x (m/s^2)\",\"{0} y (m/s^2)\",\"{0} z (m/s^2)\","
      "\"Absolute acceleration (m/s^2)\"\n",
      name);
}

void append_phone_row(std::string& out, const PhoneDesc& phone, const PhoneSample& sample) {
  // phyphox writes the magnetometer in uT.
  const double unit = phone.sensor == PhoneSensor::kMagnetometer ? 1e6 : 1.0;
  const double x = sample.value[0] * unit, y = sample.value[1] * unit, z = sample.value[2] * unit;
  fmt::format_to(std::back_inserter(out), FMT_COMPILE("{:.9E},{:.9E},{:.9E},{:.9E},{:.9E}\n"),
                 sample.t, x, y, z, std::sqrt(x * x + y * y + z * z));
}

std::string phone_csv(const PhoneDesc& phone, const std::vector<PhoneSample>& samples) {
  std::string out = phone_csv_header(phone);
  for (const PhoneSample& sample : samples) append_phone_row(out, phone, sample);
  return out;
}

double phone_csv_bytes_at_most(const PhoneDesc& phone, double duration) {
  constexpr double kRow = 5 * 17.0;  // "-1.234567890E-123" and a separator, five times
  return 256.0 + (duration * phone.rate + 2.0) * kRow;
}

}  // namespace fl
