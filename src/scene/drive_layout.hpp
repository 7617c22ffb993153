// Where the drive's shafts and gears sit: the rollers' axes, the two idlers that couple the
// rollers (below them, at the rollers' far end) and the gearbox's shafts from the motor to
// roller 0 (at the near end). The drive's gear train (physics/drivetrain.hpp) turns each shaft at
// its tooth-count ratio to the motor (one degree of freedom, no Bullet body per shaft); the
// renderer draws the gears there. Computed from the scene (once, in the compiled rig), never
// typed in.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "text/said.hpp"

namespace fl {

struct ShaftPlacement {
  std::string role;  // "roller 0", "roller 1", "idler 1", "idler 2", "motor", "stage shaft 1", ...
  double x = 0.0;    // m, of the axis (along y)
  double z = 0.0;    // m
};

struct GearPlacement {
  int shaft = 0;  // index into DriveLayout::shafts
  int teeth = 0;
  double y = 0.0;  // m, the gear's plane along the axis
};

struct GearMesh {
  int driver = 0;  // index into DriveLayout::gears
  int driven = 0;
};

struct DriveLayout {
  std::vector<ShaftPlacement> shafts;  // 0 and 1 are the rollers; the motor's shaft is `motor`
  std::vector<GearPlacement> gears;
  std::vector<GearMesh> meshes;  // in order: the gearbox from the motor, then the coupling
  int motor = 0;                 // the motor's shaft (roller 0 itself when there is no gearbox)
};

// The roller spacings the drive's coupling spans: from the idlers' meeting between the rollers
// (l = 2 x idler pitch radius, both idlers on the midline) to the chain stretched straight along
// the rollers' axis line (l = 2 x roller + 4 x idler pitch radius).
struct CouplingSpan {
  double least = 0.0;  // m
  double most = 0.0;   // m
};
CouplingSpan coupling_span(const DriveDesc& drive);

// Why the idlers cannot reach across the rollers' spacing (outside coupling_span); nullopt when
// they can.
std::optional<Said> drive_coupling_problem(const Scene& scene);

// Throws std::invalid_argument when the idlers cannot reach across the rollers' spacing (outside
// coupling_span).
DriveLayout drive_layout(const Scene& scene);

}  // namespace fl
