#pragma once
// The studio floor: a square at y = height centred under the scene, sized so
// its fade-out ring (drawn by the ground shader) ends inside it. The square is
// cut into a 3 by 3 grid whose middle cell holds every shadow the key light can
// cast on it, so the shadow lookups run on that cell only.
#include <Eigen/Core>

#include "render/gl_objects.h"

namespace recoil::render {

struct GroundLayout {
  double center_x = 0.0;   // metres, world
  double center_z = 0.0;
  double height = 0.0;     // the plane y = height
  double fade_start = 1.0; // radius where the floor starts fading into the background
  double fade_end = 3.0;   // radius where it is gone; also the square's half size
  double grid_spacing = 1.0;  // major lines; minor lines every tenth
  // The cell that can be in shadow, inside the square (metres, world); the
  // whole square until shadow_cell() narrows it.
  double cell_x0 = 0.0, cell_x1 = 0.0, cell_z0 = 0.0, cell_z1 = 0.0;
};

// Floor layout for a scene whose meshes fit in the sphere (center, radius).
GroundLayout ground_layout(double center_x, double center_z, double radius, double height);

// Narrows the layout's cell to the floor a sphere (center, radius) can shadow
// under a directional light (to_light, unit), grown by `reach` metres of the
// lookups' own spread. A light at or below the horizon keeps the whole square.
void shadow_cell(GroundLayout& layout, const Eigen::Vector3d& center, double radius, const Eigen::Vector3d& to_light,
                 double reach);

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
