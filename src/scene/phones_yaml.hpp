// The scene's `phones` list: each a phone's magnetometer beside the rig or its accelerometer on
// the plate (scene/scene.hpp, PhoneDesc), read strictly: a key of the other sensor is an error
// that says which sensor takes it.
#pragma once

#include <vector>

#include "io/yaml_node.hpp"
#include "scene/scene.hpp"

namespace fl {

std::vector<PhoneDesc> read_phones(const YamlNode& node);

}  // namespace fl
