#include "render/gl_backend.h"

namespace recoil::render {

std::optional<GlBackend> parse_gl_backend(const std::string& name) {
  if (name == "auto") return GlBackend::automatic;
  if (name == "osmesa") return GlBackend::osmesa;
  if (name == "egl") return GlBackend::egl;
  return std::nullopt;
}

const char* gl_backend_name(GlBackend backend) {
  switch (backend) {
    case GlBackend::automatic: return "auto";
    case GlBackend::osmesa: return "osmesa";
    case GlBackend::egl: return "egl";
  }
  return "auto";
}

}  // namespace recoil::render
