#include "hall_log/log_files.hpp"

#include <algorithm>
#include <filesystem>
#include <string_view>

#include "io/input_error.hpp"

namespace fl {
namespace {

namespace fs = std::filesystem;

// Whether `name` matches `pattern` (* any run of characters, ? one character).
bool matches(std::string_view pattern, std::string_view name) {
  std::size_t p = 0, n = 0, star = std::string_view::npos, resume = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

std::vector<std::string> sorted_files(const fs::path& dir, auto&& keep) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec))
    if (e.is_regular_file() && keep(e.path())) out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

bool is_log_pattern(const std::string& argument) {
  return argument.find_first_of("*?") != std::string::npos;
}

bool has_log_extension(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  return ext == ".csv" || ext == ".txt" || ext == ".log" || ext == ".tsv";
}

std::vector<std::string> expand_log_arguments(const std::vector<std::string>& arguments) {
  std::vector<std::string> logs;
  const auto add = [&](const std::string& log) {
    if (std::find(logs.begin(), logs.end(), log) == logs.end()) logs.push_back(log);
  };
  for (const std::string& a : arguments) {
    std::error_code ec;
    if (a == "-") {
      add(a);
    } else if (is_log_pattern(a)) {
      const fs::path p(a);
      const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
      if (is_log_pattern(dir.string()))
        throw InputError({a, 0, 0},
                         "expected a pattern in the file's name only (logs/*.csv), "
                         "found one in the folder's; name the folders");
      const std::string pattern = p.filename().string();
      const auto found = sorted_files(
          dir, [&](const fs::path& f) { return matches(pattern, f.filename().string()); });
      if (found.empty())
        throw InputError({a, 0, 0}, "expected the pattern to match a log, found no file in " +
                                        dir.string() + " that it matches");
      for (const std::string& f : found) add(f);
    } else if (fs::is_directory(a, ec)) {
      // A simulated run's folder: its Hall signal, not its other tables.
      if (fs::is_regular_file(fs::path(a) / "hall.csv", ec)) {
        add((fs::path(a) / "hall.csv").string());
        continue;
      }
      const auto found =
          sorted_files(a, [](const fs::path& f) { return has_log_extension(f.string()); });
      if (found.empty())
        throw InputError({a, 0, 0},
                         "expected a folder holding logs (.csv, .txt, .log or .tsv "
                         "files), found none");
      for (const std::string& f : found) add(f);
    } else if (fs::exists(a, ec)) {
      add(a);
    } else {
      throw InputError({a, 0, 0}, "cannot open the log: No such file or directory");
    }
  }
  return logs;
}

}  // namespace fl
