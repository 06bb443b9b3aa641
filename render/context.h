#pragma once
// GlContext: an offscreen OpenGL 3.3 core-profile context, so rendering needs
// no display. Two backends give it: OSMesa (Mesa's llvmpipe in software) and
// EGL on Mesa's surfaceless platform (llvmpipe too where the machine has no
// GPU render node, the GPU where it has one). Every pass draws into the
// renderer's own framebuffer objects, so neither needs a window surface.
// This and the two backend files are the only places that touch osmesa.h or
// EGL; the GL entry points render/ calls dispatch to whichever context is current.
#include <memory>
#include <string>

#include "render/gl_backend.h"

namespace recoil::render {

// One backend's context, made current or released on the calling thread.
class BackendContext {
 public:
  virtual ~BackendContext() = default;
  virtual void bind() = 0;
  virtual void release() = 0;
};

// Each throws recoil::Error(internal) saying what is missing when its library
// cannot give a 3.3 core context.
std::unique_ptr<BackendContext> make_osmesa_context();
std::unique_ptr<BackendContext> make_egl_context();

class GlContext {
 public:
  // Creates the context and makes it current on the calling thread.
  explicit GlContext(GlBackend backend = GlBackend::automatic);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Makes this context current on the calling thread, releasing the one that
  // was (cheap when this one already is).
  void make_current();

  GlBackend backend() const { return m_backend; }  // the one in use: never automatic
  // GL_RENDERER and GL_VERSION strings, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string renderer_name();
  std::string version();

 private:
  GlBackend m_backend;
  std::unique_ptr<BackendContext> m_context;
};

}  // namespace recoil::render
