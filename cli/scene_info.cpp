#include "cli/scene_info.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/format_number.h"
#include "cli/scene_parser.h"
#include "cli/scene_runner.h"
#include "core/error.h"
#include "core/text_columns.h"
#include "sim/world.h"

namespace recoil::cli {
namespace {

// A length in metres as millimetres; below a nanometre it is round-off of a
// surface that lies on the mesh itself, and reads 0.
double millimetres(double metres) { return std::abs(metres) < 1e-9 ? 0.0 : metres * 1e3; }

// How far the collision surface (#V by 3) reaches below the drawn one
// (#V by 3) along `up` (unit), m: what a body at rest floats above the ground.
double collision_below(const sim::Points& drawn, const sim::Points& collision, const Eigen::Vector3d& up) {
  return (drawn * up).minCoeff() - (collision * up).minCoeff();
}

}  // namespace

int print_scene_info(const std::filesystem::path& file, bool as_json) {
  const SceneDesc scene = load_scene(file);
  const auto world = std::make_unique<sim::World>(scene.world);  // its errors name the scene file and field
  // Heights are measured against gravity (+Y without it).
  const Eigen::Vector3d& g = scene.world.gravity;
  const Eigen::Vector3d up = g.norm() > 0.0 ? Eigen::Vector3d(-g.normalized()) : Eigen::Vector3d::UnitY();
  nlohmann::json bodies = nlohmann::json::array();
  for (const SceneBody& b : scene.bodies) {
    nlohmann::json row = {{"name", b.name}, {"type", scene_type_name(b.kind)}};
    if (b.is_plane()) {
      const sim::PlaneDesc& p = scene.world.planes[static_cast<size_t>(b.index)];
      row["point"] = {p.point.x(), p.point.y(), p.point.z()};
      row["normal"] = {p.normal.x(), p.normal.y(), p.normal.z()};
    } else if (b.kind == sim::BodyKind::deformable) {
      // World bodies are in deformable-description order.
      const sim::DeformableBody& body = world->deformable_body(b.index);
      const sim::TriMesh& drawn = body.render_surface.empty() ? body.surface : body.render_surface;
      row["surface_vertices"] = drawn.num_vertices();
      row["surface_triangles"] = drawn.num_triangles();
      row["collision_triangles"] = body.surface.num_triangles();
      row["collision_offset"] = body.collision_deviation;
      row["collision_below"] = collision_below(drawn.vertices, body.surface.vertices, up);
      row["nodes"] = body.num_nodes;
      row["tets"] = body.rest.num_tets();
      row["mass"] = body.mass.sum();
      row["volume"] = body.surface_volume;
    } else {
      const sim::RigidBodyDesc& r = scene.world.rigid_bodies[static_cast<size_t>(b.index)];
      const sim::RigidBody& body = world->rigid_body(b.index);
      row["surface_vertices"] = r.mesh.num_vertices();
      row["surface_triangles"] = r.mesh.num_triangles();
      row["collision_triangles"] = body.triangles.rows();
      row["collision_offset"] = body.collision_deviation;
      const Eigen::Matrix3d rotation = body.rotation();
      const sim::Points& drawn = body.render_local.rows() > 0 ? body.render_local : body.local;
      row["collision_below"] = collision_below(drawn * rotation.transpose(), body.local * rotation.transpose(), up);
      if (b.kind == sim::BodyKind::rigid) row["mass"] = body.mass;
    }
    if (!b.is_plane()) row["open_mesh"] = b.open_mesh;
    bodies.push_back(row);
  }
  const long steps = std::lround(scene.duration / scene.world.dt);
  if (as_json) {
    const nlohmann::json out = {{"file", file.string()},        {"name", scene.name},
                                {"dt", scene.world.dt},         {"duration", scene.duration},
                                {"steps", steps},               {"fps", scene.render.fps},
                                {"frames", scene.frame_count()}, {"solver", solver_name(scene.world.contact.solver.method)},
                                {"bodies", bodies}};
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::ostringstream text;
  text << std::setprecision(6);
  text << file.string() << ": scene \"" << scene.name << "\"\n"
       << "  simulation   " << scene.duration << " s in " << steps << " steps of " << scene.world.dt
       << " s, solver " << solver_name(scene.world.contact.solver.method) << "\n"
       << "  frames       " << scene.frame_count() << " at " << scene.render.fps << " fps, " << scene.render.resolution
       << "\n"
       << "  bodies       " << scene.bodies.size() << "\n";
  // The name column fits the longest name up to kWidestName; a longer one
  // keeps its whole line and the type starts on the next.
  constexpr size_t kWidestName = 32;
  size_t name_width = 15;
  for (const nlohmann::json& row : bodies)
    name_width = std::max(name_width, std::min(kWidestName, text_columns(row["name"].get<std::string>())));
  for (const nlohmann::json& row : bodies) {
    const std::string name = row["name"].get<std::string>();
    const std::size_t columns = text_columns(name);
    text << "    " << name;
    if (columns > name_width) text << "\n    " << std::string(name_width + 1, ' ');
    else text << std::string(name_width + 1 - columns, ' ');
    text << std::left;
    text << std::setw(11) << row["type"].get<std::string>();
    if (row.contains("surface_triangles")) text << row["surface_triangles"] << " triangles";
    if (row.contains("collision_triangles") && row["collision_triangles"] != row["surface_triangles"]) {
      const double below = millimetres(row["collision_below"].get<double>());
      const double outside = millimetres(row["collision_offset"].get<double>());
      text << " (collision surface " << row["collision_triangles"] << " triangles, up to "
           << format_number("%.3g", outside) << " mm outside the drawn mesh and "
           << format_number("%.3g", std::abs(below)) << " mm " << (below >= 0.0 ? "below" : "above")
           << " its lowest point)";
    }
    if (row.contains("tets"))
      text << ", " << row["tets"] << " tets, " << row["nodes"] << " nodes";
    if (row.contains("mass")) text << ", mass " << row["mass"].get<double>() << " kg";
    if (row.value("open_mesh", false)) text << " (open mesh: inside by winding number)";
    text << "\n";
  }
  std::cout << text.str();
  return 0;
}

}  // namespace recoil::cli
