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

namespace fl {

struct PlausibleRange {
  std::string_view what;   // "the roller spacing l"
  double least;            // SI
  double most;             // SI
  std::string_view unit;   // the unit the message shows it in ("mm")
  double per_unit;         // SI per that unit (1e-3 for mm)
  std::string_view paper;  // the paper's rig's value, for scale ("89 mm")
};

inline constexpr PlausibleRange kSpacingRange{
    "the roller spacing l", 1e-3, 2.0, "mm", 1e-3, "89 mm"};
inline constexpr PlausibleRange kMuKRange{"mu_k", 1e-3, 100.0, "", 1.0, "0.2 to 10"};
inline constexpr PlausibleRange kHcRange{
    "the centre-of-mass height h_c", 0.0, 0.5, "mm", 1e-3, "a few mm"};
inline constexpr PlausibleRange kPeriodRange{"the period T", 1e-3, 3600.0, "s", 1.0, "0.3 to 1 s"};
inline constexpr PlausibleRange kGravityRange{"gravity g", 0.1, 100.0, "m/s^2", 1.0, "9.81 m/s^2"};
inline constexpr PlausibleRange kRollerSpeedRange{"the rollers' speed",
                                                  0.0,
                                                  1e5 * 2.0 * 3.14159265358979323846 / 60.0,
                                                  "rpm",
                                                  2.0 * 3.14159265358979323846 / 60.0,
                                                  "1600 rpm"};
inline constexpr PlausibleRange kRollerRadiusRange{
    "the roller radius", 1e-4, 0.5, "mm", 1e-3, "10 mm"};

// Why `value` [SI] is beyond the range ("expected the roller spacing l from 1 to 2000 mm (the
// paper's rig: 89 mm), found 89000 mm"), or nothing when it is within it. NaN is beyond it.
std::optional<std::string> implausible(double value, const PlausibleRange& range);

}  // namespace fl
