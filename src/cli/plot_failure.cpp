#include "cli/plot_failure.hpp"

#include <fmt/format.h>

#include "lab/request/outcome.hpp"

namespace fl::cli {

int plot_failure_status(const std::string& failure) {
  if (failure.empty()) return exit_status(Outcome::kDone);
  fmt::print(stderr, "error: no plot: {}; the results above are complete\n", failure);
  return exit_status(Outcome::kIncomplete);
}

}  // namespace fl::cli
