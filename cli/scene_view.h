#pragma once
// What a scene looks like at a frame: the world's surfaces copied into a
// render::RenderScene with each body's colour and opacity (through
// render_bridge), planes drawn as the ground (a horizontal one) or as large
// slabs (tilted ones), and the camera of the scene's mode.
#include <vector>

#include "cli/scene_desc.h"
#include "render/camera.h"
#include "render/render_scene.h"
#include "sim/world.h"

namespace recoil::cli {

class SceneView {
 public:
  // `surfaces`: the world's surfaces at time 0 (they start the framing of a
  // camera without a position); `aspect` = width / height.
  SceneView(const SceneDesc& scene, const std::vector<sim::BodySurface>& surfaces, double aspect);

  // Widens the framing of a camera without a position to hold `bounds` (the
  // bodies at one frame, sim::World::body_bounds) as well as everything
  // tracked before. Called for every frame, drawn or not, so that a frame's
  // view does not depend on which frames were drawn. The framing only ever
  // widens: a body that slides or bounces away stays in view, and the
  // camera holds still while everything stays within what it frames.
  void track(const std::vector<sim::Aabb>& bounds);

  // Updates the meshes to `surfaces` (same bodies as at construction).
  const render::RenderScene& update(const std::vector<sim::BodySurface>& surfaces);
  // The camera of frame `frame` (1-based) of `frame_count`, for the current surfaces.
  render::Camera camera(int frame, int frame_count) const;

 private:
  CameraDesc m_camera;
  double m_aspect;
  render::RenderScene m_render;
  std::vector<int> m_mesh_of_surface;            // surface i -> m_render.meshes index
  int m_follow = -1;                              // surface index of the followed body
  sim::Aabb m_follow_box;                         // its current bounds
  double m_follow_radius = 0.1;                   // m: fixed at frame 1 so the view does not breathe
  sim::Aabb m_fit_box;        // everything the bodies have covered, and their footprints on the ground
  bool m_have_ground = false;
  Eigen::Vector3d m_first_center = Eigen::Vector3d::Zero();  // of the first frame's framing
};

}  // namespace recoil::cli
