#include "cli/monte_carlo_options.hpp"

#include <charconv>
#include <cstdint>

#include <fmt/format.h>

#include "io/input_error.hpp"

namespace fl::cli {

void add_monte_carlo_options(CLI::App& command, MonteCarloOptions& options) {
  CLI::Option* mc = command.add_option("--mc", options.draws,
                                       "Carry the uncertainties into mu_k by Monte Carlo with "
                                       "this many draws (e.g. 100000)");
  command
      .add_option("--seed", options.seed,
                  "The Monte Carlo's seed (the same seed, the same "
                  "numbers)")
      ->capture_default_str()
      ->needs(mc);
}

std::optional<MonteCarloRequest> monte_carlo_request(const MonteCarloOptions& o) {
  if (o.draws.empty()) return std::nullopt;
  long long draws = 0;
  const auto [end, ec] = std::from_chars(o.draws.data(), o.draws.data() + o.draws.size(), draws);
  if (ec != std::errc{} || end != o.draws.data() + o.draws.size() || draws < 1 ||
      draws > kMaxMonteCarloDraws)
    throw InputError(SourceLocation::of_field("monte_carlo.draws", o.draws),
                     fmt::format("expected the number of draws, a whole number from 1 to {} (e.g. "
                                 "--mc 100000), found \"{}\"",
                                 kMaxMonteCarloDraws, o.draws));
  std::uint64_t seed = 0;
  const auto [seed_end, seed_ec] =
      std::from_chars(o.seed.data(), o.seed.data() + o.seed.size(), seed);
  if (seed_ec != std::errc{} || seed_end != o.seed.data() + o.seed.size())
    throw InputError(
        SourceLocation::of_field("seed", o.seed),
        fmt::format("expected a whole number from 0 to 2^64 - 1, found \"{}\"", o.seed));
  return MonteCarloRequest{.draws = static_cast<int>(draws), .seed = seed, .keep_samples = true};
}

}  // namespace fl::cli
