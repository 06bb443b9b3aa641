#pragma once
// Contact scenes shared by the validation tests and the contact benchmark
// (Box2D style): small WorldDescs with the parameters each check needs.
// Conventions: gravity -y; an incline of angle theta descends along +x with
// normal (sin theta, cos theta, 0), so the down-slope direction is
// (cos theta, -sin theta, 0).
#include <cmath>
#include <string>

#include "sim/geometry/mesh_import.h"
#include "sim/geometry/primitives.h"
#include "sim/world_desc.h"
#include "tests/sim/fem/fem_scenes.h"

namespace recoil::sim::scenes {

constexpr double kPi = 3.14159265358979323846;

inline FrictionDesc friction(double mu_static, double mu_kinetic) { return {mu_static, mu_kinetic}; }

inline PlaneDesc ground(FrictionDesc f = {}) {
  PlaneDesc p;
  p.friction = f;
  return p;
}

// A plane through the origin tilted by theta (radians) about z.
inline PlaneDesc incline(double theta, FrictionDesc f) {
  PlaneDesc p = ground(f);
  p.normal = Eigen::Vector3d(std::sin(theta), std::cos(theta), 0.0);
  return p;
}
inline Eigen::Vector3d incline_normal(double theta) { return {std::sin(theta), std::cos(theta), 0.0}; }
inline Eigen::Vector3d downslope(double theta) { return {std::cos(theta), -std::sin(theta), 0.0}; }

// `cells`: of each face's grid a side (1: the corners alone; the scene
// primitive has 8).
inline RigidBodyDesc rigid_box(const std::string& name, const Eigen::Vector3d& size, const Eigen::Vector3d& position,
                               FrictionDesc f = {}, double density = 1000.0, int cells = 1) {
  RigidBodyDesc b;
  b.name = name;
  b.mesh = make_box(size, cells);
  b.transform.position = position;
  b.density = density;
  b.friction = f;
  return b;
}

inline RigidBodyDesc rigid_sphere(const std::string& name, double radius, const Eigen::Vector3d& position,
                                  FrictionDesc f = {}, int subdivisions = 3) {
  RigidBodyDesc b = rigid_box(name, Eigen::Vector3d::Ones(), position, f);
  b.mesh = make_sphere(radius, subdivisions);
  return b;
}

inline Material jelly(double youngs_modulus = 2e4, double density = 1000.0) {
  Material m;
  m.youngs_modulus = youngs_modulus;
  m.poisson_ratio = 0.3;
  m.density = density;
  m.damping_ratio = 1.0;  // critically damped lowest mode: the scenes settle
  return m;
}

inline DeformableBodyDesc soft_box(const std::string& name, const Eigen::Vector3d& size, int resolution,
                                   const Material& material, const Eigen::Vector3d& position, FrictionDesc f = {}) {
  DeformableBodyDesc b = test_scenes::box_body(size, resolution, material, position, name);
  // The surface is what touches: a grid matching the lattice puts contact
  // points across each face, not only at the 8 corners (with corners only,
  // the face between them sags through whatever it rests on).
  b.mesh = make_box(size, resolution);
  b.static_friction = f.static_coefficient;
  b.kinetic_friction = f.kinetic_coefficient;
  b.self_contact = false;
  return b;
}

inline DeformableBodyDesc soft_sphere(const std::string& name, double radius, int resolution, const Material& material,
                                      const Eigen::Vector3d& position, FrictionDesc f = {}) {
  DeformableBodyDesc b = soft_box(name, Eigen::Vector3d::Ones(), resolution, material, position, f);
  b.mesh = make_sphere(radius, 2);
  return b;
}

// A body resting on the incline: rotate about z by -theta, centre at
// `along` metres down the slope from the origin, lifted by half its height
// plus `gap` along the normal.
template <typename Desc>
void place_on_incline(Desc& body, double theta, double half_height, double along, double gap = 1e-4) {
  body.transform.rotation = Eigen::Vector3d(0.0, 0.0, -theta * 180.0 / kPi);
  body.transform.position = along * downslope(theta) + (half_height + gap) * incline_normal(theta);
}

inline WorldDesc base_world(double dt) {
  WorldDesc w;
  w.dt = dt;
  w.contact.margin = 0.002;
  w.contact.solver.tolerance = 1e-7;
  return w;
}

// Five rigid boxes (edge `size`) stacked on the ground, dropped from 1 mm
// apart, each shifted by a few millimetres and turned 7 degrees further
// about the vertical than the one below (a stack a person would build, not a
// perfectly aligned one: corners land on faces and edges cross edges).
inline WorldDesc box_stack(int count = 5, double size = 0.1, double dt = 0.01) {
  WorldDesc w = base_world(dt);
  w.planes.push_back(ground(friction(0.6, 0.6)));
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d position(0.03 * size * ((i % 2) ? 1.0 : -1.0), (i + 0.5) * size + (i + 1) * 1e-3,
                                   0.02 * size * ((i / 2 % 2) ? 1.0 : -1.0));
    w.rigid_bodies.push_back(
        rigid_box("box" + std::to_string(i), Eigen::Vector3d::Constant(size), position, friction(0.6, 0.6)));
    w.rigid_bodies.back().transform.rotation = Eigen::Vector3d(0.0, 7.0 * i, 0.0);
  }
  return w;
}

