#include "scene/drive_layout.hpp"

#include <cmath>
#include <stdexcept>

#include "text/describe.hpp"

namespace fl {

CouplingSpan coupling_span(const DriveDesc& drive) {
  const double rr = drive.gear(drive.roller_gear).pitch_radius;
  const double ri = drive.gear(drive.idler_gear).pitch_radius;
  return {2.0 * ri, 2.0 * rr + 4.0 * ri};
}

std::optional<Said> drive_coupling_problem(const Scene& scene) {
  const DriveDesc& drive = scene.drive.value();
  const double l = scene.rollers.spacing;
  const double rr = drive.gear(drive.roller_gear).pitch_radius;
  const double ri = drive.gear(drive.idler_gear).pitch_radius;
  const double half_run = 0.5 * l - ri;  // horizontal distance roller axis to idler axis
  if (half_run >= 0.0 && rr + ri >= half_run) return std::nullopt;
  const CouplingSpan span = coupling_span(drive);
  return said("check-drive-coupling",
              {arg("roller_teeth", drive.roller_gear), arg("idler_teeth", drive.idler_gear),
               arg("least_mm", span.least * 1e3), arg("most_mm", span.most * 1e3),
               arg("spacing_mm", l * 1e3)});
}

DriveLayout drive_layout(const Scene& scene) {
  const DriveDesc& drive = scene.drive.value();
  const double l = scene.rollers.spacing;
  const double a = scene.rollers.radius;
  const double far_end = -(0.5 * scene.rollers.length + 0.014);
  const double near_end = 0.5 * scene.rollers.length + 0.014;
  DriveLayout layout;
  layout.shafts.push_back({"roller 0", -0.5 * l, -a});
  layout.shafts.push_back({"roller 1", 0.5 * l, -a});

  // The coupling: roller gear, idler, idler, roller gear, symmetric about x = 0, the idlers as
  // high as their reach allows (on the rollers' axis line when the chain spans l exactly).
  const double rr = drive.gear(drive.roller_gear).pitch_radius;
  const double ri = drive.gear(drive.idler_gear).pitch_radius;
  const double reach = rr + ri;          // roller axis to idler axis
  const double half_run = 0.5 * l - ri;  // horizontal distance roller axis to idler axis
  if (const std::optional<Said> why = drive_coupling_problem(scene))
    throw std::invalid_argument(english(*why));
  const double drop = std::sqrt(reach * reach - half_run * half_run);
  layout.shafts.push_back({"idler 1", -ri, -a - drop});
  layout.shafts.push_back({"idler 2", ri, -a - drop});
  const int g_r0 = 0, g_i1 = 1, g_i2 = 2, g_r1 = 3;
  layout.gears.push_back({0, drive.roller_gear, far_end});
  layout.gears.push_back({2, drive.idler_gear, far_end});
  layout.gears.push_back({3, drive.idler_gear, far_end});
  layout.gears.push_back({1, drive.roller_gear, far_end});

  // The gearbox, from roller 0 back to the motor: each earlier shaft one mesh away, alternately
  // below and outward, each stage in its own plane along y.
  std::vector<GearMesh> gearbox;
  int shaft = 0;
  double x = -0.5 * l, z = -a;
  const int n = static_cast<int>(drive.stages.size());
  for (int k = n - 1; k >= 0; --k) {
    const GearStage& st = drive.stages[static_cast<std::size_t>(k)];
    const double d = drive.gear(st.driver).pitch_radius + drive.gear(st.driven).pitch_radius;
    if ((n - 1 - k) % 2 == 0)
      z -= d;
    else
      x -= d;
    layout.shafts.push_back({k == 0 ? "motor" : "stage shaft " + std::to_string(k), x, z});
    const int earlier = static_cast<int>(layout.shafts.size()) - 1;
    const double y = near_end + 0.008 * (n - 1 - k);
    layout.gears.push_back({shaft, st.driven, y});
    layout.gears.push_back({earlier, st.driver, y});
    gearbox.push_back(
        {static_cast<int>(layout.gears.size()) - 1, static_cast<int>(layout.gears.size()) - 2});
    shaft = earlier;
  }
  layout.motor = shaft;
  // Meshes in order from the motor.
  for (auto it = gearbox.rbegin(); it != gearbox.rend(); ++it) layout.meshes.push_back(*it);
  layout.meshes.push_back({g_r0, g_i1});
  layout.meshes.push_back({g_i1, g_i2});
  layout.meshes.push_back({g_i2, g_r1});
  return layout;
}

}  // namespace fl
