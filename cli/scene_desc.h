#pragma once
// SceneDesc: a scene file as plain data, parsed apart from
// running it (pbrt style): the physics as a sim::WorldDesc, the look as
// render options and a camera, and the bodies in scene order with the colour
// and opacity they are drawn with.
#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/render_options.h"
#include "cli/up_axis.h"
#include "render/render_scene.h"
#include "sim/body/body_kind.h"
#include "sim/world_desc.h"

namespace recoil::cli {

// A body's "type" as the scene file spells it: "plane" for no kind, "static"
// for BodyKind::fixed, otherwise the kind's own name.
const char* scene_type_name(std::optional<sim::BodyKind> kind);
// "cr", "cr-plain" or "pgs", as the scene file and --solver spell them.
const char* solver_name(sim::SolverMethod method);

struct SceneBody {
  std::string name;           // unique in the scene
  std::optional<sim::BodyKind> kind;  // empty for a plane
  int index = 0;              // into world.planes, world.rigid_bodies or world.bodies (by kind)
  render::Rgb color{};        // sRGB
  bool color_given = false;   // by the scene or --color: it replaces the mesh file's own look
  float opacity = 1.0f;
  std::string pointer;        // "/bodies/3", for messages
  bool open_mesh = false;     // from a surface file that is not watertight (inside/outside by winding number)
  // Where a mesh body's shape came from, as the scene gave it (the world
  // description holds only the meshes made from it).
  std::filesystem::path mesh_file;  // absolute; empty for a primitive
  UpAxis up = UpAxis::pos_y;        // the mesh file's up axis
  nlohmann::json primitive;         // the validated "primitive" object; null for a mesh file
  std::filesystem::path tets_file;  // deformable: the "tets" file, absolute; empty: tets.resolution

  bool is_plane() const { return !kind; }
};

enum class CameraMode { fixed, orbit, follow };
// "fixed", "orbit" or "follow", as the scene file spells camera modes.
const char* camera_mode_name(CameraMode mode);
// "corotated" or "neohookean", as the scene file spells material models.
const char* material_model_name(sim::MaterialModel model);

// A camera with `has_position` false is fitted to the scene (widening as the bodies move), seen
// from `azimuth`/`elevation`; `distance` 0 means "fit".
struct CameraDesc {
  CameraMode mode = CameraMode::fixed;
  bool has_position = false;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m
  bool has_target = false;
  Eigen::Vector3d target = Eigen::Vector3d::Zero();    // m
  double fov = 40.0;         // vertical, degrees
  double azimuth = 30.0;     // degrees about +y from +z
  double elevation = 20.0;   // degrees above the horizon
  double distance = 0.0;     // m from the target; 0: fit
  double turns = 1.0;        // orbit
  std::string body;          // follow: the body kept in view
};

struct SceneDesc {
  std::string name;
  std::string description;      // free text; empty when not given
  std::filesystem::path file;   // where it was read from (empty when built in memory)
  sim::WorldDesc world;
  double duration = 3.0;        // s of simulated time; frames cover [0, duration] after the settling
  // s: at most this long is simulated before frame 1, ending once every
  // dynamic body is at rest (cli/rest_watch.h); 0: frame 1 is the initial state.
  double settle = 0.0;
  std::vector<SceneBody> bodies;  // scene order, planes included
  RenderOptions render;         // resolution, fps, msaa, shadows, background, ...
  bool grid = true;             // grid lines on the ground
  CameraDesc camera;
  // What of the mesh files' looks could not be read (a missing texture), by
  // absolute file, in file order: the bodies are drawn without it.
  std::vector<std::pair<std::filesystem::path, std::string>> look_warnings;

  // Frames in [0, duration] at render.fps: frame k shows time (k - 1) / fps.
  int frame_count() const;
  // What messages call the scene: its file, or its name when built in memory.
  std::string label() const { return file.empty() ? name : file.string(); }
  const SceneBody* find(const std::string& body_name) const;
};

}  // namespace recoil::cli
