#include "support/reference_oscillator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/analytic_model.hpp"
#include "core/oscillation_tracker.hpp"

namespace fl::test {
namespace {

template <typename... Parts>
std::string text(const Parts&... parts) {
  std::ostringstream out;
  out.precision(17);
  (out << ... << parts);
  return out.str();
}

void require(bool ok, const std::string& message) {
  if (!ok) throw DomainError(message);
}

int sign_of(double value) {
  return value > 0.0 ? 1 : (value < 0.0 ? -1 : 0);
}

struct State {
  double x = 0.0;
  double v = 0.0;
};

// The plate's balance, per unit weight (forces in units of m g).
class Plate {
 public:
  Plate(const FrictionLaw& law, const ReferenceRig& rig) : law_(law), rig_(rig) {}

  // Surface speed of roller i: +v_r for roller 0, -v_r for roller 1.
  double roller_speed(int i) const { return i == 0 ? rig_.surface_speed : -rig_.surface_speed; }
  double half() const { return 0.5 * rig_.spacing; }
  double gravity() const { return rig_.gravity; }

  // The kinetic coefficient at slip speed s (s may be a rounding below zero inside a step).
  double mu(double s) const {
    const double value = law_.kinetic(s);
    if (!(std::isfinite(value) && value > 0.0))
      throw DomainError(
          text("the friction law's coefficient is ", value, " at slip speed ", s, " m/s"));
    return value;
  }

  struct Slip {
    double a = 0.0;   // plate acceleration [m/s^2]
    double n0 = 0.0;  // normal forces / (m g)
    double n1 = 0.0;
  };

  // Both rollers slip, with the signs s_i of the relative velocities u_i = v - w_i held: the
  // friction from roller i is c_i N_i with c_i = -s_i mu(s_i u_i). Unknowns N_0, N_1 and a from
  //   m a = c_0 N_0 + c_1 N_1,   N_0 + N_1 = m g,
  //   0 = sum over contacts of (r_z F_x - r_x F_z) about the centre of mass
  //     = -h_c (c_0 N_0 + c_1 N_1) + (l/2 + x) N_0 - (l/2 - x) N_1.
  Slip slip(const State& y, const std::array<int, 2>& s) const {
    const double c0 = -s[0] * mu(s[0] * (y.v - roller_speed(0)));
    const double c1 = -s[1] * mu(s[1] * (y.v - roller_speed(1)));
    const double p = half() + y.x - rig_.h_c * c0;  // N_0's arm, friction included
    const double q = half() - y.x + rig_.h_c * c1;  // N_1's arm
    const double den = p + q;
    if (!(den > 0.0))
      throw DomainError(text("the contact problem has no consistent solution at x = ", y.x,
                             " m, v = ", y.v, " m/s: l + h_c (c_1 - c_0) = ", den, " m <= 0"));
    Slip out;
    out.n0 = q / den;
    out.n1 = p / den;
    out.a = rig_.gravity * (c0 * out.n0 + c1 * out.n1);
    return out;
  }

  // Stuck to roller i at offset x: the plate moves at the roller's speed, a = 0, so the static
  // force F_i cancels the far roller's kinetic force and the moment balance loses its friction
  // term: N_0 (l/2 + x) = N_1 (l/2 - x). Returns F_i / (m g) and the normal force N_i / (m g).
  struct Stick {
    double force = 0.0;
    double normal = 0.0;
  };
  Stick stick(int i, double x) const {
    const int j = 1 - i;
    const double u_far = roller_speed(i) - roller_speed(j);
    const double n0 = (half() - x) / rig_.spacing;
    const double n1 = (half() + x) / rig_.spacing;
    const double c_far = -sign_of(u_far) * mu(std::abs(u_far));
    Stick out;
    out.force = -c_far * (j == 0 ? n0 : n1);
    out.normal = i == 0 ? n0 : n1;
    return out;
  }

  // mu_s N_i - |F_i|: >= 0 while the stick holds.
  double static_margin(int i, double x) const {
    const Stick s = stick(i, x);
    return law_.mu_s * s.normal - std::abs(s.force);
  }

