#include "sim/collision/brute_force.h"

#include "sim/collision/candidate_reduction.h"
#include "sim/collision/covered_faces.h"
#include "sim/collision/narrow_phase.h"

namespace recoil::sim {
namespace {

void add(std::vector<ContactCandidate>& out, std::optional<ContactCandidate> c) {
  if (c) out.push_back(std::move(*c));
}

void vertices_against_triangles(const PreparedSurface& a, const PreparedSurface& b, double margin,
                                std::vector<ContactCandidate>& out) {
  for (int v = 0; v < a.num_vertices(); ++v)
    for (int t = 0; t < b.num_triangles(); ++t) add(out, test_vertex_triangle(a, v, b, t, margin));
}

}  // namespace

std::vector<ContactCandidate> brute_force_candidates(const std::vector<CollisionSurface>& surfaces,
                                                     const std::vector<CollisionPlane>& planes,
                                                     const CollisionSettings& settings) {
  const double margin = settings.margin;
  const std::vector<std::vector<char>> covered = covered_triangles(surfaces, planes, kFeatureSnapShare * margin);
  std::vector<PreparedSurface> prepared;
  for (size_t i = 0; i < surfaces.size(); ++i) {
    prepared.push_back(prepare_surface(surfaces[i], static_cast<int>(i)));
    if (!covered[i].empty()) prepared.back().covered = &covered[i];
  }
  std::vector<ContactCandidate> out;
  for (size_t i = 0; i < prepared.size(); ++i) {
    const PreparedSurface& a = prepared[i];
    for (size_t j = i + 1; j < prepared.size(); ++j) {
      const PreparedSurface& b = prepared[j];
      if (!surfaces_interact(a, b)) continue;
      vertices_against_triangles(a, b, margin, out);
      vertices_against_triangles(b, a, margin, out);
      for (int ea = 0; ea < a.num_edges(); ++ea)
        for (int eb = 0; eb < b.num_edges(); ++eb) add(out, test_edge_edge(a, ea, b, eb, margin));
    }
    if (self_interacts(a)) {
      vertices_against_triangles(a, a, margin, out);
      for (int ea = 0; ea < a.num_edges(); ++ea)
        for (int eb = ea + 1; eb < a.num_edges(); ++eb) add(out, test_edge_edge(a, ea, a, eb, margin));
    }
    if (interacts_with_planes(a))
      for (size_t k = 0; k < planes.size(); ++k)
        for (int v = 0; v < a.num_vertices(); ++v)
          add(out, test_vertex_plane(a, v, planes[k], static_cast<int>(k), margin));
  }
  finalize_candidates(out, surfaces);
  return out;
}

}  // namespace recoil::sim
