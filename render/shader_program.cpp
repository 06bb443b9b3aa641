#include "render/shader_program.h"

#include <vector>

#include "core/check.h"

namespace recoil::render {
namespace {

std::string shader_log(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<size_t>(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  return log.data();
}

GLuint compile(const std::string& name, GLenum stage, const std::string& source) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  RECOIL_CHECK(ok == GL_TRUE, name << (stage == GL_VERTEX_SHADER ? " vertex" : " fragment")
                                   << " shader: " << shader_log(shader));
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& name, const std::string& vertex_source,
                             const std::string& fragment_source)
    : m_program(gl::Program::create()) {
  const GLuint vertex = compile(name, GL_VERTEX_SHADER, vertex_source);
  const GLuint fragment = compile(name, GL_FRAGMENT_SHADER, fragment_source);
  glAttachShader(m_program.get(), vertex);
  glAttachShader(m_program.get(), fragment);
  glLinkProgram(m_program.get());
  // The program keeps the compiled code; the shader objects can go now.
  glDetachShader(m_program.get(), vertex);
  glDetachShader(m_program.get(), fragment);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(m_program.get(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetProgramiv(m_program.get(), GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(m_program.get(), length, nullptr, log.data());
    RECOIL_CHECK(false, name << " program link: " << log.data());
  }
}

GLint ShaderProgram::location(const char* uniform) {
  auto it = m_locations.find(uniform);
  if (it == m_locations.end()) {
    it = m_locations.emplace(uniform, glGetUniformLocation(m_program.get(), uniform)).first;
  }
  return it->second;
}

}  // namespace recoil::render
