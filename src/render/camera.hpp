// The camera and the matrices of the 3D pass. World units are metres, z up (the rig's frame:
// x along the plate's motion, rollers along y). Matrices follow OpenGL: right-handed view space
// looking down -z, clip depth -1..1.
#pragma once

#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fl::render {

struct Camera {
  Eigen::Vector3f position{0.35f, -0.45f, 0.30f};  // m
  Eigen::Vector3f target{0.0f, 0.0f, 0.02f};       // m, the point at the centre of the frame
  Eigen::Vector3f up{0.0f, 0.0f, 1.0f};            // world direction shown upward
  float fov_y_degrees = 40.0f;                     // vertical field of view, degrees
  float near_plane = 0.02f;                        // m
  float far_plane = 20.0f;                         // m
};

// World to view (camera at the origin looking down -z). `up` must not be parallel to the view
// direction.
Eigen::Matrix4f look_at(const Eigen::Vector3f& eye, const Eigen::Vector3f& target,
                        const Eigen::Vector3f& up);

// View to clip, like gluPerspective; fov_y in radians, aspect = width / height.
Eigen::Matrix4f perspective(float fov_y, float aspect, float near_plane, float far_plane);

// View to clip for an orthographic box, like glOrtho.
Eigen::Matrix4f orthographic(float left, float right, float bottom, float top, float near_plane,
                             float far_plane);

Eigen::Matrix4f view_matrix(const Camera& camera);
Eigen::Matrix4f projection_matrix(const Camera& camera, int width, int height);

// One directional light (the sun of the scene) with a shadow map, plus sky/ground ambient.
struct DirectionalLight {
  Eigen::Vector3f direction{-0.55f, 0.45f, -0.70f};  // the way the light travels (need not be unit)
  float intensity = 0.85f;                           // diffuse strength of the light, 0..1
  float ambient = 0.35f;                             // strength of the sky/ground fill light, 0..1
};

// Where a world point lands in a width x height frame, in pixels from the top-left corner
// (pixel centres at +0.5); nothing if it is behind the camera.
std::optional<Eigen::Vector2f> project_to_pixel(const Camera& camera, int width, int height,
                                                const Eigen::Vector3f& world);

}  // namespace fl::render
