// The range each quantity of the friction oscillator takes on any bench. The paper's rig sets the
// scale: rollers 89 mm apart and 10 mm in radius, mu_k from 0.2 to 1.7 (10 for a flexible foam),
// periods near 0.8 s, rollers at 1600 rpm, h_c a few millimetres. A value far beyond it is not a
// rig's but a slip of the unit or of the keyboard (89 read as metres, 1e300), and a front end
// refuses it, saying the range, the value and the unit it was read in, instead of computing a
// number nobody can use.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "text/said.hpp"

namespace fl {

struct PlausibleRange {
  std::string_view what;   // its message ("quantity-spacing": "quantity-spacing")
  double least;            // SI
  double most;             // SI
  std::string_view unit;   // the unit the message shows it in ("mm")
  double per_unit;         // SI per that unit (1e-3 for mm)
  std::string_view paper;  // the message of the paper's rig's value, for scale ("paper-spacing")
};

inline constexpr PlausibleRange kSpacingRange{"quantity-spacing", 1e-3, 2.0, "mm", 1e-3,
                                              "paper-spacing"};
inline constexpr PlausibleRange kMuKRange{"quantity-mu-k", 1e-3, 100.0, "", 1.0, "paper-mu-k"};
inline constexpr PlausibleRange kHcRange{"quantity-h-c", 0.0, 0.5, "mm", 1e-3, "paper-h-c"};

namespace plausible_detail {
// sqrt for the ranges below, at compile time (Newton's iteration from above).
constexpr double root(double x) {
  double r = x > 1.0 ? x : 1.0;
  for (int i = 0; i < 200; ++i) r = 0.5 * (r + x / r);
  return r;
}
constexpr double kPi = 3.14159265358979323846;
constexpr double kStandardGravity = 9.81;  // the lab's default g [m/s^2]
// The thin plate's period T = pi sqrt(2 l / (mu_k g)) [s].
constexpr double thin_period(double spacing, double mu_k) {
  return kPi * root(2.0 * spacing / (mu_k * kStandardGravity));
}
}  // namespace plausible_detail

// The periods the spacings and mu_k above give at g = 9.81 m/s^2: from the shortest spacing at
// the largest mu_k (4.5 ms) to the longest at the smallest (63 s). A period beyond them is no
// rig's at any spacing; a mu_k derived from a period within them is checked against kMuKRange
// too, at the rig's own l and g.
inline constexpr PlausibleRange kPeriodRange{
    "quantity-period",
    plausible_detail::thin_period(kSpacingRange.least, kMuKRange.most),
    plausible_detail::thin_period(kSpacingRange.most, kMuKRange.least),
    "s",
    1.0,
    "paper-period"};
// The plate's amplitude: beyond the longest spacing the plate has long left the rollers.
inline constexpr PlausibleRange kAmplitudeRange{
    "quantity-amplitude", 0.0, kSpacingRange.most, "mm", 1e-3, "paper-amplitude"};
inline constexpr PlausibleRange kGravityRange{"quantity-gravity", 0.1, 100.0, "m/s^2", 1.0,
                                              "paper-gravity"};
inline constexpr PlausibleRange kRollerSpeedRange{"quantity-roller-speed",
                                                  0.0,
                                                  1e5 * 2.0 * 3.14159265358979323846 / 60.0,
                                                  "rpm",
                                                  2.0 * 3.14159265358979323846 / 60.0,
                                                  "paper-roller-speed"};
inline constexpr PlausibleRange kRollerRadiusRange{"quantity-roller-radius", 1e-4, 0.5, "mm", 1e-3,
                                                   "paper-roller-radius"};

// Why `value` [SI] is beyond the range ("expected the roller spacing l from 1 to 2000 mm (the
// paper's rig: 89 mm), found 89000 mm"), or nothing when it is within it. NaN is beyond it.
std::optional<std::string> implausible(double value, const PlausibleRange& range);
// The same, as the lab says it (check-implausible).
std::optional<Said> implausible_said(double value, const PlausibleRange& range);

// For a plain number (SI) beyond the range, as written (`text`): the advice that the unit a rig
// measures it in would bring it within (": a plain number is SI, so 790 was read as 790 s; write
// 790ms for milliseconds"; millimetres for a length), or "" when that unit would not either.
std::string plain_number_advice(double value, std::string_view text, const PlausibleRange& range);

}  // namespace fl
