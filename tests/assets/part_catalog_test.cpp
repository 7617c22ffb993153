// The LEGO parts' index (assets/lego/parts.yaml): the committed one carries LEGO's dimensions
// and consistent physics data, it opens no mesh, and a malformed index fails at its line.
#include <cmath>
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "assets/part_catalog.hpp"
#include "io/input_error.hpp"
#include "temp_dir.hpp"

namespace fl::assets {
namespace {

constexpr double kMm = 1e-3;
// LEGO's dimensions are asked to 0.01 mm.
constexpr double kLegoTolerance = 0.01 * kMm;

const PartCatalog& catalog() {
  static const PartCatalog c = load_part_catalog(part_catalog_path(FRICTIONLAB_TEST_ASSET_DIR));
  return c;
}

Vec3 extent(const Aabb& b) {
  return {b.max[0] - b.min[0], b.max[1] - b.min[1], b.max[2] - b.min[2]};
}

TEST(PartCatalog, HasTheRigsParts) {
  for (const char* name :
       {"brick-2x4", "brick-1x2", "technic-brick-1x2", "technic-brick-1x4", "technic-brick-1x6",
        "technic-brick-1x8", "axle-4", "axle-8", "gear-8", "gear-16", "gear-24", "gear-40"}) {
    const PartSpec* part = catalog().find(name);
    ASSERT_NE(part, nullptr) << name;
    EXPECT_EQ(part->name, name);
    EXPECT_TRUE(std::filesystem::exists(part->file)) << part->file;
    EXPECT_GT(part->triangles, 0) << name;
  }
}

TEST(PartCatalog, Brick2x4HasLegoDimensions) {
  const PartSpec& brick = catalog().at("brick-2x4");
  EXPECT_EQ(brick.kind, PartKind::kBrick);
  const Vec3 size = extent(brick.bounds);
  // 4 x 2 studs of 8 mm less 0.1 mm per side; 9.6 mm body and 1.7 mm studs.
  EXPECT_NEAR(size[0], 31.8 * kMm, kLegoTolerance);
  EXPECT_NEAR(size[1], 15.8 * kMm, kLegoTolerance);
  EXPECT_NEAR(size[2], 11.3 * kMm, kLegoTolerance);
  EXPECT_NEAR(brick.bounds.min[2], 0.0, kLegoTolerance);
  ASSERT_EQ(brick.boxes.size(), 1u);
  EXPECT_NEAR(brick.boxes[0].size[0], 31.8 * kMm, kLegoTolerance);
  EXPECT_NEAR(brick.boxes[0].size[1], 15.8 * kMm, kLegoTolerance);
  EXPECT_NEAR(brick.boxes[0].size[2], 9.6 * kMm, kLegoTolerance);
  EXPECT_NEAR(brick.boxes[0].center[2], 4.8 * kMm, kLegoTolerance);
  EXPECT_EQ(brick.studs, (std::array<int, 2>{4, 2}));
  EXPECT_EQ(brick.plates, 3);
  // A real 2x4 brick weighs about 2.3 g; the model's solid studs and plain walls, a little less.
  EXPECT_GT(brick.mass, 2.0e-3);
  EXPECT_LT(brick.mass, 2.5e-3);
  EXPECT_LT(brick.triangles, 1000);
}

TEST(PartCatalog, BricksAndPlatesFollowTheGrid) {
  for (const PartSpec& part : catalog().parts()) {
    if (part.studs[0] == 0) continue;
    const Vec3 size = extent(part.bounds);
    EXPECT_NEAR(size[0], part.studs[0] * kStudPitch - 0.2 * kMm, kLegoTolerance) << part.name;
    EXPECT_NEAR(size[1], part.studs[1] * kStudPitch - 0.2 * kMm, kLegoTolerance) << part.name;
    EXPECT_NEAR(size[2], part.plates * kPlateHeight + kStudHeight, kLegoTolerance) << part.name;
    EXPECT_NEAR(part.boxes.at(0).size[2], part.plates * kPlateHeight, kLegoTolerance) << part.name;
  }
}

TEST(PartCatalog, TechnicBricksHaveHolesBetweenTheirStuds) {
  for (int n : {2, 4, 6, 8}) {
    const PartSpec& part = catalog().at("technic-brick-1x" + std::to_string(n));
    EXPECT_EQ(part.kind, PartKind::kTechnicBrick);
    ASSERT_EQ(part.holes.size(), static_cast<std::size_t>(n - 1)) << part.name;
    for (std::size_t i = 0; i < part.holes.size(); ++i) {
      const Hole& hole = part.holes[i];
      EXPECT_EQ(hole.axis, Axis::kY);
      EXPECT_NEAR(hole.diameter, 4.8 * kMm, kLegoTolerance);
      EXPECT_NEAR(hole.center[2], 5.8 * kMm, kLegoTolerance);
      EXPECT_NEAR(hole.center[0], (static_cast<double>(i) - (n - 2) / 2.0) * kStudPitch,
                  kLegoTolerance);
    }
  }
}

TEST(PartCatalog, AxlesAreCrossesOfTheirLength) {
  for (int n : {4, 8}) {
    const PartSpec& part = catalog().at("axle-" + std::to_string(n));
    ASSERT_TRUE(part.axle.has_value());
    EXPECT_NEAR(part.axle->length, n * kStudPitch - 0.2 * kMm, kLegoTolerance);
    EXPECT_NEAR(part.axle->cross, 4.8 * kMm, kLegoTolerance);
    EXPECT_NEAR(part.axle->arm, 1.8 * kMm, kLegoTolerance);
    // The collision compound is the cross: two boxes along y.
    ASSERT_EQ(part.boxes.size(), 2u);
    for (const CollisionBox& box : part.boxes) {
      EXPECT_NEAR(box.size[1], part.axle->length, kLegoTolerance);
      EXPECT_NEAR(std::max(box.size[0], box.size[2]), part.axle->cross, kLegoTolerance);
      EXPECT_NEAR(std::min(box.size[0], box.size[2]), part.axle->arm, kLegoTolerance);
    }
    EXPECT_NEAR(extent(part.bounds)[1], part.axle->length, kLegoTolerance);
  }
}

TEST(PartCatalog, GearsHaveModuleOneTeeth) {
  std::set<int> teeth;
  for (const PartSpec& part : catalog().parts()) {
    if (part.kind != PartKind::kGear) continue;
    ASSERT_TRUE(part.gear.has_value()) << part.name;
    const GearData& g = *part.gear;
    teeth.insert(g.teeth);
    EXPECT_EQ(part.name, "gear-" + std::to_string(g.teeth));
    EXPECT_DOUBLE_EQ(g.module, 1e-3);
    EXPECT_NEAR(2 * g.pitch_radius, g.teeth * kMm, 1e-9) << part.name;
    EXPECT_NEAR(2 * g.outer_radius, (g.teeth + 2) * kMm, 1e-9) << part.name;
    EXPECT_NEAR(2 * g.root_radius, (g.teeth - 2.5) * kMm, 1e-9) << part.name;
    const Vec3 size = extent(part.bounds);
    EXPECT_NEAR(size[0], (g.teeth + 2) * kMm, kLegoTolerance) << part.name;
    EXPECT_NEAR(size[2], (g.teeth + 2) * kMm, kLegoTolerance) << part.name;
    EXPECT_NEAR(size[1], std::max(g.width, g.hub_width), kLegoTolerance) << part.name;
    // The cylinder approximation: the toothed rim at the outer radius, the teeth's width.
    ASSERT_FALSE(part.cylinders.empty());
    EXPECT_EQ(part.cylinders[0].axis, Axis::kY);
    EXPECT_NEAR(part.cylinders[0].radius, g.outer_radius, 1e-9);
    EXPECT_NEAR(part.cylinders[0].length, g.width, 1e-9);
  }
  EXPECT_EQ(teeth, (std::set<int>{8, 16, 24, 40}));
  // 8 and 24 teeth mesh two studs apart, 24 and 40 four: the pitch radii add up.
  EXPECT_NEAR(
      catalog().at("gear-8").gear->pitch_radius + catalog().at("gear-24").gear->pitch_radius,
      2 * kStudPitch, 1e-12);
  EXPECT_NEAR(
      catalog().at("gear-24").gear->pitch_radius + catalog().at("gear-40").gear->pitch_radius,
      4 * kStudPitch, 1e-12);
}

TEST(PartCatalog, MassPropertiesAreConsistent) {
  for (const PartSpec& part : catalog().parts()) {
    // ABS at 1050 kg/m^3, the index's numbers rounded to 6 digits.
    EXPECT_NEAR(part.mass, 1050.0 * part.volume, 1e-5 * part.mass) << part.name;
    EXPECT_LT(part.volume, extent(part.bounds)[0] * extent(part.bounds)[1] * extent(part.bounds)[2])
        << part.name;
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_GE(part.center_of_mass[i], part.bounds.min[i]) << part.name;
      EXPECT_LE(part.center_of_mass[i], part.bounds.max[i]) << part.name;
    }
    // Principal moments of a real body obey the triangle inequality.
    const Vec3& I = part.inertia;
    EXPECT_LE(I[0], (I[1] + I[2]) * (1 + 1e-5)) << part.name;
    EXPECT_LE(I[1], (I[0] + I[2]) * (1 + 1e-5)) << part.name;
    EXPECT_LE(I[2], (I[0] + I[1]) * (1 + 1e-5)) << part.name;
  }
  // A symmetric gear turns about its centre.
  const PartSpec& gear = catalog().at("gear-40");
  for (double c : gear.center_of_mass) EXPECT_NEAR(c, 0.0, 1e-9);
  EXPECT_GT(gear.inertia[1], gear.inertia[0]);
}

TEST(PartCatalog, CollisionShapesLieInsideTheBounds) {
  for (const PartSpec& part : catalog().parts()) {
    EXPECT_FALSE(part.boxes.empty() && part.cylinders.empty()) << part.name;
    for (const CollisionBox& box : part.boxes) {
      for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_GE(box.center[i] - box.size[i] / 2, part.bounds.min[i] - 1e-9) << part.name;
        EXPECT_LE(box.center[i] + box.size[i] / 2, part.bounds.max[i] + 1e-9) << part.name;
      }
    }
  }
}

