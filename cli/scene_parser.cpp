#include "cli/scene_parser.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <fstream>
#include <sstream>

#include "cli/json_cursor.h"
#include "cli/scene_bodies.h"
#include "core/error.h"
#include "core/regular_file.h"

namespace recoil::cli {
namespace fs = std::filesystem;
namespace {

constexpr CameraMode kCameraModes[] = {CameraMode::fixed, CameraMode::orbit, CameraMode::follow};

void parse_simulation(const JsonCursor& c, SceneDesc& scene) {
  c.expect_object({"dt", "duration", "settle", "gravity", "solver", "contact"});
  sim::WorldDesc& w = scene.world;
  w.origin = {c.file(), c.pointer(), ""};
  w.dt = c.number_in_or("dt", w.dt, kTimeStepRange);
  scene.duration = c.number_in_or("duration", 3.0, kDurationRange);
  scene.settle = c.number_in_or("settle", 0.0, kDurationRange);
  w.gravity = c.vec3_in_or("gravity", w.gravity, kAccelerationRange);

  const JsonCursor solver = c.child_or_empty("solver");
  solver.expect_object({"method", "tolerance", "max_iterations"});
  const std::string method = solver.string_or("method", "cr");
  if (method == "cr") w.contact.solver.method = sim::SolverMethod::cr;
  else if (method == "cr-plain") w.contact.solver.method = sim::SolverMethod::cr_plain;
  else if (method == "pgs") w.contact.solver.method = sim::SolverMethod::pgs;
  else solver.child("method").fail("unknown solver \"" + method + "\" (cr, pgs or cr-plain)");
  w.contact.solver.tolerance = solver.number_in_or("tolerance", w.contact.solver.tolerance, kToleranceRange);
  w.contact.solver.max_iterations =
      solver.integer_in_or("max_iterations", w.contact.solver.max_iterations, 1, kMaxIterations);

  const JsonCursor contact = c.child_or_empty("contact");
  contact.expect_object({"margin"});
  w.contact.margin = contact.number_in_or("margin", w.contact.margin, kMarginRange);
}

void parse_camera(const JsonCursor& c, SceneDesc& scene) {
  c.expect_object({"mode", "position", "target", "fov", "azimuth", "elevation", "distance", "turns", "body"});
  CameraDesc& cam = scene.camera;
  const std::string mode = c.string_or("mode", camera_mode_name(CameraMode::fixed));
  const auto known = std::find_if(std::begin(kCameraModes), std::end(kCameraModes),
                                  [&](CameraMode m) { return mode == camera_mode_name(m); });
  if (known == std::end(kCameraModes))
    c.child("mode").fail("unknown camera mode \"" + mode + "\" (fixed, orbit or follow)");
  cam.mode = *known;
  auto only_for = [&](const char* key, CameraMode allowed, const char* mode_name) {
    if (c.has(key) && cam.mode != allowed)
      c.child(key).fail(std::string("only for camera mode \"") + mode_name + "\"");
  };
  only_for("position", CameraMode::fixed, "fixed");
  only_for("turns", CameraMode::orbit, "orbit");
  only_for("body", CameraMode::follow, "follow");
  if (c.has("position")) {
    cam.has_position = true;
    cam.position = c.child("position").vec3_in(kCoordinateRange);
  }
  if (c.has("target")) {
    cam.has_target = true;
    cam.target = c.child("target").vec3_in(kCoordinateRange);
  }
  cam.fov = c.number_in_or("fov", cam.fov, {1.0, 170.0});
  cam.azimuth = c.number_in_or("azimuth", cam.azimuth, kAngleRange);
  cam.elevation = c.number_in_or("elevation", cam.elevation, {-89.0, 89.0});
  cam.distance = c.has("distance") ? c.child("distance").number_in(kCameraDistanceRange) : cam.distance;
  // Azimuth, elevation and distance place a camera round its target; a given position places it already.
  for (const char* placing : {"azimuth", "elevation", "distance"})
    if (cam.has_position && c.has(placing))
      c.child(placing).fail(std::string("has no effect on a camera at a given position; give position or ") +
                            placing);
  if (cam.mode == CameraMode::orbit) cam.turns = c.number_in_or("turns", cam.turns, kTurnsRange);
  if (cam.mode == CameraMode::follow) {
    const JsonCursor body = c.child("body");
    cam.body = body.string();
    const SceneBody* followed = scene.find(cam.body);
    if (!followed) body.fail("no body named \"" + cam.body + "\"");
    if (followed->is_plane()) body.fail("cannot follow the plane \"" + cam.body + "\"");
  }
  if (cam.has_position && cam.has_target && (cam.position - cam.target).norm() < 1e-9)
    c.child("position").fail("must differ from target");
}

void parse_render(const JsonCursor& c, SceneDesc& scene) {
  c.expect_object({"resolution", "fps", "msaa", "shadows", "background", "wireframe", "ambient_occlusion", "png_level", "ground",
                   "camera"});
  RenderOptions& r = scene.render;
  if (c.has("resolution")) {
    const auto wh = c.child("resolution").elements(2);
    int size[2];
    for (int k = 0; k < 2; ++k) size[k] = wh[static_cast<size_t>(k)].integer_in(16, 16384);
    r.resolution = std::to_string(size[0]) + "x" + std::to_string(size[1]);
  }
  r.fps = c.number_in_or("fps", r.fps, kFpsRange);
  r.msaa = c.integer_in_or("msaa", r.msaa, 0, 4);
  if (r.msaa == 1 || r.msaa == 3) c.child("msaa").fail("must be 0, 2 or 4, got " + std::to_string(r.msaa));
  r.no_shadows = !c.boolean_or("shadows", true);
  r.wireframe = c.boolean_or("wireframe", false);
  r.ambient_occlusion = c.boolean_or("ambient_occlusion", false);
  r.png_level = c.integer_in_or("png_level", r.png_level, 0, 9);
  r.background = c.string_or("background", r.background);
  if (r.background != "transparent") parse_color(r.background, c.file() + ": " + c.pointer() + "/background");
  const JsonCursor ground = c.child_or_empty("ground");
  ground.expect_object({"grid", "visible"});
  scene.grid = ground.boolean_or("grid", true);
  r.no_ground = !ground.boolean_or("visible", true);
  parse_camera(c.child_or_empty("camera"), scene);
}

}  // namespace

const char* scene_type_name(std::optional<sim::BodyKind> kind) {
  if (!kind) return "plane";
  switch (*kind) {
    case sim::BodyKind::fixed: return "static";
    case sim::BodyKind::kinematic: return "kinematic";
    case sim::BodyKind::rigid: return "rigid";
    case sim::BodyKind::deformable: return "deformable";
  }
  return "?";
}

const char* camera_mode_name(CameraMode mode) {
  switch (mode) {
    case CameraMode::fixed: return "fixed";
    case CameraMode::orbit: return "orbit";
    case CameraMode::follow: return "follow";
  }
  return "?";
}

const char* material_model_name(sim::MaterialModel model) {
  return model == sim::MaterialModel::neo_hookean ? "neohookean" : "corotated";
}

const char* solver_name(sim::SolverMethod method) {
  switch (method) {
    case sim::SolverMethod::cr: return "cr";
    case sim::SolverMethod::cr_plain: return "cr-plain";
    case sim::SolverMethod::pgs: return "pgs";
  }
  return "?";
}

int SceneDesc::frame_count() const {
  // A hair of slack so that duration 3 at 30 fps gives 91 frames, not 90.
  return static_cast<int>(std::floor(duration * render.fps + 1e-9)) + 1;
}

const SceneBody* SceneDesc::find(const std::string& body_name) const {
  for (const SceneBody& b : bodies)
    if (b.name == body_name) return &b;
  return nullptr;
}

SceneDesc parse_scene(const nlohmann::json& document, const std::string& file, const fs::path& base_dir,
                      ImportedMeshes imported) {
  SceneDesc scene;
  const JsonCursor root(document, file);
  root.expect_object({"recoil", "name", "description", "simulation", "bodies", "render"});
  if (!root.has("recoil")) root.fail("missing \"recoil\": 1 (the scene format version)");
  const JsonCursor version = root.child("recoil");
  if (version.integer_in(0, 1 << 30) != 1)
    version.fail("unsupported scene format version " + version.value().dump() + " (this recoil reads version 1)");
  scene.name = root.string_or("name", fs::path(file).stem().string());
  if (const std::string why = unsafe_name_reason(scene.name); !why.empty())
    (root.has("name") ? root.child("name") : root).fail(root.has("name") ? why : "the file's name " + why + "; give \"name\"");
  if (root.has("description")) scene.description = root.child("description").string();
  parse_simulation(root.child_or_empty("simulation"), scene);
  const JsonCursor bodies_field = root.child("bodies");
  if (bodies_field.value().is_array() && bodies_field.value().size() > static_cast<size_t>(kMaxBodies))
    bodies_field.fail(std::to_string(bodies_field.value().size()) + " bodies; at most " + std::to_string(kMaxBodies));
  const std::vector<JsonCursor> bodies = bodies_field.elements();
  if (bodies.empty()) bodies_field.fail("a scene needs at least one body");
  parse_bodies(bodies, base_dir, scene, std::move(imported));
  parse_render(root.child_or_empty("render"), scene);
  return scene;
}

SceneDesc load_scene(const fs::path& file) {
  require_regular_file(file, "the scene file");
  std::error_code ec;
  // Its parsed form takes about ten times the text: the size is bounded first.
  if (const auto size = fs::file_size(file, ec); !ec && size > kMaxSceneBytes)
    throw bad_input(file.string() + ": the scene file is " + std::to_string(size >> 20) + " MiB; at most " +
                    std::to_string(kMaxSceneBytes >> 20) + " MiB");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw bad_input(file.string() + ": cannot read the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  const nlohmann::json document = parse_json_text(text.str(), file.string());
  SceneDesc scene = parse_scene(document, file.string(), file.parent_path().empty() ? fs::path(".") : file.parent_path());
  scene.file = file;
  return scene;
}

}  // namespace recoil::cli
