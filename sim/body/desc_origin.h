#pragma once
// DescOrigin: where a description came from, so that an error about it names
// what the user wrote (the scene file and the field) rather than an index
// into one of World's lists.
#include <string>

namespace recoil::sim {

struct DescOrigin {
  std::string file;     // the scene file as the user named it; empty for a description built in code
  std::string pointer;  // JSON pointer of the description in `file`, e.g. "/bodies/3"
  std::string mesh;     // the mesh file its surface was read from; empty for a primitive or one built in code

  // The start of a message about the description: "FILE: /bodies/3", or
  // `in_code` (e.g. "rigid_bodies/0") for one built in code.
  std::string where(const std::string& in_code) const { return file.empty() ? in_code : file + ": " + pointer; }
  // The start of a message about its surface, given where(): "FILE: /bodies/3/mesh (/abs/statue.stl)".
  std::string mesh_field(const std::string& where) const {
    return where + "/mesh" + (mesh.empty() ? "" : " (" + mesh + ")");
  }
};

}  // namespace recoil::sim