// The usual rigid friction benchmarks (g 9.81, dt 2 ms, 0.2 m cubes of
// density 700, every body starting exactly touching its support).
inline constexpr double kBenchCube = 0.2;       // m
inline constexpr double kBenchDensity = 700.0;  // kg/m^3
inline constexpr double kBenchDt = 0.002;       // s

// `count` cubes stacked on the ground with no gap at all, mu 0.5.
inline WorldDesc touching_cube_stack(int count) {
  WorldDesc w = base_world(kBenchDt);
  w.planes.push_back(ground(friction(0.5, 0.5)));
  for (int i = 0; i < count; ++i)
    w.rigid_bodies.push_back(rigid_box("box" + std::to_string(i), Eigen::Vector3d::Constant(kBenchCube),
                                       Eigen::Vector3d(0.0, (i + 0.5) * kBenchCube, 0.0), friction(0.5, 0.5),
                                       kBenchDensity));
  return w;
}

// A pyramid of rigid cubes (edge kBenchCube, density kBenchDensity, mu 0.5,
// the scene primitive's 8 x 8 cells a face) on the ground: `base` cubes side
// by side `gap` m apart, and each row above one cube shorter, every cube
// resting exactly touching on the two below it.
inline WorldDesc box_pyramid(int base, double gap, double dt) {
  WorldDesc w = base_world(dt);
  w.planes.push_back(ground(friction(0.5, 0.5)));
  for (int row = 0; row < base; ++row)
    for (int i = 0; i < base - row; ++i) {
      const double x = (i - 0.5 * (base - row - 1)) * (kBenchCube + gap);
      w.rigid_bodies.push_back(rigid_box("box" + std::to_string(row) + "_" + std::to_string(i),
                                         Eigen::Vector3d::Constant(kBenchCube),
                                         Eigen::Vector3d(x, (row + 0.5) * kBenchCube, 0.0), friction(0.5, 0.5),
                                         kBenchDensity, 8));
    }
  return w;
}

// `count` jelly cubes (E 1 MPa, Poisson 0.45, damping ratio 0.02, a lattice
// of `resolution` cells a side) stacked on the ground with no gap at all, mu 0.5.
inline WorldDesc touching_jelly_stack(int count, int resolution) {
  WorldDesc w = base_world(kBenchDt);
  w.planes.push_back(ground(friction(0.5, 0.5)));
  Material m = jelly(1e6, kBenchDensity);
  m.poisson_ratio = 0.45;
  m.damping_ratio = 0.02;
  for (int i = 0; i < count; ++i)
    w.bodies.push_back(soft_box("jelly" + std::to_string(i), Eigen::Vector3d::Constant(kBenchCube), resolution, m,
                                Eigen::Vector3d(0.0, (i + 0.5) * kBenchCube, 0.0), friction(0.5, 0.5)));
  return w;
}

// A cube resting on a plane tilted by 16 degrees, mu 0.35 (tan 16 deg =
// 0.287: static friction holds it), lifted `gap` off the plane.
inline constexpr double kHoldingSlope = 16.0 * kPi / 180.0;
inline constexpr double kHoldingMu = 0.35;
inline WorldDesc cube_on_holding_slope(double gap = 0.0) {
  WorldDesc w = base_world(kBenchDt);
  w.planes.push_back(incline(kHoldingSlope, friction(kHoldingMu, kHoldingMu)));
  RigidBodyDesc b = rigid_box("cube", Eigen::Vector3d::Constant(kBenchCube), Eigen::Vector3d::Zero(),
                              friction(kHoldingMu, kHoldingMu), kBenchDensity);
  place_on_incline(b, kHoldingSlope, 0.5 * kBenchCube, 0.0, gap);
  w.rigid_bodies.push_back(b);
  return w;
}

// Three jelly cubes (edge `size`) stacked on the ground.
inline WorldDesc jelly_stack(int count = 3, double size = 0.1, int resolution = 3, double dt = 0.01) {
  WorldDesc w = base_world(dt);
  w.planes.push_back(ground(friction(0.6, 0.6)));
  for (int i = 0; i < count; ++i)
    w.bodies.push_back(soft_box("jelly" + std::to_string(i), Eigen::Vector3d::Constant(size), resolution, jelly(5e4),
                                Eigen::Vector3d(0.0, (i + 0.5) * size + (i + 1) * 5e-4, 0.0), friction(0.6, 0.6)));
  return w;
}

