// What a teaching video shows over the rig: the simulated time and the slow-motion factor, the
// motor's and the rollers' speeds, a scrolling plot of the Hall signal with the detected pulses
// marked, the running period and mu_k from the rig's estimator, and what the paper measured;
// and a title card with the material and the set-up. Sizes are laid out for 640x360 and scale
// with the frame's height, so the smallest text is 12 px at 640x360.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/units.hpp"
#include "render/overlay.hpp"
#include "render/rig/force_overlay.hpp"
#include "render/rig/motion_strip.hpp"
#include "render/rig/phase_portrait.hpp"
#include "scene/compiled_rig.hpp"

namespace fl::render {

// One Hall sample for the plot.
struct HallPoint {
  double t = 0.0;    // s
  double adc = 0.0;  // ADC counts
};

// The estimator's running values (the rig's estimator, as the Arduino computes them).
struct EstimatorValues {
  int pulses = 0;   // timed
  int periods = 0;  // periods averaged
  int periods_discarded = 0;
  std::optional<double> period;      // s, mean
  std::optional<double> period_std;  // s, standard deviation of the periods
  std::optional<double> mu_k;
  std::optional<double> mu_k_err;  // worst case, the paper's d mu/mu = dl/l + 2 dT/T
  // Before its first period: what it is doing.
  int learning_pulses = 0;      // pulses it learned the signal from (not timed)
  bool signal_learned = false;  // it times pulses
  bool geometry_known = false;  // it has recognised one pulse or a pair per period
  // The periods the timed pulses give until the geometry is known (lab/run/hall_estimator.hpp):
  // their number, mean and standard deviation [s].
  int provisional_periods = 0;
  std::optional<double> provisional_period;
  std::optional<double> provisional_std;
};

struct RigOverlayState {
  std::string heading;       // the top bar's text, e.g. "LEGO blocks on PVC rollers, l = 89 mm"
  double t = 0.0;            // s of simulated time
  double slow_motion = 1.0;  // the video's slow-motion factor
  std::optional<double> motor_speed;  // rad/s (scenes with a drive)
  double roller_speed = 0.0;          // rad/s, |roller 0|
  // The Hall trace: samples in time order (older ones are not drawn), the ADC's full scale,
  // the range the plot shows, and the detected pulses' times.
  std::span<const HallPoint> hall;
  double hall_window = 2.5;                         // s of simulated time the plot spans
  std::optional<std::array<double, 2>> hall_range;  // ADC counts shown, bottom to top
  std::span<const double> pulses;                   // s, timed by the estimator
  std::span<const double> learning_pulses;          // s, those it learned the signal from
  // The periods the estimator discarded, from, to [s]: shaded on the plot.
  std::span<const std::array<double, 2>> discarded;
  bool has_sensor = true;
  EstimatorValues estimator;
  // What the paper measured for this material, if the scene took mu_k from its table.
  std::string material;  // "LEGO blocks"
  std::optional<Measured> paper_period;
  std::optional<Measured> paper_mu_k;
  // The regime the run has diagnosed so far, with when it began ("clipped since t = 0.130 s");
  // empty: none drawn.
  std::string regime;
  // The contact forces: the weight-share panel below the regime (force_overlay.hpp). None: no
  // panel.
  std::optional<PlateForces> forces;
  ForceScale force_scale;
  // x(t) against theory, top right (motion_strip.hpp). None: no strip.
  std::optional<MotionStripState> motion;
  // v against x, right, under the strip (phase_portrait.hpp). None: no portrait.
  std::optional<PhasePortraitState> phase;
};

struct TitleCard {
  std::string title;
  std::string subtitle;
  std::vector<std::string> lines;
  std::string footer;
};

// The title card of a scene: the material, the rig's set-up and the video's settings.
// `material` is the material's name as the paper writes it ("LEGO blocks"); `title` replaces the
// default title ("The friction (Timoshenko) oscillator") unless empty.
TitleCard make_title_card(const CompiledRig& rig, const std::string& material, double slow_motion,
                          int fps, const std::string& title = {});

// The end card: what the run measured (the estimator's T and mu_k as the results panel gives
// them), the thick-plate theory's period, what the paper measured, the regime, and why a guard
// stopped the run when one did (`stopped`, empty otherwise). Drawn with draw_title_card.
TitleCard make_end_card(const RigOverlayState& state, const std::string& theory,
                        const std::string& stopped);

// A red banner across the frame saying why a guard stopped the run.
void draw_guard_banner(Overlay& overlay, int width, int height, const std::string& text);

// The top bar's heading: "LEGO blocks on PVC rollers · 77 K · l = 89 mm" (the temperature when
// the scene names one; "from 77 K" when the rollers warm).
std::string rig_heading(const CompiledRig& rig, const std::string& material);

// The results panel's text: T (or what the estimator is waiting for), mu_k, the paper's values.
struct ResultsText {
  std::string period;  // "T = 0.7767 ± 0.0002 s", "T = 0.777 s" (one period), "T: measuring…"
  std::string note;    // beside it: "(N = 4)", "(N = 1)", "(N = 2, provisional)"
  std::string detail;  // the line below: mu_k, or what the estimator is waiting for
  std::string paper;   // what the paper measured, or that it has no value
};
ResultsText results_text(const RigOverlayState& state);

// A labelled tick of the Hall plot's axes.
struct AxisTick {
  double value = 0.0;  // s, ADC counts, mm or mm/s
  std::string label;
};
// The time axis from t0 to t1 [s]: every 0.5 s (1 s for windows over 5 s), none before t = 0.
std::vector<AxisTick> hall_time_ticks(double t0, double t1);
// Draws the time axis under a plot's `area` spanning t0 to t1 [s]: hall_time_ticks' ticks and
// values; `s` is the overlay's scale.
void draw_time_axis(Overlay& overlay, const Rect& area, float s, double t0, double t1);
// A value axis over [bottom, top] (the Hall plot's counts, the strip's millimetres, the phase
// portrait's mm and mm/s): every 1, 2 or 5 times a power of ten, at most five ticks, labelled
// "500", "0.5".
std::vector<AxisTick> value_ticks(double bottom, double top);
// Draws value_ticks(bottom, top) on a plot's `area`: a faint grid line across at the row
// `row_of(value)` gives and the value left of the area, `text_size` pixels high; `s` is the
// overlay's scale.
void draw_value_axis(Overlay& overlay, const Rect& area, float s, double bottom, double top,
                     const std::function<float(double)>& row_of, float text_size);

// The frame's scale against the 640x360 layout; below kSmallestOverlayScale (320x180) the text
// would be too small to read, and nothing of the overlay is drawn.
float overlay_scale(int width, int height);

// Where the phase portrait goes in a frame `width` pixels wide at overlay scale `s`: under the
// motion strip's right end, above where two lines of caption reach (at 640x360: x 490 to 632,
// y 122 to 202).
Rect phase_portrait_panel(float width, float s);
inline constexpr float kSmallestOverlayScale = 0.5f;

// Draws the running overlay (time, speeds, Hall plot, T and mu_k) into a width x height frame.
// Frames smaller than 320x180 get none (its text would be under 6 px), nor a title card.
void draw_rig_overlay(Overlay& overlay, int width, int height, const RigOverlayState& state);

// Draws the title card over the frame; `opacity` 0..1 fades it. At 1 it is opaque: nothing drawn
// before it shows through. A title wider than the frame is drawn smaller to fit.
void draw_title_card(Overlay& overlay, int width, int height, const TitleCard& card, float opacity);

}  // namespace fl::render
