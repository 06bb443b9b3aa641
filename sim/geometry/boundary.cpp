#include "sim/geometry/boundary.h"

#include <algorithm>
#include <array>
#include <vector>

namespace recoil::sim {

namespace {
// Faces of a positively oriented tet (0,1,2,3), each wound so its normal points
// away from the opposite node.
constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

struct Face {
  std::array<int, 3> key;     // sorted node indices
  std::array<int, 3> wound;   // outward winding
};
}  // namespace

TriMesh boundary_surface(const TetMesh& mesh) {
  std::vector<Face> faces;
  faces.reserve(static_cast<size_t>(mesh.num_tets()) * 4);
  for (int t = 0; t < mesh.num_tets(); ++t)
    for (const auto& f : kFaces) {
      Face face;
      face.wound = {mesh.tets(t, f[0]), mesh.tets(t, f[1]), mesh.tets(t, f[2])};
      face.key = face.wound;
      std::sort(face.key.begin(), face.key.end());
      faces.push_back(face);
    }
  // Stable sort keeps the result independent of the standard library's
  // unstable ordering of equal keys.
  std::stable_sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.key < b.key; });
  std::vector<std::array<int, 3>> out;
  for (size_t i = 0; i < faces.size();) {
    size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key) ++j;
    if (j - i == 1) out.push_back(faces[i].wound);
    i = j;
  }
  TriMesh surface;
  surface.vertices = mesh.nodes;
  surface.triangles.resize(static_cast<Eigen::Index>(out.size()), 3);
  for (size_t i = 0; i < out.size(); ++i)
    for (int k = 0; k < 3; ++k) surface.triangles(static_cast<Eigen::Index>(i), k) = out[i][k];
  return surface;
}

}  // namespace recoil::sim
