// The paper's value for the plate's material beside a measured mu_k, as estimate, fit and compare
// --log print it: the paper's T and mu_k at that temperature (its Table I), and how many combined
// standard errors the measured mu_k lies from it.
#pragma once

#include <string_view>

#include "lab/logs/paper_comparison.hpp"

namespace fl::cli {

// `whose`: what was measured ("this log's", "the fitted"); `label_width` the report's column.
void print_paper_value(const PaperComparison& c, std::string_view whose, int label_width);

}  // namespace fl::cli
