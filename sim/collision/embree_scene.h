#pragma once
// Our own types over Embree 3. embree_scene.cpp is the only file that includes
// embree3; everything else in recoil talks to Embree through these classes.
//
// EmbreeDevice: one per World (or per offline task such as tetrahedralization).
// Embree reports errors through a C callback; the callback only records the
// message, and the wrapper throws after the Embree call has returned.
//
// TriangleScene: one triangle surface in its own Embree scene. Dynamic scenes
// (collision surfaces of moving bodies) are refitted with update_vertices().
//
// BoxScene: axis-aligned boxes as an Embree user geometry, for box-pair
// overlap queries (rtcCollide) such as the edge-edge broad phase.
//
// Embree works in float: every query here is conservative (boxes rounded
// outward, query spheres padded) and callers filter the results exactly in
// double precision.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sim/geometry/tri_mesh.h"

namespace recoil::sim {

class EmbreeDevice {
 public:
  EmbreeDevice();
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;

  // Throws recoil::Error(internal) with `what` and Embree's message if an
  // error was recorded since the last call.
  void throw_if_error(const char* what);

  struct Impl;
  Impl& impl() { return *m_impl; }

 private:
  std::unique_ptr<Impl> m_impl;
};

struct RayHit {
  double t = 0.0;         // distance along the (unit or not) direction: hit = origin + t * direction
  int triangle = -1;      // index into the scene's Triangles
  double u = 0.0, v = 0.0;  // barycentric: hit = (1-u-v) p0 + u p1 + v p2
};

class TriangleScene {
 public:
  // vertices: #V by 3, triangles: #F by 3 (copied into Embree's float buffers).
  TriangleScene(EmbreeDevice& device, const Points& vertices, const Triangles& triangles, bool dynamic);
  ~TriangleScene();
  TriangleScene(const TriangleScene&) = delete;
  TriangleScene& operator=(const TriangleScene&) = delete;

  // Moves the vertices (same count and triangles) and refits the BVH.
  void update_vertices(const Points& vertices);

  // The closest hit with t in [t_min, t_max], or none. Embree works in float,
  // so callers needing exact answers re-test the hit triangle in double.
  std::optional<RayHit> first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                  double t_min = 0.0,
                                  double t_max = std::numeric_limits<double>::infinity()) const;

  // Every hit along the ray, sorted by t (the ray is re-cast past each hit).
  // Used for inside/outside parity tests.
  std::vector<RayHit> all_hits(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) const;

  // Appends to `out` the ids of every triangle within `radius` of `center`
  // (a superset: Embree culls with float boxes, padded here for rounding),
  // sorted and without repeats. Safe to call from several threads at once.
  void triangles_near(const Eigen::Vector3d& center, double radius, std::vector<int>& out) const;

  int num_triangles() const { return m_num_triangles; }

  struct Impl;
  Impl& impl() { return *m_impl; }
  const Impl& impl() const { return *m_impl; }

 private:
  std::unique_ptr<Impl> m_impl;
  int m_num_triangles = 0;
};

class BoxScene {
 public:
  explicit BoxScene(EmbreeDevice& device);
  ~BoxScene();
  BoxScene(const BoxScene&) = delete;
  BoxScene& operator=(const BoxScene&) = delete;

  // Replaces the boxes (each rounded outward to float). The BVH is refitted
  // when the count is unchanged and rebuilt otherwise, at the first query
  // that uses it. `keys` (empty, or one
  // pair per box) only matter for self queries: two boxes with a key in common
  // are never paired (edges that share a vertex, say).
  void set_boxes(const std::vector<Aabb>& boxes, std::vector<std::array<int, 2>> keys = {});
  int num_boxes() const;

  // Every pair (i in this scene, j in `other`) whose float boxes overlap
  // (touching counts), sorted and unique. With other == *this: each pair of
  // different boxes without a common key once, as (i, j) with i < j.
  std::vector<std::pair<int, int>> overlapping_pairs(const BoxScene& other) const;

  struct Impl;

 private:
  std::unique_ptr<Impl> m_impl;
};

}  // namespace recoil::sim
