// Rigid-body mass properties against analytic solids, and the pose update.
#include "sim/rigid/rigid_body.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "core/error.h"
#include "sim/collision/embree_scene.h"
#include "sim/geometry/primitives.h"
#include "sim/geometry/skew.h"
#include "sim/geometry/tetrahedralize.h"
#include "sim/rigid/mass_properties.h"

namespace recoil::sim {
namespace {

double relative(double measured, double expected) { return std::abs(measured - expected) / std::abs(expected); }

TEST(MassProperties, BoxMatchesAnalyticValues) {
  const Eigen::Vector3d size(0.4, 0.2, 0.1);
  TriMesh box = make_box(size, 2);
  const Eigen::Vector3d shift(1.0, -2.0, 0.5);
  box.vertices.rowwise() += shift.transpose();
  const MassProperties p = mass_properties(box, 500.0);
  const double m = 500.0 * size.prod();
  std::cout << "box: mass error " << relative(p.mass, m) << ", centre error " << (p.center - shift).norm() << " m\n";
  EXPECT_LT(relative(p.mass, m), 1e-12);
  EXPECT_LT((p.center - shift).norm(), 1e-12);
  const Eigen::Vector3d s2 = size.cwiseProduct(size);
  const Eigen::Vector3d expected(m * (s2.y() + s2.z()) / 12.0, m * (s2.x() + s2.z()) / 12.0,
                                 m * (s2.x() + s2.y()) / 12.0);
  const double err = (p.inertia.diagonal() - expected).norm() / expected.norm();
  std::cout << "box: inertia relative error " << err << ", off-diagonal " << (p.inertia - Eigen::Matrix3d(p.inertia.diagonal().asDiagonal())).norm() << "\n";
  EXPECT_LT(err, 1e-12);
  EXPECT_LT((p.inertia - Eigen::Matrix3d(p.inertia.diagonal().asDiagonal())).norm(), 1e-12 * expected.norm());
}

// The six tetrahedra round a box's main diagonal fill it exactly: the solid's
// moments equal the closed surface's, box shifted and turned.
TEST(MassProperties, TetrahedraOfABoxGiveItsSurfaceValues) {
  const Eigen::Vector3d size(0.4, 0.2, 0.1), shift(1.0, -2.0, 0.5);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  TriMesh box = make_box(size, 1);
  transform_in_place(box, R, Eigen::Vector3d::Ones(), shift);
  TetMesh solid;
  solid.nodes.resize(8, 3);
  for (int c = 0; c < 8; ++c) {  // corner c: bit 0 -> +x, bit 1 -> +y, bit 2 -> +z
    const Eigen::Vector3d local((c & 1 ? 0.5 : -0.5) * size.x(), (c & 2 ? 0.5 : -0.5) * size.y(),
                                (c & 4 ? 0.5 : -0.5) * size.z());
    solid.nodes.row(c) = (R * local + shift).transpose();
  }
  solid.tets.resize(6, 4);
  solid.tets << 0, 1, 3, 7, 0, 1, 5, 7, 0, 2, 3, 7, 0, 2, 6, 7, 0, 4, 5, 7, 0, 4, 6, 7;
  for (int t = 0; t < 6; ++t)
    if (tet_volume(solid.nodes, solid.tets, t) < 0) std::swap(solid.tets(t, 2), solid.tets(t, 3));
  const MassProperties surface = mass_properties(box, 700.0), filled = mass_properties(solid, 700.0);
  EXPECT_LT(relative(filled.mass, surface.mass), 1e-12);
  EXPECT_LT((filled.center - surface.center).norm(), 1e-12);
  EXPECT_LT((filled.inertia - surface.inertia).norm(), 1e-12 * surface.inertia.norm());
}

TEST(MassProperties, RotatedBoxInertiaIsRotated) {
  TriMesh box = make_box({0.4, 0.2, 0.1}, 1);
  const MassProperties p0 = mass_properties(box, 1000.0);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  transform_in_place(box, R, Eigen::Vector3d::Ones(), Eigen::Vector3d::Zero());
  const MassProperties p1 = mass_properties(box, 1000.0);
  const double err = (p1.inertia - R * p0.inertia * R.transpose()).norm() / p0.inertia.norm();
  std::cout << "rotated box: |I1 - R I0 R^T| / |I0| = " << err << "\n";
  EXPECT_LT(err, 1e-12);
}

TEST(MassProperties, SphereAndCylinderApproachAnalyticValues) {
  const double r = 0.3;
  const MassProperties s = mass_properties(make_sphere(r, 5), 1000.0);
  const double ms = 1000.0 * 4.0 / 3.0 * M_PI * r * r * r;
  const double is = 0.4 * ms * r * r;
  std::cout << "sphere (subdivision 5): mass error " << relative(s.mass, ms) << ", inertia error "
            << relative(s.inertia(0, 0), is) << "\n";
  EXPECT_LT(relative(s.mass, ms), 2e-3);
  for (int k = 0; k < 3; ++k) EXPECT_LT(relative(s.inertia(k, k), is), 3e-3);
  EXPECT_LT(s.center.norm(), 1e-12);

  const double h = 0.5;
  const MassProperties c = mass_properties(make_cylinder(r, h, 256), 1000.0);
  const double mc = 1000.0 * M_PI * r * r * h;
  const double iy = 0.5 * mc * r * r, ix = mc * (3.0 * r * r + h * h) / 12.0;
  std::cout << "cylinder (256 segments): mass error " << relative(c.mass, mc) << ", Iyy error "
            << relative(c.inertia(1, 1), iy) << ", Ixx error " << relative(c.inertia(0, 0), ix) << "\n";
  EXPECT_LT(relative(c.mass, mc), 1e-3);
  EXPECT_LT(relative(c.inertia(1, 1), iy), 2e-3);
  EXPECT_LT(relative(c.inertia(0, 0), ix), 1e-3);
  EXPECT_LT(relative(c.inertia(2, 2), ix), 1e-3);
}

TEST(RigidBody, BuildPlacesCentreWeighsOpenSurfacesAndRejectsInwardOnes) {
  EmbreeDevice device;
  RigidBodyDesc desc;
  desc.mesh = make_box({0.2, 0.2, 0.2}, 1);
  desc.transform.position = Eigen::Vector3d(0.0, 1.0, 0.0);
  desc.transform.rotation = Eigen::Vector3d(0.0, 0.0, 30.0);
  const RigidBody body = build_rigid_body(desc, device, "rigid_bodies/0", 0.002);
  EXPECT_NEAR(body.mass, 1000.0 * 0.008, 1e-12);
  EXPECT_LT((body.pose.center - desc.transform.position).norm(), 1e-12);
  Points world;
  world_points(body.local, body.pose, world);
  EXPECT_NEAR(world.col(1).maxCoeff(), 1.0 + 0.1 * (std::cos(M_PI / 6) + std::sin(M_PI / 6)), 1e-12);

  RigidBodyDesc inward = desc;  // wound inside out: negative enclosed volume
  inward.mesh.triangles = inward.mesh.triangles.rowwise().reverse().eval();
  EXPECT_THROW(build_rigid_body(inward, device, "rigid_bodies/1", 0.002), Error);
  // Open: the lattice its winding number fills, a box of the same mass to a cell's layer.
  RigidBodyDesc open = desc;
  open.mesh.triangles = open.mesh.triangles.topRows(open.mesh.num_triangles() - 2).eval();
  const RigidBody opened = build_rigid_body(open, device, "rigid_bodies/3", 0.002);
  EXPECT_GE(opened.mass, body.mass);
  EXPECT_LT(opened.mass, 1000.0 * std::pow(0.2 * (1.0 + 2.0 / kDefaultResolution), 3) + 1e-9);
  EXPECT_LT((opened.pose.center - desc.transform.position).norm(), 0.2 / kDefaultResolution);
  RigidBodyDesc light = desc;
  light.density = 0.0;
  EXPECT_THROW(build_rigid_body(light, device, "rigid_bodies/2", 0.002), Error);
  light.kind = BodyKind::kinematic;  // density is not used by kinematic bodies
  EXPECT_NO_THROW(build_rigid_body(light, device, "rigid_bodies/2", 0.002));
}

TEST(RigidBody, PoseUpdateIsExactForConstantSpin) {
  RigidPose pose;
  const Eigen::Vector3d w(0.0, 2.0, 0.0);
  for (int i = 0; i < 1000; ++i) pose = advance_pose(pose, Eigen::Vector3d(1, 0, 0), w, 0.001);
  const double angle = rotation_vector(pose.orientation).y();
  std::cout << "spin: angle after 1 s at 2 rad/s " << angle << ", |q| - 1 = " << pose.orientation.norm() - 1.0 << "\n";
  EXPECT_NEAR(angle, 2.0, 1e-10);
  EXPECT_NEAR(pose.center.x(), 1.0, 1e-12);
  EXPECT_NEAR(pose.orientation.norm(), 1.0, 1e-14);
}

TEST(RigidBody, LeftJacobianMatchesFiniteDifferences) {
  const Eigen::Vector3d phi(0.3, -0.5, 0.8), r(0.2, 0.1, -0.4);
  Eigen::Matrix3d Rs = Eigen::Matrix3d::Zero();
  const Eigen::Vector3d p = from_rotation_vector(phi) * r;
  const Eigen::Matrix3d analytic = -skew(p) * so3_left_jacobian(phi);
  const double eps = 1e-6;
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    d[k] = eps;
    Rs.col(k) = (from_rotation_vector(phi + d) * r - from_rotation_vector(phi - d) * r) / (2 * eps);
  }
  const double err = (Rs - analytic).norm() / analytic.norm();
  std::cout << "left Jacobian vs finite differences: " << err << "\n";
  EXPECT_LT(err, 1e-8);
}

}  // namespace
}  // namespace recoil::sim
