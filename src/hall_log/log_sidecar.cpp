#include "hall_log/log_sidecar.hpp"

#include <cmath>
#include <filesystem>

#include "core/plausible_range.hpp"
#include "io/unknown_material.hpp"
#include "io/yaml_node.hpp"

namespace fl {

std::string log_sidecar_path(const std::string& log) {
  return std::filesystem::path(log).replace_extension(".yaml").string();
}

std::optional<LogSidecar> read_log_sidecar(const std::string& log, const PaperTable* materials) {
  const std::string path = log_sidecar_path(log);
  std::error_code ec;
  if (log == "-" || path == log || !std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  const YamlNode root = load_yaml_file(path, 64u << 10);
  root.expect_map();
  root.allow_keys(
      {"label", "spacing", "spacing_err", "gravity", "material", "temperature", "geometry"});
  LogSidecar out;
  out.file = path;
  const auto positive = [](const YamlNode& node, Dimension dimension, bool zero_allowed) {
    const double v = node.quantity(dimension);
    if (!std::isfinite(v) || v < 0.0 || (!zero_allowed && v == 0.0))
      node.fail(zero_allowed ? "expected a finite value, not negative"
                             : "expected a finite positive value");
    return v;
  };
  if (auto n = root.find("label")) out.label = n->text();
  if (auto n = root.find("spacing")) {
    out.spacing = positive(*n, Dimension::kLength, false);
    // A plain 70 is 70 m: a slip of the unit, never computed with.
    if (const std::optional<std::string> why = implausible(*out.spacing, kSpacingRange))
      n->fail(*why + "; a plain number is SI: write the spacing with its unit, as 70 mm");
  }
  if (auto n = root.find("spacing_err")) out.spacing_err = positive(*n, Dimension::kLength, true);
  if (auto n = root.find("gravity")) {
    out.gravity = positive(*n, Dimension::kAcceleration, false);
    if (const std::optional<std::string> why = implausible(*out.gravity, kGravityRange))
      n->fail(*why);
  }
  if (auto n = root.find("material")) {
    out.material = n->text();
    if (materials != nullptr && materials->find(*out.material) == nullptr)
      n->fail(unknown_material_message(*materials, *out.material));
  }
  if (auto n = root.find("temperature"))
    out.temperature = positive(*n, Dimension::kTemperature, false);
  if (auto n = root.find("geometry")) {
    const std::string g = n->text();
    if (g != "auto" && g != "one" && g != "pair")
      n->fail("expected auto, one or pair, found \"" + g + "\"");
    out.geometry = g;
  }
  return out;
}

}  // namespace fl
