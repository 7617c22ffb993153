// The magnetic field of a point dipole, the model of each magnet on the plate.
#pragma once

#include "scene/scene.hpp"

namespace fl {

inline constexpr double kMu0 = 1.25663706212e-6;  // vacuum permeability, T m / A

// Dipole moment [A m^2] of a uniformly magnetised cylinder: remanence x volume / mu_0.
double magnet_moment(const MagnetDesc& magnet);

// Field [T] at `point` of a dipole `moment` [A m^2] at `at` [m]:
// B = mu_0 / (4 pi) (3 (m . r^) r^ - m) / |r|^3.
Vec3 dipole_field(const Vec3& moment, const Vec3& at, const Vec3& point);

}  // namespace fl
