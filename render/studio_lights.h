#pragma once
// The three-point studio rig. Lights are placed relative to the camera (as
// a photographer's rig would be), so an orbiting turntable camera sees the
// subject lit the same way from every side while its shadow turns with it.
#include <Eigen/Core>

#include "render/camera.h"

namespace recoil::render {

struct StudioLight {
  Eigen::Vector3d to_light;  // unit, world space, from the subject towards the light
  Eigen::Vector3f color;     // linear radiance scale
};

struct StudioLights {
  StudioLight key;   // casts the shadow: high, front right
  StudioLight fill;  // low, front left, cool and weak: lifts the key's shadows
  StudioLight rim;   // behind, above: separates silhouettes from the background
  Eigen::Vector3f sky_ambient;     // hemisphere ambient, normals pointing up
  Eigen::Vector3f ground_ambient;  // ... and down
};

StudioLights studio_lights(const Camera& camera);

}  // namespace recoil::render
