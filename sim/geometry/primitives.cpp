#include "sim/geometry/primitives.h"

#include <cmath>
#include <map>
#include <vector>

#include "core/check.h"

namespace recoil::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Collects vertices and triangles, welding vertices that land on the same
// point (exact key after rounding to 1e-12 of the shape's scale) so shared
// edges between patches become topologically shared.
class MeshBuilder {
 public:
  explicit MeshBuilder(double scale) : m_quantum(1e-9 * scale) {}

  int vertex(const Eigen::Vector3d& p) {
    const std::array<long long, 3> key = {std::llround(p.x() / m_quantum), std::llround(p.y() / m_quantum),
                                          std::llround(p.z() / m_quantum)};
    auto [it, inserted] = m_index.try_emplace(key, static_cast<int>(m_points.size()));
    if (inserted) m_points.push_back(p);
    return it->second;
  }

  void triangle(int a, int b, int c) {
    if (a != b && b != c && a != c) m_triangles.push_back({a, b, c});
  }

  // Two triangles for the quad a-b-c-d (counter-clockwise seen from outside).
  void quad(int a, int b, int c, int d) {
    triangle(a, b, c);
    triangle(a, c, d);
  }

  TriMesh finish() const {
    TriMesh mesh;
    mesh.vertices.resize(static_cast<Eigen::Index>(m_points.size()), 3);
    for (size_t i = 0; i < m_points.size(); ++i) mesh.vertices.row(static_cast<Eigen::Index>(i)) = m_points[i];
    mesh.triangles.resize(static_cast<Eigen::Index>(m_triangles.size()), 3);
    for (size_t f = 0; f < m_triangles.size(); ++f)
      for (int k = 0; k < 3; ++k) mesh.triangles(static_cast<Eigen::Index>(f), k) = m_triangles[f][k];
    return mesh;
  }

 private:
  double m_quantum;
  std::map<std::array<long long, 3>, int> m_index;
  std::vector<Eigen::Vector3d> m_points;
  std::vector<std::array<int, 3>> m_triangles;
};

// A surface of revolution about y: `profile` lists (radius, y) from bottom to
// top; a radius of 0 at an end closes it with a pole.
TriMesh revolve(const std::vector<Eigen::Vector2d>& profile, int segments, double scale) {
  MeshBuilder builder(scale);
  auto at = [&](size_t ring, int s) {
    const double angle = 2.0 * kPi * (s % segments) / segments;
    const double r = profile[ring].x();
    // Counter-clockwise about +y seen from above: x = r cos, z = -r sin.
    return builder.vertex(Eigen::Vector3d(r * std::cos(angle), profile[ring].y(), -r * std::sin(angle)));
  };
  for (size_t ring = 0; ring + 1 < profile.size(); ++ring)
    for (int s = 0; s < segments; ++s) builder.quad(at(ring, s), at(ring, s + 1), at(ring + 1, s + 1), at(ring + 1, s));
  return builder.finish();
}

}  // namespace

TriMesh make_box(const Eigen::Vector3d& size, int cells) {
  RECOIL_CHECK(cells >= 1 && (size.array() > 0).all());
  MeshBuilder builder(size.maxCoeff());
  const Eigen::Vector3d half = 0.5 * size;
  // Each face: a normal axis, a sign, and two in-plane axes (u, v) with u x v = outward normal.
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign : {-1, 1}) {
      int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if (sign < 0) std::swap(u, v);
      auto point = [&](int i, int j) {
        Eigen::Vector3d p;
        p[axis] = sign * half[axis];
        p[u] = -half[u] + size[u] * i / cells;
        p[v] = -half[v] + size[v] * j / cells;
        return builder.vertex(p);
      };
      for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j) builder.quad(point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1));
    }
  }
  return builder.finish();
}

TriMesh make_sphere(double radius, int subdivisions) {
  RECOIL_CHECK(radius > 0 && subdivisions >= 0);
  // Icosahedron, then split each triangle in four and push to the sphere.
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> points = {{-1, t, 0}, {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<int, 3>> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                           {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                           {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                           {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& p : points) p.normalize();
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto [it, inserted] = midpoint.try_emplace(key, static_cast<int>(points.size()));
      if (inserted) points.push_back((points[a] + points[b]).normalized());
      return it->second;
    };
    std::vector<std::array<int, 3>> finer;
    finer.reserve(faces.size() * 4);
    for (const auto& f : faces) {
      const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    faces.swap(finer);
  }
  TriMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i) mesh.vertices.row(static_cast<Eigen::Index>(i)) = radius * points[i];
  mesh.triangles.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) mesh.triangles(static_cast<Eigen::Index>(f), k) = faces[f][k];
  return mesh;
}

TriMesh make_cylinder(double radius, double height, int segments) {
  RECOIL_CHECK(radius > 0 && height > 0 && segments >= 3);
  const double h = height / 2;
  // Cap rings at 0.97 r and side rings near the rims keep the shading of the
  // rims crisp; the poles close the caps.
  std::vector<Eigen::Vector2d> profile = {{0, -h}, {0.5 * radius, -h}, {0.97 * radius, -h}, {radius, -h}};
  for (double s : {0.03, 0.25, 0.5, 0.75, 0.97}) profile.push_back({radius, -h + height * s});
  for (const Eigen::Vector2d& p : {Eigen::Vector2d(radius, h), Eigen::Vector2d(0.97 * radius, h),
                                   Eigen::Vector2d(0.5 * radius, h), Eigen::Vector2d(0, h)})
    profile.push_back(p);
  return revolve(profile, segments, std::max(radius, height));
}

TriMesh make_capsule(double radius, double height, int segments) {
  RECOIL_CHECK(radius > 0 && height >= 0 && segments >= 3);
  const int quarter = std::max(4, segments / 4);  // rings per hemisphere
  std::vector<Eigen::Vector2d> profile;
  for (int i = 0; i <= quarter; ++i) {  // bottom hemisphere, from the pole up to the equator
    const double a = -kPi / 2 + (kPi / 2) * i / quarter;
    profile.push_back({radius * std::cos(a), -height / 2 + radius * std::sin(a)});
  }
  for (int i = 0; i <= quarter; ++i) {  // top hemisphere, from the equator up to the pole
    const double a = (kPi / 2) * i / quarter;
    profile.push_back({radius * std::cos(a), height / 2 + radius * std::sin(a)});
  }
  profile.front().x() = 0;
  profile.back().x() = 0;
  if (height == 0) profile.erase(profile.begin() + quarter);  // the two equators coincide
  return revolve(profile, segments, radius + height);
}

TriMesh make_torus(double major_radius, double minor_radius, int major_segments, int minor_segments) {
  RECOIL_CHECK(major_radius > minor_radius && minor_radius > 0 && major_segments >= 3 && minor_segments >= 3);
  MeshBuilder builder(major_radius + minor_radius);
  auto at = [&](int i, int j) {
    const double u = 2 * kPi * (i % major_segments) / major_segments;
    const double w = 2 * kPi * (j % minor_segments) / minor_segments;
    const double r = major_radius + minor_radius * std::cos(w);
    return builder.vertex(Eigen::Vector3d(r * std::cos(u), minor_radius * std::sin(w), -r * std::sin(u)));
  };
  for (int i = 0; i < major_segments; ++i)
    for (int j = 0; j < minor_segments; ++j) builder.quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  return builder.finish();
}

}  // namespace recoil::sim
