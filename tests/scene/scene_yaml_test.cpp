// Scene files: values with units into SI, strict keys with located errors and suggestions,
// --set overrides, the paper's materials by name, and refusal of impossible set-ups.
#include "scene/scene_yaml.hpp"
#include "cli/field_spelling.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "io/input_error.hpp"
#include "io/paper_table_yaml.hpp"
#include "scene/scene_checks.hpp"

namespace fl {
namespace {

const PaperTable& paper_table() {
  static const PaperTable table = load_paper_table(paper_table_path(FRICTIONLAB_TEST_ASSET_DIR));
  return table;
}

const PaperTableSource kPaper = []() -> const PaperTable& { return paper_table(); };

const PartCatalogSource kParts = []() -> const assets::PartCatalog& {
  static const assets::PartCatalog catalog =
      assets::load_part_catalog(assets::part_catalog_path(FRICTIONLAB_TEST_ASSET_DIR));
  return catalog;
};

// A small valid scene; tests change one thing at a time.
const std::string kBase = R"(format: 1
rollers:
  spacing: 89 mm
  radius: 10 mm
plate:
  length: 200 mm
  thickness: 5 mm
  offset: 20 mm
friction:
  mu_k: 0.3
)";

Scene load(const std::string& text, std::vector<SceneOverride> overrides = {}) {
  return load_scene_text(text, "t.yaml", overrides, kPaper);
}

std::string error_of(const std::string& text, std::vector<SceneOverride> overrides = {}) {
  try {
    load(text, std::move(overrides));
  } catch (const InputError& e) {
    return cli::spelled(e.what());
  }
  return "";
}

TEST(SceneYaml, MinimalSceneLoadsInSi) {
  const std::string file = std::string(FRICTIONLAB_TEST_SOURCE_DIR) + "/scenes/minimal.yaml";
  const Scene s = load_scene_file(file, {}, kPaper);
  EXPECT_EQ(s.name, "minimal");
  EXPECT_DOUBLE_EQ(s.rollers.spacing, 0.089);
  EXPECT_DOUBLE_EQ(s.rollers.radius, 0.010);
  EXPECT_NEAR(s.rollers.speed, 1600.0 * 2.0 * std::numbers::pi / 60.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.world.time_step, 0.001);
  EXPECT_EQ(s.magnets.size(), 2u);
  ASSERT_TRUE(s.sensor.has_value());
  EXPECT_DOUBLE_EQ(s.sensor->sensitivity, 25.0);
  EXPECT_DOUBLE_EQ(s.sensor->sample_rate, 1000.0);
  EXPECT_TRUE(s.friction.from_paper);
  EXPECT_EQ(s.friction.paper_material, "lego");
  EXPECT_DOUBLE_EQ(s.friction.mu_k, 0.29);
}

// Every scene the repository ships loads (a gallery test).
TEST(SceneYaml, EverySceneInTheRepositoryLoads) {
  int count = 0;
  const std::filesystem::path root = std::filesystem::path(FRICTIONLAB_TEST_SOURCE_DIR) / "scenes";
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".yaml") continue;
    // Sweep files describe sweeps, not scenes.
    if (entry.path().parent_path().filename() == "sweeps") continue;
    EXPECT_NO_THROW(load_scene_file(entry.path().string(), {}, kPaper, kParts)) << entry.path();
    ++count;
  }
  EXPECT_GE(count, 1);
}

TEST(SceneYaml, UnknownKeySuggestsAndIsLocated) {
  EXPECT_EQ(error_of(kBase + "world:\n  time_stp: 1 ms\n"),
            "t.yaml:12:3: error: world.time_stp: unknown key; did you mean 'time_step'?");
  EXPECT_EQ(error_of("format: 1\nroller:\n  spacing: 89 mm\nfriction: {mu_k: 0.3}\n"),
            "t.yaml:2:1: error: roller: unknown key; did you mean 'rollers'?");
}

