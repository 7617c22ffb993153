// The rig's period estimator: one header for the Arduino firmware, the simulator and the command
// line. It reads a Hall sensor one sample at a time and gives the oscillation period T +- dT and
// mu_k +- d mu_k.
//
// Portable C++11 subset: no heap, no exceptions, no RTTI, no standard library containers; all
// state is fixed in size by the template parameters. Arithmetic is integer on the per-sample path
// (32-bit on the AVR, 64-bit on the host: see Level) and single-precision float at pulse edges
// and periods, so the same code runs on an 8-bit AVR (avr-gcc, where double is float) and on the
// host with the same results.
//
// Units: times are uint32_t microseconds on the caller's clock and may wrap around at 2^32 us
// (71.6 min): only differences are used. ADC values are counts (10-bit: 0..1023; on the host any
// uint16_t, 0..65535, works: see Level). Periods are in microseconds in the records and in seconds
// in Stats.
//
// How it works (docs/estimator.md has the long version):
//  1. Learning the signal: the estimator watches the values (through a median of three, so a
//     lone glitch does not count) until the signal has swung at least Config::min_amplitude
//     counts, crossed the middle of its range out and back, and returned to the side where it
//     spends most of its time: that side is the resting level (the baseline, the mean of the
//     samples there), the other side holds the pulses. This gives the polarity (a magnet may
//     push the ADC up or down), the baseline and the pulse height, with nothing typed in by
//     hand; it costs the first two pulses.
//  2. Pulses: a pulse starts when the signal rises past the timing level (half the pulse height
//     from the baseline) and ends when it falls below the release level (a quarter). Each
//     crossing of the timing level is placed between its two samples by linear interpolation;
//     the pulse's time is the midpoint of its first rising and last falling crossing. For a pulse
//     that is symmetric in time (the magnet comes to the sensor and turns back) that is the
//     turning point of the plate, whatever the pulse height. The baseline follows slow drift
//     between pulses (samples within the release level, time constant about 2 s) and is frozen
//     during a pulse; the pulse height and width follow the last pulses'. A pulse whose peak or
//     width is far from the running ones is marked distorted (Pulse::distorted).
//  3. Geometry: the sensor sits near the plate's largest displacement, so each period shows
//     either one pulse (the magnet reaches the sensor and turns back) or a close pair (it passes
//     over the sensor, turns, and passes back). From five pulses in a row the estimator
//     recognises which: one pulse gives four equal intervals (within half the tolerance, 10 %,
//     of their median) that do not alternate; a pair gives intervals that alternate short, long,
//     short, long (short < 0.6 long, i.e. the pair spans less than 3/8 of the period). Intervals
//     that alternate by more than 4 % are never one pulse per period; evenly spaced pulses are
//     read as one, as a sensor at the exact middle of the travel also gives them. With
//     Config::geometry set to kPulsePair, any two pulses per period will do, evenly spaced
//     included. Pulses before that are not used (Stats::unused_pulses).
//     The pulses are then grouped: pulses closer than half the running median period form one
//     group (a pair wider than 3/8 of the period is grouped two by two instead, the second pulse
//     one span after the first), the group's turning point is the midpoint of its first and last
//     pulse (the mid-point of two passes is the turning point between them, the plate's motion
//     being symmetric in time about it). A group
//     with the expected number of pulses (1 or 2) and no distorted pulse is clean; any other (a
//     spurious pulse joined a group, one of a pair is missing, a pulse was bent out of shape) is
//     broken. Four broken groups in a row mean the geometry changed (the amplitude grew or shrank
//     past the sensor): it is recognised again.
//  4. Periods: the time between two successive clean turning points. A period is rejected when
//     it is farther than Config::tolerance (20 %) from the median of the last kMedianWindow
//     periods (a missing pulse doubles it); a period that touches a broken turning point is
//     rejected too. Rejected periods are counted, never averaged in.
//  5. Statistics: N accepted periods, their mean T, standard deviation dT, standard error
//     dT/sqrt(N), and mu_k = 2 pi^2 l / (g T^2) with the paper's worst-case uncertainty
//     d mu/mu = dl/l + 2 dT/T and the quadrature form sqrt((dl/l)^2 + (2 dT/T)^2).
//  If no pulse comes for 4 median periods (or a pulse never ends), the estimator starts learning
//  the signal again (Event kRestart); its statistics carry on.
//
// The API in short (all on BasicPeriodEstimator / PeriodEstimator):
//   PeriodEstimator e(config);                 // or e(spacing_m, spacing_err_m, gravity_m_s2)
//   uint8_t events = e.add_sample(t_us, adc);  // Event bits: kPulse, kPeriodAccepted, ...
//   e.finish();                                // at the end of the data
//   e.pulse(i), i < e.pulse_count();           // the last kPulseHistory pulses
//   e.period(i), i < e.period_count();         // the last kPeriodHistory periods
//   Stats s = e.stats();                       // N, T, dT, standard error, mu_k +- d mu_k
#ifndef FRICTIONLAB_ESTIMATOR_PERIOD_ESTIMATOR_H
#define FRICTIONLAB_ESTIMATOR_PERIOD_ESTIMATOR_H

