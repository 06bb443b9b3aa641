#include "sim/fem/deformable_body.h"

#include <Eigen/Geometry>
#include <cmath>

#include "core/error.h"
#include "sim/collision/embree_scene.h"
#include "sim/fem/vibration_modes.h"
#include "sim/geometry/boundary.h"
#include "sim/geometry/mesh_stats.h"
#include "sim/geometry/tetrahedralize.h"
#include "sim/geometry/winding_solid.h"

namespace recoil::sim {

namespace {

// The boundary of a tet mesh as a compact surface (interior nodes dropped).
TriMesh compact_boundary(const TetMesh& tets) {
  const TriMesh full = boundary_surface(tets);
  Eigen::VectorXi map = Eigen::VectorXi::Constant(full.num_vertices(), -1);
  int next = 0;
  TriMesh out;
  out.triangles.resize(full.num_triangles(), 3);
  for (int f = 0; f < full.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k) {
      int& m = map[full.triangles(f, k)];
      if (m < 0) m = next++;
      out.triangles(f, k) = m;
    }
  out.vertices.resize(next, 3);
  for (int v = 0; v < full.num_vertices(); ++v)
    if (map[v] >= 0) out.vertices.row(map[v]) = full.vertices.row(v);
  return out;
}

}  // namespace

DeformableBody build_deformable_body(const DeformableBodyDesc& desc, EmbreeDevice& device, const std::string& where,
                                     double margin, int threads) {
  validate(desc.material, where + "/material");
  if (!desc.transform.position.allFinite() || !desc.transform.rotation.allFinite() || !desc.velocity.allFinite())
    throw bad_input(where + ": transform and velocity must be finite");
  if (!desc.transform.scale.allFinite() || (desc.transform.scale.array() == 0.0).any())
    throw bad_input(where + "/transform/scale: must be finite and non-zero");
  if (desc.mesh.empty() && desc.tets.empty()) throw bad_input(where + ": needs a surface mesh or tets");

  DeformableBody body;
  body.name = desc.name;
  body.material = desc.material;
  body.lame = lame_parameters(desc.material.youngs_modulus, desc.material.poisson_ratio);

  // Whether the mesh is closed, which a transform does not change.
  const bool watertight = desc.mesh.empty() || compute_mesh_stats(desc.mesh).watertight;
  // Local rest shape, then the initial transform on both tets and surface.
  if (desc.tets.empty()) {
    try {
      body.rest = tetrahedralize(desc.mesh, desc.resolution);
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::bad_input) throw;
      throw bad_input(desc.origin.mesh_field(where) + ": " + e.what());
    }
  } else {
    body.rest = desc.tets;
  }
  body.surface = desc.mesh.empty() ? compact_boundary(body.rest) : desc.mesh;
  const Eigen::Matrix3d R = desc.transform.rotation_matrix();
  transform_in_place(body.rest, R, desc.transform.scale, desc.transform.position);
  transform_in_place(body.surface, R, desc.transform.scale, desc.transform.position);
  for (int t = 0; t < body.rest.num_tets(); ++t)
    if (!(tet_volume(body.rest, t) > 0.0)) throw bad_input(where + ": tetrahedron " + std::to_string(t) + " is degenerate");
  body.num_nodes = body.rest.num_nodes();
  body.elements = element_rest(body.rest);
  // The collision surface: the mesh itself, or a simplified copy of it
  // (then the mesh is kept to draw). Volume and mass come from the mesh.
  // The lattice cell from the tets themselves (they may come from a file):
  // a cube of edge c splits into six tets of c^3 / 6.
  const double cell = std::cbrt(6.0 * total_volume(body.rest) / body.rest.num_tets());
  // By default no surface edge is longer than the longest edge of the body's
  // tets (a lattice cell's diagonal, however the body is scaled): every cell
  // the body may rest on has contact points at its corners. A budget the
  // scene gives is kept as given.
  const bool default_budget = !desc.collision.keep_mesh && desc.collision.max_triangles == 0 && desc.collision.edge_length == 0.0;
  const double longest = default_budget ? std::max(longest_tet_edge(body.rest), 2.0 * margin) : 0.0;
  const CollisionProxy proxy =
      make_collision_proxy(device, body.surface, collision_budget(desc.collision, body.surface, cell, margin), longest);
  if (proxy.separate) {
    body.render_surface = std::move(body.surface);
    body.render_embedding = embed_points(body.rest, body.render_surface.vertices);
    body.surface = proxy.surface;
    body.collision_deviation = proxy.deviation;
  }
  body.embedding = embed_points(body.rest, body.surface.vertices);

  // Lumped masses from the tets, rescaled so the total is density times the
  // volume the surface encloses (the lattice over-covers a curved surface).
  body.mass = Eigen::VectorXd::Zero(body.num_nodes);
  double tet_mass = 0.0;
  for (int t = 0; t < body.rest.num_tets(); ++t) {
    const double m = desc.material.density * body.elements[static_cast<size_t>(t)].volume;
    tet_mass += m;
    for (int k = 0; k < 4; ++k) body.mass[body.rest.tets(t, k)] += 0.25 * m;
  }
  const TriMesh& drawn = body.render_surface.empty() ? body.surface : body.render_surface;
  // A closed surface wound inward encloses minus its volume; the lattice
  // already reads the winding number's magnitude (tetrahedralize.h). An open
  // one's signed volume counts its holes as cones from the centre of its
  // bounds: its solid is where its winding number says inside, and one that
  // encloses nothing weighs its tets.
  body.surface_volume =
      watertight ? std::abs(enclosed_volume(drawn)) : winding_solid(drawn, kWeighingResolution, threads).volume();
  body.encloses_nothing = !(body.surface_volume > 0.0);
  if (body.encloses_nothing) body.surface_volume = tet_mass / desc.material.density;
  body.mass *= desc.material.density * body.surface_volume / tet_mass;

  body.pinned.assign(static_cast<size_t>(body.num_nodes), 0);
  if (desc.pinned) {
    for (int i = 0; i < body.num_nodes; ++i) {
      const Eigen::Vector3d p = body.rest.nodes.row(i).transpose();
      body.pinned[static_cast<size_t>(i)] =
          (p.array() >= desc.pinned->min.array()).all() && (p.array() <= desc.pinned->max.array()).all();
    }
  }
  if (desc.material.damping_ratio > 0.0) {
    const VibrationMode mode = lowest_vibration_mode(
        {&body.rest, &body.elements, desc.material.model, body.lame, &body.mass, &body.pinned});
    body.lowest_frequency = mode.omega;
    if (mode.omega > 0.0) body.damping_beta = 2.0 * desc.material.damping_ratio / mode.omega;
  }
  return body;
}

}  // namespace recoil::sim
