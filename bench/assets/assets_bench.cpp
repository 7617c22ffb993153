// Loading LEGO parts as a scene with a frame of 300 parts would: read the catalogue, look up each
// placement's part, move its collision shapes into the world, and fetch its mesh through the
// cache. Run: build/<preset>/bench/assets/bench_assets [--assets DIR]
#include <array>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "assets/mesh_library.hpp"
#include "assets/part_catalog.hpp"

namespace fl::assets {
namespace {

std::string g_asset_dir = FRICTIONLAB_BENCH_ASSET_DIR;

// A frame of 300 parts: walls and towers of bricks, Technic beams holding the axles, plates, a
// few axles and the gearbox's gears.
std::vector<std::string> frame_of_300() {
  const std::vector<std::pair<std::string, int>> mix{{"brick-2x4", 90},
                                                     {"brick-1x2", 40},
                                                     {"brick-2x2", 30},
                                                     {"brick-1x4", 30},
                                                     {"plate-2x8", 20},
                                                     {"plate-2x4", 20},
                                                     {"plate-1x2", 10},
                                                     {"technic-brick-1x16", 10},
                                                     {"technic-brick-1x8", 14},
                                                     {"technic-brick-1x4", 10},
                                                     {"technic-brick-1x2", 6},
                                                     {"axle-8", 4},
                                                     {"axle-4", 4},
                                                     {"axle-12", 2},
                                                     {"gear-8", 3},
                                                     {"gear-16", 3},
                                                     {"gear-24", 2},
                                                     {"gear-40", 2}};
  std::vector<std::string> names;
  for (const auto& [name, count] : mix) names.insert(names.end(), count, name);
  return names;
}

// Placements on the stud grid: x, y in studs, z in plates.
struct Placement {
  const PartSpec* part;
  std::array<double, 3> position;  // m
};

// The catalogue plus every placement's collision shapes in world coordinates (what a physics
// builder does before it makes bodies). Returns a checksum so nothing is optimised away.
double place_collision(const PartCatalog& catalog, const std::vector<std::string>& names,
                       std::vector<Placement>& placements) {
  placements.clear();
  double checksum = 0;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const PartSpec& part = catalog.at(names[i]);
    const std::array<double, 3> at{static_cast<double>(i % 20) * 4 * kStudPitch,
                                   static_cast<double>(i / 20 % 3) * 4 * kStudPitch,
                                   static_cast<double>(i / 60) * kBrickHeight};
    placements.push_back({&part, at});
    for (const CollisionBox& box : part.boxes) {
      for (std::size_t k = 0; k < 3; ++k) checksum += box.center[k] + at[k] + box.size[k];
    }
    for (const CollisionCylinder& cylinder : part.cylinders)
      checksum += cylinder.radius + cylinder.length;
    checksum += part.mass;
  }
  return checksum;
}

// The whole load, cold cache: catalogue + collision shapes + meshes for 300 placements.
void BM_LoadFrameOf300Parts(benchmark::State& state) {
  const std::vector<std::string> names = frame_of_300();
  const std::string index = part_catalog_path(g_asset_dir);
  std::vector<Placement> placements;
  std::size_t files = 0, triangles = 0;
  for (auto _ : state) {
    const PartCatalog catalog = load_part_catalog(index);
    benchmark::DoNotOptimize(place_collision(catalog, names, placements));
    MeshLibrary library;
    triangles = 0;
    for (const Placement& p : placements) triangles += library.load(*p.part)->triangle_count();
    files = library.files_read();
    benchmark::ClobberMemory();
  }
  state.counters["placements"] = static_cast<double>(names.size());
  state.counters["mesh_files_read"] = static_cast<double>(files);
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_LoadFrameOf300Parts)->Unit(benchmark::kMillisecond)->MinTime(1.0);

// The headless path: catalogue and collision shapes only, no mesh opened.
void BM_CatalogAndCollisionOnly(benchmark::State& state) {
  const std::vector<std::string> names = frame_of_300();
  const std::string index = part_catalog_path(g_asset_dir);
  std::vector<Placement> placements;
  for (auto _ : state) {
    const PartCatalog catalog = load_part_catalog(index);
    benchmark::DoNotOptimize(place_collision(catalog, names, placements));
  }
}
BENCHMARK(BM_CatalogAndCollisionOnly)->Unit(benchmark::kMillisecond);

// 300 placements through a warm cache (a second scene in the same process).
void BM_WarmCache300Lookups(benchmark::State& state) {
  const std::vector<std::string> names = frame_of_300();
  const PartCatalog catalog = load_part_catalog(part_catalog_path(g_asset_dir));
  MeshLibrary library;
  for (const std::string& name : names) library.load(catalog.at(name));
  for (auto _ : state) {
    for (const std::string& name : names) benchmark::DoNotOptimize(library.load(catalog.at(name)));
  }
}
BENCHMARK(BM_WarmCache300Lookups)->Unit(benchmark::kMicrosecond);

// One mesh file, uncached, per part kind.
void BM_ReadOneMesh(benchmark::State& state, const std::string& name) {
  const PartCatalog catalog = load_part_catalog(part_catalog_path(g_asset_dir));
  const PartSpec& part = catalog.at(name);
  for (auto _ : state) benchmark::DoNotOptimize(read_part_mesh(part.file));
  state.counters["triangles"] = part.triangles;
}
BENCHMARK_CAPTURE(BM_ReadOneMesh, brick_2x4, std::string("brick-2x4"))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ReadOneMesh, technic_brick_1x16, std::string("technic-brick-1x16"))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ReadOneMesh, gear_40, std::string("gear-40"))->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace fl::assets

int main(int argc, char** argv) {
  // --assets DIR: another asset folder (the default is the source tree's).
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--assets") == 0 && i + 1 < argc) {
      fl::assets::g_asset_dir = argv[++i];
    } else {
      rest.push_back(argv[i]);
    }
  }
  int count = static_cast<int>(rest.size());
  benchmark::Initialize(&count, rest.data());
  if (!fl::assets::kHasAssets) {
    std::fprintf(stderr,
                 "bench_assets: this build has no mesh import (FRICTIONLAB_WITH_ASSETS=OFF)\n");
    return 0;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