#include <math.h>
#include <stdint.h>

namespace fl_estimator {

// The signal's levels and distances from the baseline, in counts << 16 (sixteen bits of fraction
// for the baseline's slow average). The Uno's 10-bit ADC needs 27 bits, and the AVR computes them
// in 32; a log of a 16-bit ADC (values up to 65535) needs 33 for a distance from the baseline and
// a pulse's headroom above it, and the host computes in 64. The two give the same numbers, to the
// bit, wherever 32 bits hold them: every ADC of up to 14 bits.
#if defined(__AVR__)
typedef int32_t Level;
#else
typedef int64_t Level;
#endif

// A time between two samples: whole microseconds on the caller's clock (wrapping with it) plus
// frac/256 of a microsecond.
struct Instant {
  uint32_t us;
  uint8_t frac;
};

// `to` - `from` in microseconds; wrap-safe while |to - from| < 2^31 us.
inline float micros_between(const Instant& from, const Instant& to) {
  const int32_t whole = static_cast<int32_t>(to.us - from.us);
  const int16_t frac = static_cast<int16_t>(static_cast<int16_t>(to.frac) - from.frac);
  return static_cast<float>(whole) + static_cast<float>(frac) * (1.0f / 256.0f);
}

// `us` plus `offset_q8`/256 microseconds.
inline Instant instant_after(uint32_t us, uint32_t offset_q8) {
  Instant r;
  r.us = us + (offset_q8 >> 8);
  r.frac = static_cast<uint8_t>(offset_q8 & 0xFFu);
  return r;
}

// The instant halfway between `a` and a later `b` (less than 2^24 us apart).
inline Instant midpoint(const Instant& a, const Instant& b) {
  const uint32_t span_q8 = ((b.us - a.us) << 8) + b.frac - a.frac;
  return instant_after(a.us, a.frac + (span_q8 >> 1));
}

// Which pulses a period shows (see step 3 above).
enum Geometry : uint8_t {
  kAutoGeometry = 0,  // recognise it from the pulse intervals (the default)
  kOnePulse = 1,      // one pulse per period: the magnet reaches the sensor and turns back
  kPulsePair = 2,     // a close pair per period: the magnet passes over the sensor and back
};

// What add_sample() saw in one sample: a bit set (several may be set at once).
enum Event : uint8_t {
  kNoEvent = 0,
  kPulse = 1,           // a pulse ended in this sample: pulse(pulse_count() - 1)
  kPeriodAccepted = 2,  // at least one period was accepted (see period_count())
  kPeriodRejected = 4,  // at least one period was rejected
  kGeometryFound = 8,   // the geometry was recognised (the periods of the pulses seen so far
                        // are judged in this same sample)
  kSignalLearned = 16,  // baseline, polarity and pulse height are known; pulses can follow
  kRestart = 32,        // the signal was lost; the estimator is learning it again
};

// Where the pulse detector is.
enum Phase : uint8_t {
  kLearning = 0,  // learning baseline, polarity and pulse height
  kArming = 1,    // learned; waiting for the signal to settle at the baseline
  kIdle = 2,      // at the baseline, waiting for a pulse
  kInPulse = 3,   // inside a pulse
};

// Why a period was kept or not.
enum PeriodStatus : uint8_t {
  kAccepted = 0,
  kRejectedOutlier = 1,  // farther than Config::tolerance from the running median
  kRejectedBroken = 2,   // starts or ends at a broken turning point (a missing or spurious pulse)
};

struct Config {
  float spacing_m = 0.089f;      // roller spacing l [m] (the paper's rig: 89 mm)
  float spacing_err_m = 0.002f;  // its uncertainty dl [m]
  float gravity_m_s2 = 9.81f;    // g [m/s^2]
  Geometry geometry = kAutoGeometry;
  float tolerance = 0.2f;       // largest accepted |T - median| / median
  uint16_t min_amplitude = 12;  // smallest swing of the signal that can be a pulse [ADC counts]
};

// One detected pulse.
struct Pulse {
  Instant time;    // midpoint of rise and fall: the turning point (one-pulse geometry)
  Instant rise;    // crossing of the timing level going away from the baseline
  Instant fall;    // last crossing of the timing level coming back
  uint16_t peak;   // largest distance from the baseline in the pulse [ADC counts]
  bool distorted;  // bent out of shape (as when the plate jumps): the peak is outside 69 % to
                   // 144 % of the running pulse height, or the width (fall - rise) is more than
                   // 31 % off the running width; its turning point counts as broken
};

// One period between two turning points.
struct Period {
  Instant start;    // turning point that starts it
  Instant end;      // turning point that ends it
  float period_us;  // end - start [us]
  uint8_t status;   // PeriodStatus
};

// Running statistics of the accepted periods.
struct Stats {
  uint32_t periods_used;       // N accepted periods
  uint32_t periods_discarded;  // rejected periods (outliers and periods at broken turns)
  uint32_t pulses;             // pulses detected
  uint32_t unused_pulses;      // pulses seen before the geometry was recognised and not used
  uint32_t restarts;           // times the signal was lost and learned again
  float period_s;              // mean T [s] (0 when N = 0)
  float period_std_s;          // standard deviation dT of the accepted periods [s] (0 when N < 2)
  float period_sem_s;          // standard error dT / sqrt(N) [s]
  float mu_k;                  // 2 pi^2 l / (g T^2) (0 when N = 0)
  float mu_k_err_worst;        // mu_k (dl/l + 2 dT/T), the paper's form
  float mu_k_err_quadrature;   // mu_k sqrt((dl/l)^2 + (2 dT/T)^2)
};

// mu_k +- d mu_k from T +- dT [s] and l +- dl [m] (thin plate, the paper's formula).
inline void mu_k_from_period(float period_s, float period_err_s, float spacing_m,
                             float spacing_err_m, float gravity_m_s2, float* mu_k, float* err_worst,
                             float* err_quadrature) {
  const float kPi = 3.14159265358979f;
  const float mu = 2.0f * kPi * kPi * spacing_m / (gravity_m_s2 * period_s * period_s);
  const float rel_l = spacing_err_m / spacing_m;
  const float rel_t = 2.0f * period_err_s / period_s;
  *mu_k = mu;
  *err_worst = mu * (rel_l + rel_t);
  *err_quadrature = mu * sqrtf(rel_l * rel_l + rel_t * rel_t);
}

// kPulseHistory, kPeriodHistory: how many of the latest pulses and periods stay readable (powers
// of two; at least 8 pulses, since five are needed to recognise the geometry).
// kMedianWindow: how many recent periods the running median is taken over (odd).
template <uint8_t kPulseHistory = 8, uint8_t kPeriodHistory = 8, uint8_t kMedianWindow = 7>
class BasicPeriodEstimator {
  static_assert(kPulseHistory >= 8 && (kPulseHistory & (kPulseHistory - 1)) == 0,
                "kPulseHistory: a power of two, at least 8");
  static_assert(kPeriodHistory >= 4 && (kPeriodHistory & (kPeriodHistory - 1)) == 0,
                "kPeriodHistory: a power of two, at least 4");
  static_assert(kMedianWindow >= 3 && kMedianWindow % 2 == 1, "kMedianWindow: odd, at least 3");

