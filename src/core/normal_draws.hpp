// Gaussian draws that are the same bits on every standard library: std::mt19937_64 (fully
// specified by the standard) through our own Box-Muller transform, since
// std::normal_distribution's algorithm is left to each implementation. Monte Carlo results are
// then reproducible from their seed alone.
#pragma once

#include <cstdint>
#include <random>

namespace fl {

class NormalDraws {
 public:
  explicit NormalDraws(std::uint64_t seed) : engine_(seed) {}

  // A standard normal draw (mean 0, standard deviation 1).
  double standard();

  // mean + sd * standard(); sd = 0 returns mean exactly (and still consumes a draw, so a value
  // given without an uncertainty does not shift the other quantities' draws).
  double next(double mean, double sd) { return mean + sd * standard(); }

 private:
  // A uniform double in (0, 1]: the top 53 bits of one engine output.
  double uniform_open_zero();

  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace fl
