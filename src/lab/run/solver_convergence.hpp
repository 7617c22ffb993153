// Whether Bullet's sequential-impulse solver converged in a step, judged from what the run records
// (docs/physics.md, numerics). Under the recorded contact forces the plate moves by its force and
// moment balance, m dv = (sum F + m g) dt and I dw = (sum r x F) dt; the solver's answer is right
// when, under those forces, every pressed contact stays closed: the plate's point on each roller
// ends the step at the normal speed the solver aims for (zero, plus its position correction). The
// check solves that balance for the normal forces exactly (two contacts: a 2 x 2 complementarity
// problem, a sliding contact's friction following its normal force) and compares them with the
// recorded ones. Bullet's own residual, the last iteration's change, cannot tell: Gauss-Seidel
// creeps on an ill-conditioned load split, so its last change is small while its error is not.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "physics/rig_world.hpp"
#include "scene/compiled_rig.hpp"

namespace fl {

// A step whose recorded normal forces are off the balanced ones by more than the tolerance.
struct SolverResidual {
  double time = 0.0;                 // s, at the step's end
  int roller = 0;                    // the roller with the larger error
  std::array<double, 2> recorded{};  // N, normal forces the solver gave
  std::array<double, 2> balanced{};  // N, what the balance needs
  double error = 0.0;                // N, the larger |recorded - balanced|
  double weight = 0.0;               // N, m g
  double relative() const { return error / weight; }
  std::string describe() const;  // "t = ... s: roller 1's normal force ... (x % of the weight)"
};

class SolverConvergence {
 public:
  // A step fails when a normal force is off by more than this fraction of the plate's weight.
  // The oscillator's restoring force is the friction difference mu (N0 - N1), of the order of
  // mu m g 2 A / (l - 2 mu h_c), about 0.15 m g for the lab's plates; a split wrong by 1e-4 m g
  // in every step moves the period by at most a few 1e-4 (the catalogue trusts 1e-3), while a
  // converged step is off by rounding (below 1e-9 m g on the shipped scenes).
  static constexpr double kTolerance = 1e-4;

  // The rig must outlive the check.
  explicit SolverConvergence(const CompiledRig& rig);

  // One step: the plate at its start and end, and the rollers' contacts over it. The residual
  // when the step did not converge; nullopt when it did, when the plate was not on both rollers,
  // or when the
  // balance has no unique answer (Painleve: friction turning the plate into a roller).
  std::optional<SolverResidual> observe(double t, const PlateState& before, const PlateState& after,
                                        const std::array<RollerContact, 2>& contacts);

  // The largest error seen so far [fraction of the weight] (0 before any contact).
  double worst_relative() const { return worst_; }

 private:
  double mass_;
  double inertia_;
  double dt_;
  double weight_;
  double worst_ = 0.0;
};

// What a run does after a pass whose solver did not converge: start again at twice the
// iterations, or stop with advice that names the setting which can help. It stops when the run
// shows its steps to an observer (a video cannot start again: world.solver_iterations, with the
// value to try), when doubling did not reduce the error (`error` not below `previous_error`, 0
// before the first pass: the step is the limit, world.time_step), or at `max_iterations` (both
// settings). `history` lists the passes so far, for the advice.
struct SolverRetry {
  std::optional<int> iterations;  // the next pass's, when there is one
  std::string advice;             // why the run stops and what to set, when it does
};
SolverRetry solver_retry(int iterations, int max_iterations, double error, double previous_error,
                         bool observer, const std::string& history, double time_step);

}  // namespace fl