 private:
  FrictionLaw law_;
  ReferenceRig rig_;
};

// One Dormand-Prince 5(4) step of size h in a slip mode; err gets the 5th-minus-4th difference.
State dp_step(const Plate& plate, const State& y, double h, const std::array<int, 2>& s,
              State* err) {
  static constexpr double a21 = 1.0 / 5.0;
  static constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
  static constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
  static constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0,
                          a54 = -212.0 / 729.0;
  static constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0,
                          a64 = 49.0 / 176.0, a65 = -5103.0 / 18656.0;
  static constexpr double b1 = 35.0 / 384.0, b3 = 500.0 / 1113.0, b4 = 125.0 / 192.0,
                          b5 = -2187.0 / 6784.0, b6 = 11.0 / 84.0;
  static constexpr double e1 = b1 - 5179.0 / 57600.0, e3 = b3 - 7571.0 / 16695.0,
                          e4 = b4 - 393.0 / 640.0, e5 = b5 + 92097.0 / 339200.0,
                          e6 = b6 - 187.0 / 2100.0, e7 = -1.0 / 40.0;
  const auto f = [&](const State& z) { return State{z.v, plate.slip(z, s).a}; };
  const auto at = [&](std::initializer_list<std::pair<double, State>> terms) {
    State z = y;
    for (const auto& [c, k] : terms) {
      z.x += h * c * k.x;
      z.v += h * c * k.v;
    }
    return z;
  };
  const State k1 = f(y);
  const State k2 = f(at({{a21, k1}}));
  const State k3 = f(at({{a31, k1}, {a32, k2}}));
  const State k4 = f(at({{a41, k1}, {a42, k2}, {a43, k3}}));
  const State k5 = f(at({{a51, k1}, {a52, k2}, {a53, k3}, {a54, k4}}));
  const State k6 = f(at({{a61, k1}, {a62, k2}, {a63, k3}, {a64, k4}, {a65, k5}}));
  const State y1 = at({{b1, k1}, {b3, k3}, {b4, k4}, {b5, k5}, {b6, k6}});
  if (err) {
    const State k7 = f(y1);
    err->x = h * (e1 * k1.x + e3 * k3.x + e4 * k4.x + e5 * k5.x + e6 * k6.x + e7 * k7.x);
    err->v = h * (e1 * k1.v + e3 * k3.v + e4 * k4.v + e5 * k5.v + e6 * k6.v + e7 * k7.v);
  }
  return y1;
}

// The smallest tau in (0, h] with crossed(tau) true, given crossed(h) true and crossed(0) false,
// to the resolution of a double.
template <typename Crossed>
double bisect(double h, const Crossed& crossed) {
  double lo = 0.0;
  double hi = h;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (crossed(mid) ? hi : lo) = mid;
  }
  return hi;
}

class Simulation {
 public:
  Simulation(const FrictionLaw& law, const ReferenceRig& rig, const ReferenceOptions& options)
      : plate_(law, rig), rig_(rig), options_(options) {
    v_scale_ = std::max(rig.surface_speed, std::sqrt(rig.gravity * rig.spacing));
  }

  ReferenceRun run(double x0, double v0) {
    y_ = {x0, v0};
    start_mode();
    record_sample(0.0, y_);
    if (stuck_ == kNoRoller && v0 == 0.0) add_event(ReferenceEventKind::kTurningPoint, y_, -1);
    next_sample_ = options_.sample_interval;
    h_ = std::min(options_.max_step, 1e-4);
    while (t_ < options_.duration && !run_.tipped) {
      if (stuck_ != kNoRoller) {
        advance_stuck();
      } else {
        advance_slip();
      }
    }
    run_.end_time = t_;
    run_.final_state = {t_, y_.x, y_.v, stuck_};
    return std::move(run_);
  }

 private:
  void add_event(ReferenceEventKind kind, const State& y, int roller) {
    run_.events.push_back({kind, t_event_, y.x, y.v, roller});
  }

  void record_sample(double t, const State& y) { run_.samples.push_back({t, y.x, y.v, stuck_}); }

  // Samples due in (t_, t_ + tau], from state(tau') for tau' in (0, tau].
  template <typename StateAt>
  void record_samples_until(double tau, const StateAt& state_at) {
    if (options_.sample_interval <= 0.0) {
      record_sample(t_ + tau, state_at(tau));
      return;
    }
    while (next_sample_ <= t_ + tau) {
      record_sample(next_sample_, state_at(next_sample_ - t_));
      next_sample_ += options_.sample_interval;
    }
  }

