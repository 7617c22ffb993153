// The plate's motion as a phase portrait: its speed v against its position x over the last
// seconds, the thick-plate theory's ellipse through the run's start, and the slip limit: the
// rollers' surface speed v_r. The friction oscillator needs the plate to slip on both rollers;
// a plate as fast as a roller's surface (|v| = v_r) no longer slips on it, and the friction that
// restores it changes (sticking, docs/physics.md). A portrait that stays between the two lines
// slips throughout.
#pragma once

#include <optional>
#include <span>

#include <Eigen/Core>

#include "render/overlay.hpp"
#include "render/rig/motion_strip.hpp"

namespace fl::render {

struct PhasePortraitState {
  double t = 0.0;       // s, now
  double window = 2.5;  // s of the trace drawn
  // The plate's centre of mass, (t [s], x [m], v [m/s]) in time order.
  std::span<const Eigen::Vector3d> simulated;
  std::optional<HarmonicMotion> theory;  // none when the rollers do not restore the plate
  double slip_speed = 0.0;               // v_r [m/s]: the rollers' surface speed
  double x_range = 0.03;                 // m: the portrait shows -x_range .. +x_range
};

// What the portrait's axes span: x from -x_range to +x_range, v from -v_range to +v_range.
// v_range is 1.15 times the larger top speed of the theory's ellipse and of the trace (at least
// 1 mm/s); the slip limit joins the view (v_range = 1.1 v_r) when v_r is at most 2.5 times that,
// and is otherwise named off the scale.
struct PhaseAxes {
  double x_range = 0.0;  // m
  double v_range = 0.0;  // m/s
  bool slip_in_view = false;
};
PhaseAxes phase_axes(const PhasePortraitState& state);

// Draws the portrait in `panel`; `s` is the overlay's scale (1 at 640x360).
void draw_phase_portrait(Overlay& overlay, const Rect& panel, float s,
                         const PhasePortraitState& state);

}  // namespace fl::render
