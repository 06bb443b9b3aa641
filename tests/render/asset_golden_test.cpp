// Golden images of real assets from Debian's assimp-testmodels, drawn with
// their own look: a textured glTF, a Collada duck with a TGA texture, a
// multi-material GLB engine and a PLY of vertex colours. They go through the
// same path as `recoil turntable`: import (the look per corner), the bridge
// to the renderer, and the renderer's material groups.
//
// To regenerate: RECOIL_UPDATE_GOLDEN=1 build/recoil_tests_render --gtest_filter='AssetGolden*'
#include <gtest/gtest.h>

#include "cli/render_bridge.h"
#include "render/renderer.h"
#include "sim/geometry/mesh_import.h"
#include "tests/render/golden_check.h"

namespace recoil::render {
namespace {

const std::filesystem::path kModels = "/usr/share/assimp/models";

// The asset on the floor, seen from a three-quarter view, 192 x 144.
Image render_asset(const std::filesystem::path& file) {
  const sim::TriMesh mesh = sim::import_surface(file);
  const sim::Aabb box = sim::bounding_box(mesh);
  RenderSettings settings;
  settings.width = 192;
  settings.height = 144;
  settings.msaa = 4;
  settings.shadows = true;
  RenderScene scene;
  scene.ground_height = static_cast<float>(box.min.y());
  scene.meshes.push_back(cli::to_render_mesh(mesh, {0.85f, 0.63f, 0.40f}));
  const Camera camera =
      frame_bounding_sphere(box.center(), 0.5 * box.extent().norm(), -35.0, 25.0, 40.0, 192.0 / 144.0);
  return Renderer(settings).render(scene, camera);
}

TEST(AssetGolden, TexturedGltfBox) {
  check_golden("asset_box_textured", render_asset(kModels / "glTF2/BoxTextured-glTF/BoxTextured.gltf"));
}

TEST(AssetGolden, ColladaDuckWithTgaTexture) {
  check_golden("asset_duck", render_asset(kModels / "Collada/duck.dae"));
}

TEST(AssetGolden, MultiMaterialGlbEngine) {
  check_golden("asset_engine", render_asset(kModels / "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
}

TEST(AssetGolden, PlyVertexColours) {
  check_golden("asset_ply_colors", render_asset(kModels / "PLY/float-color.ply"));
}

}  // namespace
}  // namespace recoil::render
