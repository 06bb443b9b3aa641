#include "render/context.h"

#include "core/error.h"
#include "render/gl.h"

namespace recoil::render {
namespace {

// The context current on this thread, across both backends: neither API knows
// when the other has taken the thread over, so switching always goes through here.
thread_local GlContext* t_current = nullptr;

}  // namespace

GlContext::GlContext(GlBackend backend) : m_backend(backend) {
  if (t_current) {  // the other backend's context must let go of the thread first
    t_current->m_context->release();
    t_current = nullptr;
  }
  if (backend == GlBackend::osmesa) {
    m_context = make_osmesa_context();
  } else if (backend == GlBackend::egl) {
    m_context = make_egl_context();
  } else {
    // OSMesa stays the default; EGL when OSMesa cannot give a context.
    try {
      m_context = make_osmesa_context();
      m_backend = GlBackend::osmesa;
    } catch (const Error& osmesa) {
      try {
        m_context = make_egl_context();
        m_backend = GlBackend::egl;
      } catch (const Error& egl) {
        throw Error(ErrorKind::internal, std::string(osmesa.what()) + "; and " + egl.what());
      }
    }
  }
  make_current();
}

GlContext::~GlContext() {
  if (t_current == this) {
    m_context->release();
    t_current = nullptr;
  }
}

void GlContext::make_current() {
  if (t_current == this) return;
  if (t_current) t_current->m_context->release();
  t_current = nullptr;
  m_context->bind();
  t_current = this;
}

std::string GlContext::renderer_name() {
  make_current();
  const GLubyte* s = glGetString(GL_RENDERER);
  return s != nullptr ? reinterpret_cast<const char*>(s) : "unknown";
}

std::string GlContext::version() {
  make_current();
  const GLubyte* s = glGetString(GL_VERSION);
  return s != nullptr ? reinterpret_cast<const char*>(s) : "unknown";
}

}  // namespace recoil::render
