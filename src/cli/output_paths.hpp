// Output paths checked before any work: a run, a sweep or a comparison that could not write its
// results is refused at once (a located error, exit status 2), not after the work.
#pragma once

#include <string>

namespace fl::cli {

// A folder the command writes into: created if missing; refused if it is a file, cannot be
// created, or cannot be written.
void prepare_output_folder(const std::string& folder, const std::string& option);

// A file the command writes: refused if it is a folder, or its folder cannot be created or
// written. The folder is created if missing.
void prepare_output_file(const std::string& file, const std::string& option);

}  // namespace fl::cli