 public:
  explicit BasicPeriodEstimator(const Config& config = Config()) : config_(config) { reset(); }

  // The rig's defaults with another spacing l +- dl [m] and gravity g [m/s^2].
  BasicPeriodEstimator(float spacing_m, float spacing_err_m, float gravity_m_s2) {
    config_.spacing_m = spacing_m;
    config_.spacing_err_m = spacing_err_m;
    config_.gravity_m_s2 = gravity_m_s2;
    reset();
  }

  // Forgets everything, statistics included; keeps the configuration.
  void reset() {
    phase_ = kLearning;
    prev_t_ = 0;
    prev_x_ = 0;
    base_ = 0;
    amp_ = 0;
    hi_ = 0;
    lo_ = 0;
    polarity_ = 1;
    base_shift_ = 10;
    base_round_ = 1 << 9;
    geometry_ = kOnePulse;
    peak_ = 0;
    width_ = 0;
    rise_ = Instant();
    fall_ = Instant();
    last_activity_us_ = 0;
    stall_us_ = kLearnStallUs;
    pulse_count_ = 0;
    period_count_ = 0;
    unused_pulses_ = 0;
    restarts_ = 0;
    used_ = 0;
    discarded_ = 0;
    ref_us_ = 0.0f;
    sum_ = 0.0f;
    sum_sq_ = 0.0f;
    for (uint8_t i = 0; i < kPulseHistory; ++i) pulses_[i] = Pulse();
    for (uint8_t i = 0; i < kPeriodHistory; ++i) periods_[i] = Period();
    forget_signal();
  }

