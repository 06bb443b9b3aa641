#pragma once
// The test oracle: every vertex against every triangle, every edge against
// every edge, every vertex against every plane -- O(n^2), double precision,
// no acceleration structure. Same candidate rule as CollisionDetector
// (narrow_phase.h), so any difference is a broad-phase miss or extra.
// Used by tests and benchmarks only.
#include <vector>

#include "sim/collision/collision_types.h"

namespace recoil::sim {

std::vector<ContactCandidate> brute_force_candidates(const std::vector<CollisionSurface>& surfaces,
                                                     const std::vector<CollisionPlane>& planes,
                                                     const CollisionSettings& settings);

}  // namespace recoil::sim