  // The contact mode at the start (or after a stick ends, through begin_slip).
  void start_mode() {
    for (int i = 0; i < 2; ++i) {
      if (y_.v == plate_.roller_speed(i)) {
        t_event_ = 0.0;
        if (plate_.static_margin(i, y_.x) >= 0.0) {
          stuck_ = i;
          add_event(ReferenceEventKind::kStickStart, y_, i);
          return;
        }
        begin_slip_after_stick(i);
        return;
      }
    }
    for (int i = 0; i < 2; ++i) {
      signs_[i] = sign_of(y_.v - plate_.roller_speed(i));
      armed_[i] = true;
    }
    check_loads();
  }

  // Slip resumes at roller i (the plate at its speed): the kinetic force keeps the static force's
  // direction, so the plate falls behind the roller in that direction: s_i = -sign(F_i).
  void begin_slip_after_stick(int i) {
    const int j = 1 - i;
    signs_[i] = -sign_of(plate_.stick(i, y_.x).force);
    signs_[j] = sign_of(y_.v - plate_.roller_speed(j));
    armed_[i] = false;
    armed_[j] = true;
    stuck_ = kNoRoller;
    const double a = plate_.slip(y_, signs_).a;
    if (signs_[i] * a < -1e-9 * rig_.gravity)
      throw std::logic_error(text("no consistent slip after the stick at roller ", i,
                                  " ends: x = ", y_.x, " m, a = ", a, " m/s^2"));
    check_loads();
  }

  void check_loads() {
    const Plate::Slip s = plate_.slip(y_, signs_);
    for (int i = 0; i < 2; ++i) {
      if ((i == 0 ? s.n0 : s.n1) <= 0.0) {
        t_event_ = t_;
        add_event(ReferenceEventKind::kTip, y_, i);
        run_.tipped = true;
        return;
      }
    }
  }

  void advance_stuck() {
    const int i = stuck_;
    const double w = plate_.roller_speed(i);
    const double x_start = y_.x;
    const auto state_at = [&](double tau) { return State{x_start + w * tau, w}; };
    // Until the run ends, or until the plate's centre reaches the far roller (the static margin
    // is negative there whenever the far roller's coefficient is positive).
    const double to_end = options_.duration - t_;
    const double to_roller = (std::copysign(plate_.half(), w) - x_start) / w;
    const double span = std::min(to_end, to_roller);
    const auto broken = [&](double tau) { return plate_.static_margin(i, state_at(tau).x) < 0.0; };
    double tau = span;
    bool breaks = false;
    if (broken(0.0)) {
      tau = 0.0;
      breaks = true;
    } else if (broken(span)) {
      tau = bisect(span, broken);
      breaks = true;
    }
    if (w > 0.0 && x_start < 0.0 && state_at(tau).x >= 0.0) {
      t_event_ = t_ - x_start / w;
      add_event(ReferenceEventKind::kUpCrossing, State{0.0, w}, -1);
    }
    record_samples_until(tau, state_at);
    t_ += tau;
    y_ = state_at(tau);
    if (!breaks) return;
    t_event_ = t_;
    add_event(ReferenceEventKind::kStickEnd, y_, i);
    begin_slip_after_stick(i);
  }