  // Feeds one sample taken at t_us [us] with value adc [counts]; samples must come in time
  // order. Returns the Event bits of what this sample completed.
  uint8_t add_sample(uint32_t t_us, uint16_t adc) {
    uint8_t events = kNoEvent;
    if (phase_ >= kIdle) {
      if (static_cast<uint32_t>(t_us - last_activity_us_) > stall_us_) {
        events |= restart();
        events |= learn(t_us, adc);
      } else {
        const Level d = (static_cast<Level>(adc) << 16) - base_;
        const Level sd = polarity_ > 0 ? d : -d;
        if (phase_ == kIdle) {
          if (sd >= hi_) {
            start_pulse(t_us, sd);
          } else {
            // Baseline: only samples near it count, so pulse tails do not drag it along.
            if (sd < lo_ && sd > -lo_) base_ += (d + base_round_) >> base_shift_;
            if (group_size_ != 0 && static_cast<uint32_t>(t_us - group_last_.us) > group_wait_us())
              events |= close_group();
          }
        } else {
          events |= pulse_sample(t_us, sd);
        }
      }
    } else {
      if (static_cast<uint32_t>(t_us - last_activity_us_) > stall_us_ && learn_n_ != 0) {
        if (phase_ == kArming) events |= restart();
        forget_signal();
      }
      events |= learn(t_us, adc);
    }
    prev_t_ = t_us;
    prev_x_ = adc;
    return events;
  }

  // The data ended: completes the last turning point (and its period) if its pulses are all
  // there; a pair cut off by the end of the data is dropped without counting.
  uint8_t finish() {
    if (group_size_ == 0) return kNoEvent;
    if (group_size_ < expected_group_size()) {
      group_size_ = 0;
      return kNoEvent;
    }
    return close_group();
  }

  // Pulses detected so far; pulse(i) is readable for i in
  // [pulse_count() - kPulseHistory, pulse_count()).
  uint32_t pulse_count() const { return pulse_count_; }
  bool has_pulse(uint32_t index) const {
    return index < pulse_count_ && pulse_count_ - index <= kPulseHistory;
  }
  const Pulse& pulse(uint32_t index) const { return pulses_[index & (kPulseHistory - 1)]; }

  // Periods judged so far (accepted and rejected); period(i) is readable for i in
  // [period_count() - kPeriodHistory, period_count()).
  uint32_t period_count() const { return period_count_; }
  bool has_period(uint32_t index) const {
    return index < period_count_ && period_count_ - index <= kPeriodHistory;
  }
  const Period& period(uint32_t index) const { return periods_[index & (kPeriodHistory - 1)]; }

  // The running statistics (computed on each call: a few float operations and two roots).
  Stats stats() const {
    Stats s;
    s.periods_used = used_;
    s.periods_discarded = discarded_;
    s.pulses = pulse_count_;
    s.unused_pulses = unused_pulses_;
    s.restarts = restarts_;
    s.period_s = 0.0f;
    s.period_std_s = 0.0f;
    s.period_sem_s = 0.0f;
    s.mu_k = 0.0f;
    s.mu_k_err_worst = 0.0f;
    s.mu_k_err_quadrature = 0.0f;
    if (used_ == 0) return s;
    const float n = static_cast<float>(used_);
    const float mean_us = ref_us_ + sum_ / n;
    float std_us = 0.0f;
    if (used_ >= 2) {
      float var = (sum_sq_ - sum_ * sum_ / n) / (n - 1.0f);
      if (var < 0.0f) var = 0.0f;
      std_us = sqrtf(var);
    }
    s.period_s = mean_us * 1e-6f;
    s.period_std_s = std_us * 1e-6f;
    s.period_sem_s = s.period_std_s / sqrtf(n);
    mu_k_from_period(s.period_s, s.period_std_s, config_.spacing_m, config_.spacing_err_m,
                     config_.gravity_m_s2, &s.mu_k, &s.mu_k_err_worst, &s.mu_k_err_quadrature);
    return s;
  }

  // Live state, for overlays and plots.
  Phase phase() const { return static_cast<Phase>(phase_); }
  // The recognised geometry; kAutoGeometry while it is not known yet.
  Geometry geometry() const { return locked_ ? geometry_ : kAutoGeometry; }
  // +1 when pulses push the ADC up, -1 when down (meaningful once the signal is learned).
  int8_t polarity() const { return polarity_; }
  // Baseline [counts] (meaningful once the signal is learned).
  float baseline() const { return static_cast<float>(base_) * (1.0f / 65536.0f); }
  // The level whose crossings time a pulse, and the level that ends one [counts].
  float timing_level() const { return level(hi_); }
  float release_level() const { return level(lo_); }
  // The running median period [us] (0 until the geometry is known).
  uint32_t median_period_us() const { return median_us_; }
  const Config& config() const { return config_; }

 private:
  // Learning starts over after 4.5 s without the signal crossing its middle (periods up to 4 s).
  static const uint32_t kLearnStallUs = 4500000u;
  static const uint32_t kMaxStallUs = 16000000u;    // stay below 2^24 us (midpoint's range)
  static const uint32_t kBaselineTauUs = 2000000u;  // baseline time constant, about 2 s

