#include "sim/collision/candidate_reduction.h"

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace recoil::sim {
namespace {

using Side = std::pair<int, int>;  // (surface, vertex)
using VertexPair = std::pair<Side, Side>;

double toi_or_never(const ContactCandidate& c) { return c.toi.value_or(2.0); }

// The order in which one vertex's candidates are considered: the earliest
// impact, then the smallest gap, then the lowest triangle id.
bool stronger(const ContactCandidate& l, const ContactCandidate& r) {
  return std::make_tuple(toi_or_never(l), l.gap, l.primitive_b) < std::make_tuple(toi_or_never(r), r.gap, r.primitive_b);
}

// The vertex a closest point sits at (all its weight there), or none.
std::optional<int> at_vertex(const SurfacePoint& p) {
  for (int i = 0; i < p.count; ++i)
    if (p.weight[i] == 1.0) return p.vertex[i];
  return std::nullopt;
}

// A vertex-triangle candidate's two vertices, ordered, when its closest
// point on B sits at a vertex. `flipped`: side A is the second of the pair,
// so the normal as seen from the first is -normal.
std::optional<VertexPair> vertex_pair(const ContactCandidate& c, bool& flipped) {
  if (c.kind != ContactKind::vertex_triangle) return std::nullopt;
  const std::optional<int> w = at_vertex(c.b);
  if (!w) return std::nullopt;
  const Side mine{c.surface_a, c.primitive_a}, theirs{c.surface_b, *w};
  flipped = theirs < mine;
  return flipped ? VertexPair{theirs, mine} : VertexPair{mine, theirs};
}

auto vertex_group(const ContactCandidate& c) { return std::make_tuple(c.surface_a, c.primitive_a, c.surface_b); }

// Where one vertex's candidates against one surface start and end in a list
// sorted by vertex_group: [begin, end) of the group starting at `begin`.
size_t vertex_group_end(const std::vector<ContactCandidate>& sorted, size_t begin) {
  size_t end = begin + 1;
  while (end < sorted.size() && vertex_group(sorted[end]) == vertex_group(sorted[begin])) ++end;
  return end;
}

// One vertex of A against one touched feature of surface B.
auto feature_group(const ContactCandidate& c) { return std::make_tuple(vertex_group(c), c.b.touched_feature()); }

// The order both per-vertex rules read: by (surface A, vertex, surface B),
// then touched feature, then strength.
void sort_by_vertex_and_feature(std::vector<ContactCandidate>& vertex_triangle) {
  // Each candidate's group is computed once, not at every comparison.
  using Group = decltype(feature_group(std::declval<const ContactCandidate&>()));
  std::vector<std::pair<Group, size_t>> order;
  order.reserve(vertex_triangle.size());
  for (size_t i = 0; i < vertex_triangle.size(); ++i) order.emplace_back(feature_group(vertex_triangle[i]), i);
  std::sort(order.begin(), order.end(), [&](const auto& l, const auto& r) {
    if (l.first != r.first) return l.first < r.first;
    return stronger(vertex_triangle[l.second], vertex_triangle[r.second]);
  });
  std::vector<ContactCandidate> sorted;
  sorted.reserve(vertex_triangle.size());
  for (const auto& entry : order) sorted.push_back(std::move(vertex_triangle[entry.second]));
  vertex_triangle.swap(sorted);
}

// Whether triangle point `b` (a candidate's closest point on its triangle)
// belongs to a triangle containing every vertex of `feature`.
bool triangle_contains(const SurfacePoint& b, const std::array<int, 3>& feature) {
  for (int v : feature) {
    if (v < 0) break;
    if (std::find(b.vertex.begin(), b.vertex.begin() + b.count, v) == b.vertex.begin() + b.count) return false;
  }
  return true;
}

// Rule 0 (candidate_reduction.h): against a prescribed surface, a candidate
// whose closest point is an edge or vertex of its triangle is dropped when a
// triangle sharing that feature is strictly closer to the same vertex (and
// met no later). Input sorted by sort_by_vertex_and_feature; the order is kept.
std::vector<ContactCandidate> drop_points_beyond_a_closer_face(std::vector<ContactCandidate> sorted,
                                                               const std::vector<CollisionSurface>& surfaces) {
  auto dominates = [](const ContactCandidate& closer, const ContactCandidate& c) {
    return toi_or_never(closer) <= toi_or_never(c) && closer.gap < c.gap - kCloserFaceTolerance;
  };
  std::vector<char> keep(sorted.size(), 1);
  std::vector<std::array<int, 3>> features;  // of the current group
  for (size_t begin = 0, end = 0; begin < sorted.size(); begin = end) {
    end = vertex_group_end(sorted, begin);
    if (!is_prescribed(surfaces[static_cast<size_t>(sorted[begin].surface_b)].kind)) continue;
    features.clear();
    for (size_t i = begin; i < end; ++i) features.push_back(sorted[i].b.touched_feature());
    for (size_t i = begin; i < end; ++i) {
      const std::array<int, 3>& feature = features[i - begin];
      if (feature[2] >= 0) continue;  // the triangle's interior: a face's own normal
      for (size_t j = begin; j < end && keep[i]; ++j)
        if (features[j - begin] != feature && triangle_contains(sorted[j].b, feature) && dominates(sorted[j], sorted[i]))
          keep[i] = 0;
    }
  }
  std::vector<ContactCandidate> out;
  for (size_t i = 0; i < sorted.size(); ++i)
    if (keep[i]) out.push_back(std::move(sorted[i]));
  return out;
}

// Rule 1 (candidate_reduction.h): per (surface A, vertex, surface B, touched
// feature of B), the strongest candidate and those whose normals point
// elsewhere. Input sorted by sort_by_vertex_and_feature.
std::vector<ContactCandidate> one_per_feature(std::vector<ContactCandidate> sorted) {
  std::vector<ContactCandidate> kept;
  size_t group_start = 0;  // first kept candidate of the current group
  for (size_t i = 0; i < sorted.size(); ++i) {
    ContactCandidate& c = sorted[i];
    if (i == 0 || feature_group(c) != feature_group(sorted[i - 1])) group_start = kept.size();
    const bool distinct =
        std::all_of(kept.begin() + static_cast<std::ptrdiff_t>(group_start), kept.end(),
                    [&](const ContactCandidate& k) { return k.normal.dot(c.normal) < kDistinctNormalCos; });
    if (distinct) kept.push_back(std::move(c));
  }
  return kept;
}

// Rule 2: a pair of vertices found from both sides is kept once. Rule 1 may
// keep a vertex's candidates in several directions, so each is compared
// with every kept candidate of its pair.
std::vector<ContactCandidate> one_per_vertex_pair(std::vector<ContactCandidate> candidates) {
  std::map<VertexPair, std::vector<size_t>> seen;  // vertex pair -> indices of its kept candidates
  std::vector<char> keep(candidates.size(), 1);
  for (size_t i = 0; i < candidates.size(); ++i) {
    const ContactCandidate& c = candidates[i];
    bool flipped = false;
    const std::optional<VertexPair> pair = vertex_pair(c, flipped);
    if (!pair) continue;
    std::vector<size_t>& kept = seen[*pair];
    // The same constraint seen from the other side has the opposite normal;
    // a pair meeting at an angle stays two contacts.
    const auto same = std::find_if(kept.begin(), kept.end(), [&](size_t j) {
      return -candidates[j].normal.dot(c.normal) >= kDistinctNormalCos;
    });
    if (same == kept.end()) {
      kept.push_back(i);
      continue;
    }
    // Inputs arrive sorted by (surface A, vertex): on equal impact times the
    // earlier one, with the smaller side A, wins.
    if (toi_or_never(c) < toi_or_never(candidates[*same])) {
      keep[*same] = 0;
      *same = i;
    } else {
      keep[i] = 0;
    }
  }
  std::vector<ContactCandidate> out;
  for (size_t i = 0; i < candidates.size(); ++i)
    if (keep[i]) out.push_back(std::move(candidates[i]));
  return out;
}

}  // namespace

void finalize_candidates(std::vector<ContactCandidate>& candidates, const std::vector<CollisionSurface>& surfaces) {
  std::vector<ContactCandidate> others, vertex_triangle;
  for (ContactCandidate& c : candidates)
    (c.kind == ContactKind::vertex_triangle ? vertex_triangle : others).push_back(std::move(c));
  candidates = std::move(others);
  sort_by_vertex_and_feature(vertex_triangle);
  for (ContactCandidate& c :
       one_per_vertex_pair(one_per_feature(drop_points_beyond_a_closer_face(std::move(vertex_triangle), surfaces))))
    candidates.push_back(std::move(c));
  std::sort(candidates.begin(), candidates.end(), candidate_less);
}

std::vector<char> already_known(const std::vector<ContactCandidate>& known, const std::vector<ContactCandidate>& found) {
  std::set<CandidateKey> primitives;
  std::multimap<std::tuple<int, int, int>, Eigen::Vector3d> vertex_normals;  // (surface A, vertex, surface B)
  std::multimap<VertexPair, Eigen::Vector3d> pair_normals;  // normal as seen from the pair's first side
  for (const ContactCandidate& c : known) {
    primitives.insert(candidate_key(c));
    if (c.kind != ContactKind::vertex_triangle) continue;
    vertex_normals.emplace(vertex_group(c), c.normal);
    bool flipped = false;
    if (const auto pair = vertex_pair(c, flipped)) pair_normals.emplace(*pair, flipped ? -c.normal : c.normal);
  }
  auto similar = [](const auto& range, const Eigen::Vector3d& normal) {
    for (auto it = range.first; it != range.second; ++it)
      if (it->second.dot(normal) >= kDistinctNormalCos) return true;
    return false;
  };
  std::vector<char> out(found.size(), 0);
  for (size_t i = 0; i < found.size(); ++i) {
    const ContactCandidate& c = found[i];
    bool flipped = false;
    const std::optional<VertexPair> pair = vertex_pair(c, flipped);
    out[i] = primitives.count(candidate_key(c)) > 0 ||
             (c.kind == ContactKind::vertex_triangle && similar(vertex_normals.equal_range(vertex_group(c)), c.normal)) ||
             (pair && similar(pair_normals.equal_range(*pair), flipped ? Eigen::Vector3d(-c.normal) : c.normal));
  }
  return out;
}

}  // namespace recoil::sim
