// Units: every accepted unit converts to SI; every bad text names the quantity, the text and
// the units it accepts.
#include "core/units.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

namespace fl {
namespace {

struct UnitCase {
  const char* text;
  Dimension dimension;
  double si;
};

class UnitsTest : public ::testing::TestWithParam<UnitCase> {};

TEST_P(UnitsTest, ConvertsToSi) {
  const UnitCase& c = GetParam();
  const double got = parse_quantity(c.text, c.dimension, "q");
  EXPECT_NEAR(got, c.si, 1e-12 * std::max(1.0, std::fabs(c.si))) << c.text;
}

constexpr double kPi = std::numbers::pi;

INSTANTIATE_TEST_SUITE_P(
    EveryUnit, UnitsTest,
    ::testing::Values(
        UnitCase{"0.5", Dimension::kDimensionless, 0.5},
        UnitCase{"5 %", Dimension::kDimensionless, 0.05},
        UnitCase{"89 mm", Dimension::kLength, 0.089}, UnitCase{"89mm", Dimension::kLength, 0.089},
        UnitCase{"2 m", Dimension::kLength, 2.0}, UnitCase{"8.9 cm", Dimension::kLength, 0.089},
        UnitCase{"250 um", Dimension::kLength, 250e-6},
        UnitCase{"250 µm", Dimension::kLength, 250e-6},
        UnitCase{"0.001 km", Dimension::kLength, 1.0},
        UnitCase{"8.9e-2 m", Dimension::kLength, 0.089},
        UnitCase{"0.089", Dimension::kLength, 0.089},
        UnitCase{"  -3 mm ", Dimension::kLength, -0.003},
        UnitCase{"+3 mm", Dimension::kLength, 0.003}, UnitCase{"0.79 s", Dimension::kTime, 0.79},
        UnitCase{"790 ms", Dimension::kTime, 0.79}, UnitCase{"100 us", Dimension::kTime, 1e-4},
        UnitCase{"100 µs", Dimension::kTime, 1e-4}, UnitCase{"2 min", Dimension::kTime, 120.0},
        UnitCase{"1 h", Dimension::kTime, 3600.0}, UnitCase{"50 g", Dimension::kMass, 0.05},
        UnitCase{"1.5 kg", Dimension::kMass, 1.5}, UnitCase{"20 mg", Dimension::kMass, 20e-6},
        UnitCase{"180 deg", Dimension::kAngle, kPi}, UnitCase{"90 °", Dimension::kAngle, kPi / 2},
        UnitCase{"1 rad", Dimension::kAngle, 1.0}, UnitCase{"5 mrad", Dimension::kAngle, 5e-3},
        UnitCase{"1600 rpm", Dimension::kAngularSpeed, 1600.0 * 2.0 * kPi / 60.0},
        UnitCase{"3 rad/s", Dimension::kAngularSpeed, 3.0},
        UnitCase{"2 rev/s", Dimension::kAngularSpeed, 4.0 * kPi},
        UnitCase{"360 deg/s", Dimension::kAngularSpeed, 2.0 * kPi},
        UnitCase{"0.2 m/s", Dimension::kSpeed, 0.2}, UnitCase{"20 cm/s", Dimension::kSpeed, 0.2},
        UnitCase{"200 mm/s", Dimension::kSpeed, 0.2},
        UnitCase{"9.81 m/s^2", Dimension::kAcceleration, 9.81},
        UnitCase{"9.81 m/s2", Dimension::kAcceleration, 9.81},
        UnitCase{"9810 mm/s^2", Dimension::kAcceleration, 9.81},
        UnitCase{"1 kHz", Dimension::kFrequency, 1000.0},
        UnitCase{"200 Hz", Dimension::kFrequency, 200.0},
        UnitCase{"16 MHz", Dimension::kFrequency, 16e6},
        UnitCase{"77 K", Dimension::kTemperature, 77.0},
        UnitCase{"27 degC", Dimension::kTemperature, 300.15},
        UnitCase{"-196 °C", Dimension::kTemperature, 77.15},
        UnitCase{"12 V", Dimension::kVoltage, 12.0}, UnitCase{"500 mV", Dimension::kVoltage, 0.5},
        UnitCase{"1.2 A", Dimension::kCurrent, 1.2}, UnitCase{"300 mA", Dimension::kCurrent, 0.3},
        UnitCase{"2 N", Dimension::kForce, 2.0}, UnitCase{"20 mN", Dimension::kForce, 0.02},
        UnitCase{"0.1 N m", Dimension::kTorque, 0.1}, UnitCase{"0.1 N*m", Dimension::kTorque, 0.1},
        UnitCase{"0.1 Nm", Dimension::kTorque, 0.1}, UnitCase{"100 mN m", Dimension::kTorque, 0.1},
        UnitCase{"100 mN*m", Dimension::kTorque, 0.1}, UnitCase{"10 N cm", Dimension::kTorque, 0.1},
        UnitCase{"1200 kg/m^3", Dimension::kDensity, 1200.0},
        UnitCase{"1200 kg/m3", Dimension::kDensity, 1200.0},
        UnitCase{"1.2 g/cm^3", Dimension::kDensity, 1200.0},
        UnitCase{"1.2 g/cm3", Dimension::kDensity, 1200.0},
        UnitCase{"1.3 T", Dimension::kMagneticField, 1.3},
        UnitCase{"10 mT", Dimension::kMagneticField, 0.01},
        UnitCase{"50 uT", Dimension::kMagneticField, 50e-6},
        UnitCase{"50 µT", Dimension::kMagneticField, 50e-6},
        UnitCase{"100 G", Dimension::kMagneticField, 0.01},
        UnitCase{"25 V/T", Dimension::kSensitivity, 25.0},
        UnitCase{"25 mV/mT", Dimension::kSensitivity, 25.0},
        UnitCase{"2.5 mV/G", Dimension::kSensitivity, 25.0},
        UnitCase{"1e-5 kg m^2", Dimension::kInertia, 1e-5},
        UnitCase{"1e-5 kg*m^2", Dimension::kInertia, 1e-5},
        UnitCase{"100 g cm^2", Dimension::kInertia, 1e-5},
        UnitCase{"100 g*cm^2", Dimension::kInertia, 1e-5},
        UnitCase{"-0.5 s/m", Dimension::kInverseSpeed, -0.5}));

std::string error_of(const char* text, Dimension dimension, const char* quantity) {
  try {
    parse_quantity(text, dimension, quantity);
  } catch (const UnitError& e) {
    return e.what();
  }
  return "";
}

TEST(UnitsErrors, WrongUnitNamesQuantityTextAndAcceptedUnits) {
  const std::string message = error_of("89 kg", Dimension::kLength, "rollers.spacing");
  EXPECT_NE(message.find("rollers.spacing"), std::string::npos) << message;
  EXPECT_NE(message.find("\"89 kg\""), std::string::npos) << message;
  EXPECT_NE(message.find("length"), std::string::npos) << message;
  EXPECT_NE(message.find("m, cm, mm, um, µm, km"), std::string::npos) << message;
  EXPECT_NE(message.find("unknown unit \"kg\""), std::string::npos) << message;
}

TEST(UnitsErrors, TheDimensionTakesItsArticle) {
  EXPECT_EQ(error_of("3 m", Dimension::kAngularSpeed, "rollers.speed"),
            "rollers.speed: expected an angular speed (a number with one of the units: rad/s, "
            "rpm, rev/s, deg/s), found \"3 m\": unknown unit \"m\" for an angular speed");
  EXPECT_EQ(dimension_with_article(Dimension::kLength), "a length");
  EXPECT_EQ(dimension_with_article(Dimension::kAcceleration), "an acceleration");
}

TEST(UnitsErrors, EveryBadTextIsRefused) {
  for (const char* bad : {"", "   ", "mm", "abc", "89 mmm", "89 MM", "1600 rmp", "nan", "inf m",
                          "1e999 m", "89 mm extra", "--3 mm", "0x10 mm"}) {
    EXPECT_FALSE(error_of(bad, Dimension::kLength, "x").empty()) << "accepted \"" << bad << "\"";
  }
  // A unit of another dimension is refused even though it is a unit.
  EXPECT_FALSE(error_of("0.79 s", Dimension::kLength, "x").empty());
  EXPECT_FALSE(error_of("77 K", Dimension::kTime, "x").empty());
  EXPECT_FALSE(error_of("5 %", Dimension::kLength, "x").empty());
}

TEST(Measured, ReadsValueUncertaintyAndPrintedPrecision) {
  const Measured m = parse_measured("0.79 +- 0.03 s", Dimension::kTime, "T");
  EXPECT_DOUBLE_EQ(m.value, 0.79);
  EXPECT_DOUBLE_EQ(m.uncertainty, 0.03);
  EXPECT_EQ(m.decimals, 2);
  EXPECT_EQ(m.uncertainty_decimals, 2);
  const Measured l = parse_measured("89 ± 2 mm", Dimension::kLength, "l");
  EXPECT_DOUBLE_EQ(l.value, 0.089);
  EXPECT_DOUBLE_EQ(l.uncertainty, 0.002);
  EXPECT_EQ(l.decimals, 0);
  const Measured mu = parse_measured("0.113 +- 0.006", Dimension::kDimensionless, "mu");
  EXPECT_EQ(mu.decimals, 3);
  const Measured plain = parse_measured("1.5 mm", Dimension::kLength, "x");
  EXPECT_DOUBLE_EQ(plain.value, 0.0015);
  EXPECT_EQ(plain.uncertainty, 0.0);
  EXPECT_EQ(plain.decimals, 1);
}

TEST(Measured, BadTextsAreRefused) {
  for (const char* bad :
       {"0.79 +- s", "0.79 s +- 0.03 s", "0.79 +- -0.03 s", "+- 0.03 s", "0.79 +- 0.03 furlong"}) {
    EXPECT_THROW(parse_measured(bad, Dimension::kTime, "T"), UnitError) << bad;
  }
}

}  // namespace
}  // namespace fl
