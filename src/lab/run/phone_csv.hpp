// A simulated phone's file as phyphox exports it ("CSV (Comma, decimal point)"): a quoted header,
// "Time (s)", the three axes and the magnitude, each number in scientific notation with nine
// decimals. phone-magnetometer.csv (uT) and phone-accelerometer.csv (m/s^2, "Acceleration" with g
// or "Linear Acceleration" without), what `frictionlab estimate` reads as phyphox's.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "scene/compiled_rig.hpp"
#include "sensor/phone_signals.hpp"

namespace fl {

// phone-magnetometer.csv for the rig's first magnetometer, phone-magnetometer-2.csv for its
// second, and so on; the same for accelerometers.
std::string phone_csv_name(const CompiledRig& rig, std::size_t phone);
std::string phone_csv_header(const PhoneDesc& phone);
// One row (the time, the axes, their magnitude) appended to `out`.
void append_phone_row(std::string& out, const PhoneDesc& phone, const PhoneSample& sample);
std::string phone_csv(const PhoneDesc& phone, const std::vector<PhoneSample>& samples);

// The most bytes a phone's file takes: its rows at their widest for `duration` [s].
double phone_csv_bytes_at_most(const PhoneDesc& phone, double duration);

}  // namespace fl
