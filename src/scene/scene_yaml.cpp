#include "scene/scene_yaml.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <string_view>

#include "io/input_error.hpp"
#include "io/unknown_material.hpp"
#include "io/yaml_node.hpp"
#include "scene/phones_yaml.hpp"
#include "scene/ramp_yaml.hpp"
#include "scene/rig_parts_yaml.hpp"
#include "scene/scene_checks.hpp"
#include "text/utf8.hpp"

namespace fl {
namespace {

Vec3 read_vec3(const YamlNode& node, Dimension dimension) {
  if (node.size() != 3) node.fail("expected a list of 3 values [x, y, z]");
  return {node[0].quantity(dimension), node[1].quantity(dimension), node[2].quantity(dimension)};
}

void read_world(const YamlNode& n, WorldDesc& w) {
  n.allow_keys({"gravity", "tilt", "time_step", "solver_iterations", "duration", "seed"});
  if (auto v = n.find("gravity")) w.gravity = v->quantity(Dimension::kAcceleration);
  if (auto v = n.find("tilt")) w.tilt = v->quantity(Dimension::kAngle);
  if (auto v = n.find("time_step")) w.time_step = v->quantity(Dimension::kTime);
  if (auto v = n.find("solver_iterations")) w.solver_iterations = static_cast<int>(v->integer());
  if (auto v = n.find("duration")) w.duration = v->quantity(Dimension::kTime);
  if (auto v = n.find("seed")) {
    const std::int64_t seed = v->integer();
    if (seed < 0) v->fail("expected a whole number >= 0");
    w.seed = static_cast<std::uint64_t>(seed);
  }
}

void read_rollers(const YamlNode& n, RollersDesc& r) {
  n.allow_keys({"spacing", "radius", "diameter", "length", "wall", "density", "speed", "speed_ramp",
                "sense", "material", "runout", "runout_phase", "rolling_resistance", "skew"});
  if (auto v = n.find("skew")) r.skew = v->quantity(Dimension::kAngle);
  if (auto v = n.find("rolling_resistance")) r.rolling_resistance = v->quantity(Dimension::kLength);
  if (auto v = n.find("runout")) r.runout = v->quantity(Dimension::kLength);
  if (auto v = n.find("runout_phase")) {
    if (v->size() != 2)
      v->fail("expected a list of 2 angles [roller 0, roller 1], e.g. [0 deg, 90 deg]");
    r.runout_phase = {(*v)[0].quantity(Dimension::kAngle), (*v)[1].quantity(Dimension::kAngle)};
  }
  if (auto v = n.find("spacing")) r.spacing = v->quantity(Dimension::kLength);
  if (n.has("radius") && n.has("diameter"))
    n.at("diameter").fail("give radius or diameter, not both");
  // One size for both rollers, or [roller 0, roller 1].
  for (const char* key : {"radius", "diameter"}) {
    const auto v = n.find(key);
    if (!v) continue;
    const double scale = std::string_view(key) == "diameter" ? 0.5 : 1.0;
    if (v->is_sequence()) {
      if (v->size() != 2)
        v->fail(std::string("expected one ") + key +
                ", or a list of 2 [roller 0, roller 1], e.g. " +
                (scale == 0.5 ? "[20 mm, 22 mm]" : "[10 mm, 11 mm]"));
      r.radius = scale * (*v)[0].quantity(Dimension::kLength);
      r.radius_roller_1 = scale * (*v)[1].quantity(Dimension::kLength);
    } else {
      r.radius = scale * v->quantity(Dimension::kLength);
    }
  }
  if (auto v = n.find("length")) r.length = v->quantity(Dimension::kLength);
  if (auto v = n.find("wall")) r.wall = v->quantity(Dimension::kLength);
  if (auto v = n.find("density")) r.density = v->quantity(Dimension::kDensity);
  if (auto v = n.find("speed")) {
    if (v->is_sequence()) {
      if (v->size() != 2)
        v->fail(
            "expected one speed, or a list of 2 speeds [roller 0, roller 1], e.g. "
            "[1600 rpm, 1500 rpm]");
      r.speed = (*v)[0].quantity(Dimension::kAngularSpeed);
      r.speed_roller_1 = (*v)[1].quantity(Dimension::kAngularSpeed);
    } else {
      r.speed = v->quantity(Dimension::kAngularSpeed);
    }
  }
  if (n.has("speed") && n.has("speed_ramp"))
    n.at("speed_ramp")
        .fail("give speed (constant) or speed_ramp (over time), not both; remove one of the keys");
  if (auto v = n.find("speed_ramp")) {
    RampPair ramps = read_ramp_pair(
        *v, {"speed", Dimension::kAngularSpeed, 0.0, std::nullopt, "{at: 0 s, speed: 100 rpm}"});
    r.speed_ramp = std::move(ramps.first);
    r.speed_ramp_roller_1 = std::move(ramps.second);
  }
  if (auto v = n.find("sense")) {
    const std::string sense = v->text();
    if (sense == "inward")
      r.sense = RollerSense::kInward;
    else if (sense == "outward")
      r.sense = RollerSense::kOutward;
    else
      v->fail("expected inward (the tops turn toward the centre) or outward, found \"" + sense +
              "\"");
  }
  if (auto v = n.find("material")) r.material = v->text();
}

void read_plate(const YamlNode& n, PlateDesc& p) {
  n.allow_keys({"length", "width", "thickness", "mass", "density", "material", "payload", "blocks",
                "offset", "velocity", "sideways_velocity"});
  if (auto v = n.find("length")) p.length = v->quantity(Dimension::kLength);
  if (auto v = n.find("width")) p.width = v->quantity(Dimension::kLength);
  if (auto v = n.find("thickness")) p.thickness = v->quantity(Dimension::kLength);
  if (n.has("mass") && n.has("density")) n.at("density").fail("give mass or density, not both");
  if (auto v = n.find("mass")) p.mass = v->quantity(Dimension::kMass);
  if (auto v = n.find("density")) p.density = v->quantity(Dimension::kDensity);
  if (auto v = n.find("material")) p.material = v->text();
  if (auto payload = n.find("payload")) {
    payload->allow_keys({"mass", "height", "x"});
    if (auto v = payload->find("x")) p.payload.x = v->quantity(Dimension::kLength);
    if (auto v = payload->find("mass")) p.payload.mass = v->quantity(Dimension::kMass);
    if (auto v = payload->find("height")) p.payload.height = v->quantity(Dimension::kLength);
  }
  if (auto v = n.find("offset")) p.offset = v->quantity(Dimension::kLength);
  if (auto v = n.find("velocity")) p.velocity = v->quantity(Dimension::kSpeed);
  if (auto v = n.find("sideways_velocity")) p.sideways_velocity = v->quantity(Dimension::kSpeed);
}

MagnetDesc read_magnet(const YamlNode& n) {
  n.allow_keys({"x", "height", "diameter", "thickness", "remanence", "density"});
  MagnetDesc m;
  m.x = n.at("x").quantity(Dimension::kLength);
  if (auto v = n.find("height")) m.height = v->quantity(Dimension::kLength);
  if (auto v = n.find("diameter")) m.diameter = v->quantity(Dimension::kLength);
  if (auto v = n.find("thickness")) m.thickness = v->quantity(Dimension::kLength);
  if (auto v = n.find("remanence")) m.remanence = v->quantity(Dimension::kMagneticField);
  if (auto v = n.find("density")) m.density = v->quantity(Dimension::kDensity);
  return m;
}

SensorDesc read_sensor(const YamlNode& n) {
  n.allow_keys({"position", "axis", "sensitivity", "supply", "offset", "adc_bits", "sample_rate",
                "noise", "jitter", "clock_error"});
  SensorDesc s;
  if (auto v = n.find("position")) s.position = read_vec3(*v, Dimension::kLength);
  if (auto v = n.find("axis")) s.axis = read_vec3(*v, Dimension::kDimensionless);
  if (auto v = n.find("sensitivity")) s.sensitivity = v->quantity(Dimension::kSensitivity);
  if (auto v = n.find("supply")) s.supply = v->quantity(Dimension::kVoltage);
  if (auto v = n.find("offset")) s.offset = v->quantity(Dimension::kVoltage);
  if (auto v = n.find("adc_bits")) s.adc_bits = static_cast<int>(v->integer());
  if (auto v = n.find("sample_rate")) s.sample_rate = v->quantity(Dimension::kFrequency);
  if (auto v = n.find("noise")) s.noise = v->quantity(Dimension::kVoltage);
  if (auto v = n.find("jitter")) s.jitter = v->quantity(Dimension::kTime);
  if (auto v = n.find("clock_error")) s.clock_error = v->quantity(Dimension::kDimensionless);
  return s;
}

void read_friction(const YamlNode& n, const std::string& plate_material, FrictionDesc& f,
                   const PaperTableSource& paper) {
  n.allow_keys({"law", "mu_k", "mu_s", "v_s", "beta", "temperature", "warming"});
  if (auto v = n.find("law")) {
    const std::string law = v->text();
    const std::optional<FrictionLawKind> kind = friction_law_kind_from_name(law);
    if (!kind) v->fail("expected coulomb or stribeck, found \"" + law + "\"");
    f.law = *kind;
  }
  for (const char* key : {"v_s", "beta"}) {
    if (auto v = n.find(key); v && f.law != FrictionLawKind::kStribeck)
      v->fail(std::string("the coulomb law has no ") + key +
              "; set friction.law: stribeck to use it, or remove the key");
  }
  if (auto v = n.find("v_s")) {
    f.v_s = v->quantity(Dimension::kSpeed);
    if (!(*f.v_s > 0.0)) v->fail("expected a speed > 0 (e.g. 10 mm/s), found " + v->text());
  }
  if (auto v = n.find("beta")) f.beta = v->quantity(Dimension::kInverseSpeed);
  if (auto v = n.find("mu_s")) f.mu_s = v->quantity(Dimension::kDimensionless);
  if (auto v = n.find("temperature")) {
    f.temperature = v->quantity(Dimension::kTemperature);
    f.temperature_set = true;
  }
  const auto mu = n.find("mu_k");
  if (!mu)
    n.fail("the key 'mu_k' is required: a number, \"paper\" or one of the paper's materials");
  const std::string text = mu->text();
  double number = 0.0;
  bool is_number = true;
  try {
    number = parse_quantity(text, Dimension::kDimensionless, "friction.mu_k");
  } catch (const UnitError&) {
    is_number = false;
  }
  std::optional<YamlNode> warming = n.find("warming");
  std::optional<YamlNode> mu_k_room;
  if (warming) {
    warming->allow_keys({"room", "time_constant", "hold", "mu_k_room"});
    WarmingDesc w;
    if (auto v = warming->find("room")) w.room_temperature = v->quantity(Dimension::kTemperature);
    if (auto v = warming->find("time_constant")) w.time_constant = v->quantity(Dimension::kTime);
    if (auto v = warming->find("hold")) w.hold = v->quantity(Dimension::kTime);
    mu_k_room = warming->find("mu_k_room");
    if (mu_k_room && mu_k_room->text() != "paper")
      w.mu_k_room = mu_k_room->quantity(Dimension::kDimensionless);
    f.warming = w;
  }
  if (is_number) {
    f.mu_k = number;
    f.from_paper = false;
    if (f.warming && !f.warming->mu_k_room)
      warming->fail(
          "rollers that warm need mu_k at the room's temperature: give warming.mu_k_room (a "
          "number), or take friction.mu_k from the paper (\"paper\" or a material)");
    return;
  }
  // "paper" takes the plate's material; any other text names a material of Table I.
  const std::string material = text == "paper" ? plate_material : text;
  const PaperTable& table = paper();
  const PaperMaterial* row = table.find(material);
  if (row == nullptr)
    mu->fail("expected a number, \"paper\" or one of the paper's materials, found \"" + text +
             "\"" + (text == "paper" ? " (plate.material is \"" + plate_material + "\")" : "") +
             "; " + unknown_material_note(table, material));
  const PaperMeasurement* at = PaperTable::at(*row, f.temperature);
  if (at == nullptr) {
    const YamlNode where = n.find("temperature") ? n.at("temperature") : *mu;
    where.fail("the paper measured " + row->name + " at 300 K" +
               (row->cold ? " and 77 K" : std::string(" only")) + ", not at " +
               std::to_string(static_cast<int>(std::lround(f.temperature))) + " K");
  }
  f.mu_k = at->mu_k.value;
  f.from_paper = true;
  if (f.warming && !f.warming->mu_k_room) {
    const PaperMeasurement* room = PaperTable::at(*row, f.warming->room_temperature);
    if (room == nullptr)
      (mu_k_room ? *mu_k_room : *warming)
          .fail("the paper measured " + row->name + " at 300 K and 77 K only, not at a room of " +
                std::to_string(static_cast<int>(std::lround(f.warming->room_temperature))) +
                " K; give warming.mu_k_room as a number");
    f.warming->mu_k_room = room->mu_k.value;
  }
  f.paper_material = row->key;
  f.paper_period = at->period;
  f.paper_mu_k = at->mu_k;
}

void read_output(const YamlNode& n, OutputDesc& o) {
  n.allow_keys({"trajectory", "hall", "summary", "cycles", "periods", "jumps", "phones"});
  if (auto v = n.find("trajectory")) o.trajectory = v->boolean();
  if (auto v = n.find("hall")) o.hall = v->boolean();
  if (auto v = n.find("summary")) o.summary = v->boolean();
  if (auto v = n.find("cycles")) o.cycles = v->boolean();
  if (auto v = n.find("periods")) o.periods = v->boolean();
  if (auto v = n.find("jumps")) o.jumps = v->boolean();
  if (auto v = n.find("phones")) o.phones = v->boolean();
}

// The node of a dotted key (or its nearest existing parent), to locate a problem.
YamlNode node_for(const YamlNode& root, const std::string& key) {
  YamlNode node = root;
  std::string_view rest = key;
  while (!rest.empty()) {
    const std::size_t dot = rest.find('.');
    const std::string part(rest.substr(0, dot));
    auto child = node.is_map() ? node.find(part) : std::nullopt;
    if (!child) break;
    node = *child;
    if (dot == std::string_view::npos) break;
    rest.remove_prefix(dot + 1);
  }
  return node;
}

Scene read_scene(YamlNode root, const std::string& name, std::span<const SceneOverride> overrides,
                 const PaperTableSource& paper, const PartCatalogSource& parts) {
  // The part index, the first time a key needs it.
  const CatalogGetter catalog = [&parts](const YamlNode& where) -> const assets::PartCatalog& {
    if (!parts)
      where.fail(
          "this key names LEGO parts, but no part index (assets/lego/parts.yaml) was given "
          "to the scene loader");
    return parts();
  };
  root.expect_map();
  for (const SceneOverride& o : overrides) root.set_path(o.path, o.value, override_location(o));
  root.allow_keys({"format", "name", "expect", "world", "rollers", "plate", "magnets", "sensor",
                   "phones", "friction", "drive", "frame", "output", "video"});
  const YamlNode format = root.at("format");
  if (format.integer() != 1) format.fail("this build reads scene format 1, found " + format.text());
  Scene scene;
  // The name goes into every output (JSON among them): bytes that are not UTF-8 are shown escaped.
  scene.name = escape_invalid_utf8(name);
  if (auto v = root.find("name")) scene.name = escape_invalid_utf8(v->text());
  if (auto expect = root.find("expect")) {
    expect->allow_keys({"regime"});
    const YamlNode regime = expect->at("regime");
    const std::string text = regime.text();
    const std::optional<Regime> expected = regime_from_name(text);
    if (!expected || *expected == Regime::kNumericallyFailed)
      regime.fail("expected one of: oscillates, sticks, tips, no restoring force, lost; found \"" +
                  text + "\"");
    scene.expected_regime = expected;
  }
  if (auto v = root.find("world")) read_world(*v, scene.world);
  if (auto v = root.find("rollers")) read_rollers(*v, scene.rollers);
  if (auto v = root.find("plate")) {
    read_plate(*v, scene.plate);
    if (auto blocks = v->find("blocks")) scene.plate.blocks = read_plate_blocks(*blocks, catalog);
  }
  if (auto v = root.find("drive")) {
    for (const char* key : {"speed", "speed_ramp"}) {
      if (root.has("rollers") && root.at("rollers").has(key))
        root.at("rollers").at(key).fail(
            "the drive sets the rollers' speed (motor, duty and gears); remove this key or the "
            "drive (drive.motor.duty_ramp ramps the motor's duty)");
    }
    scene.drive = read_drive(*v, catalog);
  }
  if (auto v = root.find("frame")) scene.frame = read_frame(*v, catalog);
  if (auto v = root.find("magnets")) {
    for (std::size_t i = 0; i < v->size(); ++i) scene.magnets.push_back(read_magnet((*v)[i]));
  }
  if (auto v = root.find("sensor")) scene.sensor = read_sensor(*v);
  if (auto v = root.find("phones")) scene.phones = read_phones(*v);
  read_friction(root.at("friction"), scene.plate.material, scene.friction, paper);
  if (auto v = root.find("output")) read_output(*v, scene.output);
  if (auto v = root.find("video")) scene.video = read_video(*v);

  const std::vector<SceneProblem> problems = check_scene(scene);
  if (!problems.empty()) {
    const SceneProblem& first = problems.front();
    // Located at the key's own entry; where only a key it involves was changed by a `set`
    // entry, at that entry: the change is what to mend.
    const auto changed = [&overrides](const std::string& key) {
      return std::any_of(overrides.begin(), overrides.end(),
                         [&key](const SceneOverride& o) { return o.path == key; });
    };
    std::string blamed = first.key;
    if (!changed(first.key))
      for (const std::string& key : first.involves)
        if (changed(key)) {
          blamed = key;
          break;
        }
    const YamlNode where = node_for(root, blamed);
    throw InputError(where.location(), first.key + ": " + first.message, first.said);
  }
  return scene;
}

}  // namespace

SourceLocation override_location(const SceneOverride& o) {
  return SourceLocation::of_field("set", o.path + "=" + o.value);
}

SceneOverride parse_override(std::string_view text) {
  const std::size_t eq = text.find('=');
  const SourceLocation where = SourceLocation::of_field("set", std::string(text));
  if (eq == std::string_view::npos)
    throw InputError(where, "expected key.path=value (e.g. plate.thickness=5mm), found no '='");
  SceneOverride o{std::string(text.substr(0, eq)), std::string(text.substr(eq + 1))};
  if (o.path.empty()) throw InputError(where, "expected key.path=value, found no key before '='");
  return o;
}

bool located_at_override(const InputError& e, std::string_view path) {
  return e.where().field == "set" && e.where().field_value &&
         e.where().field_value->starts_with(std::string(path) + "=");
}

Scene load_scene_text(std::string_view text, const std::string& name,
                      std::span<const SceneOverride> overrides, const PaperTableSource& paper,
                      const PartCatalogSource& parts) {
  return read_scene(load_yaml_text(text, name), name, overrides, paper, parts);
}

Scene load_scene_file(const std::string& file, std::span<const SceneOverride> overrides,
                      const PaperTableSource& paper, const PartCatalogSource& parts) {
  return read_scene(load_yaml_file(file), std::filesystem::path(file).stem().string(), overrides,
                    paper, parts);
}

}  // namespace fl
