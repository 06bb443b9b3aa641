#pragma once
// Camera: a pinhole looking from `eye` at `target`, plus the helpers a
// turntable needs (fit a bounding sphere, orbit about it). Angles in degrees,
// lengths in metres, world y up.
#include <Eigen/Core>

namespace recoil::render {

struct Camera {
  Eigen::Vector3d eye{0.0, 1.0, 3.0};
  Eigen::Vector3d target{0.0, 0.0, 0.0};
  Eigen::Vector3d up{0.0, 1.0, 0.0};
  double fov_y_degrees = 40.0;  // full vertical field of view

  // World to camera (OpenGL convention: camera looks down -z). 4 by 4.
  Eigen::Matrix4d view_matrix() const;
  // Camera to clip space for a symmetric frustum; aspect = width / height.
  Eigen::Matrix4d projection_matrix(double aspect, double near_plane, double far_plane) const;
};

// Near and far plane distances (metres, along the view direction).
struct DepthRange {
  double near_plane = 0.01;
  double far_plane = 100.0;
};

// The tightest planes holding the box [lo, hi] (with a little slack), with
// near clamped to far / 10^4 so a 24-bit depth buffer keeps sub-millimetre
// precision at metre scales even when the eye is inside the box.
DepthRange depth_range(const Camera& camera, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

// A camera at (azimuth, elevation) about `center` whose view just holds the
// sphere (center, radius) times `margin`, horizontally and vertically.
// Azimuth 0 puts the eye on +z, 90 on +x; elevation 90 looks straight down.
Camera frame_bounding_sphere(const Eigen::Vector3d& center, double radius, double azimuth_deg,
                             double elevation_deg, double fov_y_deg, double aspect, double margin = 1.05);

// Azimuth (degrees) of frame `frame` of `frame_count` when the camera makes
// `turns` turns: the last frame stops one step short of the first, so a
// looping turntable repeats no frame.
double orbit_azimuth_deg(int frame, int frame_count, double turns = 1.0, double start_deg = 0.0);

// `camera` rotated by `azimuth_deg` about the vertical axis through its target.
Camera orbit(const Camera& camera, double azimuth_deg);

}  // namespace recoil::render
