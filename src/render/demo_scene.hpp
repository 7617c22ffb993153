// A small rig-like test scene: a ground, a base board, two striped rollers, a plate with two
// magnets and LEGO-like bricks with studs, about 6k triangles. Tests and benchmarks share it;
// it is also an example of how the rig renderer feeds the Renderer (meshes shared, one model
// matrix per part).
#pragma once

#include <cstddef>
#include <vector>

#include "render/camera.hpp"
#include "render/mesh_data.hpp"

namespace fl::render {

struct DemoInstance {
  std::size_t mesh = 0;  // index into DemoScene::meshes
  Eigen::Affine3f pose = Eigen::Affine3f::Identity();
  bool casts_shadow = true;
};

struct DemoScene {
  std::vector<MeshData> meshes;
  std::vector<DemoInstance> instances;
  Camera camera;
  DirectionalLight light;

  // Moves the plate (and its magnets) to x = plate_x (m) and turns the rollers by
  // roller_angle (rad, in opposite senses as in the rig).
  void pose(float plate_x, float roller_angle);
  std::size_t triangle_count() const;

 private:
  std::vector<std::size_t> plate_parts_;
  std::vector<Eigen::Affine3f> plate_rest_;
  std::size_t left_roller_ = 0;
  std::size_t right_roller_ = 0;
  float roller_z_ = 0.0f;
  float spacing_ = 0.0f;

  friend DemoScene make_demo_scene(int brick_rows);
};

// `brick_rows` rows of 2x4 bricks (268 triangles each) stand behind the rig: 20 bricks (5 rows)
// give about 6k triangles in all.
DemoScene make_demo_scene(int brick_rows = 3);

}  // namespace fl::render
