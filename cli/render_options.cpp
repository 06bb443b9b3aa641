#include "cli/number_range.h"
#include "cli/render_options.h"

#include <cstdio>
#include <cstdlib>

#include "cli/scene_limits.h"
#include "core/error.h"

namespace recoil::cli {

void add_render_options(CLI::App& command, RenderOptions& options) {
  const std::string group = "Rendering";
  command.add_option("--resolution", options.resolution, "Frame size WxH in pixels")
      ->group(group)->capture_default_str();
  command.add_option("--fps", options.fps, "Frames per second of the output")
      ->check(NumberIn(kFpsRange.lo, kFpsRange.hi))->group(group)->capture_default_str();
  command.add_option("--msaa", options.msaa, "Anti-aliasing samples per pixel: 0, 2 or 4 (2 only where the OpenGL driver has it; llvmpipe has 4 only)")
      ->check(CLI::IsMember({0, 2, 4}))->group(group)->capture_default_str();
  command.add_flag("--no-shadows", options.no_shadows, "Skip the key light's shadow (faster)")->group(group);
  CLI::Option* ao = command.add_flag("--ao", options.ambient_occlusion,
                                     "Ambient occlusion: creases, and the floor where a body meets it, darken (a "
                                     "quarter to a third more render time)")
                        ->group(group);
  command.add_flag("--no-ao", options.no_ambient_occlusion,
                   "No ambient occlusion (the default; also over a scene file's \"ambient_occlusion\": true)")
      ->group(group)->excludes(ao);
  command.add_flag("--no-ground", options.no_ground,
                   "Draw no ground (it still holds the bodies up); over --background transparent the ground is "
                   "otherwise a shadow catcher: the shadows alone")
      ->group(group);
  command.add_option("--background", options.background, "Background #rrggbb, or 'transparent' for alpha 0")
      ->group(group)->capture_default_str();
  command.add_flag("--wireframe", options.wireframe, "Draw triangle edges over the shading")->group(group);
  command.add_option("--color", options.color, "Colour of the bodies, #rrggbb, in place of the mesh files' own materials, textures and vertex colours (default: those, else a palette)")->group(group);
  command.add_option("--camera-distance", options.camera_distance,
                     "Camera distance from its target in metres (default: fit the scene)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            const double d = std::strtod(text.c_str(), nullptr);
            return d == 0.0 || kCameraDistanceRange.contains(d) ? "" : "must be 0 (fit) or " + kCameraDistanceRange.describe();
          },
          "0 (fit) or METRES"))
      ->group(group);
  command.add_option("--azimuth", options.azimuth,
                     "Camera direction about the vertical, degrees from +Z towards +X (a turntable's first frame)")
      ->check(NumberIn(kAngleRange.lo, kAngleRange.hi))->group(group);
  command.add_option("--fov", options.fov, "Vertical field of view, degrees")->check(NumberIn(1.0, 170.0))->group(group);
  command.add_option("--camera-position", options.camera_position,
                     "Camera position X,Y,Z in metres (a fixed camera; not with --camera-distance or an orbit)")
      ->group(group);
  command.add_option("--camera-target", options.camera_target, "Point X,Y,Z the camera looks at, metres (default: the scene's centre)")
      ->group(group);
  command.add_option("--png-level", options.png_level, "PNG compression 0 (fastest) to 9 (smallest)")
      ->check(WholeNumberIn(0, 9))->group(group)->capture_default_str();
  command.add_option("--gl", options.gl,
                     "OpenGL backend: osmesa (software), egl (Mesa's surfaceless EGL: llvmpipe, or the GPU of a "
                     "render node) or auto (OSMesa, else EGL); both draw identical frames on llvmpipe")
      ->check(CLI::IsMember({"auto", "osmesa", "egl"}))->group(group)->capture_default_str();
}

render::Rgb parse_color(const std::string& text, const std::string& what) {
  const std::string hex = !text.empty() && text[0] == '#' ? text.substr(1) : text;
  unsigned r = 0, g = 0, b = 0;
  int consumed = 0;
  if (hex.size() != 6 || std::sscanf(hex.c_str(), "%2x%2x%2x%n", &r, &g, &b, &consumed) != 3 || consumed != 6)
    throw bad_input(what + ": expected a colour #rrggbb, got '" + text + "'");
  return {r / 255.0f, g / 255.0f, b / 255.0f};
}

Eigen::Vector3d parse_point(const std::string& text, const std::string& what) {
  Eigen::Vector3d p;
  int consumed = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf%n", &p.x(), &p.y(), &p.z(), &consumed) != 3 ||
      consumed != static_cast<int>(text.size()) || !p.allFinite() ||
      (p.array().abs() > kCoordinateRange.hi).any())
    throw bad_input(what + ": expected X,Y,Z in metres (each " + kCoordinateRange.describe() + "), got '" + text + "'");
  return p;
}

render::RenderSettings to_render_settings(const RenderOptions& options) {
  render::RenderSettings settings;
  int width = 0, height = 0, consumed = 0;
  if (std::sscanf(options.resolution.c_str(), "%dx%d%n", &width, &height, &consumed) != 2 ||
      consumed != static_cast<int>(options.resolution.size()) || width < 16 || height < 16 || width > 16384 ||
      height > 16384)
    throw bad_input("--resolution: expected WxH between 16x16 and 16384x16384, got '" + options.resolution + "'");
  settings.width = width;
  settings.height = height;
  settings.msaa = options.msaa;
  settings.shadows = !options.no_shadows;
  settings.ground = !options.no_ground;
  settings.wireframe = options.wireframe;
  settings.ambient_occlusion = options.ambient_occlusion && !options.no_ambient_occlusion;
  if (options.background == "transparent") settings.transparent_background = true;
  else settings.background = parse_color(options.background, "--background");
  if (!kFpsRange.contains(options.fps)) throw bad_input("--fps: must be " + kFpsRange.describe());
  const std::optional<render::GlBackend> gl = render::parse_gl_backend(options.gl);
  if (!gl) throw bad_input("--gl: expected auto, osmesa or egl, got '" + options.gl + "'");
  settings.gl = *gl;
  return settings;
}

render::PngOptions to_png_options(const RenderOptions& options) {
  render::PngOptions png;
  png.level = options.png_level;
  png.alpha = options.background == "transparent";  // frames over a colour are opaque
  return png;
}

render::Rgb palette_color(int index) {
  // Warm clay first (the hero body), then muted, well-separated hues.
  static const char* const palette[] = {"#d9a066", "#609ec7", "#91bc75", "#d47578",
                                        "#a68fc9", "#e2c668", "#69bbb4", "#c799b8"};
  return parse_color(palette[index % (sizeof(palette) / sizeof(palette[0]))], "palette");
}

}  // namespace recoil::cli
