// How a command prints the Monte Carlo of mu_k (analytic --mc, estimate --mc): the draws' mean,
// standard deviation and 95 % interval, then what was drawn and through which formula.
#pragma once

#include <string>

#include "lab/analytic/analytic_report.hpp"

namespace fl::cli {

// Two lines on stdout, the label padded to `width` characters after two spaces of indent; `png`
// names the histogram drawn ("" for none). The report must hold a Monte Carlo.
void print_mu_k_monte_carlo(const AnalyticReport& report, int width, const std::string& png);

}  // namespace fl::cli
