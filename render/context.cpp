#include "render/context.h"

#include <GL/osmesa.h>

#include <array>

#include "core/error.h"

namespace recoil::render {

struct GlContext::State {
  OSMesaContext context = nullptr;
  // OSMesaMakeCurrent needs a colour buffer, but every pass draws into our own
  // framebuffer objects, so one pixel is enough.
  std::array<unsigned char, 4> default_buffer{};
};

GlContext::GlContext() : m_state(std::make_unique<State>()) {
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_ACCUM_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  m_state->context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (m_state->context == nullptr) {
    throw Error(ErrorKind::internal,
                "cannot create an OpenGL 3.3 core context with OSMesa; rendering needs Mesa's "
                "libosmesa6 (22.x or newer, llvmpipe driver) — install it (scripts/install-deps.sh) "
                "or run with --no-render");
  }
  make_current();
}

GlContext::~GlContext() {
  if (m_state && m_state->context != nullptr) OSMesaDestroyContext(m_state->context);
}

void GlContext::make_current() {
  if (OSMesaGetCurrentContext() == m_state->context) return;
  if (!OSMesaMakeCurrent(m_state->context, m_state->default_buffer.data(), GL_UNSIGNED_BYTE, 1, 1)) {
    throw Error(ErrorKind::internal, "OSMesaMakeCurrent failed for the offscreen OpenGL context (libosmesa6)");
  }
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
