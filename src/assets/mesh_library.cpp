// The cache, common to the assimp build and the stub; read_part_mesh is in mesh_reader_*.cpp.
#include "assets/mesh_library.hpp"

#include <filesystem>
#include <system_error>

namespace fl::assets {
namespace {

// One key per file however it is spelt: the canonical path where it exists, else the
// normalised absolute one.
std::string cache_key(const std::string& file) {
  std::error_code ec;
  std::filesystem::path path = std::filesystem::weakly_canonical(file, ec);
  if (ec) path = std::filesystem::absolute(file, ec).lexically_normal();
  if (ec) return file;
  return path.string();
}

}  // namespace

std::shared_ptr<const PartMesh> MeshLibrary::load(const std::string& file) {
  {
    // The path as given, seen before: no file system call at all.
    const std::lock_guard<std::mutex> lock(mutex_);
    if (const auto it = by_spelling_.find(file); it != by_spelling_.end()) return it->second;
  }
  const std::string key = cache_key(file);
  const std::lock_guard<std::mutex> lock(mutex_);
  auto it = cache_.find(key);
  if (it == cache_.end()) {
    ++files_read_;
    it = cache_.emplace(key, std::make_shared<const PartMesh>(read_part_mesh(file))).first;
  }
  by_spelling_.emplace(file, it->second);
  return it->second;
}

std::size_t MeshLibrary::files_read() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return files_read_;
}

std::size_t MeshLibrary::size() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return cache_.size();
}

void MeshLibrary::clear() {
  const std::lock_guard<std::mutex> lock(mutex_);
  cache_.clear();
  by_spelling_.clear();
}

}  // namespace fl::assets
