#include "core/units.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <span>

#include "text/decimal.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

struct Unit {
  std::string_view symbol;
  double scale;   // SI value of one unit
  double offset;  // SI value of the unit's zero (only degrees Celsius have one)
};

// The first symbol of each list is the SI unit; every list is the complete set accepted.
constexpr std::array kDimensionless{Unit{"", 1.0, 0.0}, Unit{"%", 0.01, 0.0},
                                    Unit{"ppm", 1e-6, 0.0}};
constexpr std::array kLength{Unit{"m", 1.0, 0.0},   Unit{"cm", 1e-2, 0.0}, Unit{"mm", 1e-3, 0.0},
                             Unit{"um", 1e-6, 0.0}, Unit{"µm", 1e-6, 0.0}, Unit{"km", 1e3, 0.0}};
constexpr std::array kTime{Unit{"s", 1.0, 0.0},   Unit{"ms", 1e-3, 0.0},  Unit{"us", 1e-6, 0.0},
                           Unit{"µs", 1e-6, 0.0}, Unit{"min", 60.0, 0.0}, Unit{"h", 3600.0, 0.0}};
constexpr std::array kMass{Unit{"kg", 1.0, 0.0}, Unit{"g", 1e-3, 0.0}, Unit{"mg", 1e-6, 0.0}};
constexpr std::array kAngle{Unit{"rad", 1.0, 0.0}, Unit{"deg", kPi / 180.0, 0.0},
                            Unit{"°", kPi / 180.0, 0.0}, Unit{"mrad", 1e-3, 0.0}};
constexpr std::array kAngularSpeed{Unit{"rad/s", 1.0, 0.0}, Unit{"rpm", kRadPerSecondPerRpm, 0.0},
                                   Unit{"rev/s", 2.0 * kPi, 0.0}, Unit{"deg/s", kPi / 180.0, 0.0}};
constexpr std::array kSpeed{Unit{"m/s", 1.0, 0.0}, Unit{"cm/s", 1e-2, 0.0},
                            Unit{"mm/s", 1e-3, 0.0}};
constexpr std::array kAcceleration{Unit{"m/s^2", 1.0, 0.0}, Unit{"m/s2", 1.0, 0.0},
                                   Unit{"mm/s^2", 1e-3, 0.0}};
constexpr std::array kFrequency{Unit{"Hz", 1.0, 0.0}, Unit{"kHz", 1e3, 0.0}, Unit{"MHz", 1e6, 0.0}};
constexpr std::array kTemperature{Unit{"K", 1.0, 0.0}, Unit{"degC", 1.0, 273.15},
                                  Unit{"°C", 1.0, 273.15}};
constexpr std::array kVoltage{Unit{"V", 1.0, 0.0}, Unit{"mV", 1e-3, 0.0}};
constexpr std::array kCurrent{Unit{"A", 1.0, 0.0}, Unit{"mA", 1e-3, 0.0}};
constexpr std::array kForce{Unit{"N", 1.0, 0.0}, Unit{"mN", 1e-3, 0.0}};
constexpr std::array kTorque{Unit{"N m", 1.0, 0.0},   Unit{"N*m", 1.0, 0.0},
                             Unit{"Nm", 1.0, 0.0},    Unit{"mN m", 1e-3, 0.0},
                             Unit{"mN*m", 1e-3, 0.0}, Unit{"N cm", 1e-2, 0.0}};
constexpr std::array kDensity{Unit{"kg/m^3", 1.0, 0.0}, Unit{"kg/m3", 1.0, 0.0},
                              Unit{"g/cm^3", 1e3, 0.0}, Unit{"g/cm3", 1e3, 0.0}};
constexpr std::array kMagneticField{Unit{"T", 1.0, 0.0}, Unit{"mT", 1e-3, 0.0},
                                    Unit{"uT", 1e-6, 0.0}, Unit{"µT", 1e-6, 0.0},
                                    Unit{"G", 1e-4, 0.0}};
