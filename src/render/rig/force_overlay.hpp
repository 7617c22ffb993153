// The forces of the load shift on screen: at each roller's contact an arrow for the normal force
// (N0, N1, up on the plate) and one for the friction force (F0, F1, along x), the net friction
// on the plate's centre of mass, and a panel with how the plate's weight is shared between the
// rollers. The values are the solver's contact forces of the step shown, not the formula's.
//
// Every arrow is drawn to one scale for the whole video, in pixels per newton: an arrow starts
// at the projection of its point of application and runs along the projection of its force's
// direction for |force| x pixels_per_newton pixels, so lengths compare across arrows and frames
// whatever the perspective. The panel draws a reference arrow of a round force to the same scale.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "render/camera.hpp"
#include "render/overlay.hpp"

namespace fl::render {

// One roller's contact with the plate, as a frame shows it.
struct ContactForce {
  bool touching = false;
  double normal = 0.0;                              // N, on the plate, up
  double friction = 0.0;                            // N, on the plate, along +x
  Eigen::Vector3f point = Eigen::Vector3f::Zero();  // m, world: where the arrows start
};

struct PlateForces {
  std::array<ContactForce, 2> rollers;               // roller 0 (x = -l/2), roller 1
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();  // m, world: the net friction's start
  // The rig's frame in the world's (RigModel::tilt): the points above and the forces' directions
  // (x, z) are the rig's.
  Eigen::Affine3f rig_to_world = Eigen::Affine3f::Identity();
};

// The scale of a video's arrows: pixels per newton, and the round force its reference arrow
// shows.
struct ForceScale {
  float pixels_per_newton = 0.0f;
  double reference_force = 0.0;  // N: 1, 2 or 5 times a power of ten
};

// The scale that draws half the plate's weight (what each roller carries at rest) as long as
// 0.35 of the spacing looks at the rig's centre, and the reference force: the largest round
// force at most half of that. `weight` = m g [N], `spacing` [m], `centre` the rig's centre in the
// world.
ForceScale force_scale(const Camera& camera, int width, int height, const Eigen::Vector3f& centre,
                       double spacing, double weight);

// An arrow as drawn: its ends in pixels, colour and label ("N₀", "F₁", ...).
struct ForceArrow {
  std::string label;
  Eigen::Vector2f from = Eigen::Vector2f::Zero();
  Eigen::Vector2f to = Eigen::Vector2f::Zero();
  Color color;
  // Where the label goes: beyond the tip (the normal forces), under it (each roller's friction)
  // or over it (the net friction), so labels of arrows that start close apart do not collide.
  enum class Label { kBeyond, kBelow, kAbove } label_at = Label::kBeyond;
};

// The colours every video keeps: normal forces, friction forces, the net friction.
inline constexpr Color kNormalForceColor{0.30f, 0.68f, 1.00f, 1.0f};
inline constexpr Color kFrictionForceColor{1.00f, 0.47f, 0.12f, 1.0f};
inline constexpr Color kNetFrictionColor{0.93f, 0.22f, 0.62f, 1.0f};

// The arrows of a step, in the order they are drawn: F0, F1, the net friction F0 + F1, N0, N1 (a
// roller not touching has neither of its arrows). An arrow whose point is behind the camera is
// left out.
std::vector<ForceArrow> force_arrows(const Camera& camera, int width, int height,
                                     const PlateForces& forces, const ForceScale& scale);

// Draws the arrows with their labels; `s` is the overlay's scale (1 at 640x360).
void draw_force_arrows(Overlay& overlay, float s, const std::vector<ForceArrow>& arrows);

// The share of the plate's weight each roller carries, N_k / (N0 + N1); nothing when neither
// presses (the plate is in the air).
std::optional<std::array<double, 2>> weight_shares(const PlateForces& forces);

// The panel "weight on the rollers": a bar per roller as tall as its share (the panel's bars
// full at 100 %, a line at 50 %), the percentages, and the arrows' reference force to scale.
// Returns the panel's height in pixels.
float draw_weight_share(Overlay& overlay, const Eigen::Vector2f& top_left, float s,
                        const PlateForces& forces, const ForceScale& scale);

// The bar area of the panel drawn at `top_left`: where a share of 1 reaches (for tests).
struct WeightBars {
  std::array<Rect, 2> full;  // roller 0's and roller 1's bar at 100 %, pixels
};
WeightBars weight_bars(const Eigen::Vector2f& top_left, float s);

}  // namespace fl::render
