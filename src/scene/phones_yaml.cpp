#include "scene/phones_yaml.hpp"

#include <array>
#include <span>
#include <string>
#include <string_view>

namespace fl {
namespace {

Vec3 read_triple(const YamlNode& node, Dimension dimension, std::string_view example) {
  if (node.size() != 3)
    node.fail("expected a list of 3 values [x, y, z], e.g. " + std::string(example));
  return {node[0].quantity(dimension), node[1].quantity(dimension), node[2].quantity(dimension)};
}

// A key the other sensor takes, named as such.
void refuse_other_sensors_keys(const YamlNode& n, PhoneSensor sensor) {
  const bool magnetometer = sensor == PhoneSensor::kMagnetometer;
  static constexpr std::array<const char*, 5> kAccelerometers{"gravity", "x", "height", "mass",
                                                              "size"};
  static constexpr std::array<const char*, 2> kMagnetometers{"position", "earth"};
  const std::span<const char* const> others =
      magnetometer ? std::span<const char* const>(kAccelerometers) : kMagnetometers;
  for (const char* key : others) {
    if (auto v = n.find(key))
      v->fail(std::string("'") + key + "' is " +
              (magnetometer ? "an accelerometer's key (a phone lying on the plate)"
                            : "a magnetometer's key (a phone lying beside the rig)") +
              "; this phone's sensor is " + (magnetometer ? "magnetometer" : "accelerometer") +
              ": remove the key or change `sensor`");
  }
}

PhoneDesc read_phone(const YamlNode& n) {
  n.allow_keys({"sensor", "rate", "noise", "turn", "position", "earth", "gravity", "x", "height",
                "mass", "size"});
  const YamlNode kind = n.at("sensor");
  const std::string name = kind.text();
  if (name != "magnetometer" && name != "accelerometer")
    kind.fail(
        "expected magnetometer (a phone beside the rig) or accelerometer (a phone on the "
        "plate), found \"" +
        name + "\"");
  PhoneDesc p =
      phone_with(name == "magnetometer" ? PhoneSensor::kMagnetometer : PhoneSensor::kAccelerometer);
  refuse_other_sensors_keys(n, p.sensor);
  const bool magnetometer = p.sensor == PhoneSensor::kMagnetometer;
  if (auto v = n.find("rate")) p.rate = v->quantity(Dimension::kFrequency);
  if (auto v = n.find("noise"))
    p.noise = v->quantity(magnetometer ? Dimension::kMagneticField : Dimension::kAcceleration);
  if (auto v = n.find("turn")) p.turn = v->quantity(Dimension::kAngle);
  if (magnetometer) {
    p.position = read_triple(n.at("position"), Dimension::kLength, "[114 mm, 60 mm, -10 mm]");
    if (auto v = n.find("earth"))
      p.earth = read_triple(*v, Dimension::kMagneticField, "[21 uT, -4 uT, -43 uT]");
    return p;
  }
  if (auto v = n.find("gravity")) p.gravity = v->boolean();
  if (auto v = n.find("x")) p.x = v->quantity(Dimension::kLength);
  if (auto v = n.find("height")) p.height = v->quantity(Dimension::kLength);
  if (auto v = n.find("mass")) p.mass = v->quantity(Dimension::kMass);
  if (auto v = n.find("size"))
    p.size = read_triple(*v, Dimension::kLength, "[75 mm, 150 mm, 8 mm]");
  return p;
}

}  // namespace

std::vector<PhoneDesc> read_phones(const YamlNode& node) {
  if (!node.is_sequence())
    node.fail(
        "expected a list of phones, e.g. [{sensor: magnetometer, position: [114 mm, 60 mm, "
        "-10 mm]}, {sensor: accelerometer}]");
  std::vector<PhoneDesc> phones;
  for (std::size_t i = 0; i < node.size(); ++i) phones.push_back(read_phone(node[i]));
  return phones;
}

}  // namespace fl
