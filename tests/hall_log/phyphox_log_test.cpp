// A phone's magnetometer beside the rig, as phyphox exports it: a plate oscillating with a known
// period T carries a magnet past the phone, which sees a dipole's pulse on the Earth's field at
// 100 Hz with noise. The rig's estimator reads T back from each of phyphox's CSV forms, the same
// T from every form (the forms hold the same numbers), the channel that carries the pulses, and
// what was read said by name.
#include "hall_log/phyphox_log.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "hall_log/hall_log.hpp"
#include "io/input_error.hpp"
#include "lab/logs/log_estimate.hpp"

namespace fl {
namespace {

constexpr double kPeriod = 1.2345;   // s, the plate's
constexpr double kAmplitude = 0.02;  // m
constexpr double kSensorAt = 0.018;  // m, the phone near the plate's largest displacement
constexpr double kDistance = 0.008;  // m, from the magnet's path to the phone
constexpr double kRateHz = 100.0;    // phyphox's magnetometer on a typical phone
constexpr double kSeconds = 30.0;

// The field a magnet on the axis through it makes at the phone: a dipole at distance r falls as
// 1 / r^3; `peak` at the closest approach [µT]. The pulse is along `axis` (0 x, 1 y, 2 z).
struct Field {
  double x, y, z;
};
Field field_at(double t, int axis, double peak) {
  const double x = kAmplitude * std::cos(2.0 * std::numbers::pi * t / kPeriod);
  const double r2 = (x - kSensorAt) * (x - kSensorAt) + kDistance * kDistance;
  const double pulse = peak * std::pow(kDistance * kDistance / r2, 1.5);
  Field b{22.0, -6.0, -41.0};  // the Earth's field where the phone lies [µT]
  (axis == 0 ? b.x : axis == 1 ? b.y : b.z) += pulse;
  return b;
}

enum class Form { kComma, kTab, kSemicolonDecimalComma, kTabDecimalComma };

std::string number_text(double v, Form form) {
  std::ostringstream out;
  out.precision(10);
  out << std::scientific << v;
  std::string s = out.str();
  if (form == Form::kSemicolonDecimalComma || form == Form::kTabDecimalComma)
    for (char& c : s)
      if (c == '.') c = ',';
  return s;
}

// phyphox's magnetometer CSV: quoted header, one row per sample.
std::string phone_csv(Form form, int axis, bool with_absolute) {
  const char sep = form == Form::kComma ? ',' : form == Form::kSemicolonDecimalComma ? ';' : '\t';
  std::string text = "\"Time (s)\"";
  for (const char* name : {"Magnetic field x (\xC2\xB5T)", "Magnetic field y (\xC2\xB5T)",
                           "Magnetic field z (\xC2\xB5T)"})
    text += sep + std::string("\"") + name + "\"";
  if (with_absolute) text += sep + std::string("\"Absolute field (\xC2\xB5T)\"");
  text += '\n';
  std::mt19937 noise_seed(7);
  std::normal_distribution<double> noise(0.0, 0.15);
  for (int i = 0; i < static_cast<int>(kSeconds * kRateHz); ++i) {
    const double t = i / kRateHz;
    Field b = field_at(t, axis, 60.0);
    b.x += noise(noise_seed);
    b.y += noise(noise_seed);
    b.z += noise(noise_seed);
    text += number_text(t, form);
    for (double v : {b.x, b.y, b.z}) text += sep + number_text(v, form);
    if (with_absolute)
      text += sep + number_text(std::sqrt(b.x * b.x + b.y * b.y + b.z * b.z), form);
    text += '\n';
  }
  return text;
}

LogEstimate estimate(const HallLog& log) {
  return estimate_log(log, LogSetUp{}, false);
}

TEST(PhyphoxMagnetometer, TheRigsEstimatorReadsThePlatesPeriod) {
  const HallLog log = parse_hall_log(phone_csv(Form::kComma, 2, true), "phone.csv");
  EXPECT_EQ(instrument_words(log.instrument), "phyphox magnetometer");
  EXPECT_EQ(log.reading.format, "phyphox");
  EXPECT_EQ(log.t_s.size(), static_cast<std::size_t>(kSeconds * kRateHz));
  const LogEstimate e = estimate(log);
  ASSERT_GE(e.stats.periods_used, 20u);
  // The stated target: T within 0.05 % of the truth at a phone's 100 Hz over 30 s.
  EXPECT_NEAR(e.stats.period_s, kPeriod, 5e-4 * kPeriod);
  EXPECT_LT(e.stats.period_sem_s, 5e-4 * kPeriod);
}

TEST(PhyphoxMagnetometer, EveryCsvFormGivesTheSameTAndTheChannelWithThePulses) {
  for (int axis = 0; axis < 3; ++axis) {
    const HallLog comma = parse_hall_log(phone_csv(Form::kComma, axis, false), "phone.csv");
    const double t_comma = estimate(comma).stats.period_s;
    EXPECT_NEAR(t_comma, kPeriod, 5e-4 * kPeriod) << "pulse along axis " << axis;
    // The pulse lies along one axis: the channel read is that component or |B|, never a component
    // that holds only the Earth's field and noise.
    const std::string along(1, "xyz"[axis]);
    EXPECT_TRUE(comma.channel == along || comma.channel == "|B|") << comma.channel;
    for (Form form : {Form::kTab, Form::kSemicolonDecimalComma, Form::kTabDecimalComma}) {
      const HallLog other = parse_hall_log(phone_csv(form, axis, false), "phone.csv");
      EXPECT_EQ(other.reading.decimal_comma, form != Form::kTab);
      EXPECT_EQ(other.channel, comma.channel);
      EXPECT_NEAR(estimate(other).stats.period_s, t_comma, 1e-12 * kPeriod);
    }
  }
}

TEST(PhyphoxMagnetometer, ABrokenRowIsRefusedAtItsLine) {
  std::string text = phone_csv(Form::kComma, 2, true);
  const std::size_t third = text.find('\n', text.find('\n', text.find('\n') + 1) + 1);
  text.insert(third + 1, "0.031,12.0,abc,4.0,5.0\n");
  try {
    parse_hall_log(text, "phone.csv");
    FAIL() << "a row with a word in it was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("phone.csv:4"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("found \"abc\""), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fl