  void advance_slip() {
    const double h = std::min({h_, options_.max_step, options_.duration - t_});
    State err;
    const State y1 = dp_step(plate_, y_, h, signs_, &err);
    const double norm = std::max(std::abs(err.x) / (options_.tolerance * rig_.spacing),
                                 std::abs(err.v) / (options_.tolerance * v_scale_));
    const double factor = norm == 0.0 ? 5.0 : std::clamp(0.9 * std::pow(norm, -0.2), 0.2, 5.0);
    if (norm > 1.0) {
      h_ = h * factor;
      if (h_ < 1e-15 * std::max(1.0, t_))
        throw std::runtime_error(text("the step size vanished at t = ", t_, " s, x = ", y_.x));
      return;
    }
    ++run_.steps;
    const auto state_at = [&](double tau) { return dp_step(plate_, y_, tau, signs_, nullptr); };

    // The end of the mode: a relative velocity through zero or a normal force through zero.
    double tau_end = h;
    int mode_event = 0;  // 0 none, 1 relative velocity, 2 normal force
    int mode_roller = kNoRoller;
    for (int i = 0; i < 2; ++i) {
      const double g1 = signs_[i] * (y1.v - plate_.roller_speed(i));
      if (!armed_[i]) {
        if (g1 < -1e-9 * v_scale_)
          throw std::logic_error(text("slip at roller ", i, " went the wrong way at t = ", t_));
        continue;
      }
      if (g1 > 0.0) continue;
      const double tau = bisect(h, [&](double tau_try) {
        return signs_[i] * (state_at(tau_try).v - plate_.roller_speed(i)) <= 0.0;
      });
      if (tau < tau_end || mode_event == 0) {
        tau_end = tau;
        mode_event = 1;
        mode_roller = i;
      }
    }
    for (int i = 0; i < 2; ++i) {
      const auto load = [&](double tau) {
        const Plate::Slip s = plate_.slip(state_at(tau), signs_);
        return i == 0 ? s.n0 : s.n1;
      };
      if (load(h) > 0.0) continue;
      const double tau = bisect(h, [&](double tau_try) { return load(tau_try) <= 0.0; });
      if (tau < tau_end || mode_event == 0) {
        tau_end = tau;
        mode_event = 2;
        mode_roller = i;
      }
    }
    const State y_end = mode_event == 0 ? y1 : state_at(tau_end);

    // Recorded events within the step, in time order.
    struct Found {
      double tau;
      ReferenceEventKind kind;
    };
    std::vector<Found> found;
    if (y_.x < 0.0 && y_end.x >= 0.0)
      found.push_back({bisect(tau_end, [&](double tau) { return state_at(tau).x >= 0.0; }),
                       ReferenceEventKind::kUpCrossing});
    if (y_.v != 0.0 && sign_of(y_end.v) != sign_of(y_.v)) {
      const int s0 = sign_of(y_.v);
      found.push_back({bisect(tau_end, [&](double tau) { return sign_of(state_at(tau).v) != s0; }),
                       ReferenceEventKind::kTurningPoint});
    }
    std::sort(found.begin(), found.end(),
              [](const Found& a, const Found& b) { return a.tau < b.tau; });
    for (const Found& e : found) {
      t_event_ = t_ + e.tau;
      State at = state_at(e.tau);
      if (e.kind == ReferenceEventKind::kUpCrossing) at.x = 0.0;
      if (e.kind == ReferenceEventKind::kTurningPoint) at.v = 0.0;
      add_event(e.kind, at, kNoRoller);
    }

    record_samples_until(tau_end, state_at);
    t_ += tau_end;
    y_ = y_end;
    for (int i = 0; i < 2; ++i)
      if (!armed_[i] && signs_[i] * (y_.v - plate_.roller_speed(i)) > 0.0) armed_[i] = true;
    h_ = h * factor;

    if (mode_event == 2) {
      t_event_ = t_;
      add_event(ReferenceEventKind::kTip, y_, mode_roller);
      run_.tipped = true;
      return;
    }
    if (mode_event == 1) {
      const int i = mode_roller;
      y_.v = plate_.roller_speed(i);
      t_event_ = t_;
      if (plate_.static_margin(i, y_.x) >= 0.0) {
        stuck_ = i;
        add_event(ReferenceEventKind::kStickStart, y_, i);
        return;
      }
      armed_[i] = false;
      // The plate only touched the roller's speed and its acceleration takes it back: it keeps
      // slipping the same way (a graze, as in the clipped cycle at x_b = 0).
      if (signs_[i] * plate_.slip(y_, signs_).a > 0.0) return;
      add_event(ReferenceEventKind::kSlipReversal, y_, i);
      signs_[i] = -signs_[i];
      const double a = plate_.slip(y_, signs_).a;
      if (signs_[i] * a < -1e-9 * rig_.gravity)
        throw std::logic_error(text("no consistent contact mode at roller ", i, ": x = ", y_.x,
                                    " m, neither sticking nor slipping through"));
      check_loads();
    }
  }

