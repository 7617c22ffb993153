// Rollers of different radii a_0 (at x = -l/2) and a_1 on axes at one height, l apart: the plate
// rests on the common tangent above the two circles. That line rises toward roller 1 by
//   theta = asin((a_1 - a_0) / l),
// and its tangent points lie l cos(theta) apart along it. The plate is then on a tilted rig
// (core/tilted_rig.hpp) with tilt theta (plus the table's) and contacts l cos(theta) apart
// (docs/physics.md). Standard library only.
#pragma once

namespace fl {

// theta [rad]; refuses |a_1 - a_0| >= l and radii <= 0 with fl::DomainError.
double tangent_tilt(double spacing, double radius_0, double radius_1);

// l cos(theta): how far apart the tangent points are along the tangent [m].
double tangent_spacing(double spacing, double radius_0, double radius_1);

}  // namespace fl