  float level(Level offset) const {
    return static_cast<float>(base_ + (polarity_ > 0 ? offset : -offset)) * (1.0f / 65536.0f);
  }

  // Signed distance from the baseline in the pulses' direction [counts << 16].
  Level signed_dev(uint16_t x) const {
    const Level d = (static_cast<Level>(x) << 16) - base_;
    return polarity_ > 0 ? d : -d;
  }

  // Where the line through (t0, v0) and (t1, v1) reaches `level` (v0 and v1 on either side).
  static Instant crossing(uint32_t t0, uint32_t t1, Level v0, Level v1, Level lvl) {
    const float frac = static_cast<float>(lvl - v0) / static_cast<float>(v1 - v0);
    const uint32_t dt_q8 = (t1 - t0) << 8;
    return instant_after(t0, static_cast<uint32_t>(frac * static_cast<float>(dt_q8) + 0.5f));
  }

  // --- step 1: learning the signal ---------------------------------------------------------

  void forget_signal() {
    phase_ = kLearning;
    learn_n_ = 0;
    learn_t0_ = 0;
    learn_min_ = 0;
    learn_max_ = 0;
    learn_prev1_ = 0;
    learn_prev2_ = 0;
    learn_side_ = 0;
    transitions_ = 0;
    n_above_ = 0;
    n_below_ = 0;
    sum_above_ = 0;
    sum_below_ = 0;
    stall_us_ = kLearnStallUs;
    unlock();
  }

  static uint16_t median3(uint16_t a, uint16_t b, uint16_t c) {
    if (a > b) {
      const uint16_t tmp = a;
      a = b;
      b = tmp;
    }
    // Now a <= b: the median is b if b < c, else the larger of a and c.
    return b < c ? b : (a > c ? a : c);
  }

  uint8_t learn(uint32_t t, uint16_t x) {
    if (phase_ == kArming) {
      if (signed_dev(x) < lo_) {
        phase_ = kIdle;
        last_activity_us_ = t;
      }
      return kNoEvent;
    }
    // The median of the last three samples keeps a lone glitch (a wrong first sample, a spike)
    // out of the range.
    if (learn_n_ < 2) {
      if (learn_n_ == 0) {
        learn_t0_ = t;
        last_activity_us_ = t;
      }
      learn_prev2_ = learn_prev1_;
      learn_prev1_ = x;
      ++learn_n_;
      return kNoEvent;
    }
    const uint16_t raw = x;
    x = median3(raw, learn_prev1_, learn_prev2_);
    learn_prev2_ = learn_prev1_;
    learn_prev1_ = raw;
    if (learn_n_ == 2) {
      learn_min_ = x;
      learn_max_ = x;
    }
    if (learn_n_ != 0xFFFFFFFFu) ++learn_n_;
    if (x < learn_min_) learn_min_ = x;
    if (x > learn_max_) learn_max_ = x;
    const int32_t range = static_cast<int32_t>(learn_max_) - learn_min_;
    if (range < static_cast<int32_t>(config_.min_amplitude)) return kNoEvent;
    // Sides of the middle of the range seen so far, with a hysteresis of range/8.
    const int32_t twice_x = 2 * static_cast<int32_t>(x);
    const int32_t twice_mid = static_cast<int32_t>(learn_min_) + learn_max_;
    int8_t side = learn_side_;
    const int32_t band = range >> 2;
    if (twice_x > twice_mid + band) {
      side = 1;
    } else if (twice_x < twice_mid - band) {
      side = -1;
    }
    if (side == 0) return kNoEvent;
    if (side != learn_side_) {
      if (learn_side_ != 0) {
        ++transitions_;
        last_activity_us_ = t;
      }
      learn_side_ = side;
      // Back on the side where the signal spends most of its time, after a swing out and back:
      // that side is the baseline.
      const bool majority = side > 0 ? n_above_ > n_below_ : n_below_ > n_above_;
      if (transitions_ >= 2 && majority) return signal_learned(t, side);
    }
    if (side > 0) {
      ++n_above_;
      sum_above_ += x;
      if (n_above_ >= 0x10000u) {
        n_above_ >>= 1;
        sum_above_ >>= 1;
      }
    } else {
      ++n_below_;
      sum_below_ += x;
      if (n_below_ >= 0x10000u) {
        n_below_ >>= 1;
        sum_below_ >>= 1;
      }
    }
    return kNoEvent;
  }