TEST(PartCatalog, UnknownPartSuggestsTheClosest) {
  EXPECT_EQ(catalog().find("brik-2x4"), nullptr);
  try {
    catalog().at("brik-2x4");
    FAIL() << "no error";
  } catch (const UnknownPart& e) {
    EXPECT_STREQ(e.what(), "unknown LEGO part 'brik-2x4'; did you mean 'brick-2x4'?");
  }
  EXPECT_THROW(catalog().at("windmill"), UnknownPart);
}

// The index alone is enough: reading it opens no mesh, so a folder without meshes still works.
TEST(PartCatalog, ReadsWithoutAnyMeshFile) {
  const test::TempDir dir;
  std::filesystem::copy_file(part_catalog_path(FRICTIONLAB_TEST_ASSET_DIR), dir.file("parts.yaml"));
  const PartCatalog c = load_part_catalog(dir.file("parts.yaml"));
  EXPECT_EQ(c.size(), catalog().size());
  for (const PartSpec& part : c.parts()) {
    EXPECT_EQ(std::filesystem::path(part.file).parent_path(), dir.path());
    EXPECT_FALSE(std::filesystem::exists(part.file));
  }
}

// A small valid index; the tests below break one line of it at a time.
const std::string kIndex = R"(format: 1
parts:
  - name: block
    file: block.glb
    kind: brick
    color: "#C91A09"
    triangles: 12
    bounds: {min: [-0.0039, -0.0039, 0], max: [0.0039, 0.0039, 0.0113]}
    volume: 1e-6
    mass: 0.00105
    center_of_mass: [0, 0, 0.005]
    inertia: [1e-8, 1e-8, 1e-8]
    studs: [1, 1]
    plates: 3
    collision:
      boxes:
        - {center: [0, 0, 0.0048], size: [0.0078, 0.0078, 0.0096]}
)";

