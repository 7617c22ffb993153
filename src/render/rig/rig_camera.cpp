#include "render/rig/rig_camera.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/rig/rig_geometry.hpp"

namespace fl::render {
namespace {

// A camera looking along -`direction` that frames `box` inside the part of the picture the
// overlay leaves free (x from 3 % to 97 %, y from `top` to `bottom`, as fractions of the
// height from the top), as close as that allows: the target is moved down the picture so that
// the box's centre lands in the middle of that region.
// A part of the picture a panel of the overlay covers: fractions of the width (x) and the height
// (y) from the top-left corner.
struct Covered {
  float x0, y0, x1, y1;
};

// With `covered` panels, the region's middle may also move sideways (by up to 12 % of the
// width, either way): the closest camera that keeps the box off the panels wins.
Camera fit_camera(const std::vector<Eigen::Vector3f>& points, const Eigen::Vector3f& direction,
                  float fov_y, int width, int height, float top, float bottom,
                  const std::vector<Covered>& covered = {}) {
  Camera c;
  c.fov_y_degrees = fov_y;
  Eigen::AlignedBox3f box;
  for (const auto& p : points) box.extend(p);
  const Eigen::Vector3f centre = box.center();
  // The picture's up and right, in the world: the camera's up vector made orthogonal to the view.
  const Eigen::Vector3f up = (c.up - c.up.dot(direction) * direction).normalized();
  const Eigen::Vector3f right = up.cross(direction).normalized();
  const float tan_half = std::tan(fov_y * static_cast<float>(rig::kPi) / 360.0f);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  // The region's middle, in normalised device y (1 at the top).
  const float region_y = 1.0f - (top + bottom);
  float region_x = 0.0f;  // normalised device x of the box's centre
  const auto place = [&](float distance) {
    c.target = centre - up * (region_y * tan_half * distance) -
               right * (region_x * tan_half * aspect * distance);
    c.position = c.target + direction * distance;
  };
  const auto fits = [&](float distance) {
    place(distance);
    for (const auto& point : points) {
      const auto p = project_to_pixel(c, width, height, point);
      if (!p || p->x() < 0.03f * static_cast<float>(width) ||
          p->x() > 0.97f * static_cast<float>(width) || p->y() < top * static_cast<float>(height) ||
          p->y() > bottom * static_cast<float>(height))
        return false;
      const float fx = p->x() / static_cast<float>(width);
      const float fy = p->y() / static_cast<float>(height);
      for (const Covered& panel : covered)
        if (fx > panel.x0 && fx < panel.x1 && fy > panel.y0 && fy < panel.y1) return false;
    }
    return true;
  };
  const auto closest = [&] {
    float lo = 0.01f, hi = 0.05f;
    while (!fits(hi) && hi < 50.0f) hi *= 2.0f;
    for (int i = 0; i < 40; ++i) {
      const float mid = 0.5f * (lo + hi);
      (fits(mid) ? hi : lo) = mid;
    }
    return hi;
  };
  float best_x = 0.0f;
  float best = closest();
  if (!covered.empty()) {
    for (const float x : {-0.24f, -0.16f, -0.08f, 0.08f, 0.16f, 0.24f}) {
      region_x = x;
      const float distance = closest();
      if (distance < best) {
        best = distance;
        best_x = x;
      }
    }
  }
  region_x = best_x;
  place(best);
  return c;
}

}  // namespace

Camera rig_camera(const RigModel& model, const VideoDesc& video) {
  Camera c;
  if (video.placed) {
    c.position = rig::vec(video.placed->position);
    c.target = rig::vec(video.placed->target);
    c.fov_y_degrees = static_cast<float>(video.placed->fov * 180.0 / rig::kPi);
  } else if (video.camera == "sensor") {
    // The sensor and the magnet under it, with the plate's end and the board in view.
    const Eigen::Vector3f centre = 0.5f * (model.sensor + model.magnet);
    const Eigen::AlignedBox3f box(centre - Eigen::Vector3f(0.028f, 0.016f, 0.012f),
                                  centre + Eigen::Vector3f(0.028f, 0.016f, 0.012f));
    std::vector<Eigen::Vector3f> corners;
    for (int i = 0; i < 8; ++i)
      corners.push_back(box.corner(static_cast<Eigen::AlignedBox3f::CornerType>(i)));
    c = fit_camera(corners, Eigen::Vector3f(0.30f, -1.0f, 0.45f).normalized(), 30.0f, video.width,
                   video.height, 0.16f, 0.70f);
  } else if (video.camera == "phone") {
    // Level with the plate, square on to its motion, the rig filling the middle of the picture.
    c = fit_camera(model.outline, Eigen::Vector3f(0.0f, -1.0f, 0.05f).normalized(), 40.0f,
                   video.width, video.height, 0.15f, 0.85f);
  } else if (video.camera == "top") {
    c = fit_camera(model.outline, Eigen::Vector3f(0.0f, -0.30f, 1.0f).normalized(), 32.0f,
                   video.width, video.height, 0.08f, 0.70f);
  } else {
    // Clear of the motion strip (top right), the weight panel (left) and the phase portrait
    // when there is one (right, under the strip): the overlay's layout at 16:9 (rig_overlay.cpp).
    std::vector<Covered> covered = {{0.56f, 0.0f, 1.0f, 0.33f}, {0.0f, 0.0f, 0.24f, 0.56f}};
    if (video.phase_portrait) covered.push_back({0.76f, 0.0f, 1.0f, 0.57f});
    c = fit_camera(model.outline, Eigen::Vector3f(0.30f, -1.0f, 0.75f).normalized(), 30.0f,
                   video.width, video.height, 0.08f, 0.70f, covered);
  }
  const float distance = (c.position - c.target).norm();
  c.near_plane = std::max(0.005f, 0.05f * distance);
  c.far_plane = 40.0f * distance + 2.0f;
  return c;
}

Camera orbit_camera(const Camera& camera, double radians) {
  Camera c = camera;
  if (radians != 0.0)
    c.position = rig::translation(c.target) * rig::about_z(radians) * rig::translation(-c.target) *
                 c.position;
  return c;
}

DirectionalLight rig_light() {
  DirectionalLight light;
  light.direction = Eigen::Vector3f(-0.45f, 0.55f, -0.75f);
  light.intensity = 0.80f;
  light.ambient = 0.42f;
  return light;
}

}  // namespace fl::render
