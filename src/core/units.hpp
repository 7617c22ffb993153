// Quantities with units, the way the paper writes them ("89 mm", "1600 rpm", "0.79 s", "77 K").
// Parsing returns SI values; a plain number means SI. The core opens no file: callers that know
// where a text came from add the location to the error.
#pragma once

#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>

namespace fl {

// The lab's one pi, and its one conversion between rad/s and rpm (the unit "rpm" of quantities).
inline constexpr double kPi = std::numbers::pi;
inline constexpr double kRadPerSecondPerRpm = 2.0 * kPi / 60.0;
inline constexpr double kRpmPerRadPerSecond = 60.0 / (2.0 * kPi);

// The physical dimension a quantity must have; it decides which units are accepted.
enum class Dimension {
  kDimensionless,  // "", "%"
  kLength,         // m
  kTime,           // s
  kMass,           // kg
  kAngle,          // rad
  kAngularSpeed,   // rad/s
  kSpeed,          // m/s
  kAcceleration,   // m/s^2
  kFrequency,      // Hz
  kTemperature,    // K
  kVoltage,        // V
  kCurrent,        // A
  kForce,          // N
  kTorque,         // N m
  kDensity,        // kg/m^3
  kMagneticField,  // T
  kSensitivity,    // V/T (a Hall sensor's output per field)
  kInertia,        // kg m^2 (moment of inertia)
  kInverseSpeed,   // s/m (a friction coefficient's slope against slip speed)
};

// A quantity's text could not be read as the dimension asked for.
class UnitError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// "length", "angular speed", ...
std::string_view dimension_name(Dimension dimension);
// The name with its indefinite article: "a length", "an angular speed".
std::string dimension_with_article(Dimension dimension);

// The units accepted for a dimension, as a human list: "m, cm, mm, um, km".
std::string accepted_units(Dimension dimension);

// Parses "89 mm" (or "89mm", "8.9e-2 m", "0.089") into SI. `quantity` names what is being read
// ("rollers.spacing") so the error can say so. Throws UnitError naming the quantity, the text
// and the accepted units.
double parse_quantity(std::string_view text, Dimension dimension, std::string_view quantity);

// A measured value with its uncertainty as printed: "0.79 +- 0.03 s" or "0.79 ± 0.03 s".
// `decimals` is how many digits the value was printed with after the point (2 for "0.79"), so a
// recomputed value can be compared to the printed one at the printed precision.
struct Measured {
  double value = 0.0;        // SI
  double uncertainty = 0.0;  // SI, >= 0
  int decimals = 0;          // digits after the decimal point in the printed value
  int uncertainty_decimals = 0;
};

// Parses "0.79 +- 0.03 s"; a text without "+-" has zero uncertainty.
Measured parse_measured(std::string_view text, Dimension dimension, std::string_view quantity);

}  // namespace fl
