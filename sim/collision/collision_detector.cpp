#include "sim/collision/collision_detector.h"

#include <algorithm>
#include <exception>
#include <functional>
#include <limits>
#include <thread>

#include "core/check.h"
#include "sim/collision/candidate_reduction.h"
#include "sim/collision/covered_faces.h"
#include "sim/collision/embree_scene.h"
#include "sim/collision/local_deformation.h"
#include "sim/collision/narrow_phase.h"
#include "sim/collision/rest_clearance.h"
#include "sim/collision/search_memo.h"

namespace recoil::sim {

struct CollisionDetector::Impl {
  struct SurfaceScenes {
    Triangles triangles;  // the topology the scenes were built for
    std::vector<std::array<int, 2>> edges;          // unique_edges(triangles)
    std::vector<std::array<int, 2>> edge_opposite;  // edge_opposites(triangles, edges)
    std::shared_ptr<const VertexFaces> vertex_faces;  // vertex_faces(triangles)
    std::unique_ptr<TriangleScene> faces;
    std::unique_ptr<BoxScene> edge_boxes;       // padded by the edges' motion, against other surfaces
    std::unique_ptr<BoxScene> self_edge_boxes;  // the searched edges, padded by self_motion, keyed by their vertices
    std::unique_ptr<RestClearance> clearance;   // of `rest_shape`, for self-contact surfaces
    std::unique_ptr<RestCells> cells;           // of `rest_shape`, for self-contact surfaces
    const Points* rest_shape = nullptr;
  };
  EmbreeDevice device;
  std::vector<SurfaceScenes> scenes;
  SearchMemo memo;
  // covered_triangles of the last call's surfaces, and what they hold for:
  // its fixed surfaces' x0 and triangles (empty for the others) and planes.
  std::vector<std::vector<char>> covered;
  std::vector<std::pair<Points, Triangles>> covered_for;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> covered_planes;  // point, normal
  void update_covered(const std::vector<CollisionSurface>& surfaces, const std::vector<CollisionPlane>& planes,
                      double tolerance);
};

void CollisionDetector::Impl::update_covered(const std::vector<CollisionSurface>& surfaces,
                                             const std::vector<CollisionPlane>& planes, double tolerance) {
  const auto held = [&](size_t i) {  // whether surface i is as the marks were made for
    const auto& [x, t] = covered_for[i];
    if (surfaces[i].kind != BodyKind::fixed) return x.rows() == 0;
    return x.rows() == surfaces[i].x0.rows() && t.rows() == surfaces[i].triangles.rows() && x == surfaces[i].x0 &&
           t == surfaces[i].triangles;
  };
  bool same = surfaces.size() == covered_for.size() && planes.size() == covered_planes.size();
  for (size_t i = 0; same && i < surfaces.size(); ++i) same = held(i);
  for (size_t k = 0; same && k < planes.size(); ++k)
    same = planes[k].point == covered_planes[k].first && planes[k].normal == covered_planes[k].second;
  if (same) return;
  covered = covered_triangles(surfaces, planes, tolerance);
  covered_for.assign(surfaces.size(), {});
  for (size_t i = 0; i < surfaces.size(); ++i)
    if (surfaces[i].kind == BodyKind::fixed) covered_for[i] = {surfaces[i].x0, surfaces[i].triangles};
  covered_planes.clear();
  for (const CollisionPlane& p : planes) covered_planes.emplace_back(p.point, p.normal);
}

namespace {

using Chunk = std::function<void(size_t begin, size_t end, std::vector<ContactCandidate>& out)>;

// Runs `work` on contiguous chunks of [0, n) on up to `threads` threads and
// concatenates the outputs in chunk order (the caller sorts at the end anyway).
void parallel_chunks(size_t n, int threads, const Chunk& work, std::vector<ContactCandidate>& out) {
  const size_t count = std::min<size_t>(static_cast<size_t>(std::max(threads, 1)), std::max<size_t>(n / 256, 1));
  if (count <= 1) {
    work(0, n, out);
    return;
  }
  std::vector<std::vector<ContactCandidate>> parts(count);
  std::vector<std::exception_ptr> errors(count);
  std::vector<std::thread> pool;
  for (size_t c = 0; c < count; ++c)
    pool.emplace_back([&, c] {
      try {
        work(n * c / count, n * (c + 1) / count, parts[c]);
      } catch (...) {
        errors[c] = std::current_exception();
      }
    });
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  for (auto& part : parts) out.insert(out.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
}

// How far each vertex of a self-contact surface moves over the step with
// respect to the surface near it, m (#V): q with margin + q_i + q_j at least
// the distance at x0 within which two of its primitives, one holding vertex i
// and the other vertex j, can be a candidate (narrow_phase.h: distance <=
// margin + their relative motion). The step's motion m = x1 - x0 splits into
// a rigid part (R - I) x0 + t and a residual e, so |m_i - m_j| <= e_i + e_j +
// theta |x0_i - x0_j| with theta = |R - I|, and |x0_i - x0_j| <= d + 2 l for
// primitives d apart with edges at most l long; solved for d, that gives
// q = (e + theta (l + margin / 2)) / (1 - theta) for theta < 1/2. A body
// tumbling as a whole thus searches within the margin plus theta times about
// an edge, not theta times its size. R is the step's least-squares rigid fit
// (used only while theta < 1/2), or the identity (e: the motion less its
// mean) where that gives the smaller largest q.
std::vector<double> self_motion(const PreparedSurface& s, double margin) {
  const Points& x0 = s.surface->x0;
  double longest = 0.0;
  for (const auto& e : s.edges) longest = std::max(longest, (x0.row(e[0]) - x0.row(e[1])).norm());
  auto bound = [&](const RigidFit& fit) {
    const double theta = (fit.rotation - Eigen::Matrix3d::Identity()).norm();  // Frobenius >= spectral
    std::vector<double> q(fit.residual.size(), std::numeric_limits<double>::infinity());
    if (theta < 0.5)
      for (size_t v = 0; v < q.size(); ++v) q[v] = (fit.residual[v] + theta * (longest + 0.5 * margin)) / (1.0 - theta);
    return q;
  };
  RigidFit translation;
  translation.translation = (s.surface->x1 - x0).colwise().mean().transpose();
  translation.residual.resize(static_cast<size_t>(x0.rows()));
  for (int v = 0; v < x0.rows(); ++v)
    translation.residual[static_cast<size_t>(v)] =
        (s.surface->x1.row(v) - x0.row(v) - translation.translation.transpose()).norm();
  std::vector<double> q = bound(translation), rigid = bound(fit_rigid_motion(x0, s.surface->x1));
  const auto largest = [](const std::vector<double>& x) { return x.empty() ? 0.0 : *std::max_element(x.begin(), x.end()); };
  return largest(rigid) < largest(q) ? rigid : q;
}

// What the self queries of one surface search this step.
struct SelfSearch {
  std::vector<double> motion;  // #V, self_motion
  double max_motion = 0.0;
  // Whether each vertex's point query runs (#V), and the edges that go into
  // the self box scene (ascending): bent ones whose rest clearance, less their
  // displacement from the rigid fit of the rest shape and the surface's
  // largest, is within the self query's radius (rest_clearance.h), unless the
  // surface around them is rigid to within half the margin
  // (local_deformation.h) and nothing farther than the clearance's reach can
  // come that close.
  std::vector<char> vertex;
  std::vector<int> edges;
};

SelfSearch self_search(const PreparedSurface& s, const RestClearance& clearance, const RestCells& cells,
                       const std::vector<int>& bent, double margin) {
  SelfSearch out;
  out.motion = self_motion(s, margin);
  for (double q : out.motion) out.max_motion = std::max(out.max_motion, q);
  const Points& rest = *s.surface->rest;
  const std::vector<double> displacement = fit_rigid_motion(rest, s.surface->x0).residual;
  double largest = 0.0;
  for (double d : displacement) largest = std::max(largest, d);
  // Rounding of the distances compared, m (relative 1e-12 of the coordinates).
  const double slack = 1e-12 * s.length_scale;
  const double reach = margin + out.max_motion + largest + slack;
  const double cap = cells.reach;  // the clearances' cap (both clearance_reach): beyond it only the global bound holds
  LocalDeformation local(cells, rest, s.surface->x0, s.surface->x1);
  auto locally_rigid = [&](int cell) { return cell >= 0 && 2.0 * local(cell) + slack < margin; };
  // Whether a primitive with these clearance, displacement and motion, in
  // cells [first, last), may have a candidate.
  auto searched = [&](double clear, double moved, double motion, const int* first, const int* last) {
    if (!(clear - moved <= reach + motion)) return false;
    return !(cap - moved > reach + motion && std::all_of(first, last, locally_rigid));
  };
  out.vertex.resize(static_cast<size_t>(s.num_vertices()));
  for (size_t v = 0; v < out.vertex.size(); ++v) {
    const int* cell = &cells.vertex_cell[v];
    out.vertex[v] = searched(clearance.vertex[v], displacement[v], out.motion[v], cell, cell + 1);
  }
  for (int e : bent) {
    const size_t p = static_cast<size_t>(s.edges[static_cast<size_t>(e)][0]);
    const size_t q = static_cast<size_t>(s.edges[static_cast<size_t>(e)][1]);
    const int* cell = cells.edge_cells.data();
    if (searched(clearance.edge[static_cast<size_t>(e)], std::max(displacement[p], displacement[q]),
                 std::max(out.motion[p], out.motion[q]), cell + cells.edge_start[static_cast<size_t>(e)],
                 cell + cells.edge_start[static_cast<size_t>(e) + 1]))
      out.edges.push_back(e);
  }
  return out;
}

// The edges that may be edge-edge candidates (edge_may_contact), ascending.
std::vector<int> bent_edges(const PreparedSurface& s, double margin) {
  std::vector<int> out;
  for (int e = 0; e < s.num_edges(); ++e)
    if (edge_may_contact(s, e, margin)) out.push_back(e);
  return out;
}

// The x0 box of each of `edges`, padded by margin/2 plus its motion, the
// larger of its two vertices': against another surface (`self` null) its
// absolute motion; against its own surface its motion with respect to the
// surface (SelfSearch).
std::vector<Aabb> edge_boxes(const PreparedSurface& s, double margin, const std::vector<int>& edges,
                             const SelfSearch* self) {
  std::vector<Aabb> boxes(edges.size());
  for (size_t k = 0; k < edges.size(); ++k) {
    const size_t e = static_cast<size_t>(edges[k]);
    const Eigen::Vector3d p = s.surface->x0.row(s.edges[e][0]).transpose();
    const Eigen::Vector3d q = s.surface->x0.row(s.edges[e][1]).transpose();
    const double motion = self ? std::max(self->motion[static_cast<size_t>(s.edges[e][0])],
                                          self->motion[static_cast<size_t>(s.edges[e][1])])
                               : s.edge_motion[e];
    const Eigen::Vector3d pad = Eigen::Vector3d::Constant(0.5 * margin + motion);
    boxes[k].min = p.cwiseMin(q) - pad;
    boxes[k].max = p.cwiseMax(q) + pad;
  }
  return boxes;
}

}  // namespace

CollisionDetector::CollisionDetector(CollisionSettings settings)
    : m_settings(settings), m_impl(std::make_unique<Impl>()) {
  RECOIL_CHECK(settings.margin >= 0.0 && std::isfinite(settings.margin), "margin=" << settings.margin);
}

CollisionDetector::~CollisionDetector() = default;

std::vector<ContactCandidate> CollisionDetector::detect(const std::vector<CollisionSurface>& surfaces,
                                                        const std::vector<CollisionPlane>& planes) {
  m_stats = {};
  if (const std::vector<ContactCandidate>* earlier = m_impl->memo.find(surfaces, planes)) {
    m_stats.reused = true;
    return *earlier;
  }
  const double margin = m_settings.margin;
  const int threads = m_settings.num_threads;
  m_impl->update_covered(surfaces, planes, kFeatureSnapShare * margin);
  // Refit (same triangles as last call) or rebuild each surface's scenes.
  std::vector<PreparedSurface> prepared;
  prepared.reserve(surfaces.size());
  std::vector<SelfSearch> searches(surfaces.size());
  std::vector<std::vector<int>> bent(surfaces.size());  // per surface: bent_edges
  m_impl->scenes.resize(surfaces.size());
  for (size_t i = 0; i < surfaces.size(); ++i) {
    Impl::SurfaceScenes& sc = m_impl->scenes[i];
    const CollisionSurface& s = surfaces[i];
    if (s.triangles.rows() == 0) {
      sc = {};
      prepared.push_back(prepare_surface(s, static_cast<int>(i)));
      continue;
    }
    const bool same = sc.faces && sc.triangles.rows() == s.triangles.rows() && sc.triangles == s.triangles &&
                      sc.vertex_faces->start.size() == static_cast<size_t>(s.x0.rows()) + 1;
    if (!same) {
      // Until the new topology is validated the cache matches nothing, so
      // a surface rejected below is not taken for the old one next time.
      sc.faces.reset();
      sc.edges = unique_edges(s.triangles);
      sc.edge_opposite = edge_opposites(s.triangles, sc.edges);
    }
    // Validates the surface before Embree sees it (and before the vertex
    // faces index by its triangles' vertices).
    prepared.push_back(
        prepare_surface(s, static_cast<int>(i), &sc.edges, &sc.edge_opposite, same ? sc.vertex_faces : nullptr));
    if (!m_impl->covered[i].empty()) prepared.back().covered = &m_impl->covered[i];
    if (same) {
      sc.faces->update_vertices(s.x0);
    } else {
      sc.vertex_faces = prepared.back().vertex_faces;
      sc.triangles = s.triangles;
      sc.faces = std::make_unique<TriangleScene>(m_impl->device, s.x0, s.triangles, /*dynamic=*/true);
      sc.edge_boxes = std::make_unique<BoxScene>(m_impl->device);
      sc.self_edge_boxes.reset();
      ++m_stats.rebuilt_surfaces;
    }
    bent[i] = bent_edges(prepared[i], margin);
    sc.edge_boxes->set_boxes(edge_boxes(prepared[i], margin, bent[i], nullptr), {});
    if (self_interacts(prepared[i])) {
      if (!same || sc.rest_shape != s.rest || !sc.clearance) {
        sc.clearance = std::make_unique<RestClearance>(
            rest_clearance(m_impl->device, *s.rest, s.triangles, sc.edges, margin, clearance_reach(margin)));
        sc.cells = std::make_unique<RestCells>(rest_cells(*s.rest, s.triangles, sc.edges, clearance_reach(margin)));
        sc.rest_shape = s.rest;
      }
      searches[i] = self_search(prepared[i], *sc.clearance, *sc.cells, bent[i], margin);
      if (!sc.self_edge_boxes) sc.self_edge_boxes = std::make_unique<BoxScene>(m_impl->device);
      std::vector<std::array<int, 2>> keys;
      for (int e : searches[i].edges) keys.push_back(sc.edges[static_cast<size_t>(e)]);
      sc.self_edge_boxes->set_boxes(edge_boxes(prepared[i], margin, searches[i].edges, &searches[i]),
                                    std::move(keys));
    }
  }

  std::vector<ContactCandidate> out;
  auto vertices_against_triangles = [&](const PreparedSurface& a, const PreparedSurface& b) {
    const TriangleScene* scene = m_impl->scenes[b.index].faces.get();
    if (!scene) return;
    std::vector<long long> counts(static_cast<size_t>(a.num_vertices()), 0);
    parallel_chunks(static_cast<size_t>(a.num_vertices()), threads,
                    [&](size_t begin, size_t end, std::vector<ContactCandidate>& part) {
                      std::vector<int> near;
                      for (size_t v = begin; v < end; ++v) {
                        if (a.index == b.index && !searches[static_cast<size_t>(a.index)].vertex[v]) continue;
                        near.clear();
                        const int vi = static_cast<int>(v);
                        const Eigen::Vector3d p = a.surface->x0.row(vi).transpose();
                        const double radius = a.index == b.index
                                                  ? margin + searches[static_cast<size_t>(a.index)].motion[v] +
                                                        searches[static_cast<size_t>(a.index)].max_motion
                                                  : margin + a.vertex_motion[v] + b.max_motion;
                        // Farther than `radius` from all of B (its box) is never a candidate.
                        const Eigen::Vector3d outside =
                            (b.box0.min - p).cwiseMax(p - b.box0.max).cwiseMax(0.0);
                        if (outside.norm() > radius) continue;
                        scene->triangles_near(p, radius, near);
                        counts[v] = static_cast<long long>(near.size());
                        for (int t : near)
                          if (auto c = test_vertex_triangle(a, vi, b, t, margin)) part.push_back(std::move(*c));
                      }
                    },
                    out);
    for (long long c : counts) {
      m_stats.vertex_triangle_pairs += c;
      if (a.index == b.index) m_stats.self_pairs += c;
    }
  };
  auto edges_against_edges = [&](const PreparedSurface& a, const PreparedSurface& b) {
    const Impl::SurfaceScenes& sa = m_impl->scenes[a.index];
    const Impl::SurfaceScenes& sb = m_impl->scenes[b.index];
    const bool self = a.index == b.index;
    const BoxScene* boxes_a = self ? sa.self_edge_boxes.get() : sa.edge_boxes.get();
    const BoxScene* boxes_b = self ? sb.self_edge_boxes.get() : sb.edge_boxes.get();
    if (!boxes_a || !boxes_b) return;
    // The box scenes hold the bent edges (of those, the searched ones for
    // self), ascending, so a self pair stays (lo, hi) as test_edge_edge requires.
    std::vector<std::pair<int, int>> pairs = boxes_a->overlapping_pairs(*boxes_b);
    const size_t ia = static_cast<size_t>(a.index), ib = static_cast<size_t>(b.index);
    const std::vector<int>& edges_a = self ? searches[ia].edges : bent[ia];
    const std::vector<int>& edges_b = self ? searches[ib].edges : bent[ib];
    for (auto& [e, f] : pairs) {
      e = edges_a[static_cast<size_t>(e)];
      f = edges_b[static_cast<size_t>(f)];
    }
    m_stats.edge_edge_pairs += static_cast<long long>(pairs.size());
    if (self) m_stats.self_pairs += static_cast<long long>(pairs.size());
    parallel_chunks(pairs.size(), threads,
                    [&](size_t begin, size_t end, std::vector<ContactCandidate>& part) {
                      for (size_t k = begin; k < end; ++k)
                        if (auto c = test_edge_edge(a, pairs[k].first, b, pairs[k].second, margin))
                          part.push_back(std::move(*c));
                    },
                    out);
  };

  for (size_t i = 0; i < prepared.size(); ++i) {
    const PreparedSurface& a = prepared[i];
    for (size_t j = i + 1; j < prepared.size(); ++j) {
      const PreparedSurface& b = prepared[j];
      if (!surfaces_interact(a, b) || !boxes_may_interact(a, b, margin)) continue;
      vertices_against_triangles(a, b);
      vertices_against_triangles(b, a);
      edges_against_edges(a, b);
    }
    if (self_interacts(a)) {
      vertices_against_triangles(a, a);
      edges_against_edges(a, a);
    }
    if (interacts_with_planes(a))
      for (size_t k = 0; k < planes.size(); ++k)
        for (int v = 0; v < a.num_vertices(); ++v)
          if (auto c = test_vertex_plane(a, v, planes[k], static_cast<int>(k), margin)) out.push_back(std::move(*c));
  }
  finalize_candidates(out, surfaces);
  m_impl->memo.remember(surfaces, planes, out);
  return out;
}

}  // namespace recoil::sim
