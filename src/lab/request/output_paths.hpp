// Output paths checked before any work: a run, a sweep or a comparison that could not write its
// results is refused at once (bad input, located at the request's field that named the path),
// not after the work.
#pragma once

#include <string>

namespace fl {

// A folder a job writes into (`field` names it in messages): created if missing; refused if it is a
// file, cannot be created, or cannot be written.
void prepare_output_folder(const std::string& folder, const std::string& field);

// A file a job writes: refused if it is a folder, or its folder cannot be created or
// written. The folder is created if missing.
void prepare_output_file(const std::string& file, const std::string& field);

}  // namespace fl
