#include "cli/drop_scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <random>

#include "cli/json_cursor.h"
#include "cli/number_range.h"
#include "cli/scene_limits.h"
#include "core/error.h"
#include "sim/fem/deformable_body.h"
#include "sim/geometry/mesh_import.h"

namespace recoil::cli {
namespace fs = std::filesystem;
namespace {

// Meshes whose longest side lies outside this range (metres) are taken to be
// in other units and rescaled to kTargetSize.
constexpr double kMinSize = 0.05, kMaxSize = 2.0, kTargetSize = 0.3;

struct Source {
  std::string path;    // absolute
  std::string stem;
  double scale = 1.0;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // local bounding-box centre, after `up`
  double bottom = 0.0;                               // local min y, after `up`
  double radius = 0.0;                               // bounding sphere of the scaled box, m
  double size = 0.0;                                 // longest side of the scaled box, m
  sim::Points vertices;                              // #V by 3, local, after `up`, unscaled
};

// Sizes and places the mesh as it will stand: after its up axis is turned to +Y.
Source load_source(const std::string& path, UpAxis up, ImportedMeshes* imported) {
  Source s;
  s.path = fs::absolute(path).lexically_normal().string();
  s.stem = name_from_stem(fs::path(path).stem().string());
  sim::TriMesh mesh = sim::import_surface(path);
  if (imported) imported->emplace(s.path, mesh);
  apply_up(up, mesh);
  const sim::Aabb box = sim::bounding_box(mesh);
  const double size = box.extent().maxCoeff();
  if (!(size > 0)) throw bad_input(path + ": the mesh is flat or empty");
  s.scale = drop_scale(size);
  s.center = box.center();
  s.bottom = box.min.y();
  s.radius = 0.5 * s.scale * box.extent().norm();
  s.size = s.scale * size;
  s.vertices = mesh.vertices;
  return s;
}

nlohmann::json material_json(const std::string& preset) {
  // Young's modulus (Pa), Poisson ratio, density (kg/m^3), damping ratio.
  if (preset == "rubber") return {{"youngs_modulus", 1e6}, {"poisson_ratio", 0.45}, {"density", 1100}, {"damping", 0.02}};
  if (preset == "jelly") return {{"youngs_modulus", 2e4}, {"poisson_ratio", 0.45}, {"density", 1000}, {"damping", 0.05}};
  if (preset == "stiff") return {{"youngs_modulus", 1e7}, {"poisson_ratio", 0.35}, {"density", 1200}, {"damping", 0.01}};
  return {{"youngs_modulus", 1e5}, {"poisson_ratio", 0.4}, {"density", 1000}, {"damping", 0.03}};  // soft
}

// Uniform in [lo, hi) from the raw 64-bit stream (the standard distributions
// differ between library versions; the bits do not).
double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

}  // namespace

double drop_scale(double size) {
  return !(size > 0.0) || (size >= kMinSize && size <= kMaxSize) ? 1.0 : kTargetSize / size;
}

void add_collision_options(CLI::App& command, CollisionChoice& choice) {
  // The scene's {"triangles": N} takes 4 or more: a closed surface has at least a tetrahedron's faces.
  const CLI::Validator budget(
      [](std::string& text) -> std::string {
        const std::optional<long long> n = whole_number_from_text(text);
        return n && (*n == 0 || (*n >= kMinCollisionTriangles && *n <= kMaxCollisionTriangles))
                   ? std::string()
                   : "must be 0 (the mesh itself) or " + std::to_string(kMinCollisionTriangles) + " to " +
                         std::to_string(kMaxCollisionTriangles) + " triangles, not '" + text + "'";
      },
      "0 or " + std::to_string(kMinCollisionTriangles) + "-" + std::to_string(kMaxCollisionTriangles));
  CLI::Option* triangles =
      command
          .add_option("--collision-triangles", choice.triangles,
                      "Collision surface budget per body (0: the mesh itself; default: from the tet lattice)")
          ->check(budget);
  command
      .add_option("--collision-edge", choice.edge,
                  "Collision surface tiled at this edge length, m (default: a quarter lattice cell, >= 2 margins)")
      ->check(NumberAbove(0.0))
      ->excludes(triangles);
}

nlohmann::json build_drop_scene(const DropSettings& settings, ImportedMeshes* imported) {
  if (settings.meshes.empty()) throw bad_input("drop: give at least one mesh");
  std::vector<Source> sources;
  for (const std::string& path : settings.meshes) sources.push_back(load_source(path, settings.up, imported));
  const bool pile = settings.count > 1;
  const int bodies = pile ? settings.count : static_cast<int>(sources.size());
  const bool many = bodies > 2;
  double cell = 0.0;
  for (const Source& s : sources) cell = std::max(cell, 2.0 * s.radius * 1.1);

  nlohmann::json list = nlohmann::json::array();
  list.push_back({{"name", "ground"}, {"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}},
                  {"friction", settings.friction}});
  std::mt19937_64 rng(settings.seed);
  // A pile's lowest point over all its bodies (m), each turned its own way:
  // the pile moves down as one so that it stands `height` above the ground.
  double pile_bottom = std::numeric_limits<double>::infinity();
  // Piles stack layers of 2 x 2 cells; side by side is one row along x.
  const int per_layer = pile ? std::min(4, bodies) : bodies;
  const int columns = pile ? (per_layer > 1 ? 2 : 1) : bodies;
  for (int i = 0; i < bodies; ++i) {
    const Source& s = sources[static_cast<size_t>(i) % sources.size()];
    const int layer = i / per_layer, slot = i % per_layer;
    const int row = slot / columns, column = slot % columns;
    const int rows = (per_layer + columns - 1) / columns;
    Eigen::Vector3d rotation = Eigen::Vector3d::Zero();
    Eigen::Vector3d center((column - 0.5 * (columns - 1)) * cell, 0.0, (row - 0.5 * (rows - 1)) * cell);
    if (pile) {
      rotation = Eigen::Vector3d(uniform(rng, -20, 20), uniform(rng, 0, 360), uniform(rng, -20, 20));
      center.x() += uniform(rng, -0.1, 0.1) * cell;
      center.z() += uniform(rng, -0.1, 0.1) * cell;
      center.y() = settings.height + s.radius + layer * cell;
    }
    sim::Transform t;
    t.rotation = rotation;
    t.scale = Eigen::Vector3d::Constant(s.scale);
    const Eigen::Matrix3d R = t.rotation_matrix();
    Eigen::Vector3d position = center - R * (s.scale * s.center);
    // Unrotated bodies rest their lowest point exactly `height` above the ground.
    if (!pile) position.y() = settings.height + settings.height_per_size * s.size - s.scale * s.bottom;
    else pile_bottom = std::min(pile_bottom, position.y() + s.scale * (s.vertices * R.transpose()).col(1).minCoeff());
    nlohmann::json body = {{"name", pile || sources.size() > 1 ? s.stem + "-" + std::to_string(i + 1) : s.stem},
                           {"mesh", s.path},
                           {"up", to_string(settings.up)},
                           {"friction", settings.friction},
                           {"transform", {{"position", json_vec3(position)}, {"rotation", json_vec3(rotation)}, {"scale", s.scale}}}};
    if (settings.collision.triangles == 0) body["collision"] = "mesh";
    else if (settings.collision.triangles > 0) body["collision"] = {{"triangles", settings.collision.triangles}};
    else if (settings.collision.edge > 0.0) body["collision"] = {{"edge_length", settings.collision.edge}};
    if (settings.material == "rigid") {
      body["type"] = "rigid";
      body["density"] = 1000;
    } else if (settings.material == "static") {
      body["type"] = "static";
    } else {
      body["type"] = "deformable";
      body["material"] = material_json(settings.material);
      body["tets"] = {{"resolution", many ? 6 : 8}};
    }
    list.push_back(body);
  }
  if (pile)
    for (nlohmann::json& body : list) {
      if (!body.contains("transform")) continue;
      nlohmann::json& y = body["transform"]["position"][1];
      y = y.get<double>() + settings.height - pile_bottom;
    }
  std::string name = name_from_stem(fs::path(settings.meshes.front()).stem().string()) + (pile ? "-pile" : "-drop");
  return {{"recoil", 1},
          {"name", name},
          {"description", "built by recoil drop"},
          {"simulation", {{"dt", 0.004}, {"duration", settings.seconds}}},
          {"bodies", list},
          {"render", {{"camera", {{"mode", "fixed"}, {"azimuth", 30}, {"elevation", 20}}}}}};
}

}  // namespace recoil::cli