constexpr std::array kInertia{Unit{"kg m^2", 1.0, 0.0}, Unit{"kg*m^2", 1.0, 0.0},
                              Unit{"g cm^2", 1e-7, 0.0}, Unit{"g*cm^2", 1e-7, 0.0}};
constexpr std::array kInverseSpeed{Unit{"s/m", 1.0, 0.0}};
constexpr std::array kSensitivity{Unit{"V/T", 1.0, 0.0}, Unit{"mV/mT", 1.0, 0.0},
                                  Unit{"mV/G", 10.0, 0.0}};

std::span<const Unit> units_of(Dimension dimension) {
  switch (dimension) {
    case Dimension::kDimensionless:
      return kDimensionless;
    case Dimension::kLength:
      return kLength;
    case Dimension::kTime:
      return kTime;
    case Dimension::kMass:
      return kMass;
    case Dimension::kAngle:
      return kAngle;
    case Dimension::kAngularSpeed:
      return kAngularSpeed;
    case Dimension::kSpeed:
      return kSpeed;
    case Dimension::kAcceleration:
      return kAcceleration;
    case Dimension::kFrequency:
      return kFrequency;
    case Dimension::kTemperature:
      return kTemperature;
    case Dimension::kVoltage:
      return kVoltage;
    case Dimension::kCurrent:
      return kCurrent;
    case Dimension::kForce:
      return kForce;
    case Dimension::kTorque:
      return kTorque;
    case Dimension::kDensity:
      return kDensity;
    case Dimension::kMagneticField:
      return kMagneticField;
    case Dimension::kSensitivity:
      return kSensitivity;
    case Dimension::kInertia:
      return kInertia;
    case Dimension::kInverseSpeed:
      return kInverseSpeed;
  }
  return kDimensionless;
}

[[noreturn]] void fail(Dimension dimension, std::string_view text, std::string_view quantity,
                       std::string_view why) {
  std::string message;
  message += quantity;
  message += ": expected ";
  message += dimension_with_article(dimension);
  message += " (a number with one of the units: ";
  message += accepted_units(dimension);
  message += "), found \"";
  message += text;
  message += "\"";
  if (!why.empty()) {
    message += ": ";
    message += why;
  }
  throw UnitError(message);
}

struct Number {
  double value;
  std::string_view rest;  // what follows the number
  int decimals;           // digits after the decimal point
};

// Reads a leading decimal number; nullopt-like failure is signalled by rest == text.
bool read_number(std::string_view text, Number& out) {
  std::string_view s = text;
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double value = 0.0;
  const auto [ptr, ec] = read_decimal(s.data(), s.data() + s.size(), value);
  if (ec != std::errc{} || ptr == s.data()) return false;
  const std::string_view number(s.data(), static_cast<std::size_t>(ptr - s.data()));
  int decimals = 0;
  if (const auto dot = number.find('.'); dot != std::string_view::npos) {
    std::size_t i = dot + 1;
    while (i < number.size() && number[i] >= '0' && number[i] <= '9') ++i;
    decimals = static_cast<int>(i - dot - 1);
  }
  out = Number{value, s.substr(number.size()), decimals};
  return true;
}

const Unit* find_unit(Dimension dimension, std::string_view symbol) {
  for (const Unit& unit : units_of(dimension)) {
    if (unit.symbol == symbol) return &unit;
  }
  return nullptr;
}

}  // namespace

