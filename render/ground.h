#pragma once
// The studio floor: a square at y = height centred under the scene, sized so
// its fade-out ring (drawn by the ground shader) ends inside it.
#include "render/gl_objects.h"

namespace recoil::render {

struct GroundLayout {
  double center_x = 0.0;   // metres, world
  double center_z = 0.0;
  double height = 0.0;     // the plane y = height
  double fade_start = 1.0; // radius where the floor starts fading into the background
  double fade_end = 3.0;   // radius where it is gone; also the square's half size
  double grid_spacing = 1.0;  // major lines; minor lines every tenth
};

// Floor layout for a scene whose meshes fit in the sphere (center, radius).
GroundLayout ground_layout(double center_x, double center_z, double radius, double height);

class Ground {
 public:
  Ground();
  // Uploads the square's four corners (if the layout changed) and draws it.
  void draw(const GroundLayout& layout);

 private:
  gl::VertexArray m_vertex_array;
  gl::Buffer m_corners;
  GroundLayout m_uploaded{};
  bool m_has_upload = false;
};

}  // namespace recoil::render
