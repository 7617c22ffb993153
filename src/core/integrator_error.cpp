#include "core/integrator_error.hpp"

#include <cmath>

namespace fl {

double integrator_period_bias(double omega, double time_step) {
  const double omega_dt = omega * time_step;
  return -omega_dt * omega_dt / 24.0;
}

double step_for_period_bias(double omega, double bias) {
  return std::sqrt(24.0 * bias) / omega;
}

}  // namespace fl
