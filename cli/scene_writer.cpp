#include "cli/scene_writer.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cli/json_cursor.h"
#include "cli/scene_bodies.h"

namespace recoil::cli {
namespace {

using nlohmann::json;

// One number when the two coefficients are equal, as a scene file may give them.
json friction_json(double static_coefficient, double kinetic_coefficient) {
  if (static_coefficient == kinetic_coefficient) return static_coefficient;
  return {{"static", static_coefficient}, {"kinetic", kinetic_coefficient}};
}

json transform_json(const sim::Transform& t) {
  // One number only for a uniform scale that does not mirror: a scene's scalar scale is positive.
  const bool uniform = t.scale.x() > 0.0 && t.scale.x() == t.scale.y() && t.scale.y() == t.scale.z();
  return {{"position", json_vec3(t.position)},
          {"rotation", json_vec3(t.rotation)},
          {"scale", uniform ? json(t.scale.x()) : json_vec3(t.scale)}};
}

// "#rrggbb" of a colour parsed from one (its components are n / 255).
std::string color_hex(const render::Rgb& c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", static_cast<unsigned>(std::lround(c[0] * 255.0f)),
                static_cast<unsigned>(std::lround(c[1] * 255.0f)), static_cast<unsigned>(std::lround(c[2] * 255.0f)));
  return text;
}

// The shortest decimal that reads back as `x` (0.3f is written 0.3, not 0.30000001192092896).
double shortest_double(float x) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, x).ptr;
  return std::strtod(std::string(text, end).c_str(), nullptr);
}

json collision_json(const sim::CollisionSurfaceDesc& c) {
  if (c.keep_mesh) return "mesh";
  if (c.max_triangles > 0) return {{"triangles", c.max_triangles}};
  return {{"edge_length", c.edge_length}};
}
bool has_collision_setting(const sim::CollisionSurfaceDesc& c) {
  return c.keep_mesh || c.max_triangles > 0 || c.edge_length > 0.0;
}

json body_json(const SceneBody& body, const sim::WorldDesc& world) {
  json out = {{"name", body.name}, {"type", scene_type_name(body.kind)}};
  const size_t i = static_cast<size_t>(body.index);
  if (body.is_plane()) {
    const sim::PlaneDesc& p = world.planes[i];
    out["point"] = json_vec3(p.point);
    out["normal"] = json_vec3(p.normal);
    out["friction"] = friction_json(p.friction.static_coefficient, p.friction.kinetic_coefficient);
    return out;
  }
  // A colour nobody chose stays out: the palette gives it again, and a mesh's own look is not overridden.
  if (body.color_given) out["color"] = color_hex(body.color);
  out["opacity"] = shortest_double(body.opacity);
  if (body.mesh_file.empty()) {
    out["primitive"] = body.primitive;
  } else {
    out["mesh"] = body.mesh_file.string();
    out["up"] = to_string(body.up);
  }
  if (body.kind == sim::BodyKind::deformable) {
    const sim::DeformableBodyDesc& d = world.bodies[i];
    out["transform"] = transform_json(d.transform);
    out["friction"] = friction_json(d.static_friction, d.kinetic_friction);
    out["material"] = {{"model", material_model_name(d.material.model)},
                       {"youngs_modulus", d.material.youngs_modulus},
                       {"poisson_ratio", d.material.poisson_ratio},
                       {"density", d.material.density},
                       {"damping", d.material.damping_ratio}};
    out["velocity"] = json_vec3(d.velocity);
    out["self_contact"] = d.self_contact;
    if (!body.tets_file.empty()) out["tets"] = {{"file", body.tets_file.string()}};
    else if (!is_tet_file(body.mesh_file)) out["tets"] = {{"resolution", d.resolution}};
    if (d.pinned) out["pinned"] = {{"min", json_vec3(d.pinned->min)}, {"max", json_vec3(d.pinned->max)}};
    if (has_collision_setting(d.collision)) out["collision"] = collision_json(d.collision);
    return out;
  }
  const sim::RigidBodyDesc& r = world.rigid_bodies[i];
  out["transform"] = transform_json(r.transform);
  out["friction"] = friction_json(r.friction.static_coefficient, r.friction.kinetic_coefficient);
  if (r.kind == sim::BodyKind::rigid) {
    out["density"] = r.density;
    out["velocity"] = json_vec3(r.velocity);
    out["angular_velocity"] = json_vec3(r.angular_velocity);
  } else if (r.kind == sim::BodyKind::kinematic) {
    out["motion"] = {{"velocity", json_vec3(r.velocity)}, {"angular_velocity", json_vec3(r.angular_velocity)}};
  }
  if (has_collision_setting(r.collision)) out["collision"] = collision_json(r.collision);
  return out;
}

json camera_json(const CameraDesc& c) {
  json out = {{"mode", camera_mode_name(c.mode)}, {"fov", c.fov}};
  // A camera at a given position has no azimuth or elevation: the parser refuses them beside it.
  if (c.has_position) {
    out["position"] = json_vec3(c.position);
  } else {
    out["azimuth"] = c.azimuth;
    out["elevation"] = c.elevation;
  }
  if (c.has_target) out["target"] = json_vec3(c.target);
  if (c.distance > 0.0) out["distance"] = c.distance;  // 0, "fit the scene", is the key left out
  if (c.mode == CameraMode::orbit) out["turns"] = c.turns;
  if (c.mode == CameraMode::follow) out["body"] = c.body;
  return out;
}

json render_json(const SceneDesc& scene) {
  const RenderOptions& r = scene.render;
  const render::RenderSettings size = to_render_settings(r);
  return {{"resolution", {size.width, size.height}},
          {"fps", r.fps},
          {"msaa", r.msaa},
          {"shadows", !r.no_shadows},
          {"background", r.background},
          {"wireframe", r.wireframe},
          {"ambient_occlusion", r.ambient_occlusion},
          {"png_level", r.png_level},
          {"ground", {{"grid", scene.grid}, {"visible", !r.no_ground}}},
          {"camera", camera_json(scene.camera)}};
}

json simulation_json(const SceneDesc& scene) {
  const sim::WorldDesc& w = scene.world;
  return {{"dt", w.dt},
          {"duration", scene.duration},
          {"settle", scene.settle},
          {"gravity", json_vec3(w.gravity)},
          {"solver",
           {{"method", solver_name(w.contact.solver.method)},
            {"tolerance", w.contact.solver.tolerance},
            {"max_iterations", w.contact.solver.max_iterations}}},
          {"contact", {{"margin", w.contact.margin}}}};
}

}  // namespace

json resolved_scene(const SceneDesc& scene) {
  json out = {{"recoil", 1}, {"name", scene.name}, {"simulation", simulation_json(scene)}, {"render", render_json(scene)}};
  if (!scene.description.empty()) out["description"] = scene.description;
  json bodies = json::array();
  for (const SceneBody& body : scene.bodies) bodies.push_back(body_json(body, scene.world));
  out["bodies"] = std::move(bodies);
  return out;
}

}  // namespace recoil::cli
