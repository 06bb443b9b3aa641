#pragma once
// Which library gives the renderer its OpenGL context (render/context.h),
// and its names on the command line. Kept apart from the context so that
// option parsing needs no OpenGL library.
#include <optional>
#include <string>

namespace recoil::render {

enum class GlBackend {
  automatic,  // OSMesa, and EGL when OSMesa cannot give a context
  osmesa,
  egl,
};

// "auto", "osmesa" or "egl" as the command line spells them; nullopt for anything else.
std::optional<GlBackend> parse_gl_backend(const std::string& name);
const char* gl_backend_name(GlBackend backend);

}  // namespace recoil::render
