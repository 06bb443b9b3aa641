#pragma once
// Surface files a command has already read while building a scene (drop,
// turntable), handed to the scene parser so it does not read them again.
#include <filesystem>
#include <map>

#include "sim/geometry/tri_mesh.h"

namespace recoil::cli {

// By absolute, lexically normal path; each mesh as read (before any "up").
using ImportedMeshes = std::map<std::filesystem::path, sim::TriMesh>;

}  // namespace recoil::cli
