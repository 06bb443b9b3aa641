#include "sim/geometry/mesh_refine.h"

#include <algorithm>
#include <array>
#include <map>
#include <queue>
#include <utility>
#include <vector>

#include "core/check.h"

namespace recoil::sim {

double longest_edge(const TriMesh& mesh) {
  double longest = 0.0;
  for (int f = 0; f < mesh.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, (mesh.vertices.row(mesh.triangles(f, k)) -
                                   mesh.vertices.row(mesh.triangles(f, (k + 1) % 3))).norm());
  return longest;
}

TriMesh split_long_edges(const TriMesh& mesh, double max_edge) {
  RECOIL_CHECK(max_edge > 0.0, "max_edge " << max_edge);
  std::vector<Eigen::Vector3d> points;
  for (int v = 0; v < mesh.num_vertices(); ++v) points.push_back(mesh.vertices.row(v).transpose());
  std::vector<std::array<int, 3>> faces;
  for (int f = 0; f < mesh.num_triangles(); ++f) faces.push_back({mesh.triangles(f, 0), mesh.triangles(f, 1), mesh.triangles(f, 2)});

  using Edge = std::pair<int, int>;  // (lower, higher) vertex
  auto edge = [](int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; };
  auto length = [&](const Edge& e) { return (points[static_cast<size_t>(e.first)] - points[static_cast<size_t>(e.second)]).norm(); };
  std::map<Edge, std::vector<int>> faces_of;  // edge -> the faces using it
  // Longest first; ties by vertex numbers, so the order is deterministic.
  using Entry = std::pair<double, Edge>;
  std::priority_queue<Entry> queue;
  auto add_face = [&](int f) {
    const std::array<int, 3>& t = faces[static_cast<size_t>(f)];
    for (int k = 0; k < 3; ++k) {
      const Edge e = edge(t[k], t[(k + 1) % 3]);
      std::vector<int>& users = faces_of[e];
      users.push_back(f);
      if (users.size() == 1 && length(e) > max_edge) queue.push({length(e), e});
    }
  };
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) add_face(f);

  while (!queue.empty()) {
    const Edge e = queue.top().second;
    queue.pop();
    auto found = faces_of.find(e);
    if (found == faces_of.end()) continue;  // already split
    const std::vector<int> users = std::move(found->second);
    faces_of.erase(found);
    const int m = static_cast<int>(points.size());
    points.push_back(0.5 * (points[static_cast<size_t>(e.first)] + points[static_cast<size_t>(e.second)]));
    for (int f : users) {
      // Each face (a, b, c) with the edge as (a, b), in its own winding, becomes (a, m, c) and (m, b, c).
      std::array<int, 3> t = faces[static_cast<size_t>(f)];
      int k = 0;
      while (edge(t[k], t[(k + 1) % 3]) != e) ++k;
      const int a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      for (int j = 0; j < 3; ++j) {  // the face's other edges lose it as a user
        const Edge other = edge(t[j], t[(j + 1) % 3]);
        if (other == e) continue;
        std::vector<int>& list = faces_of[other];
        list.erase(std::find(list.begin(), list.end(), f));
      }
      faces[static_cast<size_t>(f)] = {a, m, c};
      faces.push_back({m, b, c});
      add_face(f);
      add_face(static_cast<int>(faces.size()) - 1);
    }
  }

  TriMesh out;
  out.vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t v = 0; v < points.size(); ++v) out.vertices.row(static_cast<Eigen::Index>(v)) = points[v].transpose();
  out.triangles.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
    out.triangles.row(static_cast<Eigen::Index>(f)) << faces[f][0], faces[f][1], faces[f][2];
  return out;
}

}  // namespace recoil::sim
