#pragma once
// Shared assertions on candidate lists (header-only; used by several tests).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/collision/collision_types.h"

namespace recoil::sim::testing {

inline std::array<int, 3> count_by_kind(const std::vector<ContactCandidate>& list) {
  std::array<int, 3> count = {0, 0, 0};
  for (const ContactCandidate& c : list) ++count[static_cast<int>(c.kind)];
  return count;
}

// Same set (same order, primitives, vertices) and values within `tol`
// (0: bit-identical). Returns the largest gap difference.
inline double expect_same_candidates(const std::vector<ContactCandidate>& got,
                                     const std::vector<ContactCandidate>& want, double tol) {
  EXPECT_EQ(got.size(), want.size());
  double largest = 0.0;
  size_t shown = 0;
  for (size_t i = 0, j = 0; i < got.size() || j < want.size();) {
    // Walk both sorted lists so that a missing or extra one is named.
    if (j == want.size() || (i < got.size() && candidate_less(got[i], want[j]))) {
      if (shown++ < 5)
        ADD_FAILURE() << "extra candidate kind " << int(got[i].kind) << " surfaces " << got[i].surface_a << ","
                      << got[i].surface_b << " primitives " << got[i].primitive_a << "," << got[i].primitive_b
                      << " gap " << got[i].gap;
      ++i;
      continue;
    }
    if (i == got.size() || candidate_less(want[j], got[i])) {
      if (shown++ < 5)
        ADD_FAILURE() << "missing candidate kind " << int(want[j].kind) << " surfaces " << want[j].surface_a << ","
                      << want[j].surface_b << " primitives " << want[j].primitive_a << "," << want[j].primitive_b
                      << " gap " << want[j].gap;
      ++j;
      continue;
    }
    const ContactCandidate& g = got[i++];
    const ContactCandidate& w = want[j++];
    largest = std::max(largest, std::abs(g.gap - w.gap));
    EXPECT_LE(std::abs(g.gap - w.gap), tol);
    EXPECT_EQ(g.body_a, w.body_a);
    EXPECT_EQ(g.body_b, w.body_b);
    EXPECT_EQ(g.a.count, w.a.count);
    EXPECT_EQ(g.b.count, w.b.count);
    EXPECT_EQ(g.a.vertex, w.a.vertex);
    EXPECT_EQ(g.b.vertex, w.b.vertex);
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(std::abs(g.a.weight[k] - w.a.weight[k]), tol);
      EXPECT_LE(std::abs(g.b.weight[k] - w.b.weight[k]), tol);
    }
    EXPECT_LE((g.normal - w.normal).norm(), tol);
    EXPECT_LE((g.plane_point - w.plane_point).norm(), tol);
    EXPECT_EQ(g.toi.has_value(), w.toi.has_value());
    if (g.toi && w.toi) {
      EXPECT_LE(std::abs(*g.toi - *w.toi), tol);
    }
  }
  return largest;
}

// Every candidate is self-consistent: finite, unit normal, weights summing to
// one, gap = normal.(p - q) from its own weights, toi in [0, 1], and the pair
// really within reach (|gap| <= margin + how far its vertices move).
inline void expect_consistent(const std::vector<ContactCandidate>& list,
                              const std::vector<CollisionSurface>& surfaces,
                              const std::vector<CollisionPlane>& planes, double margin) {
  for (const ContactCandidate& c : list) {
    ASSERT_TRUE(c.normal.allFinite() && std::isfinite(c.gap));
    EXPECT_NEAR(c.normal.norm(), 1.0, 1e-12);
    const CollisionSurface& sa = surfaces[c.surface_a];
    double reach = margin;
    auto motion = [&](const CollisionSurface& s, const SurfacePoint& sp) {
      double m = 0.0;
      for (int i = 0; i < sp.count; ++i) m = std::max(m, (s.x1.row(sp.vertex[i]) - s.x0.row(sp.vertex[i])).norm());
      return m;
    };
    auto weight_sum = [](const SurfacePoint& sp) {
      double w = 0.0;
      for (int i = 0; i < sp.count; ++i) w += sp.weight[i];
      return w;
    };
    EXPECT_NEAR(weight_sum(c.a), 1.0, 1e-12);
    const Eigen::Vector3d p = c.a.evaluate(sa.x0);
    Eigen::Vector3d q;
    if (c.kind == ContactKind::vertex_plane) {
      q = c.plane_point;
      EXPECT_EQ(c.b.count, 0);
      EXPECT_NEAR(planes[c.surface_b].normal.normalized().dot(c.normal), 1.0, 1e-12);
      reach += motion(sa, c.a);
    } else {
      const CollisionSurface& sb = surfaces[c.surface_b];
      EXPECT_NEAR(weight_sum(c.b), 1.0, 1e-12);
      q = c.b.evaluate(sb.x0);
      reach += motion(sa, c.a) + motion(sb, c.b);
    }
    EXPECT_NEAR(c.gap, c.normal.dot(p - q), 1e-12);
    if (c.kind != ContactKind::vertex_plane) {
      EXPECT_LE(std::abs(c.gap), reach + 1e-12);
    }
    if (c.toi) {
      EXPECT_GE(*c.toi, 0.0);
      EXPECT_LE(*c.toi, 1.0);
    }
  }
}

}  // namespace recoil::sim::testing
