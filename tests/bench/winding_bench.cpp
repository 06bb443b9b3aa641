// Cost of the tetrahedralizer's inside test: the generalized winding number
// through its tree (what tetrahedralize uses), summed exactly over every
// triangle, and the five-ray parity vote through Embree it replaced, at every
// lattice cell centre of the bunny, a 59k-triangle bunny, a 50k-triangle
// torus, and meshes with holes or overlapping shells; plus the whole
// tetrahedralization.
#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>

#include "sim/collision/embree_scene.h"
#include "sim/geometry/mesh_import.h"
#include "sim/geometry/primitives.h"
#include "sim/geometry/tetrahedralize.h"
#include "sim/geometry/winding_number.h"
#include "tests/bench/bench.h"

namespace recoil::bench {
namespace {

// Every triangle into four through its edge midpoints (shared per edge, so
// the surface stays closed): the same shape with four times the triangles.
sim::TriMesh split_at_midpoints(const sim::TriMesh& mesh) {
  std::map<std::pair<int, int>, int> midpoint;
  std::vector<Eigen::Vector3d> vertices;
  for (int v = 0; v < mesh.num_vertices(); ++v) vertices.push_back(mesh.vertices.row(v).transpose());
  auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto [it, added] = midpoint.emplace(key, static_cast<int>(vertices.size()));
    if (added) vertices.push_back(0.5 * (vertices[static_cast<size_t>(a)] + vertices[static_cast<size_t>(b)]));
    return it->second;
  };
  sim::TriMesh out;
  out.triangles.resize(4 * mesh.num_triangles(), 3);
  for (int f = 0; f < mesh.num_triangles(); ++f) {
    const int a = mesh.triangles(f, 0), b = mesh.triangles(f, 1), c = mesh.triangles(f, 2);
    const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    out.triangles.row(4 * f) << a, ab, ca;
    out.triangles.row(4 * f + 1) << ab, b, bc;
    out.triangles.row(4 * f + 2) << ca, bc, c;
    out.triangles.row(4 * f + 3) << ab, bc, ca;
  }
  out.vertices.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (size_t v = 0; v < vertices.size(); ++v) out.vertices.row(static_cast<Eigen::Index>(v)) = vertices[v].transpose();
  return out;
}

// The lattice cell centres tetrahedralize sees at `resolution` (all of them;
// it queries only those no triangle crosses).
std::vector<Eigen::Vector3d> lattice_centres(const sim::TriMesh& mesh, int resolution) {
  const sim::Aabb box = sim::bounding_box(mesh);
  const double h = box.extent().maxCoeff() / resolution;
  Eigen::Vector3i n;
  for (int a = 0; a < 3; ++a) n[a] = std::max(1, static_cast<int>(std::ceil(box.extent()[a] / h - 1e-9)));
  const Eigen::Vector3d origin = box.center() - 0.5 * h * n.cast<double>();
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) out.push_back(origin + h * Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5));
  return out;
}

// The inside test before the winding number: parity of Embree hits along
// five fixed directions, majority vote.
bool ray_vote_inside(const sim::TriangleScene& scene, const Eigen::Vector3d& p) {
  static const std::array<Eigen::Vector3d, 5> dirs = {
      Eigen::Vector3d(0.5362, 0.7213, 0.4385).normalized(),  Eigen::Vector3d(-0.6231, 0.2517, 0.7405).normalized(),
      Eigen::Vector3d(0.3114, -0.8427, 0.4392).normalized(), Eigen::Vector3d(-0.4471, -0.3119, -0.8386).normalized(),
      Eigen::Vector3d(0.8817, 0.1733, -0.4389).normalized()};
  int votes = 0;
  for (const Eigen::Vector3d& d : dirs) votes += scene.all_hits(p, d).size() % 2 == 1;
  return 2 * votes > 5;
}

// Every 50th triangle removed (74 of the bunny's): holes as a scan has them.
sim::TriMesh with_holes(const sim::TriMesh& mesh) {
  sim::TriMesh out;
  out.vertices = mesh.vertices;
  out.triangles.resize(mesh.num_triangles() - (mesh.num_triangles() + 49) / 50, 3);
  int next = 0;
  for (int f = 0; f < mesh.num_triangles(); ++f)
    if (f % 50 != 0) out.triangles.row(next++) = mesh.triangles.row(f);
  return out;
}

