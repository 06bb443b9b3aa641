#pragma once
// The direction of a vertex-triangle contact between two closed surfaces,
// from the normal cones of the features that meet rather than from p - q
// alone.
//
// A vertex p of surface A and the feature of surface B nearest it (a face,
// an edge or a vertex of the triangle) are closest to each other along d =
// p - q only if d lies in B's normal cone at the feature (spanned by the unit
// normals of B's faces around it) and -d in A's cone at p.
// - d is the normal whenever it lies in both cones (to rounding).
// - Else the contact takes the face normal nearest d (one of B's, or one of
//   A's reversed) that lies in B's cone and that A's surface faces: -n within
//   45 degrees of A's cone, halfway between a surface turned to the feature
//   and one sliding past it, which leaves room for A's faces to have bent
//   against B's. This is what keeps faces resting exactly on faces: the
//   solve leaves their coincident vertices 1e-10 to 1e-9 m apart in random
//   directions, so d means nothing there, while the shared face normal
//   qualifies. Since q lies on the plane of every face around its feature,
//   the gap along a face normal of B is p's height over that face.
// - A pair with no qualifying direction is not a contact: the surfaces meet
//   at a neighbouring pair.
// At an impact found by the continuous check p touches the feature, and d
// (within rounding of zero) the side it meets it from. A vertex whose surface
// faces none of the feature's faces meets B only after other parts of A have
// crossed (a body passing through a thin plate in one step); it is held
// against the face it started more than a margin in front of, if there is
// one.
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace recoil::sim {

// Largest cosine between unit x and a direction of the cone spanned by the
// unit vectors `generators` (1 inside; -1 for an empty set). The cost grows
// with the cube of their number: give each direction once
// (distinct_directions).
double cone_cosine(const Eigen::Vector3d& x, const std::vector<Eigen::Vector3d>& generators);

// `directions` with repeats (to rounding) left out, in their first order,
// into `distinct` (cleared first, so not `directions` itself): the triangles
// of one flat face give one generator.
void distinct_directions(const std::vector<Eigen::Vector3d>& directions, std::vector<Eigen::Vector3d>& distinct);

// The chosen normal (unit, from B to A) and where it came from: -1 for d,
// i < #cone_b for B's face normal i, #cone_b + j for A's face normal j reversed.
struct ConeNormal {
  Eigen::Vector3d normal;
  int source = -1;
};

// The rule above for direction `d` (p - q, any length, may be zero),
// B's outward unit face normals around the feature and A's around the vertex
// (distinct_directions of each);
// `aim` (unit or zero: the reversed relative motion) breaks ties when d is
// zero. None when no direction qualifies.
std::optional<ConeNormal> feature_cone_normal(const Eigen::Vector3d& d, const Eigen::Vector3d& aim,
                                              const std::vector<Eigen::Vector3d>& cone_b,
                                              const std::vector<Eigen::Vector3d>& cone_a);

// For an impact with no qualifying direction: the face normal of B that p
// started more than `margin` in front of (`start` = p - q at the start of the
// step), the one nearest `aim`; none when p started nearer than that.
std::optional<ConeNormal> impact_cone_normal(const Eigen::Vector3d& aim, const std::vector<Eigen::Vector3d>& cone_b,
                                             const Eigen::Vector3d& start, double margin);

}  // namespace recoil::sim
