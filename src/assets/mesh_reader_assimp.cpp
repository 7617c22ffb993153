// read_part_mesh through assimp (builds with FRICTIONLAB_WITH_ASSETS=ON).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <filesystem>
#include <string>
#include <system_error>

#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include "assets/mesh_library.hpp"
#include "io/input_error.hpp"

namespace fl::assets {
namespace {

// A LEGO part is tens of kilobytes; anything this large is not one.
constexpr std::uintmax_t kMaxBytes = std::uintmax_t{64} << 20;

[[noreturn]] void fail(const std::string& file, const std::string& what) {
  throw InputError(SourceLocation{file, 0, 0}, what);
}

bool is_gltf(const std::string& file) {
  std::string extension = std::filesystem::path(file).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".gltf" || extension == ".glb";
}

float linear_to_srgb(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

aiColor4D material_color(const aiScene& scene, unsigned index) {
  aiColor4D color(1, 1, 1, 1);
  if (index >= scene.mNumMaterials) return color;
  const aiMaterial& material = *scene.mMaterials[index];
  if (material.Get(AI_MATKEY_BASE_COLOR, color) == AI_SUCCESS) return color;
  if (material.Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS) return color;
  return aiColor4D(1, 1, 1, 1);
}

}  // namespace

PartMesh read_part_mesh(const std::string& file) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (ec || !fs::exists(status))
    fail(file, "no such mesh file; check the asset folder (--assets or $FRICTIONLAB_ASSETS)");
  if (!fs::is_regular_file(status)) fail(file, "not a regular file");
  const std::uintmax_t bytes = fs::file_size(file, ec);
  if (ec) fail(file, "cannot read the file's size");
  if (bytes == 0) fail(file, "the mesh file is empty");
  if (bytes > kMaxBytes)
    fail(file, "the file is " + std::to_string(bytes) + " bytes, more than the " +
                   std::to_string(kMaxBytes) + " bytes a part's mesh may have");

  Assimp::Importer importer;
  // Points and lines are not part of a solid's surface: drop them.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const unsigned flags = aiProcess_Triangulate | aiProcess_SortByPType |
                         aiProcess_PreTransformVertices | aiProcess_GenNormals |
                         aiProcess_ValidateDataStructure;
  const aiScene* scene = nullptr;
  try {
    scene = importer.ReadFile(file, flags);
  } catch (const std::exception& e) {
    fail(file, std::string("cannot read the mesh: ") + e.what());
  }
  if (scene == nullptr)
    fail(file, std::string("cannot read the mesh: ") + importer.GetErrorString());
  if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0 || scene->mNumMeshes == 0)
    fail(file, "the file holds no mesh");

  const bool gltf = is_gltf(file);
  PartMesh out;
  out.file = file;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& mesh = *scene->mMeshes[m];
    if ((mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0) continue;
    if (!mesh.HasNormals()) fail(file, "a mesh without normals");
    const auto base = static_cast<std::uint32_t>(out.positions.size());
    const aiColor4D material = material_color(*scene, mesh.mMaterialIndex);
    const bool vertex_colors = mesh.HasVertexColors(0);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      const aiVector3D& n = mesh.mNormals[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        fail(file, "a vertex position is not a finite number");
      // glTF is +Y up; the part's frame is +Z up.
      out.positions.emplace_back(gltf ? Eigen::Vector3f(p.x, -p.z, p.y)
                                      : Eigen::Vector3f(p.x, p.y, p.z));
      Eigen::Vector3f normal =
          gltf ? Eigen::Vector3f(n.x, -n.z, n.y) : Eigen::Vector3f(n.x, n.y, n.z);
      const float length = normal.norm();
      if (std::isfinite(length) && length > 0.0f) normal /= length;
      out.normals.push_back(normal);
      aiColor4D c = material;
      if (vertex_colors) c = c * mesh.mColors[0][v];
      if (gltf) {
        c.r = linear_to_srgb(c.r);
        c.g = linear_to_srgb(c.g);
        c.b = linear_to_srgb(c.b);
      }
      out.colors.push_back({c.r, c.g, c.b, c.a});
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (unsigned k = 0; k < 3; ++k) {
        if (face.mIndices[k] >= mesh.mNumVertices) fail(file, "a triangle's index is out of range");
        out.indices.push_back(base + face.mIndices[k]);
      }
    }
  }
  if (out.indices.empty()) fail(file, "the file holds no triangles");
  out.bounds_min = out.bounds_max = out.positions.front();
  for (const Eigen::Vector3f& p : out.positions) {
    out.bounds_min = out.bounds_min.cwiseMin(p);
    out.bounds_max = out.bounds_max.cwiseMax(p);
  }
  return out;
}

}  // namespace fl::assets