// A 0.2 m box with its top face left out: one hole as large as a face.
sim::TriMesh open_box() {
  const sim::TriMesh box = sim::make_box(Eigen::Vector3d::Constant(0.2), 8);
  sim::TriMesh out;
  out.vertices = box.vertices;
  out.triangles.resize(box.num_triangles(), 3);
  int next = 0;
  for (int f = 0; f < box.num_triangles(); ++f) {
    double y = 0.0;
    for (int k = 0; k < 3; ++k) y += box.vertices(box.triangles(f, k), 1) / 3.0;
    if (y < 0.1 - 1e-12) out.triangles.row(next++) = box.triangles.row(f);
  }
  out.triangles.conservativeResize(next, 3);
  return out;
}

// Two spheres overlapping by half a radius, as two separate shells: in the
// overlap a ray crosses both, so its parity says outside.
sim::TriMesh overlapping_spheres() {
  sim::TriMesh a = sim::make_sphere(0.5, 4), b = sim::make_sphere(0.5, 4);
  b.vertices.col(0).array() += 0.75;
  sim::append(a, b);
  return a;
}

void bench_winding_number() {
  const sim::TriMesh bunny = sim::import_surface(std::string(RECOIL_SOURCE_DIR) + "/assets/meshes/bunny.obj");
  const std::vector<std::pair<std::string, sim::TriMesh>> meshes = {
      {"bunny", bunny},
      {"bunny split twice", split_at_midpoints(split_at_midpoints(bunny))},
      {"torus 250 x 100", sim::make_torus(0.5, 0.2, 250, 100)},
      {"bunny, every 50th triangle gone", with_holes(bunny)},
      {"box, top face gone", open_box()},
      {"two overlapping spheres", overlapping_spheres()}};
  BenchTable table("tetrahedralizer inside test at every lattice cell centre (one thread)",
                   {"mesh", "triangles", "resolution", "centres", "tree build ms", "tree ms", "exact ms", "ray vote ms",
                    "worst |tree - exact|", "tree/exact sides differ", "rays/tree sides differ", "tetrahedralize ms",
                    "tets"});
  sim::EmbreeDevice device;
  for (const auto& [name, mesh] : meshes) {
    const sim::TriangleScene scene(device, mesh.vertices, mesh.triangles, false);
    for (int resolution : {8, 16, 32, 64}) {
      const std::vector<Eigen::Vector3d> centres = lattice_centres(mesh, resolution);
      std::unique_ptr<sim::WindingNumberTree> tree;
      const double build_ms = best_ms(3, [&] { tree = std::make_unique<sim::WindingNumberTree>(mesh); });
      std::vector<double> fast(centres.size()), exact(centres.size());
      std::vector<char> rays(centres.size());
      const double tree_ms = best_ms(1, [&] {
        for (size_t i = 0; i < centres.size(); ++i) fast[i] = (*tree)(centres[i]);
      });
      const double ray_ms = best_ms(1, [&] {
        for (size_t i = 0; i < centres.size(); ++i) rays[i] = ray_vote_inside(scene, centres[i]);
      });
      // The exact sum only where it finishes in seconds.
      const bool do_exact = static_cast<double>(mesh.num_triangles()) * static_cast<double>(centres.size()) < 1.5e9;
      double exact_ms = 0.0, worst = 0.0;
      int differ = 0, ray_differ = 0;
      if (do_exact) {
        exact_ms = best_ms(1, [&] {
          for (size_t i = 0; i < centres.size(); ++i) exact[i] = sim::winding_number(mesh, centres[i]);
        });
        for (size_t i = 0; i < centres.size(); ++i) {
          worst = std::max(worst, std::abs(fast[i] - exact[i]));
          differ += sim::inside_by_winding_number(fast[i]) != sim::inside_by_winding_number(exact[i]);
        }
      }
      for (size_t i = 0; i < centres.size(); ++i) ray_differ += (rays[i] != 0) != sim::inside_by_winding_number(fast[i]);
      int tets = 0;
      const double tet_ms = best_ms(1, [&] { tets = sim::tetrahedralize(mesh, resolution).num_tets(); });
      table.add_row({name, std::to_string(mesh.num_triangles()), std::to_string(resolution), std::to_string(centres.size()),
                     fixed(build_ms, 2), fixed(tree_ms, 1), do_exact ? fixed(exact_ms, 0) : "-", fixed(ray_ms, 1),
                     do_exact ? scientific(worst, 1) : "-", do_exact ? std::to_string(differ) : "-",
                     std::to_string(ray_differ), fixed(tet_ms, 1), std::to_string(tets)});
    }
  }
  table.print();
}

const Register kWindingBench("winding_number", bench_winding_number);

}  // namespace
}  // namespace recoil::bench
