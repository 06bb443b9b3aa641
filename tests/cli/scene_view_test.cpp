// Camera modes and the drawn scene of cli::SceneView (no rendering needed):
// fixed cameras stay put, orbits circle their target at a constant distance,
// follow keeps the named body centred; planes become the ground or slabs.
#include <gtest/gtest.h>

#include "cli/scene_parser.h"
#include "cli/scene_view.h"

namespace recoil::test {

namespace {

cli::SceneDesc scene_with_camera(const std::string& camera, const std::string& extra_bodies = "") {
  const std::string text = R"({"recoil": 1, "name": "view", "bodies": [
      {"name": "ground", "type": "plane", "point": [0, -0.5, 0]},
      {"name": "ball", "type": "deformable", "primitive": {"sphere": 0.1}, "opacity": 0.5})" +
                           extra_bodies + R"(],
    "render": {"camera": )" + camera + "}}";
  return cli::parse_scene(nlohmann::json::parse(text), "view.json", ".");
}

// A unit cube's corners offset by `at`, named `name`.
sim::BodySurface cube_surface(const std::string& name, const Eigen::Vector3d& at) {
  sim::BodySurface s;
  s.name = name;
  s.positions.resize(8, 3);
  for (int i = 0; i < 8; ++i)
    s.positions.row(i) = (at + 0.1 * Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1)).transpose();
  s.triangles.resize(1, 3);
  s.triangles << 0, 1, 2;
  return s;
}

}  // namespace

TEST(SceneView, FixedCameraWithAPositionStaysThere) {
  const cli::SceneDesc scene = scene_with_camera(R"({"mode": "fixed", "position": [1, 2, 3], "target": [0, 0.5, 0], "fov": 30})");
  cli::SceneView view(scene, {cube_surface("ball", Eigen::Vector3d::Zero())}, 16.0 / 9.0);
  view.update({cube_surface("ball", Eigen::Vector3d(5, 0, 0))});
  const render::Camera c = view.camera(7, 10);
  EXPECT_EQ(c.eye, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(c.target, Eigen::Vector3d(0, 0.5, 0));
  EXPECT_EQ(c.fov_y_degrees, 30.0);
}

TEST(SceneView, OrbitCirclesItsTargetAtConstantDistance) {
  const cli::SceneDesc scene = scene_with_camera(R"({"mode": "orbit", "turns": 1, "elevation": 20, "distance": 3, "target": [0, 0.2, 0]})");
  cli::SceneView view(scene, {cube_surface("ball", Eigen::Vector3d::Zero())}, 1.0);
  const render::Camera a = view.camera(1, 8), b = view.camera(3, 8);
  EXPECT_EQ(a.target, Eigen::Vector3d(0, 0.2, 0));
  EXPECT_NEAR((a.eye - a.target).norm(), 3.0, 1e-9);
  EXPECT_NEAR((b.eye - b.target).norm(), 3.0, 1e-9);
  EXPECT_NEAR(a.eye.y(), b.eye.y(), 1e-9);
  // A quarter turn apart (frame 3 of 8).
  const Eigen::Vector3d da = (a.eye - a.target).cwiseProduct(Eigen::Vector3d(1, 0, 1));
  const Eigen::Vector3d db = (b.eye - b.target).cwiseProduct(Eigen::Vector3d(1, 0, 1));
  EXPECT_NEAR(da.dot(db), 0.0, 1e-9);
}

TEST(SceneView, FollowKeepsTheBodyCentredAtAFixedOffset) {
  const cli::SceneDesc scene = scene_with_camera(R"({"mode": "follow", "body": "ball", "elevation": 15})",
                                                 R"(, {"name": "other", "type": "deformable", "primitive": {"sphere": 0.1}})");
  cli::SceneView view(scene, {cube_surface("ball", Eigen::Vector3d::Zero()), cube_surface("other", Eigen::Vector3d(2, 0, 0))}, 1.5);
  const render::Camera before = view.camera(1, 10);
  EXPECT_TRUE(before.target.isApprox(Eigen::Vector3d(0.05, 0.05, 0.05)));
  const Eigen::Vector3d moved(0.7, -0.3, 0.2);
  view.update({cube_surface("ball", moved), cube_surface("other", Eigen::Vector3d(2, 0, 0))});
  const render::Camera after = view.camera(2, 10);
  EXPECT_TRUE(after.target.isApprox(moved + Eigen::Vector3d::Constant(0.05)));
  EXPECT_TRUE((after.eye - after.target).isApprox(before.eye - before.target));
}

TEST(SceneView, HorizontalPlaneIsTheGroundAndOpacityIsKept) {
  const cli::SceneDesc scene = scene_with_camera(R"({"mode": "fixed"})");
  cli::SceneView view(scene, {cube_surface("ball", Eigen::Vector3d::Zero())}, 1.0);
  const render::RenderScene& drawn = view.update({cube_surface("ball", Eigen::Vector3d::Zero())});
  EXPECT_TRUE(drawn.ground);
  EXPECT_FLOAT_EQ(drawn.ground_height, -0.5f);
  ASSERT_EQ(drawn.meshes.size(), 1u);
  EXPECT_FLOAT_EQ(drawn.meshes[0].opacity, 0.5f);
  EXPECT_EQ(drawn.meshes[0].color, scene.bodies[1].color);
  // Without a position the camera frames the body and its footprint on the ground.
  const render::Camera c = view.camera(1, 1);
  EXPECT_NEAR(c.target.y(), 0.5 * (-0.5 + 0.1), 1e-9);
}

TEST(SceneView, TiltedPlaneIsDrawnAsASlab) {
  const std::string text = R"({"recoil": 1, "bodies": [
      {"name": "slope", "type": "plane", "normal": [0.5, 1, 0]},
      {"name": "ball", "type": "deformable", "primitive": {"sphere": 0.1}}]})";
  const cli::SceneDesc scene = cli::parse_scene(nlohmann::json::parse(text), "tilt.json", ".");
  cli::SceneView view(scene, {cube_surface("ball", Eigen::Vector3d::Zero())}, 1.0);
  const render::RenderScene& drawn = view.update({cube_surface("ball", Eigen::Vector3d::Zero())});
  EXPECT_FALSE(drawn.ground);
  ASSERT_EQ(drawn.meshes.size(), 2u);
  // The slab's top face lies in the plane through the origin.
  const Eigen::Vector3d n = Eigen::Vector3d(0.5, 1, 0).normalized();
  double top = -1e9;
  const std::vector<float>& p = drawn.meshes[0].positions;
  for (size_t i = 0; i < p.size(); i += 3) top = std::max(top, n.dot(Eigen::Vector3d(p[i], p[i + 1], p[i + 2])));
  EXPECT_NEAR(top, 0.0, 1e-6);
}

