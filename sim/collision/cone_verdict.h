#pragma once
// The feature-cone rule of narrow_phase.h for a vertex-triangle pair
// between two different closed surfaces (feature_cone.h says why cones).
#include "sim/collision/narrow_phase.h"

namespace recoil::sim {

// What the features' cones say of a vertex-triangle candidate between two
// different closed surfaces (feature_cone.h): its normal and gap set, no contact, or
// nothing where every triangle round a feature is degenerate.
enum class ConeVerdict { contact, no_contact, undecided };

// Judged where the pair is: at the impact, else at the start. `exact` is the
// true closest point on the triangle (at the impact, if any), `sep0` = p - q
// at the start and `rel` the relative motion over the step.
ConeVerdict judge_by_feature_cones(const PreparedSurface& a, int vertex, const PreparedSurface& b, int triangle,
                                   const SurfacePoint& exact, const Eigen::Vector3d& sep0, const Eigen::Vector3d& rel,
                                   double margin, double tol, ContactCandidate& c);

}  // namespace recoil::sim
