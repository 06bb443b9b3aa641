#pragma once
// How far a self-contact surface departs from a rigid motion near each
// point: the local half of the self-contact broad phase's bound
// (rest_clearance.h bounds it with one rigid fit of the whole surface).
//
// A pair of one surface whose rest distance d lies in (margin, reach] (reach:
// clearance_reach) is a candidate only if its distance at x0 comes within
// min(margin, d - margin) plus its relative motion over the step
// (narrow_phase.h). Take any rigid motion (R, t) and any shift T: the
// distance at x0 is at least d - u_a - u_b, u = |x0 - (R X + t)|, and the
// relative motion at most e_a + e_b, e = |(x1 - x0) - T|. With D and E the
// largest u and e over the vertices of every primitive the pair can involve,
// no such pair is a candidate once 2 (D + E) < margin: for d <= 2 margin the
// pair would need d - 2D <= d - margin + 2E, for larger d, d - 2D <= margin + 2E.
// A body that only bends smoothly (a sagging, wobbling soft engine) is far
// closer to rigid over a few clearance reaches (3 cm at the default margin)
// than over its whole length, so fitting (R, t) and T per neighbourhood
// prunes what the global fit cannot.
//
// Neighbourhoods are the cells of a cubic grid over the rest shape, of side
// 2 `reach` (reach = clearance_reach, the largest rest distance the clearances
// tell apart). A vertex belongs to the cell it lies in; an edge to the cells
// of points spaced at most `reach` along it, ends included, so each of its
// points lies within reach/2 of one of them. A cell lists its own vertices
// and those of every triangle whose rest box comes within 1.5 reach of it
// along each axis: that holds every primitive within `reach` of a vertex in
// the cell, or within reach of an edge point that lies within reach/2 of a
// sample point in the cell, and that vertex or edge itself.
// A primitive with a cell of -1 is never excused locally: so are all when
// reach is not positive or the grid would be too large to number.
#include <array>
#include <vector>

#include "sim/geometry/tri_mesh.h"

namespace recoil::sim {

struct RestCells {
  double reach = 0.0;              // m, clearance_reach (a cell's side is twice this)
  std::vector<int> vertex_cell;    // #V: the cell (index below) holding each vertex at rest, or -1
  std::vector<int> edge_start;     // #E + 1: edge e's cells are edge_cells[edge_start[e], edge_start[e + 1])
  std::vector<int> edge_cells;
  std::vector<int> near_start;     // #cells + 1: cell c's list is near_vertices[near_start[c], near_start[c + 1])
  std::vector<int> near_vertices;  // ascending per cell
  int num_cells() const { return static_cast<int>(near_start.size()) - 1; }
};

// Built once per rest shape (#V by 3), its triangles and their unique edges
// (unique_edges); reach in m.
RestCells rest_cells(const Points& rest, const Triangles& triangles, const std::vector<std::array<int, 2>>& edges,
                     double reach);

// D + E above (m) per cell for the step x0 -> x1 (#V by 3 each, with the
// rest shape the cells were built from): the largest residual of the
// least-squares rigid fit of the cell's listed vertices from rest to x0, plus
// the largest deviation of their step motion from its mean. Each cell is
// computed when first asked for: a search that the global bound already
// prunes pays nothing.
class LocalDeformation {
 public:
  LocalDeformation(const RestCells& cells, const Points& rest, const Points& x0, const Points& x1);
  double operator()(int cell);

 private:
  const RestCells& m_cells;
  const Points &m_rest, &m_x0, &m_x1;
  std::vector<double> m_known;  // per cell, negative until computed
  Points m_from, m_to;          // scratch
};

}  // namespace recoil::sim