// Only bodies that never change shape may have their depth drawn from a
// coarser copy (render_scene.h): rigid and static ones and slabs, never a deformable one.
TEST(SceneView, OnlyBodiesThatKeepTheirShapeAreDrawnRigid) {
  const std::string text = R"({"recoil": 1, "bodies": [
      {"name": "slope", "type": "plane", "normal": [0.5, 1, 0]},
      {"name": "ball", "type": "deformable", "primitive": {"sphere": 0.1}},
      {"name": "box", "type": "rigid", "primitive": {"box": [0.1, 0.1, 0.1]}}]})";
  const cli::SceneDesc scene = cli::parse_scene(nlohmann::json::parse(text), "kinds.json", ".");
  sim::BodySurface ball = cube_surface("ball", Eigen::Vector3d::Zero());
  sim::BodySurface box = cube_surface("box", Eigen::Vector3d(1, 0, 0));
  box.kind = sim::BodyKind::rigid;
  cli::SceneView view(scene, {ball, box}, 1.0);
  const render::RenderScene& drawn = view.update({ball, box});
  ASSERT_EQ(drawn.meshes.size(), 3u);
  EXPECT_TRUE(drawn.meshes[0].rigid);   // the slab
  EXPECT_FALSE(drawn.meshes[1].rigid);  // the deformable ball
  EXPECT_TRUE(drawn.meshes[2].rigid);
}

}  // namespace recoil::test

namespace recoil::test {

// A box shoved across the ground slides about 4.6 m (3 m/s, mu 0.1): every
// frame of a camera without a position shows all of it, and the framing never
// narrows, so the view does not breathe.
TEST(SceneView, ASlidingBodyStaysInTheFrameOfEveryFrame) {
  const std::string text = R"({"recoil": 1, "name": "shove", "simulation": {"duration": 3},
    "bodies": [
      {"name": "ground", "type": "plane", "friction": 0.1},
      {"name": "box", "type": "rigid", "primitive": {"box": [0.2, 0.2, 0.2]}, "friction": 0.1,
       "transform": {"position": [0, 0.1, 0]}, "velocity": [3, 0, 0]}]})";
  const cli::SceneDesc scene = cli::parse_scene(nlohmann::json::parse(text), "shove.json", ".");
  sim::World world(scene.world);
  const double aspect = 16.0 / 9.0;
  cli::SceneView view(scene, world.surfaces(), aspect);
  const int frames = scene.frame_count();
  const double fps = scene.render.fps;
  double last_distance = 0.0;
  for (int k = 1; k <= frames; ++k) {
    while (world.time() < (k - 1) / fps - 1e-9) world.step();
    const std::vector<sim::Aabb> bounds = world.body_bounds();
    view.track(bounds);
    const render::Camera camera = view.camera(k, frames);
    const Eigen::Matrix4d clip = camera.projection_matrix(aspect, 0.01, 100.0) * camera.view_matrix();
    const sim::Aabb& box = bounds[0];
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d p((corner & 1) ? box.max.x() : box.min.x(), (corner & 2) ? box.max.y() : box.min.y(),
                              (corner & 4) ? box.max.z() : box.min.z());
      const Eigen::Vector4d c = clip * p.homogeneous();
      ASSERT_GT(c.w(), 0.0) << "frame " << k;
      EXPECT_LE(std::abs(c.x() / c.w()), 1.0) << "frame " << k << " corner " << corner;
      EXPECT_LE(std::abs(c.y() / c.w()), 1.0) << "frame " << k << " corner " << corner;
    }
    const double distance = (camera.eye - camera.target).norm();
    EXPECT_GE(distance, last_distance - 1e-12) << "frame " << k;  // never closes in again
    last_distance = distance;
  }
  EXPECT_GT(world.body_bounds()[0].min.x(), 4.0);  // it did slide out of the first frame's view
}

}  // namespace recoil::test
