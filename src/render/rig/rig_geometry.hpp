// Small geometry helpers the rig's files share (internal to the render library): a scene's
// three doubles as a point, translations and turns about the axes as Eigen transforms.
#pragma once

#include <array>
#include <numbers>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/units.hpp"

namespace fl::render::rig {

using fl::kPi;  // the lab's one pi (core/units.hpp)

inline Eigen::Vector3f vec(const std::array<double, 3>& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

inline Eigen::Affine3f translation(const Eigen::Vector3f& at) {
  Eigen::Affine3f t = Eigen::Affine3f::Identity();
  t.translate(at);
  return t;
}

inline Eigen::Affine3f about_z(double radians) {
  return Eigen::Affine3f(Eigen::AngleAxisf(static_cast<float>(radians), Eigen::Vector3f::UnitZ()));
}

inline Eigen::Affine3f about_y(double radians) {
  return Eigen::Affine3f(Eigen::AngleAxisf(static_cast<float>(radians), Eigen::Vector3f::UnitY()));
}

inline Eigen::Affine3f about_x(double radians) {
  return Eigen::Affine3f(Eigen::AngleAxisf(static_cast<float>(radians), Eigen::Vector3f::UnitX()));
}

inline double degrees_to_radians(int degrees) {
  return degrees * kPi / 180.0;
}

}  // namespace fl::render::rig
