// The LEGO meshes through assimp: every part loads with LEGO's dimensions and its colour, the
// index's data agrees with the mesh, the cache reads each file once, and a bad file is an error
// naming the file. In a build without assimp, loading fails clearly instead.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "assets/mesh_library.hpp"
#include "assets/part_catalog.hpp"
#include "io/input_error.hpp"
#include "temp_dir.hpp"

namespace fl::assets {
namespace {

constexpr double kMm = 1e-3;
constexpr double kLegoTolerance = 0.01 * kMm;  // LEGO's dimensions, to 0.01 mm

const PartCatalog& catalog() {
  static const PartCatalog c = load_part_catalog(part_catalog_path(FRICTIONLAB_TEST_ASSET_DIR));
  return c;
}

#define SKIP_WITHOUT_ASSETS() \
  if (!kHasAssets) GTEST_SKIP() << "this build has no mesh import (FRICTIONLAB_WITH_ASSETS=OFF)"

Eigen::Vector3d size_of(const PartMesh& mesh) {
  return (mesh.bounds_max - mesh.bounds_min).cast<double>();
}

std::string read_bytes(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

TEST(MeshLibrary, EveryPartLoadsAndAgreesWithTheIndex) {
  SKIP_WITHOUT_ASSETS();
  MeshLibrary library;
  for (const PartSpec& part : catalog().parts()) {
    SCOPED_TRACE(part.name);
    const auto mesh = library.load(part);
    ASSERT_NE(mesh, nullptr);
    EXPECT_EQ(static_cast<int>(mesh->triangle_count()), part.triangles);
    ASSERT_EQ(mesh->normals.size(), mesh->vertex_count());
    ASSERT_EQ(mesh->colors.size(), mesh->vertex_count());
    for (const std::uint32_t i : mesh->indices) ASSERT_LT(i, mesh->vertex_count());
    for (const Eigen::Vector3f& n : mesh->normals) ASSERT_NEAR(n.norm(), 1.0f, 1e-4f);
    // The index's bounds are the mesh's, to the 0.1 um the generator rounds to.
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(mesh->bounds_min[i], part.bounds.min[static_cast<std::size_t>(i)], 1e-7);
      EXPECT_NEAR(mesh->bounds_max[i], part.bounds.max[static_cast<std::size_t>(i)], 1e-7);
    }
  }
  EXPECT_EQ(library.files_read(), catalog().size());
}

// Faces turn outward: the divergence theorem over the visible surface gives a positive volume
// close to the index's (the hidden faces where parts of the solid touch are left out of the file,
// so it is close, not equal).
TEST(MeshLibrary, TrianglesFaceOutward) {
  SKIP_WITHOUT_ASSETS();
  MeshLibrary library;
  for (const char* name : {"brick-2x4", "axle-4", "gear-24", "technic-brick-1x4"}) {
    const PartSpec& part = catalog().at(name);
    const auto mesh = library.load(part);
    double volume = 0;
    for (std::size_t t = 0; t < mesh->indices.size(); t += 3) {
      const Eigen::Vector3d a = mesh->positions[mesh->indices[t]].cast<double>();
      const Eigen::Vector3d b = mesh->positions[mesh->indices[t + 1]].cast<double>();
      const Eigen::Vector3d c = mesh->positions[mesh->indices[t + 2]].cast<double>();
      volume += a.dot(b.cross(c)) / 6;
    }
    EXPECT_NEAR(volume, part.volume, 0.35 * part.volume) << name;
    EXPECT_GT(volume, 0.0) << name;
  }
}

TEST(MeshLibrary, BricksHaveLegoDimensions) {
  SKIP_WITHOUT_ASSETS();
  MeshLibrary library;
  const auto brick = library.load(catalog().at("brick-2x4"));
  const Eigen::Vector3d size = size_of(*brick);
  EXPECT_NEAR(size.x(), 31.8 * kMm, kLegoTolerance);
  EXPECT_NEAR(size.y(), 15.8 * kMm, kLegoTolerance);
  EXPECT_NEAR(size.z(), 11.3 * kMm, kLegoTolerance);  // 9.6 mm body + 1.7 mm studs
  EXPECT_NEAR(brick->bounds_min.z(), 0.0, kLegoTolerance);
  // The body without its studs is 9.6 mm high: nothing between the body's top and the studs'
  // tops lies outside the stud circles (4.8 mm across, on the 8 mm grid).
  int stud_vertices = 0;
  for (const Eigen::Vector3f& p : brick->positions) {
    const double x = p.x(), y = p.y(), z = p.z();
    if (z <= 9.6 * kMm + 1e-7) continue;
    ++stud_vertices;
    const double sx = (std::floor(x / kStudPitch) + 0.5) * kStudPitch;
    const double sy = (std::floor(y / kStudPitch) + 0.5) * kStudPitch;
    EXPECT_LE(std::hypot(x - sx, y - sy), 2.4 * kMm + kLegoTolerance);
  }
  EXPECT_GT(stud_vertices, 8 * 12);

  const auto small = library.load(catalog().at("brick-1x2"));
  EXPECT_NEAR(size_of(*small).x(), 15.8 * kMm, kLegoTolerance);
  EXPECT_NEAR(size_of(*small).y(), 7.8 * kMm, kLegoTolerance);
  EXPECT_NEAR(size_of(*small).z(), 11.3 * kMm, kLegoTolerance);
  for (int n : {2, 4, 6, 8}) {
    const auto technic = library.load(catalog().at("technic-brick-1x" + std::to_string(n)));
    EXPECT_NEAR(size_of(*technic).x(), (8.0 * n - 0.2) * kMm, kLegoTolerance) << n;
    EXPECT_NEAR(size_of(*technic).y(), 7.8 * kMm, kLegoTolerance) << n;
    EXPECT_NEAR(size_of(*technic).z(), 11.3 * kMm, kLegoTolerance) << n;
  }
  const auto plate = library.load(catalog().at("plate-2x4"));
  EXPECT_NEAR(size_of(*plate).z(), (3.2 + 1.7) * kMm, kLegoTolerance);
}

TEST(MeshLibrary, AxlesHaveTheirLengthAndCross) {
  SKIP_WITHOUT_ASSETS();
  MeshLibrary library;
  for (int n : {4, 8}) {
    const auto axle = library.load(catalog().at("axle-" + std::to_string(n)));
    EXPECT_NEAR(size_of(*axle).x(), 4.8 * kMm, kLegoTolerance);
    EXPECT_NEAR(size_of(*axle).y(), (8.0 * n - 0.2) * kMm, kLegoTolerance);
    EXPECT_NEAR(size_of(*axle).z(), 4.8 * kMm, kLegoTolerance);
  }
}

// Outer diameter (teeth + 2) x module, and as many tooth tips as teeth.
TEST(MeshLibrary, GearsHaveTheirTeeth) {
  SKIP_WITHOUT_ASSETS();
  MeshLibrary library;
  for (int teeth : {8, 16, 24, 40}) {
    SCOPED_TRACE(teeth);
    const PartSpec& part = catalog().at("gear-" + std::to_string(teeth));
    const auto gear = library.load(part);
    EXPECT_NEAR(size_of(*gear).x(), (teeth + 2) * kMm, kLegoTolerance);
    EXPECT_NEAR(size_of(*gear).z(), (teeth + 2) * kMm, kLegoTolerance);
    double outer = 0;
    for (const Eigen::Vector3f& p : gear->positions)
      outer = std::max(outer, std::hypot(double{p.x()}, double{p.z()}));
    EXPECT_NEAR(2 * outer, (teeth + 2) * kMm, kLegoTolerance);
    std::set<long> tips;
    for (const Eigen::Vector3f& p : gear->positions) {
      if (std::hypot(double{p.x()}, double{p.z()}) < outer - 1e-6) continue;
      const double angle = std::atan2(double{p.z()}, double{p.x()});
      tips.insert(std::lround(angle / (2 * M_PI) * teeth + teeth) % teeth);
    }
    EXPECT_EQ(tips.size(), static_cast<std::size_t>(teeth));
    // Nothing reaches inside the axle's cross.
    for (const Eigen::Vector3f& p : gear->positions) {
      const double ax = std::fabs(p.x()), az = std::fabs(p.z());
      const bool in_cross = (ax < 2.4 * kMm - 1e-6 && az < 0.9 * kMm - 1e-6) ||
                            (az < 2.4 * kMm - 1e-6 && ax < 0.9 * kMm - 1e-6);
      EXPECT_FALSE(in_cross) << p.transpose();
    }
  }
}

TEST(MeshLibrary, ColorsSurviveLoading) {
  SKIP_WITHOUT_ASSETS();
  MeshLibrary library;
  for (const PartSpec& part : catalog().parts()) {
    const auto mesh = library.load(part);
    for (const std::array<float, 4>& c : mesh->colors) {
      for (std::size_t i = 0; i < 3; ++i) ASSERT_NEAR(c[i], part.color[i], 0.5f / 255) << part.name;
      ASSERT_FLOAT_EQ(c[3], 1.0f);
    }
  }
  // Red is red: LEGO's bright red 2x4 brick, #C91A09.
  const auto red = library.load(catalog().at("brick-2x4"));
  EXPECT_NEAR(red->colors.front()[0], 0xC9 / 255.0f, 0.5f / 255);
  EXPECT_NEAR(red->colors.front()[1], 0x1A / 255.0f, 0.5f / 255);
  EXPECT_NEAR(red->colors.front()[2], 0x09 / 255.0f, 0.5f / 255);
}

TEST(MeshLibrary, CollisionShapesLieInsideTheMesh) {
  SKIP_WITHOUT_ASSETS();
  MeshLibrary library;
  for (const PartSpec& part : catalog().parts()) {
    const auto mesh = library.load(part);
    const Eigen::Vector3d lo = mesh->bounds_min.cast<double>().array() - 1e-7;
    const Eigen::Vector3d hi = mesh->bounds_max.cast<double>().array() + 1e-7;
    for (const CollisionBox& box : part.boxes) {
      const Eigen::Vector3d c(box.center[0], box.center[1], box.center[2]);
      const Eigen::Vector3d h = Eigen::Vector3d(box.size[0], box.size[1], box.size[2]) / 2;
      EXPECT_TRUE(((c - h).array() >= lo.array()).all()) << part.name;
      EXPECT_TRUE(((c + h).array() <= hi.array()).all()) << part.name;
    }
    for (const CollisionCylinder& cylinder : part.cylinders) {
      ASSERT_EQ(cylinder.axis, Axis::kY);
      EXPECT_LE(cylinder.radius, hi.x() + 1e-7) << part.name;
      EXPECT_LE(cylinder.radius, hi.z() + 1e-7) << part.name;
      EXPECT_LE(cylinder.length / 2, hi.y() + 1e-7) << part.name;
    }
  }
}

TEST(MeshLibrary, ReadsEachFileOnce) {
  SKIP_WITHOUT_ASSETS();
  MeshLibrary library;
  EXPECT_EQ(library.files_read(), 0u);
  const PartSpec& brick = catalog().at("brick-2x4");
  const auto first = library.load(brick);
  for (int i = 0; i < 200; ++i) EXPECT_EQ(library.load(brick), first);
  // Other spellings of the same file share the entry.
  const std::filesystem::path file(brick.file);
  EXPECT_EQ(library.load(std::filesystem::absolute(file).string()), first);
  EXPECT_EQ(library.load((file.parent_path() / ".." / "lego" / file.filename()).string()), first);
  EXPECT_EQ(library.files_read(), 1u);
  EXPECT_EQ(library.size(), 1u);
  // A frame of 300 parts of a few kinds reads each kind once.
  const std::vector<std::string> kinds{"brick-2x4", "brick-1x2", "technic-brick-1x8", "axle-8",
                                       "gear-24"};
  for (int i = 0; i < 300; ++i) library.load(catalog().at(kinds[static_cast<std::size_t>(i) % 5]));
  EXPECT_EQ(library.files_read(), kinds.size());
  library.clear();
  EXPECT_EQ(library.size(), 0u);
  EXPECT_EQ(first->triangle_count(), static_cast<std::size_t>(brick.triangles));  // still valid
  library.load(brick);
  EXPECT_EQ(library.files_read(), kinds.size() + 1);
}

TEST(MeshLibrary, SharesAcrossThreads) {
  SKIP_WITHOUT_ASSETS();
  MeshLibrary library;
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&library] {
      for (int i = 0; i < 50; ++i) {
        for (const char* name : {"brick-2x4", "gear-40", "axle-4"}) {
          library.load(catalog().at(name));
        }
      }
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(library.files_read(), 3u);
}

std::string error_of(const std::string& file) {
  try {
    read_part_mesh(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MeshLibrary, BadFilesAreErrorsNamingTheFile) {
  SKIP_WITHOUT_ASSETS();
  const test::TempDir dir;
  const std::string missing = dir.file("missing.glb");
  EXPECT_EQ(error_of(missing), missing +
                                   ": error: no such mesh file; check the asset folder (--assets "
                                   "or $FRICTIONLAB_ASSETS)");
  const std::string empty = dir.write("empty.glb", "");
  EXPECT_EQ(error_of(empty), empty + ": error: the mesh file is empty");
  EXPECT_EQ(error_of(dir.path().string()), dir.path().string() + ": error: not a regular file");
  const std::string brick = read_bytes(catalog().at("brick-2x4").file);
  std::string broken_json = brick;
  broken_json[30] = '}';
  for (const std::string& file :
       {dir.write("text.glb", "hello, this is not a mesh\n"),
        dir.write("truncated.glb", brick.substr(0, brick.size() / 2)),
        dir.write("header-only.glb", brick.substr(0, 12)), dir.write("broken.glb", broken_json),
        dir.write("garbage.obj", std::string(1000, '\x7f')), dir.write("no-extension", brick)}) {
    SCOPED_TRACE(file);
    const std::string message = error_of(file);
    // "no-extension" is the one assimp reads anyway (it sniffs the glTF magic).
    if (message == "no error") continue;
    EXPECT_EQ(message.rfind(file + ": error: ", 0), 0u) << message;
  }
  // A failed load is not cached and is not a crash; the library keeps working.
  MeshLibrary library;
  EXPECT_THROW(library.load(dir.file("text.glb")), InputError);
  EXPECT_THROW(library.load(dir.file("text.glb")), InputError);
  EXPECT_EQ(library.files_read(), 2u);
  EXPECT_EQ(library.size(), 0u);
}

std::string base64(const std::string& bytes) {
  static const char* const kDigits =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 2]);
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
  }
  return out;
}

template <typename T>
void put(std::string& out, const std::vector<T>& values) {
  out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// A .gltf of one triangle with vertex colours: glTF's +Y up becomes +Z, and the colour is the
// vertex colour times the material's, both linear in the file, sRGB after loading.
TEST(MeshLibrary, ReadsVertexColorsAndTurnsGltfUpright) {
  SKIP_WITHOUT_ASSETS();
  std::string buffer;
  put(buffer, std::vector<float>{0, 0, 0, 0.01f, 0, 0, 0, 0.01f, 0});  // y up in the file
  put(buffer, std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1});
  put(buffer, std::vector<float>{1, 0, 0, 1, 0, 1, 0, 1, 0.2140411f, 0.2140411f, 1, 1});
  const std::string gltf = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
  "nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1,
  "COLOR_0":2},"material":0}]}],
  "materials":[{"pbrMetallicRoughness":{"baseColorFactor":[0.5,1,1,1]}}],
  "buffers":[{"byteLength":120,"uri":"data:application/octet-stream;base64,)" +
                           base64(buffer) + R"("}],
  "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},
                 {"buffer":0,"byteOffset":36,"byteLength":36},
                 {"buffer":0,"byteOffset":72,"byteLength":48}],
  "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",
                "min":[0,0,0],"max":[0.01,0.01,0]},
               {"bufferView":1,"componentType":5126,"count":3,"type":"VEC3"},
               {"bufferView":2,"componentType":5126,"count":3,"type":"VEC4"}]})";
  ASSERT_EQ(buffer.size(), 120u);
  const test::TempDir dir;
  const PartMesh mesh = read_part_mesh(dir.write("triangle.gltf", gltf));
  ASSERT_EQ(mesh.vertex_count(), 3u);
  ASSERT_EQ(mesh.triangle_count(), 1u);
  // The file's (0, 0.01, 0), up in glTF, is (0, 0, 0.01), up in the part's frame.
  EXPECT_NEAR(mesh.bounds_max.z(), 0.01f, 1e-7f);
  EXPECT_NEAR(mesh.bounds_max.y(), 0.0f, 1e-7f);
  EXPECT_NEAR(mesh.normals[0].y(), -1.0f, 1e-6f);  // the file's +z is the part's -y
  // Red 1 x 0.5 linear is 0.7354 sRGB; 0.2140411 linear is 0.5 sRGB.
  EXPECT_NEAR(mesh.colors[0][0], 0.7353569f, 1e-4f);
  EXPECT_NEAR(mesh.colors[1][1], 1.0f, 1e-4f);
  const double red = 0.5 * 0.2140411;  // linear
  EXPECT_NEAR(mesh.colors[2][0], 1.055 * std::pow(red, 1 / 2.4) - 0.055, 1e-4);
  EXPECT_NEAR(mesh.colors[2][1], 0.5f, 1e-4f);
  EXPECT_NEAR(mesh.colors[2][2], 1.0f, 1e-4f);
  EXPECT_FLOAT_EQ(mesh.colors[2][3], 1.0f);
}

TEST(MeshLibraryStub, LoadingNamesTheMissingComponent) {
  if (kHasAssets) GTEST_SKIP() << "this build has mesh import";
  MeshLibrary library;
  try {
    library.load(catalog().at("brick-2x4"));
    FAIL() << "no error";
  } catch (const MissingComponent& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("needs mesh import (assimp)"), std::string::npos) << message;
    EXPECT_NE(message.find("FRICTIONLAB_WITH_ASSETS=ON"), std::string::npos) << message;
  }
  // The catalogue, and with it every collision shape, needs no mesh import.
  EXPECT_GT(catalog().at("brick-2x4").boxes.size(), 0u);
}

}  // namespace
}  // namespace fl::assets