TEST(SceneYaml, WrongOrMissingUnitsAreLocated) {
  const std::string message = error_of(kBase + "world:\n  time_step: 1 mm\n");
  EXPECT_NE(message.find("t.yaml:12:14: error: world.time_step: expected a time"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("found \"1 mm\""), std::string::npos) << message;
  EXPECT_NE(message.find("s, ms, us"), std::string::npos) << message;
}

TEST(SceneYaml, FormatIsRequiredAndChecked) {
  EXPECT_NE(error_of("friction: {mu_k: 0.3}\n").find("the key 'format' is required"),
            std::string::npos);
  EXPECT_NE(error_of("format: 2\nfriction: {mu_k: 0.3}\n").find("reads scene format 1"),
            std::string::npos);
}

TEST(SceneYaml, SetOverridesAnyKeyAndErrorsNameTheOverride) {
  const Scene s = load(kBase, {{"plate.thickness", "8 mm"}, {"world.seed", "7"}});
  EXPECT_DOUBLE_EQ(s.plate.thickness, 0.008);
  EXPECT_EQ(s.world.seed, 7u);
  // A key the file does not have is created.
  EXPECT_DOUBLE_EQ(load(kBase, {{"world.duration", "2 s"}}).world.duration, 2.0);
  EXPECT_EQ(error_of(kBase, {{"plate.thickness", "8 kg"}})
                .rfind("--set plate.thickness=8 kg: error: plate.thickness: expected a length", 0),
            0u);
  EXPECT_EQ(error_of(kBase, {{"plate.thicknes", "8 mm"}}),
            "--set plate.thicknes=8 mm: error: plate.thicknes: unknown key; did you mean "
            "'thickness'?");
  EXPECT_THROW(parse_override("plate.thickness"), InputError);
  EXPECT_THROW(parse_override("=5"), InputError);
  EXPECT_EQ(parse_override("a.b=c=d").value, "c=d");
}

TEST(SceneYaml, PaperMaterialsByNameAndTemperature) {
  const std::string scene = "format: 1\nplate: {material: plexiglas}\nfriction:\n  mu_k: paper\n";
  EXPECT_DOUBLE_EQ(load(scene).friction.mu_k, 0.28);
  EXPECT_DOUBLE_EQ(load(scene + "  temperature: 77 K\n").friction.mu_k, 0.111);
  EXPECT_DOUBLE_EQ(load("format: 1\nfriction: {mu_k: cardboard}\n").friction.mu_k, 0.20);
  EXPECT_NE(error_of("format: 1\nfriction: {mu_k: iron, temperature: 77 K}\n")
                .find("the paper measured Iron at 300 K only, not at 77 K"),
            std::string::npos);
  EXPECT_NE(error_of("format: 1\nfriction: {mu_k: teflon}\n").find("one of the paper's materials"),
            std::string::npos);
}

// The friction law: Table I names keep giving mu_k; a law's keys are its own, located when wrong.
TEST(SceneYaml, FrictionLawKeysAreCheckedAndLocated) {
  const Scene coulomb = load("format: 1\nfriction: {mu_k: lego, mu_s: 0.35}\n");
  EXPECT_EQ(coulomb.friction.law, FrictionLawKind::kCoulomb);
  EXPECT_DOUBLE_EQ(coulomb.friction.mu_k, 0.29);
  EXPECT_DOUBLE_EQ(friction_law(coulomb.friction).mu_s, 0.35);
  EXPECT_DOUBLE_EQ(friction_law(load("format: 1\nfriction: {mu_k: 0.3}\n").friction).mu_s, 0.3);
  const Scene stribeck = load(
      "format: 1\nfriction: {law: stribeck, mu_k: 0.3, mu_s: 0.4, v_s: 5 mm/s, beta: -0.01}\n");
  const FrictionLaw law = friction_law(stribeck.friction);
  EXPECT_EQ(law.kind, FrictionLawKind::kStribeck);
  EXPECT_DOUBLE_EQ(law.v_s, 0.005);
  EXPECT_DOUBLE_EQ(law.kinetic(0.0), 0.4);
  EXPECT_NEAR(law.kinetic(1.0), 0.3 - 0.01, 1e-15);
  EXPECT_EQ(error_of("format: 1\nfriction: {mu_k: 0.3, v_s: 1 mm/s}\n"),
            "t.yaml:2:28: error: friction.v_s: the coulomb law has no v_s; set friction.law: "
            "stribeck to use it, or remove the key");
  EXPECT_NE(error_of("format: 1\nfriction: {law: dahl, mu_k: 0.3}\n")
                .find("t.yaml:2:17: error: friction.law: expected coulomb or stribeck"),
            std::string::npos);
  EXPECT_NE(error_of("format: 1\nfriction: {mu_k: 0.3, mu_s: 0.2}\n")
                .find("friction.mu_s: the static limit mu_s must be at least mu_k = 0.3"),
            std::string::npos);
  EXPECT_NE(error_of("format: 1\nfriction: {law: stribeck, mu_k: 0.3, mu_s: 0.4}\n")
                .find("needs friction.v_s"),
            std::string::npos);
  // At 1600 rpm the slip reaches 2 x 1.68 m/s: beta = -0.1 s/m leaves mu at 0.3 - 0.335 < 0.
  EXPECT_NE(error_of("format: 1\nfriction: {law: stribeck, mu_k: 0.3, beta: -0.1}\n")
                .find("friction.beta: the law's mu(s) goes negative"),
            std::string::npos);
}

TEST(SceneYaml, WarmingRollersTakeTheRoomsMuKFromThePaperOrTheScene) {
  const Scene cold = load(
      "format: 1\nfriction: {mu_k: lego, temperature: 77 K, warming: {time_constant: 1 min}}\n");
  ASSERT_TRUE(cold.friction.warming.has_value());
  EXPECT_DOUBLE_EQ(cold.friction.mu_k, 0.20);
  EXPECT_DOUBLE_EQ(*cold.friction.warming->mu_k_room, 0.29);  // Table I's 300 K LEGO row
  EXPECT_DOUBLE_EQ(cold.friction.warming->time_constant, 60.0);
  EXPECT_DOUBLE_EQ(cold.friction.warming->room_temperature, 300.0);
  EXPECT_DOUBLE_EQ(cold.friction.warming->hold, 0.0);
  const Scene given = load(
      "format: 1\nfriction: {mu_k: 0.2, temperature: 77 K, warming: {mu_k_room: 0.3, hold: 5 "
      "s}}\n");
  EXPECT_DOUBLE_EQ(*given.friction.warming->mu_k_room, 0.3);
  EXPECT_DOUBLE_EQ(given.friction.warming->hold, 5.0);
  EXPECT_NE(error_of("format: 1\nfriction: {mu_k: 0.2, temperature: 77 K, warming: {hold: 5 s}}\n")
                .find("t.yaml:2:51: error: friction.warming: rollers that warm need mu_k at the "
                      "room's temperature"),
            std::string::npos);
  EXPECT_NE(error_of("format: 1\nfriction: {mu_k: lego, warming: {hold: 5 s}}\n")
                .find("friction.warming.room: must be warmer than the rollers' start"),
            std::string::npos);
  EXPECT_NE(error_of("format: 1\nfriction: {mu_k: lego, temperature: 77 K, warming: {tau: 5 s}}\n")
                .find("t.yaml:2:"),
            std::string::npos);
}

TEST(SceneYaml, ImpossibleSetUpsAreRefusedWithTheReason) {
  struct Case {
    std::vector<SceneOverride> overrides;
    const char* message;
  };
  for (const Case& c : {
           Case{{{"plate.length", "120 mm"}}, "plate.length: the plate (120 mm) is shorter than"},
           Case{{{"friction.mu_k", "0"}}, "friction.mu_k: mu_k must be positive"},
           Case{{{"friction.mu_k", "-0.2"}}, "friction.mu_k: mu_k must be positive"},
           Case{{{"friction.mu_k", "10"}, {"plate.thickness", "10 mm"}},
                "rollers.spacing: no oscillation exists"},
           Case{{{"rollers.spacing", "15 mm"}}, "the rollers overlap"},
           Case{{{"world.time_step", "0 s"}}, "world.time_step: must be positive"},
           Case{{{"magnets", "[{x: 95 mm}]"}, {"sensor.position", "[110 mm, 0, 6 mm]"}},
                "sensor.position: the sensor lies inside the volume magnet 0 sweeps"},
           Case{{{"magnets", "[{x: 150 mm}]"}}, "does not sit on the plate"},
       }) {
    const std::string message = error_of(kBase, c.overrides);
    EXPECT_NE(message.find(c.message), std::string::npos) << c.message << "\n got: " << message;
  }
}

TEST(SceneYaml, BadFilesAreRefused) {
  EXPECT_EQ(error_of(""), "t.yaml:1:1: error: the file is empty; expected a YAML map");
  EXPECT_NE(error_of("format: 1\nplate: [1, 2\n").find("not valid YAML"), std::string::npos);
  EXPECT_NE(error_of("- just\n- a list\n").find("expected a map of keys"), std::string::npos);
  EXPECT_NE(error_of("just text").find("expected a map of keys"), std::string::npos);
  // A 100 MB file is refused by its size, before it is read.
  const std::string big = std::string(FRICTIONLAB_TEST_BINARY_DIR) + "/huge-scene.yaml";
  { std::ofstream(big).put('a'); }
  ASSERT_EQ(::truncate(big.c_str(), 100 << 20), 0);
  try {
    load_scene_file(big, {}, kPaper);
    ADD_FAILURE() << "a 100 MB file was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("more than the"), std::string::npos) << e.what();
  }
  std::filesystem::remove(big);
}

TEST(PlateMass, SlabPayloadAndMagnetsByHand) {
  Scene s;
  s.plate.length = 0.2;
  s.plate.width = 0.06;
  s.plate.thickness = 0.005;
  s.plate.mass = 0.060;
  EXPECT_DOUBLE_EQ(plate_mass(s).h_c, 0.0025);
  EXPECT_DOUBLE_EQ(plate_mass(s).mass, 0.060);
  s.plate.payload = {0.040, 0.010};  // 40 g centred 10 mm above the top face
  // h_c = (60 g * 2.5 mm + 40 g * 15 mm) / 100 g = 7.5 mm
  EXPECT_NEAR(plate_mass(s).h_c, 0.0075, 1e-15);
  MagnetDesc m;
  m.x = 0.095;
  m.diameter = 0.006;
  m.thickness = 0.003;
  m.density = 7500.0;
  s.magnets = {m};
  const double mm = 7500.0 * std::numbers::pi * 0.003 * 0.003 * 0.003;  // 0.636 g
  const PlateMass pm = plate_mass(s);
  EXPECT_NEAR(pm.mass, 0.1 + mm, 1e-15);
  EXPECT_NEAR(pm.x_c, mm * 0.095 / (0.1 + mm), 1e-15);
  EXPECT_NEAR(pm.h_c, (0.060 * 0.0025 + 0.040 * 0.015 + mm * 0.0065) / (0.1 + mm), 1e-15);
}

TEST(PlateMass, APhoneOnThePlateByHand) {
  Scene s;
  s.plate.length = 0.2;
  s.plate.thickness = 0.005;
  s.plate.mass = 0.060;
  PhoneDesc phone;
  phone.sensor = PhoneSensor::kAccelerometer;
  phone.mass = 0.180;
  phone.x = 0.010;
  phone.height = 0.002;
  phone.size = {0.075, 0.150, 0.008};
  s.phones = {phone};
  // h_c = (60 g * 2.5 mm + 180 g * (5 + 2 + 4) mm) / 240 g = 8.875 mm; x_c = 180 g * 10 mm / 240 g.
  const PlateMass pm = plate_mass(s);
  EXPECT_NEAR(pm.mass, 0.240, 1e-15);
  EXPECT_NEAR(pm.h_c, 0.008875, 1e-15);
  EXPECT_NEAR(pm.x_c, 0.0075, 1e-15);
  // Pitch inertia: the slab's and the phone's own (a box 150 mm along x, 8 mm thick) and their
  // offsets from the centre of mass (parallel axes).
  const double slab = 0.060 * (0.2 * 0.2 + 0.005 * 0.005) / 12.0 +
                      0.060 * (0.0075 * 0.0075 + (0.008875 - 0.0025) * (0.008875 - 0.0025));
  const double own = 0.180 * (0.150 * 0.150 + 0.008 * 0.008) / 12.0 +
                     0.180 * (0.0025 * 0.0025 + (0.011 - 0.008875) * (0.011 - 0.008875));
  EXPECT_NEAR(pm.inertia_pitch, slab + own, 1e-15);
  // A magnetometer lies beside the rig: it weighs nothing on the plate.
  s.phones[0].sensor = PhoneSensor::kMagnetometer;
  EXPECT_NEAR(plate_mass(s).h_c, 0.0025, 1e-15);
}

TEST(SceneYaml, PhonesLoadInSiAndTheirErrorsAreLocated) {
  const Scene s = load(kBase + R"(magnets:
  - {x: 95 mm}
phones:
  - {sensor: magnetometer, position: [114 mm, 60 mm, -10 mm], earth: [20 uT, 0 uT, -40 uT]}
  - {sensor: accelerometer, gravity: false, turn: 90 deg, mass: 150 g, height: 9.6 mm}
)");
  ASSERT_EQ(s.phones.size(), 2u);
  EXPECT_EQ(s.phones[0].sensor, PhoneSensor::kMagnetometer);
  EXPECT_DOUBLE_EQ(s.phones[0].rate, 100.0);
  EXPECT_DOUBLE_EQ(s.phones[0].noise, 0.2e-6);
  EXPECT_DOUBLE_EQ(s.phones[0].position[1], 0.060);
  EXPECT_DOUBLE_EQ(s.phones[0].earth[2], -40e-6);
  EXPECT_EQ(s.phones[1].sensor, PhoneSensor::kAccelerometer);
  EXPECT_DOUBLE_EQ(s.phones[1].rate, 400.0);
  EXPECT_DOUBLE_EQ(s.phones[1].noise, 0.05);
  EXPECT_FALSE(s.phones[1].gravity);
  EXPECT_NEAR(s.phones[1].turn, std::numbers::pi / 2, 1e-15);
  EXPECT_DOUBLE_EQ(s.phones[1].mass, 0.150);

  // A key of the other sensor, a sensor no phone has, a magnetometer without its place.
  EXPECT_NE(error_of(kBase + "phones: [{sensor: magnetometer, position: [0, 0.1, 0], mass: 1 g}]")
                .find("'mass' is an accelerometer's key (a phone lying on the plate)"),
            std::string::npos);
  EXPECT_NE(error_of(kBase + "phones: [{sensor: accelerometer, position: [0, 0.1, 0]}]")
                .find("'position' is a magnetometer's key"),
            std::string::npos);
  EXPECT_NE(error_of(kBase + "phones: [{sensor: gps}]")
                .find("t.yaml:11:19: error: phones[0].sensor: expected magnetometer (a phone "
                      "beside the rig) or accelerometer (a phone on the plate), found \"gps\""),
            std::string::npos);
  EXPECT_NE(error_of(kBase + "phones: [{sensor: magnetometer}]").find("'position' is required"),
            std::string::npos);
  EXPECT_NE(error_of(kBase + "phones: [{sensor: accelerometer, noise: 0.2 uT}]").find("noise"),
            std::string::npos);
  // Impossible places and values, said with the phone's index.
  EXPECT_NE(error_of(kBase + "phones: [{sensor: magnetometer, position: [50 mm, 0 mm, 2 mm]}]")
                .find("phone 0: the magnetometer at [50, 0, 2] mm lies inside the volume the "
                      "plate sweeps"),
            std::string::npos);
  EXPECT_NE(error_of(kBase + "phones: [{sensor: accelerometer, x: 150 mm}]")
                .find("phone 0: x = 150 mm puts the phone's centre off the plate"),
            std::string::npos);
  EXPECT_NE(error_of(kBase + "phones: [{sensor: accelerometer, rate: 0.5 Hz}]")
                .find("phone 0: rate must lie from 1 Hz to 10 kHz"),
            std::string::npos);
  EXPECT_NE(error_of(kBase + "phones: [{sensor: accelerometer, mass: 0 g}]")
                .find("phone 0: mass must be positive"),
            std::string::npos);
}

TEST(SceneYaml, AnUnknownMaterialIsAnsweredWithTheTablesMaterials) {
  const std::string message = error_of("format: 1\nfriction: {mu_k: plexiglass}\n");
  EXPECT_NE(message.find("found \"plexiglass\"; the paper's materials are lego, paper, "),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("did you mean 'plexiglas'?"), std::string::npos) << message;
}

}  // namespace
}  // namespace fl