  Plate plate_;
  ReferenceRig rig_;
  ReferenceOptions options_;
  double v_scale_ = 1.0;
  ReferenceRun run_;
  State y_;
  double t_ = 0.0;
  double t_event_ = 0.0;
  double h_ = 1e-4;
  double next_sample_ = 0.0;
  int stuck_ = kNoRoller;
  std::array<int, 2> signs_{-1, 1};
  std::array<bool, 2> armed_{true, true};
};

void check_inputs(const FrictionLaw& law, const ReferenceRig& rig, double x0, double v0,
                  const ReferenceOptions& options) {
  const auto positive = [](double value) { return std::isfinite(value) && value > 0.0; };
  require(positive(rig.spacing), text("the spacing must be positive, got ", rig.spacing));
  require(std::isfinite(rig.h_c) && rig.h_c >= 0.0, text("h_c must be >= 0, got ", rig.h_c));
  require(positive(rig.surface_speed),
          text("the surface speed must be positive, got ", rig.surface_speed));
  require(positive(rig.gravity), text("gravity must be positive, got ", rig.gravity));
  require(std::isfinite(x0) && std::abs(x0) < 0.5 * rig.spacing,
          text("the start offset must lie between the rollers, got ", x0));
  require(std::isfinite(v0), text("the start speed must be finite, got ", v0));
  require(positive(options.duration), text("the duration must be positive"));
  require(std::isfinite(options.sample_interval) && options.sample_interval >= 0.0,
          "the sample interval must be >= 0");
  require(positive(options.tolerance) && positive(options.max_step),
          "the tolerance and the largest step must be positive");
  require(
      std::isfinite(law.mu_k) && law.mu_k > 0.0 && std::isfinite(law.mu_s) && law.mu_s >= law.mu_k,
      text("the law needs 0 < mu_k <= mu_s, got ", law.mu_k, ", ", law.mu_s));
  if (law.kind == FrictionLawKind::kStribeck)
    require(positive(law.v_s) && std::isfinite(law.beta),
            text("a stribeck law needs v_s > 0 and a finite beta"));
}

}  // namespace

ReferenceRun simulate_reference(const FrictionLaw& law, const ReferenceRig& rig, double x0,
                                double v0, const ReferenceOptions& options) {
  check_inputs(law, rig, x0, v0, options);
  return Simulation(law, rig, options).run(x0, v0);
}

double period_from_up_crossings(const ReferenceRun& run, double t_from) {
  std::vector<double> index;
  std::vector<double> times;
  for (const ReferenceEvent& e : run.events) {
    if (e.kind != ReferenceEventKind::kUpCrossing || e.t < t_from) continue;
    index.push_back(static_cast<double>(times.size()));
    times.push_back(e.t);
  }
  if (times.size() < 3)
    throw std::runtime_error(text("only ", times.size(), " up-crossings after t = ", t_from));
  return fit_line(index, times).slope;
}

std::vector<TurningPoint> turning_points(const ReferenceRun& run, double t_from) {
  std::vector<TurningPoint> out;
  for (const ReferenceEvent& e : run.events)
    if (e.kind == ReferenceEventKind::kTurningPoint && e.t >= t_from) out.push_back({e.t, e.x});
  return out;
}

std::vector<StickInterval> stick_intervals(const ReferenceRun& run) {
  std::vector<StickInterval> out;
  for (const ReferenceEvent& e : run.events) {
    if (e.kind == ReferenceEventKind::kStickStart) {
      out.push_back({e.roller, e.t, run.end_time, e.x, e.x});
    } else if (e.kind == ReferenceEventKind::kStickEnd && !out.empty()) {
      out.back().end = e.t;
      out.back().x_end = e.x;
    }
  }
  // A stick still running at the end ends with the run.
  if (!out.empty() && run.final_state.stuck == out.back().roller && out.back().end == run.end_time)
    out.back().x_end = run.final_state.x;
  return out;
}

double amplitude_growth_rate(const ReferenceRun& run, double t_from) {
  std::vector<double> t;
  std::vector<double> log_amplitude;
  for (const TurningPoint& p : turning_points(run, t_from)) {
    t.push_back(p.t);
    log_amplitude.push_back(std::log(std::abs(p.x)));
  }
  if (t.size() < 3)
    throw std::runtime_error(text("only ", t.size(), " turning points after t = ", t_from));
  return fit_line(t, log_amplitude).slope;
}

}  // namespace fl::test
