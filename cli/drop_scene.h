#pragma once
// The scene `recoil drop` builds: a ground plane and the meshes above it,
// sized sensibly, one each side by side or `count` copies in a loose pile
// (seeded, so reruns match). It is built as a scene file document so that
// --save-scene writes exactly what runs, and `run` can rerun it.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/imported_meshes.h"
#include "cli/up_axis.h"

namespace recoil::cli {

// Every body's collision surface: at most `triangles` triangles (0: the mesh
// itself), or tiled at `edge` m; neither (-1, 0): the scene's default.
struct CollisionChoice {
  int triangles = -1;
  double edge = 0.0;
};

// `--collision-triangles N` and `--collision-edge M` (one or neither) for a
// mesh command; a value the scene would refuse is a usage error (exit 2).
void add_collision_options(CLI::App& command, CollisionChoice& choice);

// The uniform scale `drop` and `turntable` give a mesh whose longest side is
// `size` (file units): 1 between 5 cm and 2 m, else what makes it 30 cm.
double drop_scale(double size);

struct DropSettings {
  std::vector<std::string> meshes;
  std::string material = "soft";  // soft | rubber | jelly | stiff | rigid | static (held where it stands)
  double height = 0.3;            // m: gap between the ground and the lowest body
  // Added to `height` for each body: this fraction of the body's longest side,
  // so a drop from the ground clears the collision surface, which reaches a
  // little below the drawn mesh.
  double height_per_size = 0.0;
  double friction = 0.5;
  int count = 1;                  // copies in the pile (cycling through the meshes); 1: one of each
  double seconds = 3.0;           // simulated
  unsigned seed = 1;              // of the pile's jitter and orientations
  UpAxis up = UpAxis::pos_y;      // of every mesh file; recorded in each body's "up"
  CollisionChoice collision;
};

// A scene file document with absolute mesh paths; the meshes read to size it
// go into `imported` when given. Throws bad_input naming the mesh for
// unreadable or empty meshes.
nlohmann::json build_drop_scene(const DropSettings& settings, ImportedMeshes* imported = nullptr);

}  // namespace recoil::cli
