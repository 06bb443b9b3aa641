#include "cli/scene_view.h"

#include <Eigen/Geometry>
#include <cmath>

#include "cli/render_bridge.h"
#include "core/check.h"
#include "sim/geometry/primitives.h"

namespace recoil::cli {
namespace {

// A plane this close to facing +y is drawn by the renderer's own ground.
constexpr double kHorizontal = 0.9999;
// Tilted planes are drawn as square slabs this wide and thick (metres).
constexpr double kSlabSize = 12.0;
constexpr double kSlabThickness = 0.02;
const render::Rgb kSlabColor = {0.55f, 0.56f, 0.58f};

sim::TriMesh slab_for(const sim::PlaneDesc& plane) {
  const Eigen::Vector3d n = plane.normal.normalized();
  sim::TriMesh slab = sim::make_box(Eigen::Vector3d(kSlabSize, kSlabThickness, kSlabSize), 4);
  const Eigen::Matrix3d R = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitY(), n).toRotationMatrix();
  sim::transform_in_place(slab, R, Eigen::Vector3d::Ones(), plane.point - 0.5 * kSlabThickness * n);
  return slab;
}

}  // namespace

SceneView::SceneView(const SceneDesc& scene, const std::vector<sim::BodySurface>& surfaces, double aspect)
    : m_camera(scene.camera), m_aspect(aspect) {
  m_render.ground = false;
  m_render.grid = scene.grid;
  bool have_ground = false;
  for (const SceneBody& body : scene.bodies) {
    if (!body.is_plane()) continue;
    const sim::PlaneDesc& plane = scene.world.planes[static_cast<size_t>(body.index)];
    if (plane.normal.normalized().y() > kHorizontal && !have_ground) {
      have_ground = true;
      m_render.ground = true;
      m_render.ground_height = static_cast<float>(plane.point.y());
    } else {
      m_render.meshes.push_back(to_render_mesh(slab_for(plane), kSlabColor));
      m_render.meshes.back().rigid = true;
    }
  }
  RenderLookCache looks;
  for (size_t i = 0; i < surfaces.size(); ++i) {
    const sim::BodySurface& s = surfaces[i];
    const SceneBody* body = scene.find(s.name);
    const render::Rgb color = body ? body->color : palette_color(static_cast<int>(i));
    const float opacity = body ? body->opacity : 1.0f;
    sim::TriMesh mesh{s.positions, s.triangles, body && body->color_given ? nullptr : s.look};
    m_mesh_of_surface.push_back(static_cast<int>(m_render.meshes.size()));
    m_render.meshes.push_back(to_render_mesh(mesh, color, opacity, &looks));
    m_render.meshes.back().rigid = s.kind != sim::BodyKind::deformable;
    const sim::Aabb b = sim::bounding_box(s.positions);
    if (!b.valid()) continue;
    if (s.name == m_camera.body) {
      m_follow = static_cast<int>(i);
      m_follow_box = b;
      // Room around the body so its surroundings show: a few body sizes.
      m_follow_radius = std::max(1.5 * b.extent().norm(), 0.1);
    }
    m_fit_box.extend(b.min);
    m_fit_box.extend(b.max);
  }
  m_have_ground = have_ground;
  track({});
  if (!m_fit_box.valid()) {
    m_fit_box.extend(Eigen::Vector3d::Constant(-0.5));
    m_fit_box.extend(Eigen::Vector3d::Constant(0.5));
  }
  m_first_center = m_fit_box.center();
}

void SceneView::track(const std::vector<sim::Aabb>& bounds) {
  for (const sim::Aabb& b : bounds) {
    if (!b.valid() || !b.min.allFinite() || !b.max.allFinite()) continue;
    m_fit_box.extend(b.min);
    m_fit_box.extend(b.max);
  }
  // Keep the landing spot in view: the footprint on the ground too.
  if (m_have_ground && m_fit_box.valid()) {
    m_fit_box.extend(Eigen::Vector3d(m_fit_box.min.x(), m_render.ground_height, m_fit_box.min.z()));
    m_fit_box.extend(Eigen::Vector3d(m_fit_box.max.x(), m_render.ground_height, m_fit_box.max.z()));
  }
}

const render::RenderScene& SceneView::update(const std::vector<sim::BodySurface>& surfaces) {
  RECOIL_CHECK(surfaces.size() == m_mesh_of_surface.size(),
               "surfaces=" << surfaces.size() << " meshes=" << m_mesh_of_surface.size());
  for (size_t i = 0; i < surfaces.size(); ++i)
    update_positions(m_render.meshes[static_cast<size_t>(m_mesh_of_surface[i])], surfaces[i].positions);
  if (m_follow >= 0) m_follow_box = sim::bounding_box(surfaces[static_cast<size_t>(m_follow)].positions);
  return m_render;
}

render::Camera SceneView::camera(int frame, int frame_count) const {
  const CameraDesc& c = m_camera;
  auto place = [&](const Eigen::Vector3d& target, double radius, double azimuth) {
    render::Camera cam = render::frame_bounding_sphere(target, radius, azimuth, c.elevation, c.fov, m_aspect);
    if (c.distance > 0) cam.eye = cam.target + c.distance * (cam.eye - cam.target).normalized();
    return cam;
  };
  const Eigen::Vector3d target = c.has_target ? c.target : m_fit_box.center();
  const double fit_radius = std::max(0.5 * m_fit_box.extent().norm(), 0.05);
  switch (c.mode) {
    case CameraMode::fixed: {
      if (!c.has_position) return place(target, fit_radius, c.azimuth);
      // A camera standing somewhere looks at the first frame's centre and stays.
      render::Camera cam;
      cam.target = c.has_target ? c.target : m_first_center;
      cam.eye = c.position;
      cam.fov_y_degrees = c.fov;
      return cam;
    }
    case CameraMode::orbit:
      return place(target, fit_radius, render::orbit_azimuth_deg(frame - 1, frame_count, c.turns, c.azimuth));
    case CameraMode::follow: {
      if (m_follow < 0) return place(target, fit_radius, c.azimuth);
      const sim::Aabb& b = m_follow_box;
      if (!b.valid() || !b.min.allFinite() || !b.max.allFinite()) return place(target, fit_radius, c.azimuth);
      return place(b.center(), m_follow_radius, c.azimuth);
    }
  }
  return place(target, fit_radius, c.azimuth);
}

}  // namespace recoil::cli
