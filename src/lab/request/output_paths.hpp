// Output paths checked before any work: a run, a sweep or a comparison that could not write its
// results is refused at once (bad input, located at the request's field that named the path),
// not after the work.
#pragma once

#include <string>
#include <vector>

namespace fl {

// A file a job reads, for the check below: its path as given ("-", standard input, is never a
// clash) and what it is in a message ("the log", "the series").
struct InputFile {
  std::string path;
  std::string what;
};

// Refuses an output that is one of the job's inputs or would overwrite one, before anything is
// written or created (bad input, at `field`, naming both): writing it would replace what the job
// reads (a student's data by a PNG). The same file is std::filesystem::equivalent, or the same
// path once made canonical (weakly_canonical). `output` is a file the job writes; with `names`, a
// folder the job writes those files into.
void refuse_overwriting_inputs(const std::string& output, const std::string& field,
                               const std::vector<InputFile>& inputs);
void refuse_overwriting_inputs(const std::string& folder, const std::vector<std::string>& names,
                               const std::string& field, const std::vector<InputFile>& inputs);

// A folder a job writes into (`field` names it in messages): created if missing; refused if it is a
// file, cannot be created, or cannot be written.
void prepare_output_folder(const std::string& folder, const std::string& field);

// A file a job writes: refused if it is a folder, or its folder cannot be created or
// written. The folder is created if missing.
void prepare_output_file(const std::string& file, const std::string& field);

}  // namespace fl
