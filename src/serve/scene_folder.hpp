// The scenes folder as the server offers it (`serve --scenes DIR`): the `*.yaml` files directly in
// it whose path, links followed, stays inside it. A file or link that leads outside is neither
// listed nor read: a page asking for it is told the scenes there are, as for a name not there.
#pragma once

#include <string>
#include <vector>

#include "lab/request/session_request.hpp"

namespace fl::serve {

class SceneFolder {
 public:
  explicit SceneFolder(std::string folder) : folder_(std::move(folder)) {}

  // The scenes offered, by name (the file's stem), with their first comment line as title.
  std::vector<SceneEntry> list() const;
  // Throws RequestError (the field "scene") unless `name` is a scene offered; the message names
  // the scenes offered and the one asked for, never a path.
  void check(const std::string& name) const;
  const std::string& path() const { return folder_; }

 private:
  // Whether `name.yaml` is a file that, links followed, lies inside the folder.
  bool offers(const std::string& name) const;

  std::string folder_;
};

}  // namespace fl::serve