namespace fl {
namespace {

// A ramp's scene: the small scene's rollers with a speed ramp instead of a speed.
std::string with_rollers(const std::string& rollers) {
  return "format: 1\nrollers:\n" + rollers + "friction:\n  mu_k: 0.3\n";
}

TEST(SceneYaml, RampKeysLoadInSiAndTheirErrorsAreLocated) {
  const Scene s =
      load(with_rollers("  speed_ramp: [{at: 0 s, speed: 100 rpm}, {at: 1 min, speed: 1600 rpm}, "
                        "{at: 120 s, speed: 100 rpm}]\n"));
  ASSERT_EQ(s.rollers.speed_ramp.size(), 3u);
  EXPECT_DOUBLE_EQ(s.rollers.speed_ramp[1].at, 60.0);
  EXPECT_NEAR(s.rollers.speed_ramp[1].value, 1600.0 * 2.0 * std::numbers::pi / 60.0, 1e-12);
  // The run's bounds rest on the ramp's largest speed.
  EXPECT_NEAR(nominal_roller_speed(s), 1600.0 * 2.0 * std::numbers::pi / 60.0, 1e-12);
  EXPECT_EQ(error_of(with_rollers("  speed_ramp: [{at: 0 s, speed: 100 rpm}, {at: 0 s, speed: "
                                  "200 rpm}]\n")),
            "t.yaml:3:48: error: rollers.speed_ramp[1].at: expected a time after the previous "
            "point's 0 s (times must increase), found 0 s");
  EXPECT_EQ(error_of(with_rollers("  speed_ramp: [{at: 0 s, speed: -5 rpm}]\n")),
            "t.yaml:3:33: error: rollers.speed_ramp[0].speed: expected a value >= 0, found -5 rpm");
  EXPECT_EQ(error_of(with_rollers("  speed_ramp: [{at: -1 s, speed: 5 rpm}]\n")),
            "t.yaml:3:21: error: rollers.speed_ramp[0].at: expected a time >= 0 s (from the run's "
            "start), found -1 s");
  EXPECT_NE(error_of(with_rollers("  speed_ramp: [{at: 0 s, sped: 5 rpm}]\n")).find("unknown key"),
            std::string::npos);
  EXPECT_NE(error_of(with_rollers("  speed_ramp: []\n")).find("expected a list of points"),
            std::string::npos);
  EXPECT_EQ(error_of(with_rollers("  speed: 100 rpm\n  speed_ramp: [{at: 0 s, speed: 5 rpm}]\n")),
            "t.yaml:4:15: error: rollers.speed_ramp: give speed (constant) or speed_ramp (over "
            "time), not both; remove one of the keys");
}

TEST(SceneYaml, DutyRampBelongsToTheDriveAndStaysWithinZeroAndOne) {
  const std::string drive =
      "format: 1\nfriction: {mu_k: 0.3}\ndrive:\n  motor: {duty_ramp: [{at: 0 s, duty: 20 %}, "
      "{at: 10 s, duty: 100 %}]}\n";
  const Scene s = load_scene_text(drive, "t.yaml", {}, kPaper, kParts);
  ASSERT_EQ(s.drive->motor.duty_ramp.size(), 2u);
  EXPECT_DOUBLE_EQ(s.drive->motor.duty_ramp[0].value, 0.2);
  const auto error = [&](const std::string& text) {
    try {
      load_scene_text(text, "t.yaml", {}, kPaper, kParts);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("format: 1\nfriction: {mu_k: 0.3}\ndrive:\n  motor: {duty_ramp: [{at: 0 s, "
                  "duty: 120 %}]}\n")
                .find("drive.motor.duty_ramp[0].duty: expected a value from 0 to 1, found 120 %"),
            std::string::npos);
  EXPECT_NE(error("format: 1\nfriction: {mu_k: 0.3}\ndrive:\n  motor: {duty: 50 %, duty_ramp: "
                  "[{at: 0 s, duty: 20 %}]}\n")
                .find("give duty (constant) or duty_ramp (over time), not both"),
            std::string::npos);
  // The ideal drive's ramp with a drive is refused: the motor sets the speed.
  EXPECT_NE(error("format: 1\nfriction: {mu_k: 0.3}\nrollers: {speed_ramp: [{at: 0 s, speed: 5 "
                  "rpm}]}\ndrive: {}\n")
                .find("rollers.speed_ramp: the drive sets the rollers' speed"),
            std::string::npos);
}

TEST(SceneChecks, RampsBuiltByHandAreChecked) {
  Scene s;
  s.rollers.speed_ramp = {{0.0, 10.0}, {5.0, -1.0}};
  const auto problems = check_scene(s);
  ASSERT_FALSE(problems.empty());
  EXPECT_EQ(problems.front().key, "rollers.speed_ramp");
  s.rollers.speed_ramp = {{2.0, 10.0}, {1.0, 20.0}};
  ASSERT_FALSE(check_scene(s).empty());
  EXPECT_EQ(check_scene(s).front().key, "rollers.speed_ramp");
}

}  // namespace
}  // namespace fl
