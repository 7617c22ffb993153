// The scene keys that schedule a quantity over time (rollers.speed_ramp, drive.motor.duty_ramp):
// a list of points {at: TIME, KEY: VALUE}, read strictly, each error located at the point.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/ramp.hpp"
#include "io/yaml_node.hpp"

namespace fl {

struct RampKey {
  std::string value_key;       // "speed", "duty"
  Dimension dimension;         // of the value
  double least = 0.0;          // the smallest value allowed (SI)
  std::optional<double> most;  // the largest value allowed (SI), if any
  std::string example;         // "{at: 0 s, speed: 100 rpm}"
};

// Reads the list; refuses an empty list, a point without `at` or the value key, an unknown key,
// a time < 0 or not after the previous point's, and a value outside [least, most].
std::vector<RampPoint> read_ramp(const YamlNode& node, const RampKey& key);

// A schedule for two (rollers.speed_ramp: each point's value one speed for both rollers, or
// [roller 0, roller 1]): `first` the one or roller 0's, `second` roller 1's when the points give
// two (empty otherwise). Every point gives one value, or every point two.
struct RampPair {
  std::vector<RampPoint> first;
  std::vector<RampPoint> second;
};
RampPair read_ramp_pair(const YamlNode& node, const RampKey& key);

}  // namespace fl
