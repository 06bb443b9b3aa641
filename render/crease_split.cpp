#include "render/crease_split.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <utility>

namespace recoil::render {
namespace {

// Union-find over face corners (corner c = 3 * face + k).
class Corners {
 public:
  explicit Corners(size_t count) : m_parent(count) { std::iota(m_parent.begin(), m_parent.end(), 0u); }
  std::uint32_t root(std::uint32_t c) {
    while (m_parent[c] != c) {
      m_parent[c] = m_parent[m_parent[c]];  // path halving
      c = m_parent[c];
    }
    return c;
  }
  // The smaller root wins, so the result does not depend on the union order.
  void join(std::uint32_t a, std::uint32_t b) {
    a = root(a);
    b = root(b);
    if (a != b) m_parent[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::uint32_t> m_parent;
};

}  // namespace

CreaseSplit split_creases(std::span<const float> positions, std::span<const std::uint32_t> indices,
                          double crease_degrees, std::span<const float> corner_keys, size_t key_stride) {
  auto same_key = [&](std::uint32_t a, std::uint32_t b) {
    if (key_stride == 0) return true;
    return std::equal(corner_keys.begin() + a * key_stride, corner_keys.begin() + (a + 1) * key_stride,
                      corner_keys.begin() + b * key_stride);
  };
  const size_t faces = indices.size() / 3;
  std::vector<Eigen::Vector3f> normal(faces, Eigen::Vector3f::Zero());
  for (size_t f = 0; f < faces; ++f) {
    auto p = [&](size_t k) { return Eigen::Vector3f(positions.subspan(3 * size_t{indices[3 * f + k]}, 3).data()); };
    const Eigen::Vector3f n = (p(1) - p(0)).cross(p(2) - p(0));
    const float length = n.norm();
    if (length > 0.0f && std::isfinite(length)) normal[f] = n / length;
  }

  // Undirected edges with the corner of each end in the face that has them.
  struct EdgeUse {
    std::uint64_t key;  // (min vertex) << 32 | (max vertex)
    std::uint32_t corner_lo, corner_hi;  // corners at the min and max vertex
  };
  std::vector<EdgeUse> uses;
  uses.reserve(3 * faces);
  for (size_t f = 0; f < faces; ++f) {
    for (size_t k = 0; k < 3; ++k) {
      const auto ca = static_cast<std::uint32_t>(3 * f + k), cb = static_cast<std::uint32_t>(3 * f + (k + 1) % 3);
      std::uint64_t a = indices[ca], b = indices[cb];
      if (a == b) continue;
      const bool swapped = a > b;
      if (swapped) std::swap(a, b);
      uses.push_back({(a << 32) | b, swapped ? cb : ca, swapped ? ca : cb});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.key != y.key ? x.key < y.key : x.corner_lo < y.corner_lo;
  });

  // Join the corners across every manifold edge that is not a crease. A
  // degenerate face (zero normal) is smooth with its neighbours.
  const float cos_crease = static_cast<float>(std::cos(crease_degrees * std::numbers::pi / 180.0));
  Corners corners(indices.size() - indices.size() % 3);
  // Whether a face runs along its edge from the min to the max vertex.
  auto forward = [](const EdgeUse& use) { return use.corner_hi == 3 * (use.corner_lo / 3) + (use.corner_lo % 3 + 1) % 3; };
  bool closed = faces > 0 && uses.size() == 3 * faces;  // no degenerate edges
  for (size_t i = 0; i < uses.size();) {
    size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    closed = closed && j - i == 2 && forward(uses[i]) != forward(uses[i + 1]);
    if (j - i == 2) {
      const Eigen::Vector3f& n1 = normal[uses[i].corner_lo / 3];
      const Eigen::Vector3f& n2 = normal[uses[i + 1].corner_lo / 3];
      const bool degenerate = n1.isZero() || n2.isZero();
      if (degenerate || n1.dot(n2) >= cos_crease) {
        if (same_key(uses[i].corner_lo, uses[i + 1].corner_lo)) corners.join(uses[i].corner_lo, uses[i + 1].corner_lo);
        if (same_key(uses[i].corner_hi, uses[i + 1].corner_hi)) corners.join(uses[i].corner_hi, uses[i + 1].corner_hi);
      }
    }
    i = j;
  }

  // One render vertex per group of joined corners, numbered by first corner;
  // the first group of each input vertex keeps that vertex's number so an
  // unsplit mesh maps onto itself.
  const size_t vertex_count = positions.size() / 3;
  CreaseSplit split;
  split.closed = closed;
  split.source.resize(vertex_count);
  std::iota(split.source.begin(), split.source.end(), 0u);
  std::vector<std::uint32_t> first_root(vertex_count, UINT32_MAX);
  std::vector<std::uint32_t> render_of_root(indices.size(), UINT32_MAX);
  split.indices.resize(indices.size() - indices.size() % 3);
  for (std::uint32_t c = 0; c < split.indices.size(); ++c) {
    const std::uint32_t r = corners.root(c);
    if (render_of_root[r] == UINT32_MAX) {
      const std::uint32_t v = indices[c];
      if (first_root[v] == UINT32_MAX) {
        first_root[v] = r;
        render_of_root[r] = v;
      } else {
        render_of_root[r] = static_cast<std::uint32_t>(split.source.size());
        split.source.push_back(v);
        split.identity = false;
      }
    }
    split.indices[c] = render_of_root[r];
  }
  return split;
}

}  // namespace recoil::render
