#pragma once
// The render options shared by `run`, `drop` and `turntable`,
// parsed from the command line into render::RenderSettings.
#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <optional>
#include <string>

#include "render/png.h"
#include "render/renderer.h"

namespace recoil::cli {

struct RenderOptions {
  std::string resolution = "1280x720";  // WxH
  double fps = 30.0;
  int msaa = 4;
  bool no_shadows = false;
  bool no_ground = false;               // the ground plane is not drawn
  std::string background = "#1d2127";   // #rrggbb or "transparent"
  bool wireframe = false;
  bool ambient_occlusion = false;
  bool no_ambient_occlusion = false;    // --no-ao: off even where a scene file turns it on
  std::string color;                    // #rrggbb, empty: the default palette
  double camera_distance = 0.0;         // metres from the target; 0: fit the scene
  double azimuth = 0.0;                 // degrees about +y from +z (only when given)
  double fov = 40.0;                    // vertical, degrees (only when given)
  std::string camera_position;          // "x,y,z" metres (only when given)
  std::string camera_target;            // "x,y,z" metres (only when given)
  int png_level = 1;
  std::string gl = "auto";              // the OpenGL backend: auto, osmesa or egl (a property of the machine, not the scene)
};

// Adds --resolution, --fps, --msaa, --no-shadows, --ao, --no-ground, --background, --wireframe,
// --color, --camera-distance, --azimuth, --fov, --camera-position,
// --camera-target, --png-level, --gl to `command`, in a "Rendering" group.
void add_render_options(CLI::App& command, RenderOptions& options);

// Validated settings; throws recoil::Error(bad_input) naming the option.
render::RenderSettings to_render_settings(const RenderOptions& options);
render::PngOptions to_png_options(const RenderOptions& options);

// "#rrggbb" (or "rrggbb") as sRGB components in [0, 1]; throws bad_input
// naming `what` (the option or field) for anything else.
render::Rgb parse_color(const std::string& text, const std::string& what);

// "x,y,z" as a point in metres; throws bad_input naming `what` otherwise.
Eigen::Vector3d parse_point(const std::string& text, const std::string& what);

// The colour of the i-th body when none is given: a soft, distinguishable
// palette of 8-bit colours, so a scene file records them exactly.
render::Rgb palette_color(int index);

}  // namespace recoil::cli