std::string replaced(const std::string& from, const std::string& to) {
  std::string text = kIndex;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

std::string error_of(const std::string& text) {
  try {
    parse_part_catalog(text, "idx.yaml", "parts");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(PartCatalogErrors, TheSmallIndexIsValid) {
  const PartCatalog c = parse_part_catalog(kIndex, "idx.yaml", "parts");
  ASSERT_EQ(c.size(), 1u);
  const PartSpec& block = c.at("block");
  EXPECT_EQ(block.file, "parts/block.glb");
  EXPECT_FLOAT_EQ(block.color[0], 201.0f / 255.0f);
  EXPECT_DOUBLE_EQ(block.boxes.at(0).size[2], 0.0096);
}

TEST(PartCatalogErrors, LengthsAndMassesTakeUnits) {
  // docs/lego-parts.md: numbers are SI, and the reader takes lengths and masses with units too.
  std::string text = replaced("mass: 0.00105", "mass: 1.05 g");
  text.replace(text.find("[0.0039, 0.0039, 0.0113]"), 24, "[3.9 mm, 3.9 mm, 11.3 mm]");
  const PartCatalog c = parse_part_catalog(text, "idx.yaml", "parts");
  const PartCatalog si = parse_part_catalog(kIndex, "idx.yaml", "parts");
  EXPECT_DOUBLE_EQ(c.at("block").mass, si.at("block").mass);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_DOUBLE_EQ(c.at("block").bounds.max[i], si.at("block").bounds.max[i]);
}

TEST(PartCatalogErrors, AreLocatedAtTheirLine) {
  EXPECT_EQ(error_of(replaced("    color:", "    colr:")),
            "idx.yaml:6:5: error: parts[0].colr: unknown key; did you mean 'color'?");
  EXPECT_EQ(error_of(replaced("kind: brick", "kind: brik")),
            "idx.yaml:5:11: error: parts[0].kind: unknown kind \"brik\"; did you mean 'brick'? "
            "(the kinds are brick, plate, technic-brick, axle, gear)");
  EXPECT_EQ(error_of(replaced("format: 1", "format: 2")),
            "idx.yaml:1:9: error: format: this build reads format 1 of the parts index");
  EXPECT_EQ(error_of(replaced("mass: 0.00105", "mass: -1 g")),
            "idx.yaml:10:11: error: parts[0].mass: expected a positive value");
  EXPECT_EQ(error_of(replaced("file: block.glb", "file: ../block.glb")),
            "idx.yaml:4:11: error: parts[0].file: the mesh file must lie in the index's folder or "
            "below it");
  EXPECT_EQ(error_of(replaced("\"#C91A09\"", "\"red\"")),
            "idx.yaml:6:12: error: parts[0].color: expected an sRGB colour \"#RRGGBB\", found "
            "\"red\"");
  EXPECT_EQ(error_of(replaced("studs: [1, 1]", "studs: [1]")),
            "idx.yaml:13:12: error: parts[0].studs: expected [along x, along y]");
}

TEST(PartCatalogErrors, ShapesOutsideThePartFail) {
  const std::string message =
      error_of(replaced("size: [0.0078, 0.0078, 0.0096]", "size: [0.0098, 0.0078, 0.0096]"));
  EXPECT_EQ(message.rfind("idx.yaml:17:11: error: parts[0].collision.boxes[0]: the shape reaches "
                          "outside the part's bounds along x",
                          0),
            0u)
      << message;
  EXPECT_EQ(error_of(replaced("      boxes:\n        - {center: [0, 0, 0.0048], size: [0.0078, "
                              "0.0078, 0.0096]}\n",
                              "      {}\n")),
            "idx.yaml:16:7: error: parts[0].collision: expected at least one collision shape "
            "(boxes or cylinders)");
}

TEST(PartCatalogErrors, KindsNeedTheirData) {
  EXPECT_EQ(error_of(replaced("kind: brick", "kind: gear")),
            "idx.yaml:13:12: error: parts[0].studs: a gear has no studs");
  const std::string gear = replaced("kind: brick", "kind: gear");
  const std::string no_grid =
      gear.substr(0, gear.find("    studs:")) + gear.substr(gear.find("    collision:"));
  EXPECT_EQ(error_of(no_grid),
            "idx.yaml:3:5: error: parts[0]: a gear needs 'gear: {teeth, module, pitch_radius, "
            "...}'");
  const std::string wrong_pitch =
      no_grid.substr(0, no_grid.find("    collision:")) +
      "    gear: {teeth: 8, module: 0.001, pitch_radius: 0.005, outer_radius: 0.005, "
      "root_radius: 0.00275, width: 0.0078, hub_width: 0.0078}\n" +
      no_grid.substr(no_grid.find("    collision:"));
  EXPECT_EQ(error_of(wrong_pitch),
            "idx.yaml:13:51: error: parts[0].gear.pitch_radius: expected teeth x module / 2 = "
            "0.004000 m, found 0.005000 m");
}

TEST(PartCatalogErrors, DuplicatesAndBrokenYamlFail) {
  const std::string twice = kIndex + kIndex.substr(kIndex.find("  - name:"));
  EXPECT_EQ(error_of(twice),
            "idx.yaml:18:11: error: parts[1].name: the part 'block' is listed twice (first at "
            "parts[0])");
  EXPECT_EQ(
      error_of("format: 1\nparts: [\n").rfind("idx.yaml:3:1: error: this is not valid YAML", 0),
      0u);
  EXPECT_EQ(error_of("format: 1\nparts: []\n"),
            "idx.yaml:2:8: error: parts: expected at least one part");
}

TEST(PartCatalogErrors, AMissingIndexNamesItsPath) {
  try {
    load_part_catalog("/nonexistent/lego/parts.yaml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/lego/parts.yaml: error: ", 0), 0u)
        << e.what();
  }
}

}  // namespace
}  // namespace fl::assets
