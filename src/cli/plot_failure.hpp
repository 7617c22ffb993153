// The exit status of a command whose results are printed (and written) but whose plot failed.
#pragma once

#include <string>

namespace fl::cli {

// 0 without a failure; else 1 (an incomplete job, lab/request/outcome.hpp), after "error: no
// plot: FAILURE; the results above are complete" on stderr.
int plot_failure_status(const std::string& failure);

}  // namespace fl::cli
