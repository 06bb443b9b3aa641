#pragma once
// The studio floor: a square at y = height centred under the scene, sized so
// its fade-out ring (drawn by the ground shader) ends inside it. The square is
// cut into a 3 by 3 grid whose middle cell holds every shadow the key light can
// cast on it and every place the ambient occlusion can darken, so the lookups
// for those run on that cell only.
#include <Eigen/Core>
#include <optional>

#include "render/gl_objects.h"

namespace recoil::render {

// A rectangle of the floor: world x in [x0, x1], z in [z0, z1] (metres).
struct FloorRect {
  double x0 = 0.0, x1 = 0.0, z0 = 0.0, z1 = 0.0;
  FloorRect united(const FloorRect& other) const;
  bool operator==(const FloorRect& other) const = default;
};

struct GroundLayout {
  double center_x = 0.0;   // metres, world
  double center_z = 0.0;
  double height = 0.0;     // the plane y = height
  double fade_start = 1.0; // radius where the floor starts fading into the background
  double fade_end = 3.0;   // radius where it is gone; also the square's half size
  double grid_spacing = 1.0;  // major lines; minor lines every tenth
  // The middle cell, inside the square; the whole square until set_cell().
  FloorRect cell;
};

// Floor layout for a scene whose meshes fit in the sphere (center, radius).
GroundLayout ground_layout(double center_x, double center_z, double radius, double height);

// The floor (y = height) a sphere (center, radius) can shadow under a
// directional light (to_light, unit), grown by `reach` metres of the lookups'
// own spread; none where the light is so low that the shadow stretches across
// the whole floor.
std::optional<FloorRect> shadow_reach(double height, const Eigen::Vector3d& center, double radius,
                                      const Eigen::Vector3d& to_light, double reach);
// The floor within `reach` metres of the box [lo, hi], seen from above.
FloorRect near_reach(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double reach);
// Sets the middle cell to `cell` clamped into the square.
void set_cell(GroundLayout& layout, const FloorRect& cell);

class Ground {
 public:
  Ground();
  // Each uploads the grid's corners if the layout changed, then draws.
  void draw(const GroundLayout& layout);           // the whole square
  void draw_cell(const GroundLayout& layout);      // the middle cell only
  void draw_surround(const GroundLayout& layout);  // the eight cells around it

 private:
  void bind(const GroundLayout& layout);

  gl::VertexArray m_vertex_array;
  gl::Buffer m_corners;   // 4 by 4 vertices, row-major in z then x
  gl::Buffer m_elements;  // the middle cell's 6 indices, then the surround's 48
  GroundLayout m_uploaded{};
  bool m_has_upload = false;
};

}  // namespace recoil::render