std::string_view dimension_name(Dimension dimension) {
  switch (dimension) {
    case Dimension::kDimensionless:
      return "dimensionless number";
    case Dimension::kLength:
      return "length";
    case Dimension::kTime:
      return "time";
    case Dimension::kMass:
      return "mass";
    case Dimension::kAngle:
      return "angle";
    case Dimension::kAngularSpeed:
      return "angular speed";
    case Dimension::kSpeed:
      return "speed";
    case Dimension::kAcceleration:
      return "acceleration";
    case Dimension::kFrequency:
      return "frequency";
    case Dimension::kTemperature:
      return "temperature";
    case Dimension::kVoltage:
      return "voltage";
    case Dimension::kCurrent:
      return "current";
    case Dimension::kForce:
      return "force";
    case Dimension::kTorque:
      return "torque";
    case Dimension::kDensity:
      return "density";
    case Dimension::kMagneticField:
      return "magnetic field";
    case Dimension::kSensitivity:
      return "sensitivity";
    case Dimension::kInertia:
      return "moment of inertia";
    case Dimension::kInverseSpeed:
      return "inverse speed";
  }
  return "quantity";
}

std::string dimension_with_article(Dimension dimension) {
  const std::string_view name = dimension_name(dimension);
  const bool vowel = std::string_view("aeiou").find(name.front()) != std::string_view::npos;
  return std::string(vowel ? "an " : "a ").append(name);
}

std::string accepted_units(Dimension dimension) {
  std::string list;
  for (const Unit& unit : units_of(dimension)) {
    if (!list.empty()) list += ", ";
    list += unit.symbol.empty() ? std::string_view("none (a plain number)") : unit.symbol;
  }
  return list;
}

double parse_quantity(std::string_view text, Dimension dimension, std::string_view quantity) {
  const std::string_view body = trim(text);
  if (body.empty()) fail(dimension, text, quantity, "the text is empty");
  Number number{};
  if (!read_number(body, number))
    fail(dimension, text, quantity, "it does not start with a number");
  if (!std::isfinite(number.value)) fail(dimension, text, quantity, "the number is not finite");
  const std::string_view symbol = trim(number.rest);
  // A plain number means SI.
  if (symbol.empty()) return number.value;
  const Unit* unit = find_unit(dimension, symbol);
  if (unit == nullptr) {
    std::string why = "unknown unit \"";
    why += symbol;
    why += "\" for ";
    why += dimension_with_article(dimension);
    fail(dimension, text, quantity, why);
  }
  const double si = number.value * unit->scale + unit->offset;
  if (!std::isfinite(si)) fail(dimension, text, quantity, "the value overflows");
  return si;
}

Measured parse_measured(std::string_view text, Dimension dimension, std::string_view quantity) {
  const std::string_view body = trim(text);
  std::size_t sep = body.find("+-");
  std::size_t sep_len = 2;
  if (sep == std::string_view::npos) {
    sep = body.find("±");
    sep_len = std::string_view("±").size();
  }
  Measured measured{};
  if (sep == std::string_view::npos) {
    measured.value = parse_quantity(body, dimension, quantity);
    Number number{};
    if (read_number(body, number)) measured.decimals = number.decimals;
    return measured;
  }
  // "0.79 +- 0.03 s": the unit after the uncertainty applies to both numbers.
  const std::string_view value_text = trim(body.substr(0, sep));
  const std::string_view error_text = trim(body.substr(sep + sep_len));
  Number value{};
  Number error{};
  if (!read_number(value_text, value) || !trim(value.rest).empty())
    fail(dimension, text, quantity, "the value before \"+-\" must be a plain number");
  if (!read_number(error_text, error))
    fail(dimension, text, quantity, "the uncertainty after \"+-\" must be a number");
  if (error.value < 0.0) fail(dimension, text, quantity, "the uncertainty is negative");
  const std::string_view unit_text = trim(error.rest);
  double scale = 1.0;
  double offset = 0.0;
  if (!unit_text.empty()) {
    const Unit* unit = find_unit(dimension, unit_text);
    if (unit == nullptr) {
      fail(dimension, text, quantity,
           std::string("unknown unit \"").append(unit_text).append("\""));
    }
    scale = unit->scale;
    offset = unit->offset;
  }
  measured.value = value.value * scale + offset;
  measured.uncertainty = error.value * scale;
  measured.decimals = value.decimals;
  measured.uncertainty_decimals = error.decimals;
  return measured;
}

}  // namespace fl
