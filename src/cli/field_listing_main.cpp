// frictionlab-fields FILE...: writes the listings of a run's fields
// (lab/listings/field_listing.hpp) and of the web API's bodies (api/api_listing.hpp) into each
// file's generated blocks; @LIST names a file that lists the files, one a line. With
// --check, writes nothing and exits 1 naming each file whose blocks are not what the declaration
// gives (tools/generate-fields mends them).
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "api/api_listing.hpp"
#include "io/atomic_file.hpp"
#include "lab/listings/field_listing.hpp"

int main(int argc, char** argv) {
  bool check = false;
  int stale = 0;
  std::vector<fl::FieldListing> listings = fl::field_listings();
  for (fl::FieldListing& listing : fl::api::api_listings()) listings.push_back(std::move(listing));
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--check") {
      check = true;
    } else if (arg.size() > 1 && arg[0] == '@') {
      std::ifstream list(arg.substr(1));
      if (!list) {
        std::fprintf(stderr, "%s: error: cannot read the list of files\n", arg.c_str() + 1);
        return 2;
      }
      for (std::string line; std::getline(list, line);)
        if (!line.empty()) files.push_back(line);
    } else {
      files.push_back(arg);
    }
  }
  for (const std::string& file : files) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "%s: error: cannot read it\n", file.c_str());
      return 2;
    }
    std::ostringstream text;
    text << in.rdbuf();
    std::string problem;
    const std::optional<std::string> written = fl::with_listings(text.str(), listings, &problem);
    if (!written) {
      std::fprintf(stderr, "%s: error: %s\n", file.c_str(), problem.c_str());
      return 2;
    }
    if (*written == text.str()) continue;
    if (check) {
      std::fprintf(stderr,
                   "%s: error: its lists of fields are not what src/lab/run/summary_fields.cpp "
                   "and src/api/api_fields.cpp declare; run tools/generate-fields\n",
                   file.c_str());
      ++stale;
    } else {
      fl::write_file_atomic(file, *written);
      std::printf("frictionlab-fields: wrote %s\n", file.c_str());
    }
  }
  return stale == 0 ? 0 : 1;
}