  uint8_t signal_learned(uint32_t t, int8_t resting_side) {
    polarity_ = static_cast<int8_t>(-resting_side);
    const uint32_t n = resting_side > 0 ? n_above_ : n_below_;
    const uint32_t sum = resting_side > 0 ? sum_above_ : sum_below_;
    base_ = static_cast<Level>(static_cast<float>(sum) / static_cast<float>(n) * 65536.0f);
    const Level extreme = static_cast<Level>(polarity_ > 0 ? learn_max_ : learn_min_) << 16;
    amp_ = polarity_ > 0 ? extreme - base_ : base_ - extreme;
    width_ = 0;
    set_levels();
    // Baseline time constant: 2^base_shift_ samples of the mean sample interval, about 2 s.
    const uint32_t dt = learn_n_ > 1 ? (t - learn_t0_) / (learn_n_ - 1) : 1u;
    uint32_t span = dt;
    uint8_t shift = 0;
    while (span < kBaselineTauUs && shift < 24) {
      span <<= 1;
      ++shift;
    }
    base_shift_ = shift < 2 ? 2 : shift;
    base_round_ = static_cast<Level>(1) << (base_shift_ - 1);
    phase_ = kArming;
    last_activity_us_ = t;
    stall_us_ = kLearnStallUs;
    return kSignalLearned;
  }

  void set_levels() {
    const Level minimum = static_cast<Level>(config_.min_amplitude) << 15;  // half the minimum
    if (amp_ < minimum) amp_ = minimum;
    hi_ = amp_ >> 1;
    lo_ = amp_ >> 2;
  }

  uint8_t restart() {
    ++restarts_;
    forget_signal();
    return kRestart;
  }

  // --- step 2: pulses ------------------------------------------------------------------------

  void start_pulse(uint32_t t, Level sd) {
    rise_ = crossing(prev_t_, t, signed_dev(prev_x_), sd, hi_);
    fall_ = rise_;
    peak_ = sd;
    phase_ = kInPulse;
    last_activity_us_ = t;
  }

  uint8_t pulse_sample(uint32_t t, Level sd) {
    if (sd > peak_) peak_ = sd;
    if (sd >= hi_) return kNoEvent;
    const Level prev_sd = signed_dev(prev_x_);
    if (prev_sd >= hi_) fall_ = crossing(prev_t_, t, prev_sd, sd, hi_);
    if (sd >= lo_) return kNoEvent;
    // The pulse is over.
    Pulse& p = pulses_[pulse_count_ & (kPulseHistory - 1)];
    p.rise = rise_;
    p.fall = fall_;
    p.time = midpoint(rise_, fall_);
    const Level peak_counts = peak_ >> 16;
    p.peak = static_cast<uint16_t>(peak_counts > 0xFFFF ? 0xFFFF : peak_counts);
    // The peak within 0.6875 = 1/2 + 1/8 + 1/16 and 1.4375 = 1 + 1/4 + 1/8 + 1/16 of the running
    // height, the width within 5/16 = 31 % of the running width.
    const Level sixteenth = amp_ >> 4;
    p.distorted = peak_ < hi_ + 3 * sixteenth || peak_ > amp_ + 7 * sixteenth;
    const int32_t width = static_cast<int32_t>(fall_.us - rise_.us);
    if (width_ == 0) width_ = width;
    const int32_t slack = (width_ >> 2) + (width_ >> 4);
    p.distorted = p.distorted || width > width_ + slack || width < width_ - slack;
    width_ += (width - width_) >> 2;
    ++pulse_count_;
    amp_ += (peak_ - amp_) >> 2;
    set_levels();
    phase_ = kIdle;
    last_activity_us_ = t;
    return static_cast<uint8_t>(kPulse | on_pulse(p));
  }

  // --- step 3: geometry and turning points ---------------------------------------------------

  void unlock() {
    locked_ = false;
    window_pulses_ = 0;
    group_size_ = 0;
    group_distorted_ = false;
    have_turn_ = false;
    broken_streak_ = 0;
    ring_count_ = 0;
    ring_pos_ = 0;
    median_us_ = 0;
    theta_us_ = 0;
    by_span_ = false;
    span_us_ = 0.0f;
  }

  uint8_t on_pulse(const Pulse& p) {
    if (locked_) return group_add(p);
    if (++window_pulses_ < 5) return kNoEvent;
    return try_lock();
  }

  static float median4(const float* v) {
    float s[4] = {v[0], v[1], v[2], v[3]};
    for (uint8_t i = 1; i < 4; ++i) {
      for (uint8_t j = i; j > 0 && s[j] < s[j - 1]; --j) {
        const float tmp = s[j];
        s[j] = s[j - 1];
        s[j - 1] = tmp;
      }
    }
    return 0.5f * (s[1] + s[2]);
  }

  static bool near(float a, float b, float tolerance, float scale) {
    return fabsf(a - b) <= tolerance * scale;
  }