// Deformable bunnies (about `height` tall), jelly, no self-contact, each
// turned 45 degrees about y from the last; `place(i, height)` gives the
// centre of bunny i.
template <typename Place>
WorldDesc bunnies_dropped(const std::string& bunny_path, int count, double height, int resolution, double dt,
                          Place place) {
  WorldDesc w = base_world(dt);
  w.planes.push_back(ground(friction(0.5, 0.5)));
  TriMesh bunny = import_surface(bunny_path);
  const Aabb box = bounding_box(bunny);
  const double scale = height / box.extent().maxCoeff();
  bunny.vertices = ((bunny.vertices.rowwise() - box.center().transpose()) * scale).eval();
  for (int i = 0; i < count; ++i) {
    DeformableBodyDesc b;
    b.name = "bunny" + std::to_string(i);
    b.mesh = bunny;
    b.resolution = resolution;
    b.material = jelly(5e4);
    b.self_contact = false;
    b.transform.position = place(i, height);
    b.transform.rotation = Eigen::Vector3d(0.0, 45.0 * i, 0.0);
    w.bodies.push_back(std::move(b));
  }
  return w;
}

// Bunnies in one column, 1 cm apart, alternating round the axis 3 cm off it:
// each lands on the pile below at up to 4 m/s (the eighth falls 0.9 m).
inline WorldDesc bunny_pile(const std::string& bunny_path, int count = 8, double height = 0.12, int resolution = 4,
                            double dt = 0.005) {
  return bunnies_dropped(bunny_path, count, height, resolution, dt, [](int i, double h) {
    const double x = 0.03 * ((i % 2) ? 1.0 : -1.0), z = 0.03 * ((i / 2 % 2) ? 1.0 : -1.0);
    return Eigen::Vector3d(x, 0.5 * h + 0.01 + i * (h + 0.01), z);
  });
}

// Eight bunnies in two layers of four, laid out like
// assets/scenes/validation/pile.json (whose bunnies are larger, finer and
// stiffer):
// a 2 x 2 grid `spacing` between centres, the upper layer 1.5 heights up and
// shifted (3, -2) cm, so that each upper bunny falls about half a height onto
// the one below it, off-centre. With h = 0.12, resolution 3: they land at
// 0.13-0.15 s and slide off it into the middle and round the outside,
// reaching the ground by 0.45 s.
inline WorldDesc bunny_layers(const std::string& bunny_path, double height = 0.12, int resolution = 4,
                              double dt = 0.005) {
  return bunnies_dropped(bunny_path, 8, height, resolution, dt, [](int i, double h) {
    const int layer = i / 4, j = i % 4;
    const double half_spacing = 0.75 * h;
    const double x = ((j % 2) ? half_spacing : -half_spacing) + (layer ? 0.03 : 0.0);
    const double z = ((j / 2) ? half_spacing : -half_spacing) + (layer ? -0.02 : 0.0);
    return Eigen::Vector3d(x, 0.5 * h + 0.01 + layer * 1.5 * h, z);
  });
}

// A soft block pushed down between two kinematic cylinders (axes along z)
// turning inwards at `omega` rad/s, no gravity needed beyond the push.
inline WorldDesc rollers(double omega = 6.0, int resolution = 4, double dt = 0.005) {
  WorldDesc w = base_world(dt);
  const double radius = 0.05, gap = 0.06;
  for (int side = -1; side <= 1; side += 2) {
    RigidBodyDesc c;
    c.name = side < 0 ? "roller_left" : "roller_right";
    c.kind = BodyKind::kinematic;
    c.mesh = make_cylinder(radius, 0.2, 32);
    c.transform.rotation = Eigen::Vector3d(90.0, 0.0, 0.0);
    c.transform.position = Eigen::Vector3d(side * (radius + 0.5 * gap), 0.0, 0.0);
    // The faces towards the gap move down: w_z = -omega on the left, +omega on the right.
    c.angular_velocity = Eigen::Vector3d(0.0, 0.0, side * omega);
    c.friction = friction(0.8, 0.8);
    w.rigid_bodies.push_back(std::move(c));
  }
  DeformableBodyDesc b = soft_box("dough", Eigen::Vector3d(0.08, 0.08, 0.08), resolution, jelly(3e4),
                                  Eigen::Vector3d(0.0, 0.095, 0.0), friction(0.8, 0.8));
  b.velocity = Eigen::Vector3d(0.0, -0.3, 0.0);
  w.bodies.push_back(std::move(b));
  return w;
}

}  // namespace recoil::sim::scenes
