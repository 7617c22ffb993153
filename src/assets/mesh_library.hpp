// LEGO part meshes for drawing: a part file (glTF 2.0 from tools/generate-lego-parts, or anything
// assimp reads) loaded into a plain struct of positions, normals, colours and triangles, in
// metres in the part's frame (z up; see part_catalog.hpp). MeshLibrary caches by path, so a part
// placed 200 times is read once. Physics never needs this: its shapes come from PartCatalog.
//
// Mesh import is optional (FRICTIONLAB_WITH_ASSETS, assimp). Without it this header still
// compiles and every load throws MissingComponent; tests skip on kHasAssets.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "assets/part_catalog.hpp"
#include "io/missing_component.hpp"

#ifndef FRICTIONLAB_HAS_ASSETS
#error "FRICTIONLAB_HAS_ASSETS is set by the fl_assets target; link fl_assets"
#endif

namespace fl::assets {

// True when this build reads meshes (assimp); false when it has the stub.
inline constexpr bool kHasAssets = FRICTIONLAB_HAS_ASSETS != 0;

// A component this build was configured without: the one error type of every layer
// (io/missing_component.hpp).
using MissingComponent = fl::MissingComponent;

struct PartMesh {
  std::string file;                          // as it was asked for
  std::vector<Eigen::Vector3f> positions;    // m, part frame, z up
  std::vector<Eigen::Vector3f> normals;      // unit length, one per position
  std::vector<std::array<float, 4>> colors;  // sRGB + alpha, 0..1, one per position
  std::vector<std::uint32_t> indices;        // three per triangle, counter-clockwise outside
  Eigen::Vector3f bounds_min = Eigen::Vector3f::Zero();  // m, of the positions
  Eigen::Vector3f bounds_max = Eigen::Vector3f::Zero();  // m

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return indices.size() / 3; }
};

// Reads one mesh file, uncached. A .gltf/.glb file is turned from glTF's +Y up to the part's +Z
// up ((x, y, z) -> (x, -z, y)) and its linear colours to sRGB; other formats are taken as they
// are. Colour = the material's base (or diffuse) colour times the vertex colours, if any.
// Throws InputError located at the file for a missing, oversized, unreadable or empty file (the
// message carries assimp's reason), MissingComponent in a build without assimp.
PartMesh read_part_mesh(const std::string& file);

// A cache of meshes, shared by every placement of a part. Thread-safe.
class MeshLibrary {
 public:
  // The mesh of `file`, read on first use. Paths that name the same file (relative, absolute,
  // "a/../b") share one entry. A failed read is not cached: it throws again next time.
  std::shared_ptr<const PartMesh> load(const std::string& file);
  std::shared_ptr<const PartMesh> load(const PartSpec& part) { return load(part.file); }

  // How many times a file was actually read (successfully or not) since construction.
  std::size_t files_read() const;
  // How many meshes the cache holds.
  std::size_t size() const;
  // Drops every cached mesh (meshes still held by callers stay valid).
  void clear();

 private:
  mutable std::mutex mutex_;
  std::unordered_map<std::string, std::shared_ptr<const PartMesh>> cache_;        // canonical path
  std::unordered_map<std::string, std::shared_ptr<const PartMesh>> by_spelling_;  // path as given
  std::size_t files_read_ = 0;
};

}  // namespace fl::assets
