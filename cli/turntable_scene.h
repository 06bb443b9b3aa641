#pragma once
// The scene `recoil turntable` builds: the mesh stood on a ground plane and a
// camera orbiting it once, run by the same frame loop as `run` and `drop`.
// Without settling the mesh is static, as modelled; with it, the mesh is
// released just above the ground and simulated until it rests, and the orbit
// starts there. Meshes are sized as `drop` sizes them.
#include <nlohmann/json.hpp>
#include <string>

#include "cli/drop_scene.h"
#include "cli/imported_meshes.h"
#include "cli/up_axis.h"

namespace recoil::cli {

struct TurntableSettings {
  std::string mesh;
  int turn_frames = 120;          // frames in one full turn
  double fps = 30.0;              // of the scene; the turn lasts (turn_frames - 1) / fps s
  double elevation = 20.0;        // degrees above the horizon
  UpAxis up = UpAxis::pos_y;
  double settle = 0.0;            // s at most before the orbit; 0: the mesh is static
  std::string material = "rigid"; // of a settling mesh: a `drop` preset
  CollisionChoice collision;      // of a settling mesh
};

// A scene file document with an absolute mesh path; the mesh read to size it
// goes into `imported` when given. Throws bad_input naming the mesh for
// unreadable or empty meshes.
nlohmann::json build_turntable_scene(const TurntableSettings& settings, ImportedMeshes* imported = nullptr);

}  // namespace recoil::cli
