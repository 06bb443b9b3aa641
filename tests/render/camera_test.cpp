// Camera matrices and the turntable helpers.
#include "render/camera.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <iostream>

namespace recoil::render {
namespace {

Eigen::Vector3d project(const Eigen::Matrix4d& clip_from_world, const Eigen::Vector3d& p) {
  const Eigen::Vector4d clip = clip_from_world * p.homogeneous();
  return clip.head<3>() / clip.w();
}

TEST(Camera, ViewMatrixPutsTargetOnTheAxisInFront) {
  Camera camera;
  camera.eye = {1.0, 2.0, 3.0};
  camera.target = {-0.5, 0.3, 0.2};
  const Eigen::Vector3d t = (camera.view_matrix() * camera.target.homogeneous()).head<3>();
  EXPECT_NEAR(t.x(), 0.0, 1e-12);
  EXPECT_NEAR(t.y(), 0.0, 1e-12);
  EXPECT_NEAR(t.z(), -(camera.target - camera.eye).norm(), 1e-12);
  // Rotation part is orthonormal.
  const Eigen::Matrix3d r = camera.view_matrix().block<3, 3>(0, 0);
  EXPECT_LT((r * r.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
}

TEST(Camera, LookingStraightDownStillHasAFrame) {
  Camera camera;
  camera.eye = {0.0, 5.0, 0.0};
  camera.target = {0.0, 0.0, 0.0};
  const Eigen::Matrix4d view = camera.view_matrix();
  EXPECT_TRUE(view.allFinite());
  EXPECT_NEAR((view * camera.target.homogeneous()).z(), -5.0, 1e-12);
}

TEST(Camera, DepthRangeHoldsTheBoxAndMapsItIntoClipSpace) {
  Camera camera;
  camera.eye = {0.0, 1.0, 4.0};
  camera.target = {0.0, 0.0, 0.0};
  const Eigen::Vector3d lo(-1, 0, -1), hi(1, 1, 1);
  const DepthRange range = depth_range(camera, lo, hi);
  std::cout << "near " << range.near_plane << " far " << range.far_plane << "\n";
  EXPECT_GT(range.near_plane, 2.0);  // tight: the box's nearest corner is ~3 m away
  EXPECT_LT(range.far_plane, 6.0);
  const Eigen::Matrix4d clip = camera.projection_matrix(1.5, range.near_plane, range.far_plane) * camera.view_matrix();
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d p((c & 1) ? hi.x() : lo.x(), (c & 2) ? hi.y() : lo.y(), (c & 4) ? hi.z() : lo.z());
    const double z = project(clip, p).z();
    EXPECT_GT(z, -1.0);
    EXPECT_LT(z, 1.0);
  }
}

TEST(Camera, DepthRangeClampsNearWhenTheEyeIsInside) {
  Camera camera;
  camera.eye = {0.0, 0.5, 0.0};
  camera.target = {0.0, 0.5, -1.0};
  const DepthRange range = depth_range(camera, Eigen::Vector3d(-10, 0, -10), Eigen::Vector3d(10, 1, 10));
  EXPECT_GT(range.near_plane, 0.0);
  EXPECT_GE(range.near_plane, range.far_plane * 1e-4 * 0.999);
}

TEST(Camera, FrameBoundingSphereJustFitsTheSphere) {
  const Eigen::Vector3d center(0.3, 0.5, -0.2);
  const double radius = 0.8;
  for (double aspect : {16.0 / 9.0, 1.0, 0.5}) {
    const Camera camera = frame_bounding_sphere(center, radius, 35.0, 25.0, 40.0, aspect, 1.0);
    EXPECT_NEAR((camera.eye - center).norm() * std::sin(std::min(
                    20.0 * M_PI / 180.0, std::atan(std::tan(20.0 * M_PI / 180.0) * aspect))), radius, 1e-9);
    const Eigen::Matrix4d clip = camera.projection_matrix(aspect, 0.1, 100.0) * camera.view_matrix();
    // Sample the sphere densely: every point inside the frame, and the widest
    // reach touches the tighter frame edge.
    double reach = 0.0;
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j < 80; ++j) {
        const double theta = M_PI * i / 40.0, phi = 2 * M_PI * j / 80.0;
        const Eigen::Vector3d p = center + radius * Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                                      std::sin(theta) * std::sin(phi));
        const Eigen::Vector3d ndc = project(clip, p);
        reach = std::max({reach, std::abs(ndc.x()), std::abs(ndc.y())});
      }
    std::cout << "aspect " << aspect << " widest NDC reach " << reach << "\n";
    EXPECT_LE(reach, 1.0 + 1e-9);
    EXPECT_GT(reach, 0.97);
  }
}

TEST(Camera, FrameBoundingSphereAnglesFollowTheConvention) {
  const Camera front = frame_bounding_sphere({0, 0, 0}, 1.0, 0.0, 0.0, 40.0, 1.0);
  EXPECT_NEAR(front.eye.x(), 0.0, 1e-12);
  EXPECT_GT(front.eye.z(), 0.0);
  const Camera side = frame_bounding_sphere({0, 0, 0}, 1.0, 90.0, 0.0, 40.0, 1.0);
  EXPECT_GT(side.eye.x(), 0.0);
  EXPECT_NEAR(side.eye.z(), 0.0, 1e-12);
  const Camera high = frame_bounding_sphere({0, 0, 0}, 1.0, 0.0, 30.0, 40.0, 1.0);
  EXPECT_NEAR(std::asin(high.eye.normalized().y()) * 180.0 / M_PI, 30.0, 1e-9);
}

TEST(Camera, OrbitStepsEvenlyAndKeepsDistance) {
  EXPECT_DOUBLE_EQ(orbit_azimuth_deg(0, 120), 0.0);
  EXPECT_DOUBLE_EQ(orbit_azimuth_deg(60, 120), 180.0);
  EXPECT_DOUBLE_EQ(orbit_azimuth_deg(119, 120), 357.0);
  EXPECT_DOUBLE_EQ(orbit_azimuth_deg(30, 120, 2.0, 10.0), 190.0);
  const Camera base = frame_bounding_sphere({0.5, 0.2, 0}, 1.0, 0.0, 20.0, 40.0, 1.5);
  const Camera quarter = orbit(base, 90.0);
  EXPECT_NEAR((quarter.eye - quarter.target).norm(), (base.eye - base.target).norm(), 1e-12);
  EXPECT_NEAR(quarter.eye.y(), base.eye.y(), 1e-12);
  const Camera expected = frame_bounding_sphere({0.5, 0.2, 0}, 1.0, 90.0, 20.0, 40.0, 1.5);
  EXPECT_LT((quarter.eye - expected.eye).norm(), 1e-12);
}

}  // namespace
}  // namespace recoil::render
