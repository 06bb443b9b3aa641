#pragma once
// Plain input and output types of collision detection, independent of the
// World, FEM and rigid-body code: the World copies each body's collision
// surface into a CollisionSurface, and the contact code maps the surface-vertex
// weights of each ContactCandidate to DoFs (embedding weights for FEM bodies,
// v + w x r for rigid ones).
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "sim/body/body_kind.h"
#include "sim/geometry/tet_mesh.h"
#include "sim/geometry/tri_mesh.h"

namespace recoil::sim {

struct CollisionSurface {
  int body = -1;           // caller's body id, copied into candidates
  BodyKind kind = BodyKind::deformable;
  Points x0;               // #V by 3, positions at the start of the step (m)
  Points x1;               // #V by 3, predicted positions at the end of the step (m)
  Triangles triangles;     // #F by 3, indices into x0/x1, counter-clockwise from outside
  bool self_contact = false;  // only honoured for deformable surfaces
  // #V by 3, the rest shape (m); required with self_contact. A pair of the
  // surface's primitives is a contact only within min(margin, rest distance
  // - margin) of each other: deformation must have closed a margin of what
  // the rest shape holds apart. Closeness at rest is modelled (neighbouring
  // triangles, a narrow gap) and the elasticity, not a constraint, keeps it;
  // a pair within the margin at rest is never a contact.
  const Points* rest = nullptr;
  // Optional with self_contact, for a surface embedded in a tet lattice: the
  // element each vertex moves with (#V, into `elements`) and the elements'
  // nodes (#T by 4). Two primitives in one element, or in two that share a
  // face, come together only as those elements strain, which their
  // elasticity governs: such a pair is never a contact (a contact inside the
  // lattice's own resolution can be met only by collapsing its elements).
  // Elements meeting at a node or an edge can fold about it without
  // straining, and their pairs stay contacts.
  const Eigen::VectorXi* vertex_element = nullptr;
  const Tets* elements = nullptr;
};

// An infinite static plane: points x with normal.(x - point) >= 0 are outside.
struct CollisionPlane {
  int body = -1;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // normalised on use
};

struct CollisionSettings {
  // A pair becomes a candidate when it is (or may come, during the step)
  // closer than this, in metres.
  double margin = 0.002;
  // Worker threads for the queries; the result is identical for any value.
  int num_threads = 1;
};

enum class ContactKind { vertex_triangle = 0, edge_edge = 1, vertex_plane = 2 };

// One side of a contact: the point is sum_i weight[i] * x[vertex[i]] over the
// first `count` entries, with x the side's surface-vertex positions.
struct SurfacePoint {
  int count = 0;                        // 1 (vertex), 2 (edge) or 3 (triangle); 0 for a plane
  std::array<int, 3> vertex = {-1, -1, -1};
  std::array<double, 3> weight = {0.0, 0.0, 0.0};

  Eigen::Vector3d evaluate(const Points& x) const {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int i = 0; i < count; ++i) p += weight[i] * x.row(vertex[i]).transpose();
    return p;
  }

  // The feature the point lies on: the vertices with a non-zero weight (a
  // vertex, an edge or the triangle's interior), ascending, unused entries -1.
  std::array<int, 3> touched_feature() const {
    std::array<int, 3> feature = {-1, -1, -1};
    int n = 0;
    for (int i = 0; i < count; ++i)
      if (weight[static_cast<size_t>(i)] != 0.0) feature[static_cast<size_t>(n++)] = vertex[static_cast<size_t>(i)];
    // Insertion sort by hand: std::sort over the first n entries of a
    // three-element array trips GCC 12's -Warray-bounds.
    for (int i = 1; i < n; ++i)
      for (int j = i; j > 0 && feature[static_cast<size_t>(j)] < feature[static_cast<size_t>(j - 1)]; --j)
        std::swap(feature[static_cast<size_t>(j)], feature[static_cast<size_t>(j - 1)]);
    return feature;
  }
};

// A potential contact between point p on side A and point q on side B.
// Everything is evaluated at the start of the step (x0): gap = normal.(p - q)
// with p = a.evaluate(x0_A), q = b.evaluate(x0_B) (or plane_point for planes).
// When the continuous check found a time of impact, the weights and normal are
// those at the moment of impact (so the linearised constraint stops the
// crossing), and `toi` is the step fraction in [0, 1].
struct ContactCandidate {
  ContactKind kind = ContactKind::vertex_triangle;
  int surface_a = -1, surface_b = -1;  // indices into the surfaces (planes: into the planes) given
  int body_a = -1, body_b = -1;        // the surfaces' / plane's body ids
  int primitive_a = -1;                // vertex (vertex_*) or edge id (edge_edge)
  int primitive_b = -1;                // triangle, edge or plane id
  SurfacePoint a, b;                   // b.count == 0 for vertex_plane
  Eigen::Vector3d plane_point = Eigen::Vector3d::Zero();  // q for vertex_plane only
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();      // unit, from q (B) towards p (A)
  double gap = 0.0;                    // normal.(p - q) at x0, metres, signed
  std::optional<double> toi;           // first contact time as a step fraction, if any
};

// A candidate's identity: kind, surfaces, primitives. Orders candidate
// lists deterministically and keys a contact from one step to the next.
using CandidateKey = std::array<int, 5>;
inline CandidateKey candidate_key(const ContactCandidate& c) {
  return {static_cast<int>(c.kind), c.surface_a, c.surface_b, c.primitive_a, c.primitive_b};
}

inline bool candidate_less(const ContactCandidate& l, const ContactCandidate& r) {
  return candidate_key(l) < candidate_key(r);
}

}  // namespace recoil::sim
