#include "sim/collision/covered_faces.h"

#include <algorithm>
#include <memory>

#include "sim/collision/embree_scene.h"
#include "sim/collision/exact_distance.h"
#include "sim/collision/narrow_phase.h"
#include "sim/geometry/winding_number.h"

namespace recoil::sim {
namespace {

// A fixed closed surface as the solid that may cover others' faces; its
// search structures are built on first use.
class FixedSolid {
 public:
  FixedSolid(EmbreeDevice& device, const CollisionSurface& s) : m_device(&device), m_surface(&s) {
    m_box = bounding_box(s.x0);
  }

  const Aabb& box() const { return m_box; }

  // The nearest face within `reach` (m) of p: its index, or -1.
  int nearest_face(const Eigen::Vector3d& p, double reach) {
    if (!m_faces) m_faces = std::make_unique<TriangleScene>(*m_device, m_surface->x0, m_surface->triangles, false);
    m_near.clear();
    m_faces->triangles_near(p, reach, m_near);
    int best = -1;
    double best_distance = reach;
    for (int f : m_near) {
      const double d = (p - closest_point_on_triangle(p, corner(f, 0), corner(f, 1), corner(f, 2)).point).norm();
      if (d <= best_distance && (best < 0 || d < best_distance)) {
        best = f;
        best_distance = d;
      }
    }
    return best;
  }

  bool inside(const Eigen::Vector3d& p) {
    if (!m_winding) m_winding = std::make_unique<WindingNumberTree>(TriMesh{m_surface->x0, m_surface->triangles, {}});
    return (*m_winding)(p) > 0.5;
  }

  // Unit outward normal of face f (zero if degenerate).
  Eigen::Vector3d normal(int f) const {
    const Eigen::Vector3d n = face_normal(corner(f, 0), corner(f, 1), corner(f, 2));
    return n.isZero() ? n : Eigen::Vector3d(n.normalized());
  }

 private:
  Eigen::Vector3d corner(int f, int k) const { return point_at(m_surface->x0, m_surface->triangles(f, k)); }

  EmbreeDevice* m_device;
  const CollisionSurface* m_surface;
  Aabb m_box;
  std::unique_ptr<TriangleScene> m_faces;
  std::unique_ptr<WindingNumberTree> m_winding;
  std::vector<int> m_near;
};

bool fixed_and_closed(const CollisionSurface& s) {
  if (s.kind != BodyKind::fixed || s.triangles.rows() == 0) return false;
  const std::vector<std::array<int, 2>> opposite = edge_opposites(s.triangles, unique_edges(s.triangles));
  return std::all_of(opposite.begin(), opposite.end(), [](const std::array<int, 2>& o) { return o[0] >= 0; });
}

// The rule in covered_faces.h for triangle f of `s` against `solid`.
// `vertex_in` (#V of s) memoises each vertex's test: -1 not yet made, 0
// outside, 1 inside or within the tolerance.
bool covers(FixedSolid& solid, const CollisionSurface& s, Eigen::Index f, double tolerance,
            std::vector<signed char>& vertex_in) {
  std::array<Eigen::Vector3d, 3> corners;
  for (int k = 0; k < 3; ++k) corners[static_cast<size_t>(k)] = point_at(s.x0, s.triangles(f, k));
  const Eigen::Vector3d pad = Eigen::Vector3d::Constant(tolerance);
  for (const Eigen::Vector3d& p : corners)
    if ((p.array() < (solid.box().min - pad).array()).any() || (p.array() > (solid.box().max + pad).array()).any())
      return false;
  for (int k = 0; k < 3; ++k) {
    signed char& in = vertex_in[static_cast<size_t>(s.triangles(f, k))];
    const Eigen::Vector3d& p = corners[static_cast<size_t>(k)];
    if (in < 0) in = solid.nearest_face(p, tolerance) >= 0 || solid.inside(p) ? 1 : 0;
    if (in == 0) return false;
  }
  const Eigen::Vector3d own = face_normal(corners[0], corners[1], corners[2]);
  const Eigen::Vector3d centroid = (corners[0] + corners[1] + corners[2]) / 3.0;
  const int face = solid.nearest_face(centroid, tolerance);
  if (face >= 0) return solid.normal(face).dot(own) < 0.0;
  return solid.inside(centroid);
}

// The same rule against the half-space behind a plane.
bool covers(const CollisionPlane& plane, const CollisionSurface& s, Eigen::Index f, double tolerance) {
  const Eigen::Vector3d n = plane.normal.normalized();
  std::array<Eigen::Vector3d, 3> corners;
  for (int k = 0; k < 3; ++k) {
    corners[static_cast<size_t>(k)] = point_at(s.x0, s.triangles(f, k));
    if (n.dot(corners[static_cast<size_t>(k)] - plane.point) > tolerance) return false;
  }
  const double centroid = n.dot((corners[0] + corners[1] + corners[2]) / 3.0 - plane.point);
  if (centroid < -tolerance) return true;
  return n.dot(face_normal(corners[0], corners[1], corners[2])) < 0.0;
}

}  // namespace

std::vector<std::vector<char>> covered_triangles(const std::vector<CollisionSurface>& surfaces,
                                                 const std::vector<CollisionPlane>& planes, double tolerance) {
  std::vector<std::vector<char>> out(surfaces.size());
  std::vector<size_t> fixed;
  for (size_t i = 0; i < surfaces.size(); ++i)
    if (fixed_and_closed(surfaces[i])) fixed.push_back(i);
  if (fixed.empty()) return out;
  EmbreeDevice device;
  std::vector<FixedSolid> solids;
  solids.reserve(fixed.size());
  for (size_t i : fixed) solids.emplace_back(device, surfaces[i]);
  const Eigen::Vector3d pad = Eigen::Vector3d::Constant(tolerance);
  for (size_t a = 0; a < fixed.size(); ++a) {
    const CollisionSurface& s = surfaces[fixed[a]];
    // The solids whose boxes, padded by the tolerance, meet this surface's.
    std::vector<FixedSolid*> near;
    for (size_t b = 0; b < fixed.size(); ++b)
      if (b != a && ((solids[b].box().min - pad).array() <= solids[a].box().max.array()).all() &&
          ((solids[a].box().min).array() <= (solids[b].box().max + pad).array()).all())
        near.push_back(&solids[b]);
    if (near.empty() && planes.empty()) continue;
    std::vector<char> flags(static_cast<size_t>(s.triangles.rows()), 0);
    for (Eigen::Index f = 0; f < s.triangles.rows(); ++f)
      for (const CollisionPlane& plane : planes) flags[static_cast<size_t>(f)] |= covers(plane, s, f, tolerance);
    std::vector<signed char> vertex_in;
    for (FixedSolid* solid : near) {
      vertex_in.assign(static_cast<size_t>(s.x0.rows()), -1);
      for (Eigen::Index f = 0; f < s.triangles.rows(); ++f)
        if (!flags[static_cast<size_t>(f)]) flags[static_cast<size_t>(f)] = covers(*solid, s, f, tolerance, vertex_in);
    }
    if (std::find(flags.begin(), flags.end(), 1) != flags.end()) out[fixed[a]] = std::move(flags);
  }
  return out;
}

}  // namespace recoil::sim
