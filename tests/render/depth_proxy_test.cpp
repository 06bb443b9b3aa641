// The coarser copy that a rigid mesh's depth passes draw: how coarse, how
// close to the mesh, and that the frames it gives look like the full mesh's.
#include "render/depth_proxy.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "render/context.h"
#include "render/mesh_buffers.h"
#include "render/renderer.h"
#include "tests/render/test_meshes.h"

namespace recoil::render {
namespace {

constexpr float kMajor = 0.4f, kMinor = 0.15f;

// Distance (metres) from p to the surface of the torus about the origin.
double off_torus(const Eigen::Vector3d& p) {
  const double ring = std::hypot(p.x(), p.z()) - kMajor;
  return std::abs(std::hypot(ring, p.y()) - kMinor);
}

Eigen::Vector3d vertex(const RenderMesh& mesh, std::uint32_t v) {
  return {mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]};
}

TEST(DepthProxy, AFineTorusIsCutToAFractionAndStaysWithinATexel) {
  const RenderMesh torus = test::make_torus({0.0f, 0.0f, 0.0f}, kMajor, kMinor, 400, 150, {1.0f, 1.0f, 1.0f});
  const std::vector<std::uint32_t> proxy =
      depth_proxy_indices(torus.positions, torus.indices, MeshBuffers::kDepthProxyError);
  ASSERT_EQ(proxy.size() % 3, 0u);
  EXPECT_LT(proxy.size(), torus.indices.size() / 3);
  // One texel of the largest shadow map over the torus's bounding sphere
  // (half its box's diagonal), in metres.
  const double radius = 0.5 * Eigen::Vector3d(2.0 * (kMajor + kMinor), 2.0 * kMinor, 2.0 * (kMajor + kMinor)).norm();
  const double texel = 2.0 * radius / ShadowMap::kLargestSize;
  // The facets' far points from the curved surface: centroids and edge midpoints.
  double worst = 0.0;
  for (size_t t = 0; t < proxy.size(); t += 3) {
    const Eigen::Vector3d a = vertex(torus, proxy[t]), b = vertex(torus, proxy[t + 1]), c = vertex(torus, proxy[t + 2]);
    for (const Eigen::Vector3d& p : {Eigen::Vector3d((a + b + c) / 3.0), Eigen::Vector3d((a + b) / 2.0),
                                     Eigen::Vector3d((b + c) / 2.0), Eigen::Vector3d((c + a) / 2.0)})
      worst = std::max(worst, off_torus(p));
  }
  // Inside the receivers' normal offset, so the copy's shadow cannot fall on the mesh's own lit surface.
  EXPECT_LE(worst, 1.5 * texel) << "texel " << texel << " m";
}

TEST(DepthProxy, OnlyARigidMeshDrawsItsDepthFromACopy) {
  GlContext context;
  RenderMesh torus = test::make_torus({0.0f, 0.5f, 0.0f}, kMajor, kMinor, 400, 150, {1.0f, 1.0f, 1.0f});
  MeshBuffers deforming;
  ASSERT_TRUE(deforming.upload(torus));
  EXPECT_EQ(deforming.depth_triangle_count(), deforming.triangle_count());
  torus.rigid = true;
  MeshBuffers rigid;
  ASSERT_TRUE(rigid.upload(torus));
  EXPECT_LT(3 * rigid.depth_triangle_count(), rigid.triangle_count());
}

// A rigid fine torus over the floor with shadows and ambient occlusion: the
// frame from the coarser depth copy is the full mesh's within a level or two.
TEST(DepthProxy, ARigidMeshsFrameMatchesItsFullDepthFrame) {
  RenderSettings settings;
  settings.width = 256;
  settings.height = 192;
  settings.ambient_occlusion = true;
  RenderScene scene;
  scene.meshes.push_back(test::make_torus({0.0f, 0.5f, 0.0f}, kMajor, kMinor, 200, 80, {0.8f, 0.6f, 0.4f}));
  // Tilted, so that it shadows itself and the floor.
  const Eigen::Matrix3f tilt = Eigen::AngleAxisf(0.6f, Eigen::Vector3f::UnitX()).toRotationMatrix();
  for (size_t v = 0; v < scene.meshes[0].positions.size(); v += 3) {
    Eigen::Map<Eigen::Vector3f> p(scene.meshes[0].positions.data() + v);
    p = tilt * (p - Eigen::Vector3f(0.0f, 0.5f, 0.0f)) + Eigen::Vector3f(0.0f, 0.6f, 0.0f);
  }
  const Camera camera = frame_bounding_sphere({0.0, 0.5, 0.0}, 0.7, 30.0, 25.0, 40.0, 256.0 / 192.0);
  const Image full = Renderer(settings).render(scene, camera);
  scene.meshes[0].rigid = true;
  const Image coarse = Renderer(settings).render(scene, camera);
  int worst = 0, differing = 0;
  for (size_t i = 0; i < full.rgba.size(); ++i) {
    const int d = std::abs(int(full.rgba[i]) - int(coarse.rgba[i]));
    worst = std::max(worst, d);
    if (d > 1) ++differing;
  }
  EXPECT_LE(worst, 8);
  EXPECT_LT(differing, static_cast<int>(full.rgba.size() / 1000));
}

}  // namespace
}  // namespace recoil::render
