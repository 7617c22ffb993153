// A reference model of the friction oscillator for tests: the thick plate on two rollers as one
// degree of freedom (x along the motion), under a friction law (core/friction_law.hpp), integrated
// event by event with high accuracy. It shares no code with the lab's Bullet world, nor with the
// closed forms it is used to check (core/friction_oscillator.hpp): the forces come from the
// plate's balance written out here, and every transition is found by root finding.
//
// The model: roller 0 at x = -l/2 with surface speed +v_r, roller 1 at x = +l/2 with -v_r (tops
// turning inward); the plate's centre of mass h_c above the contact line at offset x; no pitch or
// vertical acceleration (both rollers carry the plate: N_0 + N_1 = m g, and the moments about the
// centre of mass balance). A contact slips with the kinetic coefficient at its slip speed and
// against its relative velocity; a contact whose relative velocity reaches zero sticks if the
// static force it must carry (the plate then moves at the roller's speed, so the two friction
// forces cancel) is at most mu_s times its normal force, and stays stuck, exactly at the roller's
// speed, until that limit is reached.
//
// Integration: Dormand-Prince 5(4) with error control, the vector field smooth within each
// contact mode (the slip directions are held for the mode); the ends of modes (a relative
// velocity reaching zero, the static limit reached, a normal force reaching zero) and the
// recorded events (x = 0 upwards, v = 0) are placed by bisection on a re-integrated step.
#pragma once

#include <vector>

#include "core/friction_law.hpp"

namespace fl::test {

struct ReferenceRig {
  double spacing = 0.089;        // l [m]
  double h_c = 0.0;              // centre of mass above the contact line [m]
  double surface_speed = 1.676;  // v_r > 0 [m/s]
  double gravity = 9.81;         // [m/s^2]
};

// -1: both rollers slip; 0 or 1: the plate moves with that roller.
inline constexpr int kNoRoller = -1;

struct ReferenceSample {
  double t = 0.0;
  double x = 0.0;
  double v = 0.0;
  int stuck = kNoRoller;
};

enum class ReferenceEventKind {
  kStickStart,    // the relative speed at `roller` reached zero and the static limit holds
  kStickEnd,      // the static limit at `roller` was reached: it slips again
  kSlipReversal,  // the relative speed at `roller` passed through zero without sticking
  kUpCrossing,    // x = 0 with v > 0
  kTurningPoint,  // v = 0
  kTip,           // the normal force at `roller` reached zero: the run stops
};

struct ReferenceEvent {
  ReferenceEventKind kind = ReferenceEventKind::kUpCrossing;
  double t = 0.0;
  double x = 0.0;
  double v = 0.0;
  int roller = kNoRoller;
};

struct ReferenceOptions {
  double duration = 10.0;         // [s]
  double sample_interval = 1e-3;  // [s]; 0 records every step's end
  double tolerance = 1e-13;       // local error per step, relative to l and to the speed scale
  double max_step = 2e-3;         // [s]
};

struct ReferenceRun {
  std::vector<ReferenceSample> samples;
  std::vector<ReferenceEvent> events;
  bool tipped = false;
  double end_time = 0.0;
  ReferenceSample final_state;  // the state at end_time
  long steps = 0;               // accepted integration steps
};

// Runs from offset x0 [m] and speed v0 [m/s] (a speed equal to a roller's starts stuck if the
// static limit allows). Throws fl::DomainError for a rig or start that means nothing (|x0| >=
// l/2, v_r <= 0, ...) and when the law's coefficient is not positive at a slip speed reached, or
// the contact problem has no consistent solution (l + h_c (c_1 - c_0) <= 0).
ReferenceRun simulate_reference(const FrictionLaw& law, const ReferenceRig& rig, double x0,
                                double v0, const ReferenceOptions& options = {});

// The period from the up-crossings of x = 0 at or after t_from: least-squares slope of crossing
// time against index. Needs three crossings (throws std::runtime_error otherwise).
double period_from_up_crossings(const ReferenceRun& run, double t_from = 0.0);

struct TurningPoint {
  double t = 0.0;
  double x = 0.0;
};

// The turning points (v = 0) at or after t_from, in time order.
std::vector<TurningPoint> turning_points(const ReferenceRun& run, double t_from = 0.0);

struct StickInterval {
  int roller = kNoRoller;
  double start = 0.0;  // [s]
  double end = 0.0;    // [s]; the run's end time if it was still stuck
  double x_start = 0.0;
  double x_end = 0.0;
};

// The stick phases, in time order.
std::vector<StickInterval> stick_intervals(const ReferenceRun& run);

// The amplitude's e-folding rate [1/s]: least-squares slope of ln|x| at the turning points at or
// after t_from against their times. Needs three turning points (throws std::runtime_error).
double amplitude_growth_rate(const ReferenceRun& run, double t_from = 0.0);

}  // namespace fl::test
