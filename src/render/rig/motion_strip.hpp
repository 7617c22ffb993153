// The plate's motion against theory on screen: a strip of the plate's position x(t) over the last
// seconds, the analytic thick-plate curve for the run's parameters over it, and the turning
// points the rig's Hall estimator measures its periods between, marked on the simulated curve.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/harmonic_motion.hpp"
#include "render/overlay.hpp"

namespace fl::render {

struct MotionStripState {
  double t = 0.0;       // s, now: the strip's right end
  double window = 2.5;  // s the strip spans
  // The plate's centre of mass, (t [s], x [m]) in time order.
  std::span<const Eigen::Vector2d> simulated;
  std::optional<HarmonicMotion> theory;    // none when the rollers do not restore the plate
  std::string theory_label;                // "thick plate, μₖ = 0.29"
  std::span<const double> turning_points;  // s
  double x_range = 0.03;                   // m: the strip shows -x_range .. +x_range
};

// Draws the strip in `panel`; `s` is the overlay's scale (1 at 640x360).
void draw_motion_strip(Overlay& overlay, const Rect& panel, float s, const MotionStripState& state);

// The simulated x at time t, linearly interpolated (the nearest end outside the samples);
// nothing without samples.
std::optional<double> position_at(std::span<const Eigen::Vector2d> simulated, double t);

}  // namespace fl::render
