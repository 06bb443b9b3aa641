// The EGL backend of GlContext (context.h): Mesa's surfaceless platform
// (EGL_MESA_platform_surfaceless) and a context with no surface
// (EGL_KHR_surfaceless_context). The display is initialised once per process
// and never terminated: eglTerminate is not reference-counted, and another
// renderer may still use it.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <mutex>
#include <string>

#include "core/error.h"
#include "render/context.h"

namespace recoil::render {
namespace {

std::string egl_error_text() {
  char text[16];
  std::snprintf(text, sizeof text, "0x%04x", static_cast<unsigned>(eglGetError()));
  return text;
}

[[noreturn]] void fail(const std::string& what) {
  throw Error(ErrorKind::internal, "cannot create an OpenGL 3.3 core context with EGL: " + what +
                                       "; rendering through EGL needs Mesa's libegl-mesa0 (22.x or newer) — "
                                       "install it (scripts/install-deps.sh), try --gl osmesa, or run with --no-render");
}

EGLDisplay surfaceless_display() {
  static std::once_flag once;
  static EGLDisplay display = EGL_NO_DISPLAY;
  static std::string problem;
  std::call_once(once, [] {
    const char* extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!extensions || std::string(extensions).find("EGL_MESA_platform_surfaceless") == std::string::npos) {
      problem = "the EGL library offers no surfaceless platform (EGL_MESA_platform_surfaceless)";
      return;
    }
    const auto get_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_display) {
      problem = "eglGetPlatformDisplayEXT is missing";
      return;
    }
    EGLDisplay d = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (d == EGL_NO_DISPLAY || !eglInitialize(d, &major, &minor)) {
      problem = "eglInitialize failed (" + egl_error_text() + ")";
      return;
    }
    display = d;
  });
  if (display == EGL_NO_DISPLAY) fail(problem);
  return display;
}

class EglContext final : public BackendContext {
 public:
  EglContext() : m_display(surfaceless_display()) {
    if (!eglBindAPI(EGL_OPENGL_API)) fail("desktop OpenGL is not offered (" + egl_error_text() + ")");
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 3,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    m_context = eglCreateContext(m_display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (m_context == EGL_NO_CONTEXT) fail("eglCreateContext failed (" + egl_error_text() + ")");
  }
  ~EglContext() override { eglDestroyContext(m_display, m_context); }

  void bind() override {
    if (!eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context))
      throw Error(ErrorKind::internal, "eglMakeCurrent failed for the offscreen OpenGL context (" + egl_error_text() + ")");
  }
  void release() override { eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }

 private:
  EGLDisplay m_display;
  EGLContext m_context = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<BackendContext> make_egl_context() { return std::make_unique<EglContext>(); }

}  // namespace recoil::render
