#pragma once
// Surface import through assimp (mesh_import.cpp and look_import.cpp are its only includers).
#include <filesystem>

#include "sim/geometry/tri_mesh.h"

namespace recoil::sim {

// Reads any format assimp knows (OBJ, PLY, STL, glTF/GLB, Collada, FBX, ...):
// every mesh of the file is placed under its node transforms and merged,
// polygons are triangulated, points and lines dropped, vertices at the same
// position welded (so a surface split by normals or UV seams is closed again)
// and degenerate triangles dropped; a closed surface wound inward is turned
// outward. The file's materials, base-colour
// textures, UVs and vertex colours come along as the mesh's look
// (surface_look.h), per triangle corner, so welding loses none of them; a
// texture that cannot be read is a warning in the look, not an error.
// assimp reads in a child process (isolated_reader.h), so a file that crashes
// it is a bad file like any other. Throws recoil::Error(bad_input) naming the
// file when it cannot be read or holds no triangles.
// `turned_outward`, when given, says whether the file's surface was wound inward.
TriMesh import_surface(const std::filesystem::path& path, bool* turned_outward = nullptr);

// Whether assimp has a reader for files named like `path` (by extension).
bool is_mesh_file_name(const std::filesystem::path& path);

// Welds vertices with bit-identical positions and drops triangles that then
// repeat a vertex or have zero area; unused vertices are removed. Keeps the
// first occurrence order, so the result is deterministic.
TriMesh weld_and_clean(const TriMesh& mesh);

}  // namespace recoil::sim
