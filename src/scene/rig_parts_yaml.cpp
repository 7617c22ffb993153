#include "scene/rig_parts_yaml.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/units.hpp"
#include "io/input_error.hpp"
#include "scene/ramp_yaml.hpp"

namespace fl {
namespace {

const assets::PartSpec& part_at(const YamlNode& node, const CatalogGetter& catalog) {
  const std::string name = node.text();
  try {
    return catalog(node).at(name);
  } catch (const assets::UnknownPart& e) {
    node.fail(e.what());
  }
}

int read_turn(const std::optional<YamlNode>& node) {
  if (!node) return 0;
  const double degrees = node->quantity(Dimension::kAngle) * 180.0 / kPi;
  const long rounded = std::lround(degrees);
  if (std::fabs(degrees - static_cast<double>(rounded)) > 1e-9 || rounded % 90 != 0)
    node->fail("LEGO parts turn by 0, 90, 180 or 270 degrees on the stud grid");
  return static_cast<int>(((rounded % 360) + 360) % 360);
}

std::array<float, 3> read_color(const YamlNode& node) {
  const std::string text = node.text();
  struct Named {
    const char* name;
    std::array<float, 3> rgb;
  };
  // LEGO's common colours (sRGB).
  static constexpr Named kNamed[] = {
      {"red", {0.706f, 0.0f, 0.0f}},           {"blue", {0.0f, 0.333f, 0.749f}},
      {"yellow", {0.980f, 0.784f, 0.039f}},    {"black", {0.106f, 0.165f, 0.204f}},
      {"white", {0.957f, 0.957f, 0.957f}},     {"gray", {0.627f, 0.647f, 0.663f}},
      {"dark-gray", {0.392f, 0.392f, 0.392f}}, {"green", {0.0f, 0.522f, 0.169f}},
      {"orange", {0.855f, 0.522f, 0.251f}},    {"tan", {0.894f, 0.804f, 0.620f}}};
  for (const Named& n : kNamed)
    if (text == n.name) return n.rgb;
  if (text.size() == 7 && text[0] == '#') {
    std::array<float, 3> rgb{};
    for (int i = 0; i < 3; ++i) {
      const std::string hex = text.substr(1 + 2 * static_cast<std::size_t>(i), 2);
      char* end = nullptr;
      const long value = std::strtol(hex.c_str(), &end, 16);
      if (end != hex.c_str() + 2) node.fail("expected a colour \"#RRGGBB\" or a LEGO colour name");
      rgb[static_cast<std::size_t>(i)] = static_cast<float>(value) / 255.0f;
    }
    return rgb;
  }
  node.fail(
      "expected a colour \"#RRGGBB\" or one of: red, blue, yellow, black, white, gray, "
      "dark-gray, green, orange, tan; found \"" +
      text + "\"");
}

// Rotation about z by a multiple of 90 degrees.
Vec3 turned(const Vec3& v, int turn) {
  switch (turn) {
    case 90:
      return {-v[1], v[0], v[2]};
    case 180:
      return {-v[0], -v[1], v[2]};
    case 270:
      return {v[1], -v[0], v[2]};
    default:
      return v;
  }
}

}  // namespace

Vec3 grid_position(const assets::PartSpec& part, const std::array<int, 3>& at, int turn,
                   const Vec3& origin) {
  constexpr double kPitch = assets::kStudPitch;
  // Studs along the part's own x and y; turned a quarter, they run along the world's y and x.
  const int nx = std::max(1, part.studs[0]);
  const int ny = std::max(1, part.studs[1]);
  const bool quarter = turn == 90 || turn == 270;
  const double span_x = quarter ? ny : nx;
  const double span_y = quarter ? nx : ny;
  return {origin[0] + (at[0] + 0.5 * (span_x - 1.0)) * kPitch,
          origin[1] + (at[1] + 0.5 * (span_y - 1.0)) * kPitch,
          origin[2] + at[2] * assets::kPlateHeight};
}

std::vector<PlateBlock> read_plate_blocks(const YamlNode& node, const CatalogGetter& catalog) {
  std::vector<PlateBlock> blocks;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YamlNode b = node[i];
    b.allow_keys({"part", "x", "y", "turn"});
    const assets::PartSpec& part = part_at(b.at("part"), catalog);
    PlateBlock block;
    block.part = part.name;
    block.x = b.at("x").quantity(Dimension::kLength);
    if (auto v = b.find("y")) block.y = v->quantity(Dimension::kLength);
    block.turn = read_turn(b.find("turn"));
    block.mass = part.mass;
    block.com_z = part.center_of_mass[2];
    block.height = part.plates > 0 ? part.plates * assets::kPlateHeight : part.bounds.max[2];
    blocks.push_back(block);
  }
  return blocks;
}

