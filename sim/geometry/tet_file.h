#pragma once
// Readers for conforming tetrahedral meshes (`mesh`/`tets`):
// Gmsh `.msh` (ASCII versions 2.x, 4.0 and 4.1) and TetGen `.node` + `.ele`.
// Bad files throw recoil::Error(bad_input) naming the file and line; garbage
// never crashes or hangs (counts are checked against what the file holds).
#include <filesystem>
#include <string>

#include "sim/geometry/tet_mesh.h"

namespace recoil::sim {

// Dispatches on the extension: .msh -> Gmsh; .node or .ele -> TetGen (the
// sibling file with the other extension is read too).
TetMesh read_tet_file(const std::filesystem::path& path);

// Parsers over file contents; `name` is used in error messages only. Only
// tetrahedra are kept (10-node ones as their 4 corners); other Gmsh element
// types are skipped. Tets are
// re-oriented positive; unused nodes are dropped.
TetMesh parse_gmsh(const std::string& text, const std::string& name);
TetMesh parse_tetgen(const std::string& node_text, const std::string& node_name,
                     const std::string& ele_text, const std::string& ele_name);

}  // namespace recoil::sim
