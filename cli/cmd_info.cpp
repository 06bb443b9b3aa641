// `recoil info MESH [--json]`: what a mesh is made of, before anyone simulates it.
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "cli/commands.h"
#include "cli/drop_scene.h"
#include "cli/number_range.h"
#include "cli/scene_info.h"
#include "core/error.h"
#include "sim/fem/deformable_body.h"
#include "sim/geometry/mesh_import.h"
#include "sim/geometry/mesh_stats.h"
#include "sim/geometry/tetrahedralize.h"
#include "sim/geometry/winding_solid.h"

namespace recoil::cli {
namespace {

struct InfoOptions {
  std::string path;
  bool json = false;
  // Lattice cells along the longest side, as a deformable body's tets.resolution.
  int resolution = sim::DeformableBodyDesc{}.resolution;
};

nlohmann::json to_json(const sim::Aabb& box) {
  return {{"min", {box.min.x(), box.min.y(), box.min.z()}}, {"max", {box.max.x(), box.max.y(), box.max.z()}}};
}

// What the renderer draws of the file's own look: the materials its
// triangles use, their textures, UVs and vertex colours; null without one.
nlohmann::json look_json(const sim::TriMesh& mesh) {
  if (!mesh.look || (!mesh.look->draws_anything() && mesh.look->warnings.empty())) return nullptr;
  const sim::SurfaceLook& look = *mesh.look;
  std::vector<char> used(look.materials.size(), 0);
  for (int m : look.triangle_material) used[static_cast<size_t>(m)] = 1;
  nlohmann::json materials = nlohmann::json::array();
  for (size_t m = 0; m < look.materials.size(); ++m) {
    if (!used[m]) continue;
    const sim::LookMaterial& material = look.materials[m];
    nlohmann::json entry = {{"name", material.name}};
    entry["color"] = material.has_color ? nlohmann::json(material.color) : nlohmann::json(nullptr);
    entry["surface"] = material.has_surface
                           ? nlohmann::json{{"metallic", material.metallic}, {"roughness", material.roughness}}
                           : nlohmann::json(nullptr);
    entry["texture"] = material.texture ? nlohmann::json{{"width", material.texture->width}, {"height", material.texture->height}}
                                        : nlohmann::json(nullptr);
    materials.push_back(entry);
  }
  return {{"materials", materials},
          {"uvs", !look.corner_uv.empty()},
          {"vertex_colors", !look.corner_color.empty()},
          {"warnings", look.warnings}};
}

std::string look_text(const nlohmann::json& look) {
  if (look.is_null()) return "none (drawn in the body's colour)";
  int textured = 0;
  for (const nlohmann::json& m : look["materials"]) textured += !m["texture"].is_null();
  std::string text = std::to_string(look["materials"].size()) + " material" + (look["materials"].size() == 1 ? "" : "s");
  if (textured > 0) text += ", " + std::to_string(textured) + " textured";
  if (look["vertex_colors"].get<bool>()) text += ", vertex colours";
  for (const nlohmann::json& w : look["warnings"]) text += "\n  warning      " + w.get<std::string>();
  return text;
}

// The cells in file units, and as `drop` and `turntable` size the mesh when they rescale it.
std::string scaled_cells(double size, double cell) {
  const double scale = drop_scale(size);
  if (scale == 1.0) return " m";
  std::ostringstream text;
  text << std::setprecision(3) << " file units; " << cell * scale << " m once `drop` or `turntable` scale it to "
       << size * scale << " m";
  return text.str();
}

int run_info(const InfoOptions& options, bool resolution_given) {
  if (std::filesystem::path(options.path).extension() == ".json") {
    if (resolution_given) throw bad_input("--resolution applies to a mesh; a scene gives each body's tets.resolution");
    return print_scene_info(options.path, options.json);
  }
  bool wound_inward = false;
  const sim::TriMesh mesh = sim::import_surface(options.path, &wound_inward);
  const sim::MeshStats stats = sim::compute_mesh_stats(mesh);
  const Eigen::Vector3d size = stats.bounds.extent();
  // The tets a deformable body of this mesh gets (the same call the World
  // makes); a mesh that cannot have any (flat) still gets its statistics.
  sim::TetrahedralizeStats lattice;
  sim::TetMesh tets;
  std::string no_tets;
  try {
    tets = sim::tetrahedralize(mesh, options.resolution, &lattice);
  } catch (const Error& e) {
    no_tets = e.what();
  }
  const nlohmann::json tetrahedra =
      no_tets.empty() ? nlohmann::json{{"resolution", options.resolution},
                                       {"cell_size", lattice.cell_size},
                                       {"drop_scale", drop_scale(size.maxCoeff())},
                                       {"nodes", tets.num_nodes()},
                                       {"tets", tets.num_tets()}}
                      : nlohmann::json(nullptr);
  // An open surface's solid is where its winding number says inside, weighed on every core.
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const double volume =
      stats.watertight ? std::abs(stats.volume) : sim::winding_solid(mesh, sim::kWeighingResolution, cores).volume();
  if (options.json) {
    nlohmann::json out = {{"file", options.path},
                          {"vertices", stats.vertices},
                          {"triangles", stats.triangles},
                          {"components", stats.components},
                          {"watertight", stats.watertight},
                          {"boundary_edges", stats.boundary_edges},
                          {"non_manifold_edges", stats.non_manifold_edges},
                          {"inconsistent_edges", stats.inconsistent_edges},
                          {"bounds", to_json(stats.bounds)},
                          {"area", stats.area},
                          {"volume", volume},
                          {"wound_inward", wound_inward},
                          {"tetrahedra", tetrahedra},
                          {"look", look_json(mesh)}};
    // Material names come from the file as bytes; invalid UTF-8 is shown as U+FFFD.
    std::cout << out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    return 0;
  }
  std::ostringstream text;
  text << std::setprecision(6);
  text << options.path << "\n"
       << "  vertices     " << stats.vertices << "\n"
       << "  triangles    " << stats.triangles << "\n"
       << "  components   " << stats.components << "\n";
  if (stats.watertight) {
    text << "  watertight   yes\n";
  } else {
    text << "  watertight   no: open mesh (" << stats.boundary_edges << " boundary, " << stats.non_manifold_edges
         << " non-manifold, " << stats.inconsistent_edges
         << " inconsistently oriented edges); inside by winding number\n";
  }
  text << "  bounds       [" << stats.bounds.min.transpose() << "] .. [" << stats.bounds.max.transpose() << "]\n"
       << "  size         " << size.x() << " x " << size.y() << " x " << size.z() << "\n"
       << "  area         " << stats.area << "\n";
  if (wound_inward)
    text << "  volume       " << stats.volume << " (the file's faces are wound inward; recoil turns them outward)\n";
  else if (stats.watertight) text << "  volume       " << stats.volume << "\n";
  else if (volume > 0.0)
    text << "  volume       " << volume << " (inside by winding number, on a grid of " << sim::kWeighingResolution
         << " cells along the longest side)\n";
  else
    text << "  volume       0 (it encloses nothing: a sheet, or parts thinner than 1/" << sim::kWeighingResolution
         << " of its longest side; a body of it weighs the lattice cells it crosses)\n";
  if (no_tets.empty())
    text << "  tetrahedra   " << tets.num_tets() << " tets, " << tets.num_nodes() << " nodes at resolution "
         << options.resolution << " (cells of " << lattice.cell_size << scaled_cells(size.maxCoeff(), lattice.cell_size)
         << ")\n";
  else
    text << "  tetrahedra   - (" << no_tets << ")\n";
  text << "  look         " << look_text(look_json(mesh)) << "\n";
  std::cout << text.str();
  return 0;
}

}  // namespace

void add_info_command(CLI::App& app, const GlobalOptions&, Action& action) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* cmd = app.add_subcommand("info", "Print a mesh's or a scene's statistics: size, watertightness, volume, bodies");
  cmd->add_option("MESH|SCENE", options->path,
                  "Mesh file (OBJ, PLY, STL, glTF, Collada, FBX, ... anything assimp reads) or scene file (.json)")
      ->required();
  cmd->add_flag("--json", options->json, "Print the statistics as one JSON object on stdout");
  CLI::Option* resolution =
      cmd->add_option("--resolution", options->resolution,
                      "Lattice cells along the mesh's longest side for the tetrahedra it would get "
                      "(a deformable body's tets.resolution)")
          ->check(WholeNumberIn(1, 256))
          ->capture_default_str();
  cmd->footer(
      "Examples:\n"
      "  recoil info assets/meshes/bunny.obj\n"
      "  recoil info model.glb --json | jq .volume\n"
      "  recoil info part.stl --resolution 16             # the tetrahedra at 16 cells along the longest side\n"
      "  recoil info assets/scenes/bunny-drop.json       # bodies, tetrahedra, masses, frames\n"
      "Open meshes (holes, flipped faces, several shells) can be simulated too: inside and outside are\n"
      "decided by the generalized winding number, and runs name them in their summary.\n");
  cmd->callback([options, resolution, &action] {
    const bool given = resolution->count() > 0;
    action = [options, given] { return run_info(*options, given); };
  });
}

}  // namespace recoil::cli
