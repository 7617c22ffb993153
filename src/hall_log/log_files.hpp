// The logs a command line names: files, folders (a simulated run's hall.csv, else every log in
// them: .csv, .txt, .log and .tsv files, by name) and file-name patterns with * and ? (for shells
// that leave them unexpanded, or quoted on purpose), in the order given, each log once.
#pragma once

#include <string>
#include <vector>

namespace fl {

// True when `argument` is a pattern (holds * or ?).
bool is_log_pattern(const std::string& argument);

// True for the extensions a folder's logs have: .csv, .txt, .log, .tsv.
bool has_log_extension(const std::string& path);

// Expands the arguments into log files. Throws InputError naming the argument for a path that
// does not exist, a pattern or folder that matches no log, and a pattern in a folder's name.
std::vector<std::string> expand_log_arguments(const std::vector<std::string>& arguments);

}  // namespace fl
