#pragma once
// The scene `recoil drop` builds: a ground plane and the meshes above it,
// sized sensibly, one each side by side or `count` copies in a loose pile
// (seeded, so reruns match). It is built as a scene file document so that
// --save-scene writes exactly what runs, and `run` can rerun it.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/imported_meshes.h"
#include "cli/up_axis.h"

namespace recoil::cli {

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
  // Every body's collision surface: at most this many triangles (0: the mesh
  // itself), or tiled at this edge length (m); neither (-1, 0): the default.
  int collision_triangles = -1;
  double collision_edge = 0.0;
};

// A scene file document with absolute mesh paths; the meshes read to size it
// go into `imported` when given. Throws bad_input naming the mesh for
// unreadable or empty meshes.
nlohmann::json build_drop_scene(const DropSettings& settings, ImportedMeshes* imported = nullptr);

}  // namespace recoil::cli
