#pragma once
// WorldDesc: the plain description a World is built from (Box2D-style
// definition structs with defaults). The scene parser in cli/ fills it; tests
// and benchmarks build it directly. Scene files are the user-facing form.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "sim/body/desc_origin.h"
#include "sim/fem/deformable_body.h"
#include "sim/fem/pcg.h"
#include "sim/geometry/tri_mesh.h"
#include "sim/rigid/rigid_body_desc.h"
#include "sim/solver/contact_problem.h"

namespace recoil::sim {

// An infinite static plane; the render draws it as the ground.
struct PlaneDesc {
  std::string name = "ground";
  DescOrigin origin;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // m
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  // outside is normal.(x - point) > 0; normalised on use
  FrictionDesc friction;
};

struct ContactSettings {
  double margin = 0.002;        // m: candidates closer than this (plus their motion) enter the solver
  ContactSolverSettings solver;
  int num_threads = 1;          // collision queries and weighing open meshes; results identical for any value
};

struct WorldDesc {
  DescOrigin origin;  // of the simulation settings ("/simulation" in a scene file)
  double dt = 0.004;                                           // s
  Eigen::Vector3d gravity = Eigen::Vector3d(0.0, -9.81, 0.0);  // m/s^2
  PcgSettings solver;            // the linear solve of a step without active contacts
  ContactSettings contact;
  std::vector<DeformableBodyDesc> bodies;   // deformable bodies
  std::vector<RigidBodyDesc> rigid_bodies;  // dynamic, kinematic and fixed rigid bodies
  std::vector<PlaneDesc> planes;
};

}  // namespace recoil::sim
