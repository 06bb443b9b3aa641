#pragma once
// Move-only owners of OpenGL object names. Each deletes its object in the
// destructor, so the context that created it must be current then (Renderer
// makes its context current before its members are destroyed).
#include <utility>

#include "render/gl.h"

namespace recoil::render::gl {

// Deleter signatures differ (glDeleteProgram takes one name, glDeleteBuffers
// a count and an array), so each kind supplies a small policy.
template <typename Policy>
class Object {
 public:
  Object() = default;
  explicit Object(GLuint name) : m_name(name) {}
  ~Object() { reset(); }
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;
  Object(Object&& other) noexcept : m_name(std::exchange(other.m_name, 0)) {}
  Object& operator=(Object&& other) noexcept {
    if (this != &other) {
      reset();
      m_name = std::exchange(other.m_name, 0);
    }
    return *this;
  }

  // Creates a fresh object, deleting any held one.
  static Object create() { return Object(Policy::create()); }
  GLuint get() const { return m_name; }
  explicit operator bool() const { return m_name != 0; }
  void reset() {
    if (m_name != 0) Policy::destroy(m_name);
    m_name = 0;
  }

 private:
  GLuint m_name = 0;
};

struct BufferPolicy {
  static GLuint create() { GLuint n = 0; glGenBuffers(1, &n); return n; }
  static void destroy(GLuint n) { glDeleteBuffers(1, &n); }
};
struct VertexArrayPolicy {
  static GLuint create() { GLuint n = 0; glGenVertexArrays(1, &n); return n; }
  static void destroy(GLuint n) { glDeleteVertexArrays(1, &n); }
};
struct TexturePolicy {
  static GLuint create() { GLuint n = 0; glGenTextures(1, &n); return n; }
  static void destroy(GLuint n) { glDeleteTextures(1, &n); }
};
struct FramebufferPolicy {
  static GLuint create() { GLuint n = 0; glGenFramebuffers(1, &n); return n; }
  static void destroy(GLuint n) { glDeleteFramebuffers(1, &n); }
};
struct RenderbufferPolicy {
  static GLuint create() { GLuint n = 0; glGenRenderbuffers(1, &n); return n; }
  static void destroy(GLuint n) { glDeleteRenderbuffers(1, &n); }
};
struct ProgramPolicy {
  static GLuint create() { return glCreateProgram(); }
  static void destroy(GLuint n) { glDeleteProgram(n); }
};

using Buffer = Object<BufferPolicy>;
using VertexArray = Object<VertexArrayPolicy>;
using Texture = Object<TexturePolicy>;
using Framebuffer = Object<FramebufferPolicy>;
using Renderbuffer = Object<RenderbufferPolicy>;
using Program = Object<ProgramPolicy>;

}  // namespace recoil::render::gl
