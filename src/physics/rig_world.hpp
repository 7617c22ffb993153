// The Bullet world of a scene: a plate on two counter-rotating rollers, built from exactly the
// parts the scene names. Bullet types stay behind this interface (and in double precision).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "scene/compiled_rig.hpp"

namespace fl {

// The plate's centre of mass in the x-z plane, and its pitch about y (and, between guides, its
// sideways position and yaw). SI.
struct PlateState {
  double x = 0.0;           // m
  double z = 0.0;           // m, of the centre of mass
  double pitch = 0.0;       // rad, about +y
  double vx = 0.0;          // m/s
  double vz = 0.0;          // m/s
  double pitch_rate = 0.0;  // rad/s
  double y = 0.0;           // m, sideways (0 unless guides let the plate move)
  double yaw = 0.0;         // rad, about +z
};

// What one roller does to the plate over the last step (impulses divided by the step).
struct RollerContact {
  bool touching = false;
  double normal_force = 0.0;    // N, pushing the plate up
  double friction_force = 0.0;  // N, along +x on the plate
  double penetration = 0.0;     // m, deepest, >= 0
  // How far the plate's bottom face is above the roller's surface, along the face's normal [m]:
  // > 0 when the plate has left the roller (how high it jumped), 0 while they press.
  double gap = 0.0;
  // The plate held to this roller's surface in the step: pressed, and its friction below the
  // limit (decided by saturation, physics/contact_friction.hpp).
  bool stuck = false;
  // For judging whether the solver converged (lab/run/solver_convergence.hpp), at the deepest
  // point:
  double point_x = 0.0;  // m, where the roller touches the plate, world x
  double point_z = 0.0;  // m, world z
  // The speed along the contact normal (out of the roller, > 0) the solver aims the plate's
  // point at by the step's end [m/s]: its position correction pushes a penetrating point out at
  // erp depth / dt; a point still apart may close its gap within the step (a negative target).
  double normal_speed_target = 0.0;
};

// The motor drive's state (scenes with a `drive`).
struct DriveState {
  double motor_speed = 0.0;               // rad/s about +y, the motor's output shaft
  double motor_torque = 0.0;              // N m, in the motor's driving sense
  std::array<double, 2> roller_speeds{};  // rad/s about +y
};

// One shaft of the drive layout (scene/drive_layout.hpp), to pose its gears.
struct ShaftState {
  double angle = 0.0;  // rad about +y since the start, unwrapped
  double speed = 0.0;  // rad/s about +y
};

class RigWorld {
 public:
  // The world of a compiled rig, which must outlive the world.
  explicit RigWorld(const CompiledRig& rig);
  // The same for a scene, compiled for (and kept by) this world.
  explicit RigWorld(const Scene& scene);
  ~RigWorld();
  RigWorld(const RigWorld&) = delete;
  RigWorld& operator=(const RigWorld&) = delete;

  // Advances one fixed step of scene.world.time_step.
  void step();

  double time() const;  // s since the start
  long long steps() const;
  PlateState plate() const;
  // Index 0 is the roller at x = -l/2, 1 at x = +l/2.
  std::array<RollerContact, 2> contacts() const;
  // Angular velocity about +y of each roller [rad/s] (roller 0 positive when turning inward).
  std::array<double, 2> roller_speeds() const;

  // The Bullet roller bodies' own angular velocity about +y [rad/s]: what the contact solver
  // used in the last step (the drive's speed, as the world handed it to Bullet).
  std::array<double, 2> roller_body_speeds() const;

  // Each roller's angle about +y since the start [rad] (the rollers' bodies keep a fixed
  // transform; this is their speed integrated step by step, for drawing).
  std::array<double, 2> roller_angles() const;

  // Surface speed of each roller's top along +x [m/s].
  std::array<double, 2> roller_surface_speeds() const;

  // The motor and gears, when the scene has a drive (nullopt for the ideal drive).
  std::optional<DriveState> drive() const;
  // Every shaft of the drive layout, in its order (empty for the ideal drive).
  std::vector<ShaftState> shafts() const;

  const CompiledRig& rig() const;

  // The contact solver's iterations in the last step: it stops once an iteration changes no
  // velocity by more than 1e-12 m/s, or at world.solver_iterations (0 for a step with no contact).
  int solver_iterations_used() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fl
