// frictionlab.load_scene and frictionlab.Scene: a scene file (or text) read by the scene loader
// with overrides, as `frictionlab run SCENE --set key=value` reads it; its keys readable by their
// path in the file (scene["rollers.spacing"], SI) or as attributes (scene.rollers.spacing).
#include <pybind11/stl.h>

#include <string>
#include <utility>
#include <vector>

#include "io/suggest.hpp"
#include "python/arguments.hpp"
#include "python/bindings.hpp"
#include "python/lab_data.hpp"
#include "python/loaded_scene.hpp"

namespace fl::python {

std::vector<SceneOverride> overrides_argument(py::handle set) {
  std::vector<SceneOverride> out;
  if (set.is_none()) return out;
  if (py::isinstance<py::dict>(set) || py::hasattr(set, "items")) {
    for (const py::handle item : set.attr("items")()) {
      const py::tuple pair = py::reinterpret_borrow<py::tuple>(item);
      out.push_back({pair[0].cast<std::string>(), override_text(pair[1])});
    }
    return out;
  }
  if (py::isinstance<py::str>(set))
    throw py::type_error(
        "set: expected a mapping {\"key.path\": value} or a list of \"key.path=value\" texts, "
        "found a str");
  for (const py::handle text : set) out.push_back(parse_override(text.cast<std::string>()));
  return out;
}

SceneSource scene_source_argument(const SceneArgument& scene) {
  if (const LoadedScene* loaded = std::get_if<LoadedScene>(&scene)) return loaded->source;
  SceneSource source;
  source.file = std::get<std::filesystem::path>(scene).string();
  source.asset_dir = asset_dir(std::nullopt);
  return source;
}

LoadedScene scene_argument(const SceneArgument& scene) {
  if (const LoadedScene* loaded = std::get_if<LoadedScene>(&scene)) return *loaded;
  return load_scene_source(scene_source_argument(scene));
}

namespace {

// The public, non-callable attributes of a scene's part: its keys.
std::vector<std::string> keys_of(py::handle node) {
  std::vector<std::string> keys;
  if (py::isinstance<py::dict>(node)) {
    for (const py::handle k : node) keys.push_back(k.cast<std::string>());
    return keys;
  }
  for (const py::handle name : py::module_::import("builtins").attr("dir")(node)) {
    const std::string key = name.cast<std::string>();
    if (key.empty() || key[0] == '_') continue;
    if (PyCallable_Check(py::getattr(node, name).ptr())) continue;
    keys.push_back(key);
  }
  return keys;
}

[[noreturn]] void no_key(const std::string& key, const std::string& parent, const std::string& part,
                         const std::vector<std::string>& keys) {
  std::vector<std::string_view> candidates(keys.begin(), keys.end());
  const std::string match = closest_match(part, candidates);
  throw py::key_error(
      "scene key \"" + key + "\": " + (parent.empty() ? "the scene" : "\"" + parent + "\"") +
      " has no key \"" + part + "\"" + (match.empty() ? "" : "; did you mean '" + match + "'?"));
}

// scene["plate.payload.mass"], scene["magnets.0.x"]: the value at a key path (SI).
py::object scene_key(py::object scene, const std::string& key) {
  py::object node = std::move(scene);
  std::string parent;
  std::size_t pos = 0;
  for (;;) {
    const std::size_t dot = key.find('.', pos);
    const std::string part = key.substr(pos, dot == std::string::npos ? dot : dot - pos);
    if (py::isinstance<py::list>(node)) {
      const py::list list = node;
      std::size_t index = 0;
      bool digits = !part.empty();
      for (char c : part) digits = digits && c >= '0' && c <= '9';
      if (digits) index = std::stoul(part);
      if (!digits || index >= list.size())
        throw py::key_error("scene key \"" + key + "\": \"" + parent + "\" is a list of " +
                            std::to_string(list.size()) + "; expected an index below it, found \"" +
                            part + "\"");
      node = list[index];
    } else {
      const std::vector<std::string> keys = keys_of(node);
      if (std::find(keys.begin(), keys.end(), part) == keys.end()) no_key(key, parent, part, keys);
      node = py::isinstance<py::dict>(node) ? py::object(node[py::str(part)])
                                            : py::object(py::getattr(node, part.c_str()));
    }
    if (dot == std::string::npos) return node;
    parent = key.substr(0, dot);
    pos = dot + 1;
  }
}

std::string sense_name(RollerSense sense) {
  return sense == RollerSense::kInward ? "inward" : "outward";
}

// The rig's parts as the scene describes them: the world, rollers, plate, magnets and sensor.
void bind_rig_parts(py::class_<LoadedScene>& scene) {
  py::class_<RampPoint>(scene, "RampPoint", "A point of a ramp: at [s], value (rad/s or duty).")
      .def_readonly("at", &RampPoint::at)
      .def_readonly("value", &RampPoint::value);
  py::class_<WorldDesc>(scene, "World", "world: gravity, time step, solver, duration, seed (SI).")
      .def_readonly("gravity", &WorldDesc::gravity, "m/s^2")
      .def_readonly("time_step", &WorldDesc::time_step, "s")
      .def_readonly("solver_iterations", &WorldDesc::solver_iterations)
      .def_readonly("duration", &WorldDesc::duration, "s of simulated time")
      .def_readonly("seed", &WorldDesc::seed, "seeds the sensor's noise and jitter");
  py::class_<RollersDesc>(scene, "Rollers", "rollers: the two rollers (SI).")
      .def_readonly("spacing", &RollersDesc::spacing, "l [m], between the axes")
      .def_readonly("radius", &RollersDesc::radius, "a [m]")
      .def_property_readonly(
          "diameter", [](const RollersDesc& r) { return 2.0 * r.radius; }, "2 a [m]")
      .def_readonly("length", &RollersDesc::length, "m, along y")
      .def_readonly("speed", &RollersDesc::speed, "rad/s, each roller (ideal drive)")
      .def_readonly("speed_ramp", &RollersDesc::speed_ramp, "the speed over time [s, rad/s]")
      .def_readonly("wall", &RollersDesc::wall, "m")
      .def_readonly("density", &RollersDesc::density, "kg/m^3")
      .def_property_readonly(
          "sense", [](const RollersDesc& r) { return sense_name(r.sense); },
          "\"inward\" or \"outward\"")
      .def_readonly("runout", &RollersDesc::runout, "m, each tube's axis off its shaft")
      .def_readonly("runout_phase", &RollersDesc::runout_phase, "rad, each tube's at t = 0")
      .def_readonly("material", &RollersDesc::material);
  py::class_<PayloadDesc>(scene, "Payload", "plate.payload: mass [kg] and height [m].")
      .def_readonly("mass", &PayloadDesc::mass)
      .def_readonly("height", &PayloadDesc::height);
  py::class_<PlateBlock>(scene, "PlateBlock", "A LEGO block on the plate (SI; turn in degrees).")
      .def_readonly("part", &PlateBlock::part)
      .def_readonly("x", &PlateBlock::x)
      .def_readonly("y", &PlateBlock::y)
      .def_readonly("turn", &PlateBlock::turn)
      .def_readonly("mass", &PlateBlock::mass)
      .def_readonly("com_z", &PlateBlock::com_z)
      .def_readonly("height", &PlateBlock::height);
  py::class_<PlateDesc>(scene, "Plate", "plate: the oscillating plate (SI).")
      .def_readonly("length", &PlateDesc::length, "m, along x")
      .def_readonly("width", &PlateDesc::width, "m, along y")
      .def_readonly("thickness", &PlateDesc::thickness, "m, along z")
      .def_readonly("mass", &PlateDesc::mass, "kg of the slab, or None (density x volume)")
      .def_readonly("density", &PlateDesc::density, "kg/m^3")
      .def_readonly("material", &PlateDesc::material)
      .def_readonly("payload", &PlateDesc::payload)
      .def_readonly("blocks", &PlateDesc::blocks)
      .def_readonly("offset", &PlateDesc::offset, "m, initial x of the centre of mass")
      .def_readonly("velocity", &PlateDesc::velocity, "m/s, initial x velocity")
      .def_readonly("sideways_velocity", &PlateDesc::sideways_velocity, "m/s, initial y velocity");
  py::class_<MagnetDesc>(scene, "Magnet", "A magnet on the plate (SI).")
      .def_readonly("x", &MagnetDesc::x)
      .def_readonly("height", &MagnetDesc::height)
      .def_readonly("diameter", &MagnetDesc::diameter)
      .def_readonly("thickness", &MagnetDesc::thickness)
      .def_readonly("remanence", &MagnetDesc::remanence, "T")
      .def_readonly("density", &MagnetDesc::density);
  py::class_<SensorDesc>(scene, "Sensor", "sensor: the Hall sensor and its ADC (SI).")
      .def_readonly("position", &SensorDesc::position, "m, world")
      .def_readonly("axis", &SensorDesc::axis)
      .def_readonly("sensitivity", &SensorDesc::sensitivity, "V/T")
      .def_readonly("supply", &SensorDesc::supply, "V")
      .def_readonly("offset", &SensorDesc::offset, "V at zero field, or None (supply / 2)")
      .def_readonly("adc_bits", &SensorDesc::adc_bits)
      .def_readonly("sample_rate", &SensorDesc::sample_rate, "Hz")
      .def_readonly("noise", &SensorDesc::noise, "V rms")
      .def_readonly("jitter", &SensorDesc::jitter, "s rms")
      .def_readonly("clock_error", &SensorDesc::clock_error, "relative");
  py::class_<PhoneDesc>(scene, "Phone", "phones[]: a phone's sensor as phyphox records it (SI).")
      .def_property_readonly("sensor",
                             [](const PhoneDesc& p) {
                               return p.sensor == PhoneSensor::kMagnetometer ? "magnetometer"
                                                                             : "accelerometer";
                             })
      .def_readonly("rate", &PhoneDesc::rate, "Hz")
      .def_readonly("noise", &PhoneDesc::noise, "rms per axis: T or m/s^2")
      .def_readonly("turn", &PhoneDesc::turn, "rad, from +x to the phone's top")
      .def_readonly("position", &PhoneDesc::position, "m, world (a magnetometer)")
      .def_readonly("earth", &PhoneDesc::earth, "T, the rig's frame (a magnetometer)")
      .def_readonly("gravity", &PhoneDesc::gravity, "records g (an accelerometer)")
      .def_readonly("x", &PhoneDesc::x, "m along the plate (an accelerometer)")
      .def_readonly("height", &PhoneDesc::height, "m above the plate's top (an accelerometer)")
      .def_readonly("mass", &PhoneDesc::mass, "kg (an accelerometer)")
      .def_readonly("size", &PhoneDesc::size, "m: width, length, thickness (an accelerometer)");
}

// The friction law, the rollers warming, and the drive.
void bind_friction_and_drive(py::class_<LoadedScene>& scene) {
  py::class_<WarmingDesc>(scene, "Warming", "friction.warming: rollers warming from the start.")
      .def_readonly("room", &WarmingDesc::room_temperature, "K")
      .def_readonly("time_constant", &WarmingDesc::time_constant, "s")
      .def_readonly("hold", &WarmingDesc::hold, "s at the start temperature first")
      .def_readonly("mu_k_room", &WarmingDesc::mu_k_room, "mu_k at the room's temperature");
  py::class_<FrictionDesc>(scene, "Friction", "friction: the law between plate and rollers.")
      .def_property_readonly(
          "law", [](const FrictionDesc& f) { return std::string(friction_law_kind_name(f.law)); },
          "\"coulomb\" or \"stribeck\"")
      .def_readonly("mu_k", &FrictionDesc::mu_k, "mu_k (the paper's value, for a material)")
      .def_readonly("mu_s", &FrictionDesc::mu_s, "the static limit, or None (mu_k)")
      .def_readonly("v_s", &FrictionDesc::v_s, "m/s, the Stribeck speed, or None")
      .def_readonly("beta", &FrictionDesc::beta, "s/m")
      .def_readonly("temperature", &FrictionDesc::temperature, "K (at the start)")
      .def_readonly("warming", &FrictionDesc::warming, "or None: the rollers stay at it")
      .def_property_readonly(
          "paper_material",
          [](const FrictionDesc& f) {
            return f.from_paper ? std::optional<std::string>(f.paper_material) : std::nullopt;
          },
          "the Table I key mu_k came from, or None")
      .def_readonly("paper_period", &FrictionDesc::paper_period, "T +- dT the paper measured [s]")
      .def_readonly("paper_mu_k", &FrictionDesc::paper_mu_k, "mu_k +- d mu_k the paper printed");
  py::class_<MotorDesc>(scene, "Motor", "drive.motor: a 12 V DC motor (SI).")
      .def_readonly("rated_voltage", &MotorDesc::rated_voltage)
      .def_readonly("no_load_speed", &MotorDesc::no_load_speed)
      .def_readonly("stall_torque", &MotorDesc::stall_torque)
      .def_readonly("duty", &MotorDesc::duty)
      .def_readonly("duty_ramp", &MotorDesc::duty_ramp)
      .def_readonly("inertia", &MotorDesc::inertia);
  py::class_<GearStage>(scene, "GearStage", "One mesh of the gearbox (tooth counts).")
      .def_readonly("driver", &GearStage::driver)
      .def_readonly("driven", &GearStage::driven);
  py::class_<DriveDesc>(scene, "Drive", "drive: the motor, the gearbox and the coupling.")
      .def_readonly("motor", &DriveDesc::motor)
      .def_property_readonly(
          "gearbox", [](const DriveDesc& d) { return py::dict(py::arg("stages") = d.stages); },
          "{\"stages\": [GearStage, ...]}")
      .def_property_readonly(
          "coupling",
          [](const DriveDesc& d) {
            return py::dict(py::arg("roller_gear") = d.roller_gear,
                            py::arg("idler_gear") = d.idler_gear);
          },
          "{\"roller_gear\": teeth, \"idler_gear\": teeth}")
      .def_property_readonly("ratio", &gearbox_ratio, "the gearbox's speed-up");
}

// The LEGO frame and the files a run writes.
void bind_frame_and_output(py::class_<LoadedScene>& scene) {
  py::class_<FramePart>(scene, "FramePart", "A LEGO part of the frame on the stud grid.")
      .def_readonly("part", &FramePart::part)
      .def_readonly("at", &FramePart::at, "studs x, studs y, plates up")
      .def_readonly("turn", &FramePart::turn, "degrees about z")
      .def_readonly("guide", &FramePart::guide, "collides with the plate")
      .def_readonly("position", &FramePart::position, "m, the part's origin in the world");
  py::class_<FrameDesc>(scene, "Frame", "frame: the LEGO frame.")
      .def_readonly("origin", &FrameDesc::origin, "m")
      .def_readonly("parts", &FrameDesc::parts);
  py::class_<OutputDesc>(scene, "Output", "output: the files a run with out= writes.")
      .def_readonly("trajectory", &OutputDesc::trajectory)
      .def_readonly("hall", &OutputDesc::hall)
      .def_readonly("summary", &OutputDesc::summary)
      .def_readonly("cycles", &OutputDesc::cycles)
      .def_readonly("periods", &OutputDesc::periods)
      .def_readonly("jumps", &OutputDesc::jumps)
      .def_readonly("phones", &OutputDesc::phones);
}

void bind_scene_parts(py::class_<LoadedScene>& scene) {
  constexpr auto ref = py::return_value_policy::reference_internal;
  bind_rig_parts(scene);
  bind_friction_and_drive(scene);
  bind_frame_and_output(scene);

  const auto part = [](auto member) {
    return [member](const LoadedScene& s) -> const auto& {
      return (*s.scene).*member;
    };
  };
  scene.def_property_readonly("world", part(&Scene::world), ref)
      .def_property_readonly("rollers", part(&Scene::rollers), ref)
      .def_property_readonly("plate", part(&Scene::plate), ref)
      .def_property_readonly("magnets", part(&Scene::magnets))
      .def_property_readonly("sensor", part(&Scene::sensor), "None without a sensor")
      .def_property_readonly("phones", part(&Scene::phones), "the phones' sensors")
      .def_property_readonly("friction", part(&Scene::friction), ref)
      .def_property_readonly("drive", part(&Scene::drive), "None for the ideal drive")
      .def_property_readonly("frame", part(&Scene::frame), "None without a frame")
      .def_property_readonly("output", part(&Scene::output), ref);
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<LoadedScene> scene(m, "Scene", R"(A scene: one experiment, loaded and checked.

Made by load_scene(path, set=...) or parse_scene(text). Its keys are read by their
path in the scene file, in SI units, scene["rollers.spacing"] (0.089), scene["magnets.0.x"],
or as attributes, scene.rollers.spacing. A key the file leaves out has its default; an
optional one that is absent is None. A scene never changes: with_set gives a new one.)");
  bind_scene_parts(scene);
  scene
      .def_property_readonly(
          "name", [](const LoadedScene& s) { return s.scene->name; }, "The scene's name")
      .def_property_readonly(
          "file",
          [](const LoadedScene& s) {
            return s.source.file.empty() ? std::nullopt : std::optional(s.source.file);
          },
          "The scene file, or None for a scene given as text")
      .def_property_readonly(
          "overrides",
          [](const LoadedScene& s) {
            py::dict out;
            for (const SceneOverride& o : s.source.overrides) out[py::str(o.path)] = o.value;
            return out;
          },
          "The overrides applied, {key path: text}")
      .def_property_readonly(
          "expected_regime", [](const LoadedScene& s) { return s.scene->expected_regime; },
          "The regime the scene says theory expects (expect.regime), or None")
      .def("__getitem__", &scene_key, py::arg("key"),
           "The value at a key path, e.g. scene[\"plate.payload.mass\"] (SI); KeyError for a key "
           "the format does not have.")
      .def(
          "get",
          [](py::object self, const std::string& key, py::object fallback) {
            try {
              return scene_key(std::move(self), key);
            } catch (const py::key_error&) {
              return fallback;
            }
          },
          py::arg("key"), py::arg("default") = py::none(),
          "The value at a key path, or `default` when there is no such key.")
      .def(
          "with_set",
          [](const LoadedScene& s, const py::object& set) {
            return with_overrides(s, overrides_argument(set));
          },
          py::arg("set"),
          "The same scene loaded again with more overrides after its own, e.g.\n"
          "scene.with_set({\"rollers.spacing\": \"100mm\"}). Raises InputError.")
      .def("__repr__", [](const LoadedScene& s) {
        std::string text = "<frictionlab.Scene '" + s.scene->name + "'";
        if (!s.source.file.empty()) text += " from " + s.source.file;
        for (const SceneOverride& o : s.source.overrides) text += " " + o.path + "=" + o.value;
        return text + ">";
      });

  m.def(
      "load_scene",
      [](const Path& path, const py::object& set, const std::optional<Path>& assets) {
        SceneSource source;
        source.file = path.string();
        source.overrides = overrides_argument(set);
        source.asset_dir = asset_dir(assets);
        return load_scene_source(std::move(source));
      },
      py::arg("path"), py::kw_only(), py::arg("set") = py::none(), py::arg("assets") = py::none(),
      R"(Loads a scene file (scenes/*.yaml, docs/scene-format.md) with overrides.

set: {"key.path": value} (or ["key.path=value", ...]) as `frictionlab run --set`; a
value is text as the file would hold it ("89mm", "lego", "[]") or a Python value
(0.3, True, [{"x": "95mm"}]). assets: the folder of the lab's data (default
$FRICTIONLAB_ASSETS, else the build's assets/). Raises InputError with the command's
message ("scenes/x.yaml:12:5: error: ...") for a scene the loader refuses.)");
  m.def(
      "parse_scene",
      [](const std::string& text, const std::string& name, const py::object& set,
         const std::optional<Path>& assets) {
        SceneSource source;
        source.text = text;
        source.name = name;
        source.overrides = overrides_argument(set);
        source.asset_dir = asset_dir(assets);
        return load_scene_source(std::move(source));
      },
      py::arg("text"), py::arg("name") = "inline", py::kw_only(), py::arg("set") = py::none(),
      py::arg("assets") = py::none(),
      "A scene from its YAML text; `name` stands for the file in messages. As load_scene.");
}

}  // namespace fl::python
