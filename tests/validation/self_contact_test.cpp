// Self-contact that is real: a fine surface falling freely offers no self
// candidates (its neighbours are close at rest, which is modelled, not a
// collision), while a ring squashed until its inner faces meet keeps its
// surface from passing through itself; and a real asset whose details are
// finer than its lattice (a spider's legs and body parts) is crushed without
// collapsing its elements.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <iostream>
#include <map>

#include "sim/geometry/mesh_import.h"
#include "tests/scenes/contact_scenes.h"
#include "tests/validation/measured.h"

namespace recoil::sim {
namespace {

using namespace scenes;

TEST(SelfContact, AFineSurfaceFallingFreelyHasNoCandidates) {
  // Edges of about 1.3 mm, finer than the 2 mm margin: every vertex is
  // within the margin of its neighbours' triangles.
  WorldDesc w = base_world(0.004);
  DeformableBodyDesc b = soft_sphere("ball", 0.02, 5, jelly(1e5), Eigen::Vector3d::Zero());
  b.mesh = make_sphere(0.02, 4);
  b.collision.keep_mesh = true;  // contact sees the fine mesh itself
  b.self_contact = true;
  w.bodies.push_back(b);
  World world(w);
  validation::Measured() << "falling sphere: " << world.deformable_body(0).surface.num_triangles() << " triangles\n";
  int most = 0;
  for (int i = 0; i < 50; ++i) {
    const StepReport r = world.step();
    ASSERT_EQ(r.status, StepStatus::ok);
    most = std::max(most, r.contacts);
  }
  EXPECT_EQ(most, 0);
}

// Segment p0-p1 crosses triangle abc (strictly inside both).
bool segment_crosses_triangle(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& a,
                              const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d d = p1 - p0, e1 = b - a, e2 = c - a, h = d.cross(e2);
  const double det = e1.dot(h);
  if (std::abs(det) < 1e-18) return false;
  const Eigen::Vector3d s = p0 - a;
  const double u = s.dot(h) / det;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = d.dot(q) / det, t = e2.dot(q) / det;
  return u > 0.0 && v > 0.0 && u + v < 1.0 && t > 0.0 && t < 1.0;
}

// Edges of the surface that pass through one of its triangles (not their own).
int self_crossings(const Points& x, const Triangles& triangles) {
  int crossings = 0;
  for (int f = 0; f < triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int i = triangles(f, k), j = triangles(f, (k + 1) % 3);
      if (i > j) continue;  // each edge once (closed surface: it has a twin running j -> i)
      for (int g = 0; g < triangles.rows(); ++g) {
        const auto t = triangles.row(g);
        if (t(0) == i || t(1) == i || t(2) == i || t(0) == j || t(1) == j || t(2) == j) continue;
        crossings += segment_crosses_triangle(x.row(i).transpose(), x.row(j).transpose(), x.row(t(0)).transpose(),
                                              x.row(t(1)).transpose(), x.row(t(2)).transpose());
      }
    }
  return crossings;
}

// Tets of a set of cubic cells (cell (i, j, k) spans [i, i+1] x [j, j+1] x
// [k, k+1] times `size`), six per cell around its main diagonal so that
// neighbouring cells share their faces' diagonals.
TetMesh voxel_tets(const std::vector<Eigen::Vector3i>& cells, double size) {
  std::map<std::array<int, 3>, int> index;
  TetMesh mesh;
  std::vector<Eigen::Vector3d> nodes;
  auto node = [&](const Eigen::Vector3i& p) {
    const auto [it, added] = index.try_emplace({p.x(), p.y(), p.z()}, static_cast<int>(nodes.size()));
    if (added) nodes.push_back(size * p.cast<double>());
    return it->second;
  };
  std::vector<std::array<int, 4>> tets;
  const int axes[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const Eigen::Vector3i& c : cells)
    for (const auto& order : axes) {
      // The path from corner 0 to corner 1 of the cell along the axes in this order.
      Eigen::Vector3i p = c;
      std::array<int, 4> t;
      t[0] = node(p);
      for (int k = 0; k < 3; ++k) {
        p[order[k]] += 1;
        t[static_cast<size_t>(k + 1)] = node(p);
      }
      tets.push_back(t);
    }
  mesh.nodes.resize(static_cast<Eigen::Index>(nodes.size()), 3);
  for (size_t i = 0; i < nodes.size(); ++i) mesh.nodes.row(static_cast<Eigen::Index>(i)) = nodes[i].transpose();
  mesh.tets.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (size_t t = 0; t < tets.size(); ++t)
    for (int k = 0; k < 4; ++k) mesh.tets(static_cast<Eigen::Index>(t), k) = tets[t][static_cast<size_t>(k)];
  orient_positive(mesh);
  return mesh;
}

// A soft U (2 cm cells: a base 5 cells wide, two arms 1 cell wide and 5
// tall, 6 cm apart) held by its base, whose arm tips two plates push inward
// by 3.5 cm each: the arms bend at their roots until their tips meet.
int squeezed_u_crossings(bool self_contact, double& penetration, int& unconverged) {
  const double dt = 0.002, speed = 0.2, cell = 0.02, push = 0.035;
  WorldDesc w = base_world(dt);
  std::vector<Eigen::Vector3i> cells;
  for (int k = 0; k < 2; ++k) {
    for (int i = 0; i < 5; ++i) cells.emplace_back(i, 0, k);
    for (int j = 1; j < 6; ++j) {
      cells.emplace_back(0, j, k);
      cells.emplace_back(4, j, k);
    }
  }
  DeformableBodyDesc u = test_scenes::box_body(Eigen::Vector3d::Ones(), 1, jelly(3e4), Eigen::Vector3d::Zero(), "u");
  u.mesh = TriMesh{};
  u.tets = voxel_tets(cells, cell);
  u.pinned = PinBox{Eigen::Vector3d::Constant(-1.0), Eigen::Vector3d(1.0, cell + 1e-9, 1.0)};
  u.self_contact = self_contact;
  u.static_friction = u.kinetic_friction = 0.3;
  w.bodies.push_back(u);
  for (int side = -1; side <= 1; side += 2) {
    const double x = side < 0 ? -0.011 - 0.01 : 5 * cell + 0.001 + 0.01;  // 1 mm off the arm's outer face
    RigidBodyDesc plate = rigid_box(side < 0 ? "left" : "right", {0.02, 0.04, 0.1}, {x, 5 * cell, cell});
    plate.kind = BodyKind::kinematic;
    plate.velocity = Eigen::Vector3d(-side * speed, 0.0, 0.0);
    w.rigid_bodies.push_back(plate);
  }
  World world(w);
  penetration = 0.0;
  unconverged = 0;
  const int n = static_cast<int>(std::lround((push + 0.001) / speed / dt));
  for (int i = 0; i < n; ++i) {
    const StepReport r = world.step();
    EXPECT_EQ(r.status, StepStatus::ok) << "step " << r.step;
    if (r.status != StepStatus::ok) break;
    penetration = std::max(penetration, r.max_penetration);
    unconverged += r.solver_converged ? 0 : 1;
  }
  const BodySurface s = world.surfaces()[0];
  return self_crossings(s.positions, s.triangles);
}

TEST(SelfContact, ASoftUFoldedShutDoesNotPassThroughItself) {
  double penetration = 0.0;
  int unconverged = 0;
  const int without = squeezed_u_crossings(false, penetration, unconverged);
  const int with = squeezed_u_crossings(true, penetration, unconverged);
  validation::Measured() << "squeezed U: " << without << " edges through its own surface without self-contact, " << with
            << " with it (max penetration " << penetration * 1e3 << " mm, " << unconverged << " unconverged steps)\n";
  EXPECT_GT(without, 0) << "the squeeze must bring the arms together";
  EXPECT_EQ(with, 0);
  EXPECT_LT(penetration, 0.002);
}

// `recoil drop` of the assimp test models' spider (0.3 m, 0.5 kg, soft,
// lattice 6: legs and body parts of a few millimetres share 5 cm cells) with
// a 14 kg soft sphere landing on it at 3.3 m/s. Pairs of the spider's
// surface in one element, or in two sharing a face, can meet only by
// collapsing those elements: as contacts they inverted one within 0.11 s,
// and the energy blew up a step later. Checked over the crush, 0.12 s;
// after it the sphere rests on the flattened spider, the contact solve
// caps every step (its best answers up to 1e4 m/s from the contact laws)
// and whether an element survives those answers turns on rounding.
TEST(SelfContact, ASpiderCrushedByAHeavySphereKeepsItsElements) {
  const std::string models = "/usr/share/assimp/models";
  WorldDesc w = base_world(0.004);
  w.contact.solver.tolerance = 1e-6;
  w.planes.push_back(ground(friction(0.5, 0.5)));
  Material soft;  // `recoil drop --material soft`
  soft.youngs_modulus = 1e5;
  soft.poisson_ratio = 0.4;
  soft.damping_ratio = 0.03;
  auto body = [&](const std::string& name, const std::string& file, double scale, const Eigen::Vector3d& position,
                  const Eigen::Vector3d& rotation) {
    DeformableBodyDesc b;
    b.name = name;
    b.mesh = import_surface(models + file);
    b.resolution = 6;
    b.material = soft;
    b.self_contact = true;
    b.transform.position = position;
    b.transform.rotation = rotation;
    b.transform.scale = Eigen::Vector3d::Constant(scale);
    return b;
  };
  w.bodies.push_back(body("spider", "/OBJ/spider.obj", 0.00155133, {0.268512, 0.120857, -0.288778},
                          {-17.023, 169.4708, 16.4543}));
  DeformableBodyDesc sphere =
      body("sphere", "/STL/sphereWithHole.stl", 0.1, {0.087279, 0.447731, -0.238967}, {-17.2352, 42.9671, -15.473});
  sphere.velocity = Eigen::Vector3d(0.0, -std::sqrt(2.0 * 9.81 * 0.55), 0.0);
  w.bodies.push_back(sphere);
  World world(w);
  double least = 1.0;
  int unconverged = 0;
  for (int i = 0; i < 30; ++i) {  // 0.12 s: the sphere lands and crushes the spider
    const StepReport r = world.step();
    ASSERT_EQ(r.status, StepStatus::ok) << "step " << r.step << ": " << to_string(r.status) << " (" << r.body << ")";
    least = std::min(least, world.stats()[0].min_volume_ratio);
    unconverged += r.solver_converged ? 0 : 1;
  }
  validation::Measured() << "spider crushed by a 14 kg sphere: least volume ratio " << least << ", " << unconverged
                         << " of 30 steps unconverged\n";
  EXPECT_GT(least, 0.1);
}

}  // namespace
}  // namespace recoil::sim
