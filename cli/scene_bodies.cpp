#include "cli/scene_bodies.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <optional>
#include <unordered_set>

#include "cli/format_number.h"
#include "cli/input_file.h"
#include "cli/up_axis.h"
#include "core/error.h"
#include "sim/geometry/boundary.h"
#include "sim/geometry/mesh_import.h"
#include "sim/geometry/mesh_stats.h"
#include "sim/geometry/primitives.h"
#include "sim/geometry/tet_file.h"

namespace recoil::cli {
namespace fs = std::filesystem;
namespace {

const std::vector<std::string> kAllBodyKeys = {
    "name",     "type",     "mesh",     "primitive", "tets",     "material", "density", "friction", "transform",
    "velocity", "angular_velocity", "motion", "pinned", "color", "opacity", "point",   "normal",   "self_contact",
    "up", "collision"};

// The keys a body of this kind (none: a plane) may have.
std::vector<std::string> keys_for(std::optional<sim::BodyKind> kind) {
  std::vector<std::string> keys = {"name", "type"};
  auto add = [&](std::initializer_list<const char*> more) { keys.insert(keys.end(), more.begin(), more.end()); };
  if (!kind) {
    add({"point", "normal", "friction"});
    return keys;
  }
  switch (*kind) {
    case sim::BodyKind::fixed:
      add({"mesh", "up", "primitive", "friction", "transform", "color", "opacity", "collision"});
      break;
    case sim::BodyKind::kinematic:
      add({"mesh", "up", "primitive", "friction", "transform", "color", "opacity", "motion", "collision"});
      break;
    case sim::BodyKind::rigid:
      add({"mesh", "up", "primitive", "friction", "transform", "color", "opacity", "density", "velocity",
           "angular_velocity", "collision"});
      break;
    case sim::BodyKind::deformable:
      add({"mesh", "up", "primitive", "friction", "transform", "color", "opacity", "tets", "material", "velocity",
           "pinned", "self_contact", "collision"});
      break;
  }
  return keys;
}

// Every body "type" a scene may give, as kinds; empty: a plane.
constexpr std::optional<sim::BodyKind> kSceneTypes[] = {std::nullopt, sim::BodyKind::fixed, sim::BodyKind::kinematic,
                                                        sim::BodyKind::rigid, sim::BodyKind::deformable};

// The kind a scene "type" names; empty for "plane".
std::optional<sim::BodyKind> parse_type(const JsonCursor& c) {
  const std::string t = c.string();
  for (const std::optional<sim::BodyKind>& kind : kSceneTypes)
    if (t == scene_type_name(kind)) return kind;
  const std::string guess = near_miss(t, {"plane", "static", "kinematic", "rigid", "deformable"});
  c.fail("unknown body type \"" + t + "\"" + (guess.empty() ? "" : "; did you mean \"" + guess + "\"?") +
         " (plane, static, kinematic, rigid or deformable)");
}

sim::FrictionDesc parse_friction(const JsonCursor& c) {
  sim::FrictionDesc f;
  if (c.is_number()) {
    f.static_coefficient = f.kinetic_coefficient = c.number_in(kFrictionRange);
    return f;
  }
  if (!c.value().is_object()) c.type_error("a number or an object {\"static\", \"kinetic\"}");
  c.expect_object({"static", "kinetic"});
  f.static_coefficient = c.child("static").number_in(kFrictionRange);
  const JsonCursor kinetic = c.child("kinetic");
  f.kinetic_coefficient = kinetic.number_in(kFrictionRange);
  if (f.kinetic_coefficient > f.static_coefficient)
    kinetic.fail("must be <= the static coefficient " + c.child("static").value().dump());
  return f;
}

sim::Transform parse_transform(const JsonCursor& c) {
  c.expect_object({"position", "rotation", "scale"});
  sim::Transform t;
  t.position = c.vec3_in_or("position", Eigen::Vector3d::Zero(), kCoordinateRange);
  t.rotation = c.vec3_in_or("rotation", Eigen::Vector3d::Zero(), kAngleRange);
  if (c.has("scale")) {
    const JsonCursor s = c.child("scale");
    if (s.is_number()) {
      t.scale = Eigen::Vector3d::Constant(s.number_in(kScaleRange));
    } else {
      if (!s.is_array()) s.type_error("a number or an array of 3 numbers");
      t.scale = s.vec3_in({-kScaleRange.hi, kScaleRange.hi});
      for (int k = 0; k < 3; ++k)
        if (!kScaleRange.contains(std::abs(t.scale[k])))
          s.fail("each component's magnitude must be " + kScaleRange.describe());
    }
  }
  return t;
}

// A box also reports its edge lengths in `box_size` (m), so that a
// deformable one can be re-gridded to its lattice (parse_body).
sim::TriMesh parse_primitive(const JsonCursor& c, std::optional<Eigen::Vector3d>& box_size) {
  c.expect_object({"box", "sphere", "cylinder", "capsule", "torus"});
  if (c.value().size() != 1) c.fail("expected exactly one of box, sphere, cylinder, capsule, torus");
  if (c.has("box")) {
    const JsonCursor box = c.child("box");
    const Eigen::Vector3d size = box.vec3_in(kSizeRange);
    box_size = size;
    return sim::make_box(size);
  }
  if (c.has("sphere")) return sim::make_sphere(c.child("sphere").number_in(kSizeRange));
  auto radius_height = [&](const char* key, double& r, double& h) {
    const JsonCursor p = c.child(key);
    p.expect_object({"radius", "height"});
    r = p.child("radius").number_in(kSizeRange);
    // A capsule of height 0 is a sphere; a cylinder needs a height.
    h = std::string(key) == "cylinder" ? p.child("height").number_in(kSizeRange)
                                       : p.child("height").number_in({0.0, kSizeRange.hi});
  };
  double r = 0, h = 0;
  if (c.has("cylinder")) {
    radius_height("cylinder", r, h);
    return sim::make_cylinder(r, h);
  }
  if (c.has("capsule")) {
    radius_height("capsule", r, h);
    return sim::make_capsule(r, h);
  }
  const JsonCursor torus = c.child("torus");
  torus.expect_object({"major", "minor"});
  const double major = torus.child("major").number_in(kSizeRange);
  const JsonCursor minor_c = torus.child("minor");
  const double minor = minor_c.number_in(kSizeRange);
  if (!(minor < major)) minor_c.fail("must be < major (" + torus.child("major").value().dump() + ")");
  return sim::make_torus(major, minor);
}

// A file named by the scene: resolved against its folder.
fs::path resolve_file(const JsonCursor& c, const fs::path& base_dir) {
  const std::string text = c.string();
  if (text.empty()) c.fail("empty file name");
  const fs::path path = fs::path(text).is_absolute() ? fs::path(text) : (base_dir / text).lexically_normal();
  require_regular_file(c, path);
  return path;
}

// How the resolved scene names a file: absolute, so it reruns from anywhere.
fs::path absolute_path(const fs::path& path) { return fs::absolute(path).lexically_normal(); }

// Loads a geometry file, turning the reader's error into one that names the field.
template <typename F>
auto load_geometry(const JsonCursor& c, F&& read) {
  try {
    return read();
  } catch (const Error& e) {
    c.fail(e.what());
  }
}

struct Geometry {
  fs::path file;                        // the mesh file, absolute; empty for a primitive
  nlohmann::json primitive;             // the validated primitive object; null for a mesh file
  sim::TriMesh surface;
  sim::TetMesh tets;                    // when the mesh file is tetrahedral
  std::optional<Eigen::Vector3d> box;   // a box primitive's edge lengths, m
  bool open = false;                    // a surface file that is not watertight
  UpAxis up = UpAxis::pos_y;            // already applied to surface and tets
};

// Mesh files already read while parsing one scene, by resolved path: a
// scene with a thousand copies of one mesh (`recoil drop --count 1000`)
// imports it once.
using MeshFiles = std::map<fs::path, Geometry>;

// What parsing one body needs to know of those before it, kept as it goes so
// that a scene of a million bodies parses in linear time.
struct BodiesSoFar {
  MeshFiles files;
  std::unordered_set<std::string> names;
  int mesh_bodies = 0;  // bodies other than planes, for the palette
};

// A mesh file as read, cached unrotated (bodies may give it different "up"s).
Geometry read_mesh_file(const JsonCursor& c, const fs::path& base_dir, MeshFiles& files) {
  const fs::path path = resolve_file(c, base_dir).lexically_normal();
  Geometry g;
  if (const auto known = files.find(path); known != files.end()) {
    g = known->second;
  } else {
    if (is_tet_file(path)) {
      g.tets = load_geometry(c, [&] { return sim::read_tet_file(path); });
      if (g.tets.empty()) c.fail("holds no tetrahedra: " + path.string());
      g.surface = sim::boundary_surface(g.tets);
    } else {
      g.surface = load_geometry(c, [&] { return sim::import_surface(path); });
      g.open = !sim::compute_mesh_stats(g.surface).watertight;
    }
    if (g.surface.empty()) c.fail("holds no triangles: " + path.string());
    files.emplace(path, g);
  }
  g.file = absolute_path(path);
  return g;
}

// A mesh body's "up" (default "+Y").
UpAxis parse_up(const JsonCursor& body) {
  if (!body.has("up")) return UpAxis::pos_y;
  const JsonCursor c = body.child("up");
  const std::string text = c.string();
  const std::optional<UpAxis> axis = parse_up_axis(text);
  if (!axis) c.fail("unknown up axis \"" + text + "\" (" + kUpAxisChoices + ")");
  return *axis;
}

Geometry parse_geometry(const JsonCursor& body, const fs::path& base_dir, MeshFiles& files) {
  const bool mesh = body.has("mesh"), primitive = body.has("primitive");
  if (mesh == primitive) body.fail(mesh ? "give either \"mesh\" or \"primitive\", not both" : "needs a \"mesh\" or a \"primitive\"");
  Geometry g;
  if (primitive) {
    if (body.has("up")) body.child("up").fail("only for mesh files; a primitive's axes are its own (use transform.rotation)");
    g.surface = parse_primitive(body.child("primitive"), g.box);
    g.primitive = body.child("primitive").value();
    return g;
  }
  g = read_mesh_file(body.child("mesh"), base_dir, files);
  g.up = parse_up(body);
  apply_up(g.up, g.surface);
  apply_up(g.up, g.tets);
  return g;
}

void parse_material(const JsonCursor& c, sim::Material& m) {
  c.expect_object({"model", "youngs_modulus", "poisson_ratio", "density", "damping"});
  const std::string model = c.string_or("model", material_model_name(sim::MaterialModel::corotated));
  if (model == material_model_name(sim::MaterialModel::corotated)) m.model = sim::MaterialModel::corotated;
  else if (model == material_model_name(sim::MaterialModel::neo_hookean)) m.model = sim::MaterialModel::neo_hookean;
  else c.child("model").fail("unknown material model \"" + model + "\" (corotated or neohookean)");
  m.youngs_modulus = c.number_in_or("youngs_modulus", 1e5, kYoungsModulusRange);
  m.poisson_ratio = c.number_in_or("poisson_ratio", 0.3, {0.0, 0.5, false, true});
  m.density = c.number_in_or("density", 1000.0, kDensityRange);
  m.damping_ratio = c.number_in_or("damping", 0.0, {0.0, 10.0});
}

// `collision`: "mesh" (the mesh itself), {"triangles": N} or
// {"edge_length": m}; absent: the default edge (sim/collision/collision_proxy.h).
sim::CollisionSurfaceDesc parse_collision(const JsonCursor& c) {
  sim::CollisionSurfaceDesc out;
  if (c.value().is_string()) {
    if (c.string() != "mesh") c.fail("expected \"mesh\", {\"triangles\": N} or {\"edge_length\": metres}");
    out.keep_mesh = true;
    return out;
  }
  c.expect_object({"triangles", "edge_length"});
  if (c.has("triangles") && c.has("edge_length")) c.fail("give triangles or edge_length, not both");
  if (c.has("triangles")) {
    out.max_triangles = c.child("triangles").integer_in(kMinCollisionTriangles, kMaxCollisionTriangles);
  } else if (c.has("edge_length")) {
    out.edge_length = c.child("edge_length").number_in(kSizeRange);
  }
  return out;
}

// A body placed by its transform must stay inside the world's coordinate
// range (rotation keeps lengths, so scale and translation bound it) and,
// whatever the mesh's units, be at least as large as a primitive may be.
void check_placed_extent(const JsonCursor& body, const sim::TriMesh& mesh, const sim::Transform& transform) {
  const double reach = (mesh.vertices.array().rowwise() * transform.scale.transpose().array()).matrix().rowwise().norm().maxCoeff() +
                       transform.position.norm();
  if (!(reach <= kCoordinateRange.hi))
    body.fail("reaches " + format_number("%.3g", reach) + " m from the origin once placed by its transform; at most " +
              format_number("%g", kCoordinateRange.hi) + " m");
  if (mesh.vertices.rows() == 0) return;
  const Eigen::Vector3d extent =
      (mesh.vertices.colwise().maxCoeff() - mesh.vertices.colwise().minCoeff()).transpose().cwiseProduct(
          transform.scale.cwiseAbs());
  if (!(extent.maxCoeff() >= kSizeRange.lo))
    body.fail("is " + format_number("%.3g", extent.maxCoeff()) + " m across once scaled by its transform; at least " +
              format_number("%g", kSizeRange.lo) + " m");
}

render::Rgb parse_body_color(const JsonCursor& c) {
  return parse_color(c.string(), c.file() + ": " + c.pointer());
}

void parse_body(const JsonCursor& body, int index, const fs::path& base_dir, BodiesSoFar& so_far, SceneDesc& scene) {
  body.expect_object(kAllBodyKeys);
  const std::optional<sim::BodyKind> kind = parse_type(body.child("type"));
  const std::vector<std::string> allowed = keys_for(kind);
  for (const auto& [key, value] : body.value().items())
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      body.child(key).fail("not allowed for a " + std::string(scene_type_name(kind)) + " body" +
                           (kind == sim::BodyKind::kinematic && (key == "velocity" || key == "angular_velocity")
                                ? std::string("; a kinematic body moves by its \"motion\": {\"") + key + "\": ...}"
                                : std::string()));

  SceneBody out;
  out.kind = kind;
  out.pointer = body.pointer();
  out.name = body.string_or("name", std::string(scene_type_name(kind)) + std::to_string(index));
  if (const std::string why = unsafe_name_reason(out.name); !why.empty()) body.child("name").fail(why);
  if (!so_far.names.insert(out.name).second) body.child("name").fail("duplicate body name \"" + out.name + "\"");
  const sim::FrictionDesc friction = body.has("friction") ? parse_friction(body.child("friction")) : sim::FrictionDesc{};

  if (out.is_plane()) {
    sim::PlaneDesc plane;
    plane.name = out.name;
    plane.origin = {body.file(), body.pointer(), ""};
    plane.point = body.vec3_in_or("point", Eigen::Vector3d::Zero(), kCoordinateRange);
    plane.normal = body.vec3_in_or("normal", Eigen::Vector3d::UnitY(), kCoordinateRange);
    if (!(plane.normal.norm() > 1e-12)) body.child("normal").fail("must not be zero");
    plane.friction = friction;
    out.index = static_cast<int>(scene.world.planes.size());
    scene.world.planes.push_back(plane);
    scene.bodies.push_back(out);
    return;
  }

  if (body.has("color")) {
    out.color = parse_body_color(body.child("color"));
    out.color_given = true;
  } else {
    out.color = palette_color(so_far.mesh_bodies++);
  }
  out.opacity = static_cast<float>(body.number_in_or("opacity", 1.0, {0.0, 1.0}));
  Geometry geometry = parse_geometry(body, base_dir, so_far.files);
  out.open_mesh = geometry.open;
  out.mesh_file = geometry.file;
  out.up = geometry.up;
  out.primitive = geometry.primitive;
  const sim::Transform transform = parse_transform(body.child_or_empty("transform"));
  check_placed_extent(body, geometry.surface, transform);

  if (kind == sim::BodyKind::deformable) {
    sim::DeformableBodyDesc d;
    d.name = out.name;
    d.origin = {body.file(), body.pointer(), geometry.file.empty() ? "" : geometry.file.string()};
    d.transform = transform;
    d.static_friction = friction.static_coefficient;
    d.kinetic_friction = friction.kinetic_coefficient;
    parse_material(body.child_or_empty("material"), d.material);
    d.velocity = body.vec3_in_or("velocity", Eigen::Vector3d::Zero(), kSpeedRange);
    if (body.has("collision")) d.collision = parse_collision(body.child("collision"));
    d.self_contact = body.boolean_or("self_contact", true);
    // A tetrahedral mesh file gives the tets; its boundary is the surface.
    d.tets = std::move(geometry.tets);
    d.mesh = std::move(geometry.surface);
    if (body.has("tets")) {
      const JsonCursor tets = body.child("tets");
      tets.expect_object({"resolution", "file"});
      if (!d.tets.empty()) tets.fail("the mesh file is already tetrahedral; remove \"tets\"");
      if (tets.has("resolution") == tets.has("file")) tets.fail("give either \"resolution\" or \"file\"");
      if (tets.has("resolution")) {
        const JsonCursor r = tets.child("resolution");
        d.resolution = r.integer_in(1, 256);
      } else {
        const JsonCursor f = tets.child("file");
        const fs::path path = resolve_file(f, base_dir);
        out.tets_file = absolute_path(path);
        if (!is_tet_file(path)) f.fail("expected a tetrahedral mesh (.msh, .node or .ele), got " + path.string());
        d.tets = load_geometry(f, [&] { return sim::read_tet_file(path); });
        if (d.tets.empty()) f.fail("holds no tetrahedra: " + path.string());
        apply_up(geometry.up, d.tets);  // the tets share the mesh file's axes
      }
    }
    // A deformable box's faces get `resolution` cells per edge, the lattice's
    // spacing for a cube, in place of the primitive's default 8: a surface
    // finer than its lattice gives several nearly dependent contact rows per
    // touching lattice cell, which the contact solver cannot hold together
    // (the jelly-stack example; docs/solver-log.md). Coarser than the
    // lattice it would not do either: a face held only at its corners sags
    // through what it rests on (the validation jelly cubes did).
    if (geometry.box && d.tets.empty()) d.mesh = sim::make_box(*geometry.box, d.resolution);
    if (body.has("pinned")) {
      const JsonCursor p = body.child("pinned");
      p.expect_object({"min", "max"});
      sim::PinBox pin{p.child("min").vec3_in(kCoordinateRange), p.child("max").vec3_in(kCoordinateRange)};
      if (!(pin.min.array() <= pin.max.array()).all()) p.fail("min must be <= max in every coordinate");
      d.pinned = pin;
    }
    out.index = static_cast<int>(scene.world.bodies.size());
    scene.world.bodies.push_back(std::move(d));
  } else {
    sim::RigidBodyDesc r;
    r.name = out.name;
    r.origin = {body.file(), body.pointer(), geometry.file.empty() ? "" : geometry.file.string()};
    r.kind = *kind;
    r.mesh = std::move(geometry.surface);
    r.transform = transform;
    r.friction = friction;
    if (body.has("collision")) r.collision = parse_collision(body.child("collision"));
    if (kind == sim::BodyKind::rigid) {
      r.density = body.number_in_or("density", 1000.0, kDensityRange);
      r.velocity = body.vec3_in_or("velocity", Eigen::Vector3d::Zero(), kSpeedRange);
      r.angular_velocity = body.vec3_in_or("angular_velocity", Eigen::Vector3d::Zero(), kAngularSpeedRange);
    } else if (kind == sim::BodyKind::kinematic) {
      const JsonCursor m = body.child_or_empty("motion");
      m.expect_object({"velocity", "angular_velocity"});
      r.velocity = m.vec3_in_or("velocity", Eigen::Vector3d::Zero(), kSpeedRange);
      r.angular_velocity = m.vec3_in_or("angular_velocity", Eigen::Vector3d::Zero(), kAngularSpeedRange);
    }
    out.index = static_cast<int>(scene.world.rigid_bodies.size());
    scene.world.rigid_bodies.push_back(std::move(r));
  }
  scene.bodies.push_back(out);
}

}  // namespace

bool is_tet_file(const fs::path& path) {
  const std::string ext = path.extension().string();
  return ext == ".msh" || ext == ".node" || ext == ".ele";
}

void parse_bodies(const std::vector<JsonCursor>& bodies, const fs::path& base_dir, SceneDesc& scene,
                  ImportedMeshes imported) {
  BodiesSoFar so_far;
  for (auto& [path, mesh] : imported) {
    Geometry g;
    g.open = !sim::compute_mesh_stats(mesh).watertight;
    g.surface = std::move(mesh);
    so_far.files.emplace(path, std::move(g));
  }
  scene.bodies.reserve(bodies.size());
  for (size_t i = 0; i < bodies.size(); ++i) parse_body(bodies[i], static_cast<int>(i), base_dir, so_far, scene);
  // Each file's look warnings once, however many bodies use it.
  for (const auto& [path, geometry] : so_far.files)
    if (geometry.surface.look)
      for (const std::string& warning : geometry.surface.look->warnings)
        scene.look_warnings.emplace_back(absolute_path(path), warning);
}

}  // namespace recoil::cli
