#include "scene/ramp_yaml.hpp"

#include <cmath>

#include "core/describe.hpp"

namespace fl {

std::vector<RampPoint> read_ramp(const YamlNode& node, const RampKey& key) {
  if (!node.is_sequence() || node.size() == 0)
    node.fail("expected a list of points, e.g. [" + key.example + ", ...]");
  std::vector<RampPoint> points;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YamlNode item = node[i];
    if (!item.is_map()) item.fail("expected a point " + key.example);
    item.allow_keys({"at", key.value_key});
    if (!item.has("at")) item.fail("a point needs its time 'at', e.g. " + key.example);
    if (!item.has(key.value_key))
      item.fail("a point needs its '" + key.value_key + "', e.g. " + key.example);
    const YamlNode at = item.at("at");
    const YamlNode value = item.at(key.value_key);
    RampPoint p;
    p.at = at.quantity(Dimension::kTime);
    p.value = value.quantity(key.dimension);
    if (!(std::isfinite(p.at) && p.at >= 0.0))
      at.fail("expected a time >= 0 s (from the run's start), found " + at.text());
    if (!points.empty() && !(p.at > points.back().at))
      at.fail(describe("expected a time after the previous point's ", points.back().at,
                       " s (times must increase), found ", at.text()));
    const bool low = !(p.value >= key.least);
    const bool high = key.most && p.value > *key.most;
    if (!std::isfinite(p.value) || low || high)
      value.fail(key.most ? describe("expected a value from ", key.least, " to ", *key.most,
                                     ", found ", value.text())
                          : describe("expected a value >= ", key.least, ", found ", value.text()));
    points.push_back(p);
  }
  return points;
}

}  // namespace fl
