#pragma once
// GlContext: an offscreen OpenGL 3.3 core-profile context from OSMesa
// (software rendering with Mesa's llvmpipe), so rendering needs no display
// and no GPU. This is the only place that touches GL/osmesa.h; an EGL backend
// would sit beside it with the same interface.
#include <memory>
#include <string>

namespace recoil::render {

class GlContext {
 public:
  // Creates the context and makes it current on the calling thread. Throws
  // recoil::Error when OSMesa cannot give a 3.3 core context (missing or too
  // old libosmesa6 / Mesa).
  GlContext();
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Makes this context current on the calling thread (cheap when it already is).
  void make_current();

  // GL_RENDERER and GL_VERSION strings, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string renderer_name();
  std::string version();

 private:
  struct State;
  std::unique_ptr<State> m_state;
};

}  // namespace recoil::render