DriveDesc read_drive(const YamlNode& node, const CatalogGetter& catalog) {
  node.allow_keys({"motor", "gearbox", "coupling"});
  DriveDesc d;
  if (auto m = node.find("motor")) {
    m->allow_keys(
        {"rated_voltage", "no_load_speed", "stall_torque", "duty", "duty_ramp", "inertia"});
    if (auto v = m->find("rated_voltage")) d.motor.rated_voltage = v->quantity(Dimension::kVoltage);
    if (auto v = m->find("no_load_speed"))
      d.motor.no_load_speed = v->quantity(Dimension::kAngularSpeed);
    if (auto v = m->find("stall_torque")) d.motor.stall_torque = v->quantity(Dimension::kTorque);
    if (auto v = m->find("duty")) d.motor.duty = v->quantity(Dimension::kDimensionless);
    if (auto v = m->find("inertia")) d.motor.inertia = v->quantity(Dimension::kInertia);
    if (!(d.motor.no_load_speed > 0.0)) m->at("no_load_speed").fail("must be positive");
    if (!(d.motor.stall_torque > 0.0)) m->at("stall_torque").fail("must be positive");
    if (!(d.motor.inertia > 0.0)) m->at("inertia").fail("must be positive");
    if (d.motor.duty < 0.0 || d.motor.duty > 1.0)
      m->at("duty").fail(said("check-duty", {arg("duty_percent", 100.0 * d.motor.duty)}));
    if (m->has("duty") && m->has("duty_ramp"))
      m->at("duty_ramp")
          .fail("give duty (constant) or duty_ramp (over time), not both; remove one of the keys");
    if (auto v = m->find("duty_ramp"))
      d.motor.duty_ramp =
          read_ramp(*v, {"duty", Dimension::kDimensionless, 0.0, 1.0, "{at: 0 s, duty: 20 %}"});
  }
  const auto teeth = [](const YamlNode& v) {
    const std::int64_t n = v.integer();
    if (n < 6 || n > 200) v.fail("expected a tooth count between 6 and 200");
    return static_cast<int>(n);
  };
  if (auto g = node.find("gearbox")) {
    g->allow_keys({"stages"});
    if (auto stages = g->find("stages")) {
      for (std::size_t i = 0; i < stages->size(); ++i) {
        const YamlNode st = (*stages)[i];
        st.allow_keys({"driver", "driven"});
        d.stages.push_back({teeth(st.at("driver")), teeth(st.at("driven"))});
      }
    }
  }
  if (auto c = node.find("coupling")) {
    c->allow_keys({"roller_gear", "idler_gear"});
    if (auto v = c->find("roller_gear")) d.roller_gear = teeth(*v);
    if (auto v = c->find("idler_gear")) d.idler_gear = teeth(*v);
  }
  // Every gear is a part of the index: its mass, inertia and pitch radius come from there.
  std::vector<int> used{d.roller_gear, d.idler_gear};
  for (const GearStage& st : d.stages) used.insert(used.end(), {st.driver, st.driven});
  for (const int n : used) {
    bool have = false;
    for (const GearSpec& g : d.gears) have = have || g.teeth == n;
    if (have) continue;
    const assets::PartSpec* part = catalog(node).find("gear-" + std::to_string(n));
    if (part == nullptr || !part->gear)
      node.fail("the part index has no " + std::to_string(n) +
                "-tooth gear (LEGO Technic spur gears: 8, 16, 24, 40)");
    d.gears.push_back({n, part->mass, part->inertia[1], part->gear->pitch_radius});
  }
  return d;
}

FrameDesc read_frame(const YamlNode& node, const CatalogGetter& catalog) {
  node.allow_keys({"origin", "parts"});
  FrameDesc f;
  if (auto v = node.find("origin")) {
    if (v->size() != 3) v->fail("expected [x, y, z]");
    f.origin = {(*v)[0].quantity(Dimension::kLength), (*v)[1].quantity(Dimension::kLength),
                (*v)[2].quantity(Dimension::kLength)};
  }
  const YamlNode parts = node.at("parts");
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const YamlNode p = parts[i];
    p.allow_keys({"part", "at", "turn", "color", "guide"});
    const assets::PartSpec& spec = part_at(p.at("part"), catalog);
    FramePart part;
    part.part = spec.name;
    const YamlNode at = p.at("at");
    if (at.size() != 3) at.fail("expected [studs along x, studs along y, plates up]");
    for (std::size_t k = 0; k < 3; ++k) part.at[k] = static_cast<int>(at[k].integer());
    part.turn = read_turn(p.find("turn"));
    part.color = spec.color;
    if (auto v = p.find("color")) part.color = read_color(*v);
    if (auto v = p.find("guide")) part.guide = v->boolean();
    part.position = grid_position(spec, part.at, part.turn, f.origin);
    for (const assets::CollisionBox& box : spec.boxes) {
      const Vec3 size = turned(box.size, part.turn);
      part.boxes.push_back({turned(box.center, part.turn),
                            {std::fabs(size[0]), std::fabs(size[1]), std::fabs(size[2])}});
    }
    if (part.guide && part.boxes.empty())
      p.at("guide").fail("a guide needs collision boxes; " + spec.name + " has none");
    f.parts.push_back(std::move(part));
  }
  return f;
}

}  // namespace fl
