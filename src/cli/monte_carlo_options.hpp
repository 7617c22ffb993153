// --mc N and --seed S, shared by the commands that carry measured uncertainties into mu_k by
// Monte Carlo (analytic, fit).
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "core/mu_k_monte_carlo.hpp"

namespace fl::cli {

struct MonteCarloOptions {
  std::string draws;       // --mc; empty: no Monte Carlo
  std::string seed = "1";  // --seed: fixed by default, so a report can be reproduced
};

void add_monte_carlo_options(CLI::App& command, MonteCarloOptions& options);

// The request, or nullopt without --mc. Throws InputError for a count that is not a whole number
// from 1 to kMaxMonteCarloDraws or a seed that is not a whole number >= 0 (CLI11 refuses --seed
// without --mc).
std::optional<MonteCarloRequest> monte_carlo_request(const MonteCarloOptions& options);

}  // namespace fl::cli
