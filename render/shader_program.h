#pragma once
// ShaderProgram: a linked GLSL program with its uniform locations cached by
// name, so per-frame uniform updates do no string lookups in the driver.
#include <string>
#include <unordered_map>

#include "render/gl_objects.h"

namespace recoil::render {

class ShaderProgram {
 public:
  ShaderProgram() = default;
  // Compiles and links; a compile or link error is a bug in our shaders and
  // aborts through RECOIL_CHECK with the driver's log.
  ShaderProgram(const std::string& name, const std::string& vertex_source, const std::string& fragment_source);

  void use() const { glUseProgram(m_program.get()); }
  // Location of `uniform` or -1 when the compiler removed it (GL ignores -1).
  GLint location(const char* uniform);

 private:
  gl::Program m_program;
  std::unordered_map<std::string, GLint> m_locations;
};

}  // namespace recoil::render
