#include "scene/ramp_yaml.hpp"

#include <cmath>

#include "text/describe.hpp"

namespace fl {

namespace {

// A point's value, checked against the key's range.
double ramp_value(const YamlNode& value, const RampKey& key) {
  const double v = value.quantity(key.dimension);
  const bool low = !(v >= key.least);
  const bool high = key.most && v > *key.most;
  if (!std::isfinite(v) || low || high)
    value.fail(key.most ? describe("expected a value from ", key.least, " to ", *key.most,
                                   ", found ", value.text())
                        : describe("expected a value >= ", key.least, ", found ", value.text()));
  return v;
}

RampPair read_points(const YamlNode& node, const RampKey& key, bool pairs) {
  if (!node.is_sequence() || node.size() == 0)
    node.fail("expected a list of points, e.g. [" + key.example + ", ...]");
  RampPair out;
  std::vector<RampPoint>& points = out.first;
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
    if (!(std::isfinite(p.at) && p.at >= 0.0))
      at.fail("expected a time >= 0 s (from the run's start), found " + at.text());
    if (!points.empty() && !(p.at > points.back().at))
      at.fail(describe("expected a time after the previous point's ", points.back().at,
                       " s (times must increase), found ", at.text()));
    const bool two = pairs && value.is_sequence();
    if (two && value.size() != 2)
      value.fail("expected one " + key.value_key + ", or a list of 2 [roller 0, roller 1]");
    if (i > 0 && two != !out.second.empty())
      value.fail(two ? "expected one " + key.value_key +
                           " as the first point gives, or two at "
                           "every point"
                     : "expected two, [roller 0, roller 1], as the first point gives: every "
                       "point gives one or every point two");
    p.value = ramp_value(two ? value[0] : value, key);
    points.push_back(p);
    if (two) out.second.push_back({p.at, ramp_value(value[1], key)});
  }
  return out;
}

}  // namespace

std::vector<RampPoint> read_ramp(const YamlNode& node, const RampKey& key) {
  return read_points(node, key, false).first;
}

RampPair read_ramp_pair(const YamlNode& node, const RampKey& key) {
  return read_points(node, key, true);
}

}  // namespace fl
