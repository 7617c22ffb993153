#include "render/demo_scene.hpp"

namespace fl::render {
namespace {

// LEGO dimensions (m): pitch, brick height, stud diameter and height.
constexpr float kPitch = 0.008f;
constexpr float kBrickHeight = 0.0096f;
constexpr float kStudRadius = 0.0024f;
constexpr float kStudHeight = 0.0017f;

MeshData make_brick(int nx, int ny, const Color& color) {
  MeshData brick =
      make_box(Eigen::Vector3f(kPitch * static_cast<float>(nx) - 0.0002f,
                               kPitch * static_cast<float>(ny) - 0.0002f, kBrickHeight),
               color);
  // Studs: cylinders along y turned upright, 8 sides each.
  const MeshData stud = make_cylinder(kStudRadius, kStudHeight, 8, color);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      Eigen::Affine3f at = Eigen::Affine3f::Identity();
      at.translate(Eigen::Vector3f(kPitch * (static_cast<float>(i) - (nx - 1) / 2.0f),
                                   kPitch * (static_cast<float>(j) - (ny - 1) / 2.0f),
                                   (kBrickHeight + kStudHeight) / 2.0f));
      at.rotate(Eigen::AngleAxisf(EIGEN_PI / 2.0f, Eigen::Vector3f::UnitX()));
      brick.append(stud, at);
    }
  }
  return brick;
}

Eigen::Affine3f translation(float x, float y, float z) {
  Eigen::Affine3f t = Eigen::Affine3f::Identity();
  t.translate(Eigen::Vector3f(x, y, z));
  return t;
}

}  // namespace

DemoScene make_demo_scene(int brick_rows) {
  DemoScene s;
  const float spacing = 0.089f;  // roller spacing l
  const float roller_radius = 0.010f;
  const float roller_z = 0.030f;  // roller axes above the ground
  const float plate_thickness = 0.005f;

  const auto add_mesh = [&](MeshData mesh) {
    s.meshes.push_back(std::move(mesh));
    return s.meshes.size() - 1;
  };
  const auto add = [&](std::size_t mesh, const Eigen::Affine3f& pose, bool casts = true) {
    s.instances.push_back(DemoInstance{mesh, pose, casts});
    return s.instances.size() - 1;
  };

  const std::size_t ground =
      add_mesh(make_ground(1.2f, 0.08f, Color{0.80f, 0.80f, 0.78f}, Color{0.70f, 0.71f, 0.70f}));
  add(ground, Eigen::Affine3f::Identity(), false);
  const std::size_t board =
      add_mesh(make_box(Eigen::Vector3f(0.26f, 0.24f, 0.0064f), Color{0.20f, 0.45f, 0.25f}));
  add(board, translation(0.0f, 0.0f, 0.0032f));

  const std::size_t roller = add_mesh(make_cylinder(
      roller_radius, 0.10f, 32, Color{0.92f, 0.92f, 0.90f}, Color{0.85f, 0.10f, 0.10f}));
  s.left_roller_ = add(roller, translation(-spacing / 2.0f, 0.0f, roller_z));
  s.right_roller_ = add(roller, translation(spacing / 2.0f, 0.0f, roller_z));

  // Towers of bricks holding the roller axles, and the plate with a magnet at each end.
  const std::size_t tower = add_mesh(make_brick(2, 2, Color{0.95f, 0.80f, 0.10f}));
  for (const float x : {-spacing / 2.0f, spacing / 2.0f}) {
    for (const float y : {-0.062f, 0.062f}) {
      for (int level = 0; level < 2; ++level) {
        add(tower, translation(x, y, 0.0064f + kBrickHeight * (0.5f + static_cast<float>(level))));
      }
    }
  }
  const std::size_t plate = add_mesh(
      make_box(Eigen::Vector3f(0.16f, 0.07f, plate_thickness), Color{0.60f, 0.42f, 0.25f}));
  const std::size_t magnet_block = add_mesh(make_brick(2, 4, Color{0.10f, 0.35f, 0.80f}));
  const float plate_z = roller_z + roller_radius + plate_thickness / 2.0f;
  s.plate_parts_.push_back(add(plate, translation(0.0f, 0.0f, plate_z)));
  for (const float x : {-0.064f, 0.064f}) {
    s.plate_parts_.push_back(
        add(magnet_block,
            translation(x, 0.0f, plate_z + plate_thickness / 2.0f + kBrickHeight / 2.0f)));
  }
  for (const std::size_t part : s.plate_parts_) s.plate_rest_.push_back(s.instances[part].pose);

  // A wall of red bricks behind the rig, which makes up the triangle budget.
  const std::size_t wall = add_mesh(make_brick(4, 2, Color{0.75f, 0.12f, 0.10f}));
  for (int row = 0; row < brick_rows; ++row) {
    for (int col = 0; col < 4; ++col) {
      const float x =
          (static_cast<float>(col) - 1.5f) * 4.0f * kPitch + (row % 2 == 0 ? 0.0f : 2.0f * kPitch);
      add(wall, translation(x, 0.10f, 0.0064f + kBrickHeight * (0.5f + static_cast<float>(row))));
    }
  }

  s.roller_z_ = roller_z;
  s.spacing_ = spacing;
  s.camera.position = Eigen::Vector3f(0.15f, -0.28f, 0.20f);
  s.camera.target = Eigen::Vector3f(0.0f, 0.0f, 0.035f);
  s.camera.fov_y_degrees = 40.0f;
  return s;
}

void DemoScene::pose(float plate_x, float roller_angle) {
  for (std::size_t i = 0; i < plate_parts_.size(); ++i) {
    instances[plate_parts_[i]].pose = translation(plate_x, 0.0f, 0.0f) * plate_rest_[i];
  }
  // Rollers turn about their axis (y); their tops turn toward the centre.
  const float sides[2] = {-1.0f, 1.0f};
  const std::size_t rollers[2] = {left_roller_, right_roller_};
  for (int k = 0; k < 2; ++k) {
    Eigen::Affine3f pose = translation(sides[k] * spacing_ / 2.0f, 0.0f, roller_z_);
    pose.rotate(Eigen::AngleAxisf(-sides[k] * roller_angle, Eigen::Vector3f::UnitY()));
    instances[rollers[k]].pose = pose;
  }
}

std::size_t DemoScene::triangle_count() const {
  std::size_t n = 0;
  for (const auto& instance : instances) n += meshes[instance.mesh].triangle_count();
  return n;
}

}  // namespace fl::render
