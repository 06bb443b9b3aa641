#pragma once
// Lattice tetrahedralization of a triangle surface, closed or not: a cubic grid with `resolution` cells along the
// surface's longest side; every cell that is inside the surface or crossed by
// it is kept and split into six tets around a diagonal (the Freudenthal /
// Kuhn split), mirrored from cell to cell so that the lattice has no preferred
// direction: a body of an even number of cells a side is symmetric.
// A cell is inside when the surface's generalized winding number at its centre
// exceeds 1/2 in magnitude (sim/geometry/winding_number.h): holes, flipped
// patches and overlapping shells shift it smoothly instead of flipping it, and
// the magnitude keeps a wholly inward-wound surface solid.
#include "sim/geometry/tet_mesh.h"

namespace recoil::sim {

class EmbreeDevice;

// The cubic grid the lattice (and the weighing of an open solid,
// winding_solid.h) lays over a surface's bounds: cells of side `cell`,
// `resolution` of them along the longest side and at least one along each
// axis, centred on the bounds.
struct CubicGrid {
  double cell = 0.0;                                 // m
  Eigen::Vector3i cells = Eigen::Vector3i::Ones();   // along x, y, z
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // m, the outer corner of cell (0, 0, 0)
  Eigen::Vector3d center(int i, int j, int k) const { return origin + cell * Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5); }
};
// box: non-empty, longest side > 0.
CubicGrid cubic_grid(const Aabb& box, int resolution);

struct TetrahedralizeStats {
  int cells_crossing = 0;  // cells a surface triangle overlaps
  int cells_inside = 0;    // cells whose centre is inside (and not crossing)
  double cell_size = 0.0;  // metres
};

// surface: #V by 3 / #F by 3, outward-wound. Throws bad_input when the surface
// is empty or flat, or resolution is outside [1, 512]. Nodes are numbered in
// grid order (x fastest), tets in cell order; all tets positively oriented.
// Deterministic: the same surface and resolution give the same bytes.
TetMesh tetrahedralize(const TriMesh& surface, int resolution, TetrahedralizeStats* stats = nullptr);

// Lattice cells along the longest side when a scene does not say.
inline constexpr int kDefaultResolution = 8;

// The same; the device is no longer used (the inside test needs no rays) and
// stays only so existing callers build unchanged.
inline TetMesh tetrahedralize(EmbreeDevice& /*device*/, const TriMesh& surface, int resolution,
                              TetrahedralizeStats* stats = nullptr) {
  return tetrahedralize(surface, resolution, stats);
}

// The inside test alone: |winding number| > 1/2.
bool inside_by_winding_number(double winding_number);

// Separating-axis test of a triangle against an axis-aligned box.
bool triangle_overlaps_box(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                           const Eigen::Vector3d& box_center, const Eigen::Vector3d& half_extent);

}  // namespace recoil::sim
