#pragma once
// Lattice tetrahedralization of a closed (or nearly closed) triangle surface
// (METHOD.md section 7): a cubic grid with `resolution` cells along the
// surface's longest side; every cell that is inside the surface or crossed by
// it is kept and split into six tets around its main diagonal (Freudenthal /
// Kuhn split: neighbouring cells share faces without alternating patterns).
// The inside test is a majority vote of ray parities through Embree, so small
// holes or a ray grazing an edge flip at most a minority of the votes.
#include "sim/collision/embree_scene.h"
#include "sim/geometry/tet_mesh.h"

namespace recoil::sim {

struct TetrahedralizeStats {
  int cells_crossing = 0;  // cells a surface triangle overlaps
  int cells_inside = 0;    // cells whose centre voted inside (and not crossing)
  double cell_size = 0.0;  // metres
};

// surface: #V by 3 / #F by 3, outward-wound. Throws bad_input when the surface
// is empty or flat, or resolution is outside [1, 512]. Nodes are numbered in
// grid order (x fastest), tets in cell order; all tets positively oriented.
TetMesh tetrahedralize(EmbreeDevice& device, const TriMesh& surface, int resolution,
                       TetrahedralizeStats* stats = nullptr);

// The inside test alone: majority vote over a fixed set of ray directions of
// the parity of Embree hits from `point`. Exposed for tests.
bool inside_by_rays(const TriangleScene& scene, const Eigen::Vector3d& point);

// Separating-axis test of a triangle against an axis-aligned box.
bool triangle_overlaps_box(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                           const Eigen::Vector3d& box_center, const Eigen::Vector3d& half_extent);

}  // namespace recoil::sim
