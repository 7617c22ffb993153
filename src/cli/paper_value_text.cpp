#include "cli/paper_value_text.hpp"

#include <cmath>

#include <fmt/format.h>

namespace fl::cli {

void print_paper_value(const PaperComparison& c, std::string_view whose, int label_width) {
  fmt::print("  {:<{}} {} at {:.0f} K: mu_k {} +- {}, T {} +- {} s (Table I)\n", "paper",
             label_width, c.name, c.temperature, c.mu_k.value, c.mu_k.uncertainty, c.period.value,
             c.period.uncertainty);
  if (c.standard_errors)
    fmt::print("  {:<{}} {} mu_k is {:+.1f} combined standard errors from it ({})\n", "",
               label_width, whose, *c.standard_errors,
               std::fabs(*c.standard_errors) <= 2.0 ? "they agree" : "they disagree");
}

}  // namespace fl::cli
