#include "render/camera.hpp"
#include "core/units.hpp"

#include <cmath>
#include <numbers>

namespace fl::render {

Eigen::Matrix4f look_at(const Eigen::Vector3f& eye, const Eigen::Vector3f& target,
                        const Eigen::Vector3f& up) {
  const Eigen::Vector3f f = (target - eye).normalized();
  const Eigen::Vector3f s = f.cross(up).normalized();
  const Eigen::Vector3f u = s.cross(f);
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

Eigen::Matrix4f perspective(float fov_y, float aspect, float near_plane, float far_plane) {
  const float t = 1.0f / std::tan(fov_y / 2.0f);
  Eigen::Matrix4f m = Eigen::Matrix4f::Zero();
  m(0, 0) = t / aspect;
  m(1, 1) = t;
  m(2, 2) = (far_plane + near_plane) / (near_plane - far_plane);
  m(2, 3) = 2.0f * far_plane * near_plane / (near_plane - far_plane);
  m(3, 2) = -1.0f;
  return m;
}

Eigen::Matrix4f orthographic(float left, float right, float bottom, float top, float near_plane,
                             float far_plane) {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m(0, 0) = 2.0f / (right - left);
  m(1, 1) = 2.0f / (top - bottom);
  m(2, 2) = -2.0f / (far_plane - near_plane);
  m(0, 3) = -(right + left) / (right - left);
  m(1, 3) = -(top + bottom) / (top - bottom);
  m(2, 3) = -(far_plane + near_plane) / (far_plane - near_plane);
  return m;
}

Eigen::Matrix4f view_matrix(const Camera& camera) {
  return look_at(camera.position, camera.target, camera.up);
}

Eigen::Matrix4f projection_matrix(const Camera& camera, int width, int height) {
  const float fov = camera.fov_y_degrees * static_cast<float>(kPi) / 180.0f;
  return perspective(fov, static_cast<float>(width) / static_cast<float>(height), camera.near_plane,
                     camera.far_plane);
}

std::optional<Eigen::Vector2f> project_to_pixel(const Camera& camera, int width, int height,
                                                const Eigen::Vector3f& world) {
  const Eigen::Vector4f clip =
      projection_matrix(camera, width, height) * view_matrix(camera) * world.homogeneous();
  if (clip.w() <= 0.0f) return std::nullopt;
  const float ndc_x = clip.x() / clip.w();
  const float ndc_y = clip.y() / clip.w();
  return Eigen::Vector2f((ndc_x + 1.0f) * 0.5f * static_cast<float>(width),
                         (1.0f - ndc_y) * 0.5f * static_cast<float>(height));
}

}  // namespace fl::render
