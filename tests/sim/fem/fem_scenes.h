#pragma once
// Scene builders shared by the FEM tests, validation tests and benchmarks
// (Box2D style): small descriptions with the parameters each check needs.
#include <string>

#include "sim/geometry/primitives.h"
#include "sim/world.h"

namespace recoil::sim::test_scenes {

// A box body of full size `size` tetrahedralized at `resolution`, centred at `position`.
inline DeformableBodyDesc box_body(const Eigen::Vector3d& size, int resolution, const Material& material,
                                   const Eigen::Vector3d& position = Eigen::Vector3d::Zero(),
                                   const std::string& name = "box") {
  DeformableBodyDesc body;
  body.name = name;
  body.mesh = make_box(size, 1);
  body.resolution = resolution;
  body.material = material;
  body.transform.position = position;
  return body;
}

inline Material soft_material(MaterialModel model = MaterialModel::corotated) {
  Material m;
  m.model = model;
  m.youngs_modulus = 1e5;
  m.poisson_ratio = 0.3;
  m.density = 1000.0;
  return m;
}

}  // namespace recoil::sim::test_scenes
