#pragma once
// Contact candidates for one step, accelerated by Embree.
//
// One EmbreeDevice per detector (one detector per World). Per surface it keeps
// a dynamic triangle scene over x0 and a box scene over its edges; both are
// refitted (RTC_BUILD_QUALITY_REFIT) while the surface keeps its triangles,
// rebuilt when they change.
// - vertex-triangle: rtcPointQuery around each vertex with radius
//   margin + d(v) + (largest vertex motion of the other surface), then the
//   exact test and continuous check of narrow_phase.h on each offered triangle;
// - edge-edge: rtcCollide of edge boxes (x0 box inflated by margin/2 + d(e)),
//   then the exact segment test;
// - self-contact: the same two queries over the surface's own primitives,
//   for only those that deformation may have brought within reach of a
//   primitive they may contact (rest_clearance.h);
// - vertex-plane: analytic.
// The rule for what becomes a candidate is in narrow_phase.h; the brute-force
// oracle (brute_force.h) applies the same rule to all pairs. An input equal
// to one of the last two calls' gets their answer again (search_memo.h).
//
// The continuous check (time of impact) is solved exactly in double for every
// pair the distance query offers, with both primitives moving: the query
// radius already covers the whole motion of both sides, so every pair that can
// meet during the step is offered. An Embree ray from x0 to x1 would only see
// the other surface frozen at one instant, so it is not used here.
#include <memory>
#include <vector>

#include "sim/collision/collision_types.h"

namespace recoil::sim {

struct CollisionStats {
  long long vertex_triangle_pairs = 0;  // pairs offered by point queries (exact tests run)
  long long edge_edge_pairs = 0;        // pairs offered by rtcCollide
  long long self_pairs = 0;             // of both, those within one surface
  int rebuilt_surfaces = 0;             // scenes built from scratch this call (others refitted)
  bool reused = false;                  // the input was one of the last two calls': their answer, no query run
};

class CollisionDetector {
 public:
  explicit CollisionDetector(CollisionSettings settings = {});
  ~CollisionDetector();
  CollisionDetector(const CollisionDetector&) = delete;
  CollisionDetector& operator=(const CollisionDetector&) = delete;

  // All candidates for the step x0 -> x1 of every surface, sorted by
  // candidate_less. Surface i of this call is matched with surface i of the
  // previous call for refitting.
  std::vector<ContactCandidate> detect(const std::vector<CollisionSurface>& surfaces,
                                       const std::vector<CollisionPlane>& planes);

  const CollisionStats& last_stats() const { return m_stats; }
  const CollisionSettings& settings() const { return m_settings; }

  struct Impl;

 private:
  CollisionSettings m_settings;
  CollisionStats m_stats;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace recoil::sim
