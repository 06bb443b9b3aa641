// The OSMesa backend of GlContext (context.h).
#include <GL/osmesa.h>

#include <array>

#include "core/error.h"
#include "render/context.h"

namespace recoil::render {
namespace {

class OsmesaContext final : public BackendContext {
 public:
  OsmesaContext() {
    const int attributes[] = {OSMESA_FORMAT,        OSMESA_RGBA,         OSMESA_DEPTH_BITS,           0,
                              OSMESA_STENCIL_BITS,  0,                   OSMESA_ACCUM_BITS,           0,
                              OSMESA_PROFILE,       OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                              OSMESA_CONTEXT_MINOR_VERSION, 3,           0};
    m_context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (m_context == nullptr) {
      throw Error(ErrorKind::internal,
                  "cannot create an OpenGL 3.3 core context with OSMesa; rendering needs Mesa's "
                  "libosmesa6 (22.x or newer, llvmpipe driver) — install it (scripts/install-deps.sh), "
                  "try --gl egl, or run with --no-render");
    }
  }
  ~OsmesaContext() override { OSMesaDestroyContext(m_context); }

  void bind() override {
    // OSMesaMakeCurrent needs a colour buffer, but every pass draws into the
    // renderer's own framebuffer objects, so one pixel is enough.
    if (!OSMesaMakeCurrent(m_context, m_default_buffer.data(), GL_UNSIGNED_BYTE, 1, 1))
      throw Error(ErrorKind::internal, "OSMesaMakeCurrent failed for the offscreen OpenGL context (libosmesa6)");
  }
  void release() override { OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0); }

 private:
  OSMesaContext m_context = nullptr;
  std::array<unsigned char, 4> m_default_buffer{};
};

}  // namespace

std::unique_ptr<BackendContext> make_osmesa_context() { return std::make_unique<OsmesaContext>(); }

}  // namespace recoil::render