  // Recognises the geometry from the last five pulses, then replays them.
  uint8_t try_lock() {
    const uint32_t oldest = pulse_count_ - 5;
    float iv[4];
    for (uint8_t i = 0; i < 4; ++i)
      iv[i] = micros_between(pulse(oldest + i).time, pulse(oldest + i + 1).time);
    const float tol = config_.tolerance;
    bool one = false;
    bool pair = false;
    // Intervals that alternate: the 1st and 3rd both shorter (or both longer) than the 2nd and
    // 4th, their sums more than 4 % apart. That is two pulses per period (a sensor inside the
    // turning point, near the middle of the travel), never one.
    const float lo02 = iv[0] < iv[2] ? iv[0] : iv[2];
    const float hi02 = iv[0] < iv[2] ? iv[2] : iv[0];
    const float lo13 = iv[1] < iv[3] ? iv[1] : iv[3];
    const float hi13 = iv[1] < iv[3] ? iv[3] : iv[1];
    const float sum02 = iv[0] + iv[2];
    const float sum13 = iv[1] + iv[3];
    const bool alternates =
        (hi02 < lo13 && sum02 < 0.96f * sum13) || (hi13 < lo02 && sum13 < 0.96f * sum02);
    if (config_.geometry != kPulsePair) {
      // Four intervals within half the tolerance of their median, not alternating.
      const float m = median4(iv);
      one = m > 0.0f && !alternates;
      for (uint8_t i = 0; i < 4; ++i) one = one && near(iv[i], m, 0.5f * tol, m);
    }
    const float shorter = iv[0] < iv[1] ? iv[0] : iv[1];
    const float longer = iv[0] < iv[1] ? iv[1] : iv[0];
    if (!one && config_.geometry != kOnePulse) {
      const float t01 = iv[0] + iv[1];
      const float t12 = iv[1] + iv[2];
      const float t23 = iv[2] + iv[3];
      const float t = (t01 + t12 + t23) * (1.0f / 3.0f);
      // Auto needs a clear pair (short < 0.6 long); a forced pair is any two pulses per period,
      // evenly spaced too (the sensor at the middle of the travel).
      const float ratio = config_.geometry == kPulsePair ? 1.0f : 0.6f;
      pair = t > 0.0f && shorter > 0.0f && shorter <= ratio * longer &&
             near(iv[0], iv[2], tol, t) && near(iv[1], iv[3], tol, t) && near(t01, t, tol, t) &&
             near(t12, t, tol, t) && near(t23, t, tol, t);
    }
    if (!one && !pair) {
      // The oldest of the five will not be in the next attempt.
      ++unused_pulses_;
      --window_pulses_;
      return kNoEvent;
    }
    locked_ = true;
    geometry_ = one ? kOnePulse : kPulsePair;
    window_pulses_ = 0;
    if (one) {
      for (uint8_t i = 0; i < 4; ++i) push_period(iv[i]);
    } else {
      push_period(iv[0] + iv[1]);
      push_period(iv[1] + iv[2]);
      push_period(iv[2] + iv[3]);
    }
    // A pair starts with a short interval: if the first interval is long, the first pulse is the
    // second of a pair whose first pulse came before the window.
    const uint8_t first = (pair && iv[0] > iv[1]) ? 1 : 0;
    unused_pulses_ += first;
    // A pair wider than 3/8 of the period cannot be told from the gap between pairs by a time
    // threshold: its pulses are grouped two by two, the second one span after the first.
    by_span_ = pair && shorter > 0.6f * longer;
    span_us_ = 0.5f * (iv[first] + iv[first + 2]);
    uint8_t events = kGeometryFound;
    for (uint8_t i = first; i < 5; ++i) events |= group_add(pulse(oldest + i));
    return events;
  }

  uint8_t expected_group_size() const { return geometry_ == kPulsePair ? 2 : 1; }

  // How long an open group waits for its next pulse [us].
  uint32_t group_wait_us() const {
    if (!by_span_) return theta_us_;
    return static_cast<uint32_t>(span_us_ +
                                 0.5f * config_.tolerance * static_cast<float>(median_us_));
  }

  uint8_t group_add(const Pulse& p) {
    uint8_t events = kNoEvent;
    if (group_size_ != 0) {
      const uint32_t since = p.time.us - group_last_.us;
      if (by_span_) {
        // A wide pair: the second pulse comes one span (within 10 % of the period) after the
        // first, and completes the group.
        const float off = fabsf(static_cast<float>(since) - span_us_);
        if (group_size_ == 1 && off <= 0.5f * config_.tolerance * static_cast<float>(median_us_)) {
          group_last_ = p.time;
          group_distorted_ = group_distorted_ || p.distorted;
          ++group_size_;
          if (!group_distorted_) span_us_ += 0.25f * (static_cast<float>(since) - span_us_);
          return close_group();
        }
      } else if (since <= theta_us_) {
        group_last_ = p.time;
        group_distorted_ = group_distorted_ || p.distorted;
        if (group_size_ != 0xFF) ++group_size_;
        return kNoEvent;
      }
      events |= close_group();
    }
    group_first_ = p.time;
    group_last_ = p.time;
    group_distorted_ = p.distorted;
    group_size_ = 1;
    return events;
  }

