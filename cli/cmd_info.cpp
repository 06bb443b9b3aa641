// `recoil info MESH [--json]`: what a mesh is made of, before anyone simulates it.
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/commands.h"
#include "cli/scene_info.h"
#include "sim/geometry/mesh_import.h"
#include "sim/geometry/mesh_stats.h"

namespace recoil::cli {
namespace {

struct InfoOptions {
  std::string path;
  bool json = false;
};

nlohmann::json to_json(const sim::Aabb& box) {
  return {{"min", {box.min.x(), box.min.y(), box.min.z()}}, {"max", {box.max.x(), box.max.y(), box.max.z()}}};
}

int run_info(const InfoOptions& options) {
  if (std::filesystem::path(options.path).extension() == ".json") return print_scene_info(options.path, options.json);
  const sim::TriMesh mesh = sim::import_surface(options.path);
  const sim::MeshStats stats = sim::compute_mesh_stats(mesh);
  const Eigen::Vector3d size = stats.bounds.extent();
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
                          {"volume", stats.watertight ? nlohmann::json(stats.volume) : nlohmann::json(nullptr)}};
    std::cout << out.dump(2) << "\n";
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
    text << "  watertight   no (" << stats.boundary_edges << " boundary, " << stats.non_manifold_edges
         << " non-manifold, " << stats.inconsistent_edges << " inconsistently oriented edges)\n";
  }
  text << "  bounds       [" << stats.bounds.min.transpose() << "] .. [" << stats.bounds.max.transpose() << "]\n"
       << "  size         " << size.x() << " x " << size.y() << " x " << size.z() << "\n"
       << "  area         " << stats.area << "\n";
  if (stats.watertight) text << "  volume       " << stats.volume << "\n";
  else text << "  volume       - (the surface is not closed)\n";
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
  cmd->footer(
      "Examples:\n"
      "  recoil info assets/meshes/bunny.obj\n"
      "  recoil info model.glb --json | jq .volume\n"
      "  recoil info assets/scenes/bunny-drop.json       # bodies, tetrahedra, masses, frames\n"
      "A mesh must be watertight (closed, manifold, consistently oriented) to become a deformable or rigid body.\n");
  cmd->callback([options, &action] { action = [options] { return run_info(*options); }; });
}

}  // namespace recoil::cli
