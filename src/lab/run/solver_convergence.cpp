#include "lab/run/solver_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace fl {

std::string SolverResidual::describe() const {
  return fmt::format(
      "t = {:.6f} s: roller {}'s normal force came out {:.6g} N where the plate's force and "
      "moment balance needs {:.6g} N ({:.3g} % of the weight {:.3g} N; roller {}: {:.6g} N "
      "against {:.6g} N)",
      time, roller, recorded[static_cast<std::size_t>(roller)],
      balanced[static_cast<std::size_t>(roller)], 100.0 * relative(), weight, 1 - roller,
      recorded[static_cast<std::size_t>(1 - roller)],
      balanced[static_cast<std::size_t>(1 - roller)]);
}

SolverConvergence::SolverConvergence(const CompiledRig& rig)
    : mass_(rig.plate.mass),
      inertia_(rig.plate.inertia_pitch),
      dt_(rig.world.time_step),
      weight_(rig.plate.mass * rig.gravity_normal) {}

std::optional<SolverResidual> SolverConvergence::observe(
    double t, const PlateState& before, const PlateState& after,
    const std::array<RollerContact, 2>& contacts) {
  // Judged only while the plate rests on both rollers: the load split is what the oscillator
  // needs and what Gauss-Seidel finds slowly. On one roller the plate is lifting off or
  // tumbling, which the monitor reports and which does not converge with the step anyway.
  // Resting on a roller: a normal force above 1e-3 of the weight (the monitor's lift-off bound).
  for (const RollerContact& c : contacts)
    if (!c.touching || !(c.normal_force > 1e-3 * weight_)) return std::nullopt;
  // The contact normal is the plate's bottom face's (its body z axis), the tangent its body x
  // axis, both as they were when the solver ran: at the step's start.
  const double nx = std::sin(before.pitch), nz = std::cos(before.pitch);
  const double tx = nz, tz = -nx;
  // Per roller: lever (r x n)_y, (r x d)_y for the impulse direction d = n + mu t (a sliding
  // contact's friction follows its normal force; a stuck one's is held), the end speed along n,
  // the aim, and the recorded normal impulse.
  std::array<double, 2> lever_n{}, lever_d{}, speed{}, aim{}, impulse{};
  for (std::size_t i = 0; i < 2; ++i) {
    const RollerContact& c = contacts[i];
    const double rx = c.point_x - before.x, rz = c.point_z - before.z;
    const double normal = c.friction_force * nx + c.normal_force * nz;
    const double tangential = c.friction_force * tx + c.normal_force * tz;
    const double mu = (!c.stuck && normal > 0.0) ? tangential / normal : 0.0;
    lever_n[i] = rz * nx - rx * nz;
    lever_d[i] = rz * (nx + mu * tx) - rx * (nz + mu * tz);
    speed[i] = nx * (after.vx + after.pitch_rate * rz) + nz * (after.vz - after.pitch_rate * rx);
    aim[i] = c.normal_speed_target;
    impulse[i] = std::max(0.0, normal) * dt_;
  }
  // Speed change along n at i per unit impulse at j (n . d = 1).
  const auto a = [&](std::size_t i, std::size_t j) {
    return 1.0 / mass_ + lever_n[i] * lever_d[j] / inertia_;
  };

  // With friction following the normal forces the matrix need not be a P-matrix: when a normal
  // impulse's own friction turns the plate into its roller (l <= 2 mu h_c, Painleve's paradox),
  // the balance has no unique answer, and the step says nothing about the solver.
  for (std::size_t i = 0; i < 2; ++i)
    if (contacts[i].touching && !(a(i, i) > 0.0)) return std::nullopt;
  if (contacts[0].touching && contacts[1].touching &&
      !(a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0) > 0.0))
    return std::nullopt;

  // The complementarity problem for the normal impulses q: each active contact ends at its aim,
  // each inactive one carries nothing and does not end below its aim. A is then a P-matrix, so
  // exactly one active set holds (a P-matrix); the one with the least violation is taken
  // (rounding).
  std::array<double, 2> best{};
  double best_violation = std::numeric_limits<double>::infinity();
  for (int set = 3; set >= 0; --set) {
    std::array<bool, 2> active{(set & 1) != 0 && contacts[0].touching,
                               (set & 2) != 0 && contacts[1].touching};
    if (((set & 1) != 0 && !contacts[0].touching) || ((set & 2) != 0 && !contacts[1].touching))
      continue;
    // delta = q - impulse; inactive: q = 0.
    std::array<double, 2> delta{-impulse[0], -impulse[1]};
    if (active[0] && active[1]) {
      const double r0 = aim[0] - speed[0], r1 = aim[1] - speed[1];
      const double a00 = a(0, 0), a01 = a(0, 1), a10 = a(1, 0), a11 = a(1, 1);
      const double det = a00 * a11 - a01 * a10;
      delta = {(r0 * a11 - a01 * r1) / det, (a00 * r1 - a10 * r0) / det};
    } else {
      for (std::size_t i = 0; i < 2; ++i) {
        if (!active[i]) continue;
        const std::size_t j = 1 - i;
        delta[i] = (aim[i] - speed[i] - a(i, j) * delta[j]) / a(i, i);
      }
    }
    double violation = 0.0;
    for (std::size_t i = 0; i < 2; ++i) {
      if (!contacts[i].touching) continue;
      const double q = impulse[i] + delta[i];
      if (active[i]) {
        violation = std::max(violation, -q / dt_);
      } else {
        const double end = speed[i] + a(i, 0) * delta[0] + a(i, 1) * delta[1];
        violation = std::max(violation, (aim[i] - end) / a(i, i) / dt_);
      }
    }
    if (violation < best_violation) {
      best_violation = violation;
      best = delta;
    }
  }

  SolverResidual r;
  r.time = t;
  r.weight = weight_;
  for (std::size_t i = 0; i < 2; ++i) {
    r.recorded[i] = impulse[i] / dt_;
    r.balanced[i] = contacts[i].touching ? (impulse[i] + best[i]) / dt_ : 0.0;
    const double error = std::fabs(best[i]) / dt_;
    if (error > r.error) {
      r.error = error;
      r.roller = static_cast<int>(i);
    }
  }
  worst_ = std::max(worst_, r.relative());
  if (r.relative() <= kTolerance) return std::nullopt;
  return r;
}

SolverRetry solver_retry(int iterations, int max_iterations, double error, double previous_error,
                         bool observer, const std::string& history, double time_step) {
  SolverRetry r;
  const bool helps = previous_error == 0.0 || error < previous_error;
  if (observer)
    r.advice = fmt::format(
        "this run hands its steps to a video and does not start again: set "
        "world.solver_iterations to {} or more (a run without video raises it itself)",
        2 * iterations);
  else if (!helps)
    r.advice = fmt::format(
        "doubling the iterations did not reduce the error ({}): the step, not the solver, is "
        "the limit; set a smaller world.time_step (now {:.3g} ms)",
        history, time_step * 1e3);
  else if (iterations >= max_iterations)
    r.advice = fmt::format(
        "raised by doubling up to {} iterations ({}); set world.solver_iterations above {} "
        "or a smaller world.time_step (now {:.3g} ms)",
        iterations, history, iterations, time_step * 1e3);
  else
    r.iterations = std::min(2 * iterations, max_iterations);
  return r;
}

}  // namespace fl