  uint8_t close_group() {
    const Instant turn = midpoint(group_first_, group_last_);
    const bool clean = group_size_ == expected_group_size() && !group_distorted_;
    group_size_ = 0;
    uint8_t events = kNoEvent;
    if (have_turn_) {
      const float c = micros_between(turn_, turn);
      uint8_t status = kRejectedBroken;
      if (clean && turn_clean_) {
        push_period(c);
        const float m = static_cast<float>(median_us_);
        status = near(c, m, config_.tolerance, m) ? kAccepted : kRejectedOutlier;
      }
      Period& r = periods_[period_count_ & (kPeriodHistory - 1)];
      r.start = turn_;
      r.end = turn;
      r.period_us = c;
      r.status = status;
      ++period_count_;
      if (status == kAccepted) {
        if (used_ == 0) ref_us_ = c;
        const float dev = c - ref_us_;
        sum_ += dev;
        sum_sq_ += dev * dev;
        ++used_;
        events |= kPeriodAccepted;
      } else {
        ++discarded_;
        events |= kPeriodRejected;
      }
    }
    turn_ = turn;
    turn_clean_ = clean;
    have_turn_ = true;
    broken_streak_ = clean ? 0 : static_cast<uint8_t>(broken_streak_ + 1);
    // Four broken turning points in a row: the geometry changed (the amplitude grew or shrank
    // past the sensor); recognise it again from the next pulses.
    if (broken_streak_ >= 4) unlock();
    return events;
  }

  // --- step 4: the running median ------------------------------------------------------------

  void push_period(float period_us) {
    ring_[ring_pos_] = static_cast<uint32_t>(period_us + 0.5f);
    ring_pos_ = static_cast<uint8_t>(ring_pos_ + 1 == kMedianWindow ? 0 : ring_pos_ + 1);
    if (ring_count_ < kMedianWindow) ++ring_count_;
    uint32_t s[kMedianWindow];
    for (uint8_t i = 0; i < ring_count_; ++i) {
      const uint32_t v = ring_[i];
      uint8_t j = i;
      for (; j > 0 && s[j - 1] > v; --j) s[j] = s[j - 1];
      s[j] = v;
    }
    median_us_ = s[ring_count_ / 2];
    theta_us_ = median_us_ / 2;
    const uint32_t stall = median_us_ < kMaxStallUs / 4 ? 4 * median_us_ : kMaxStallUs;
    stall_us_ = stall;
  }

  Config config_;

  // Signal model (values in counts << 16: Level).
  uint8_t phase_;
  int8_t polarity_;
  uint8_t base_shift_;
  Level base_round_;
  uint16_t prev_x_;
  uint32_t prev_t_;
  Level base_;
  Level amp_;
  Level hi_;
  Level lo_;
  Level peak_;
  int32_t width_;  // running pulse width [us] (0: none yet)
  Instant rise_;
  Instant fall_;
  uint32_t last_activity_us_;
  uint32_t stall_us_;

  // Learning.
  uint32_t learn_n_;
  uint32_t learn_t0_;
  uint16_t learn_min_;
  uint16_t learn_max_;
  uint16_t learn_prev1_;
  uint16_t learn_prev2_;
  int8_t learn_side_;
  uint8_t transitions_;
  uint32_t n_above_;
  uint32_t n_below_;
  uint32_t sum_above_;
  uint32_t sum_below_;

  // Pulses, geometry, turning points.
  Pulse pulses_[kPulseHistory];
  uint32_t pulse_count_;
  uint32_t unused_pulses_;
  uint32_t restarts_;
  bool locked_;
  bool by_span_;   // a wide pair: grouped two by two (see try_lock)
  float span_us_;  // its running span: first to second pulse [us]
  Geometry geometry_;
  uint8_t window_pulses_;
  uint8_t group_size_;
  bool group_distorted_;
  Instant group_first_;
  Instant group_last_;
  bool have_turn_;
  bool turn_clean_;
  uint8_t broken_streak_;
  Instant turn_;

  // Periods and statistics.
  uint32_t ring_[kMedianWindow];
  uint8_t ring_count_;
  uint8_t ring_pos_;
  uint32_t median_us_;
  uint32_t theta_us_;
  Period periods_[kPeriodHistory];
  uint32_t period_count_;
  uint32_t used_;
  uint32_t discarded_;
  float ref_us_;
  float sum_;
  float sum_sq_;
};

// The estimator with its default history sizes (about 420 bytes on an AVR).
typedef BasicPeriodEstimator<> PeriodEstimator;

}  // namespace fl_estimator

#endif  // FRICTIONLAB_ESTIMATOR_PERIOD_ESTIMATOR_H
