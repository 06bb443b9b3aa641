// A mesh's look in the renderer: vertex colours replace the mesh colour, a
// texture is sampled the right way up, materials are drawn group by group,
// and corners that differ in colour or UV never share a render vertex.
#include <gtest/gtest.h>

#include "render/crease_split.h"
#include "render/renderer.h"

namespace recoil::render {
namespace {

// A square facing the camera (+z), x and y in [-0.8, 0.8]: two triangles.
RenderMesh facing_square() {
  RenderMesh mesh;
  mesh.positions = {-0.8f, -0.8f, 0.0f, 0.8f, -0.8f, 0.0f, 0.8f, 0.8f, 0.0f, -0.8f, 0.8f, 0.0f};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.color = {0.85f, 0.63f, 0.40f};
  return mesh;
}

// UVs of facing_square's six corners: the whole texture, v up.
std::vector<float> square_uvs() { return {0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 1}; }

Image render_front(const RenderMesh& mesh) {
  RenderSettings settings;
  settings.width = 64;
  settings.height = 64;
  settings.msaa = 0;
  settings.shadows = false;
  RenderScene scene;
  scene.ground = false;
  scene.meshes = {mesh};
  Camera camera;
  camera.eye = {0.0, 0.0, 3.0};
  camera.target = {0.0, 0.0, 0.0};
  camera.fov_y_degrees = 40.0;
  return Renderer(settings).render(scene, camera);
}

std::array<int, 3> rgb(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return {p[0], p[1], p[2]};
}

TEST(MeshLook, TextureIsSampledTheRightWayUp) {
  // Two rows: red on top, blue below (image rows are stored top first).
  auto texture = std::make_shared<Image>(1, 2);
  texture->rgba = {255, 0, 0, 255, 0, 0, 255, 255};
  RenderMesh mesh = facing_square();
  auto look = std::make_shared<RenderLook>();
  look->corner_colors.assign(18, 1.0f);
  look->corner_uvs = square_uvs();
  look->triangle_materials = {0, 0};
  look->materials = {RenderMaterial{texture}};
  mesh.look = look;
  const Image image = render_front(mesh);
  const auto top = rgb(image, 32, 20), bottom = rgb(image, 32, 44);
  EXPECT_GT(top[0], top[2] + 60) << top[0] << " " << top[2];
  EXPECT_GT(bottom[2], bottom[0] + 60) << bottom[0] << " " << bottom[2];
}

TEST(MeshLook, EachMaterialGroupKeepsItsColourAndTheMeshColourIsUnused) {
  // Lower-right triangle green, upper-left triangle red, through two materials.
  RenderMesh mesh = facing_square();
  auto look = std::make_shared<RenderLook>();
  look->corner_colors = {0, 0.8f, 0, 0, 0.8f, 0, 0, 0.8f, 0, 0.8f, 0, 0, 0.8f, 0, 0, 0.8f, 0, 0};
  look->triangle_materials = {1, 0};
  look->materials = {RenderMaterial{}, RenderMaterial{}};
  mesh.look = look;
  const Image image = render_front(mesh);
  const auto lower_right = rgb(image, 44, 44), upper_left = rgb(image, 20, 20);
  EXPECT_GT(lower_right[1], lower_right[0] + 60);
  EXPECT_GT(upper_left[0], upper_left[1] + 60);
  EXPECT_LT(lower_right[2], 30);  // nothing of the orange mesh colour's blue or red mix
}

TEST(MeshLook, CornersThatDifferInKeyAreNotJoined) {
  // Two coplanar triangles sharing the edge 0-2: smooth, so four render
  // vertices; with a key that differs across the edge, six.
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 2, 3};
  EXPECT_EQ(split_creases(positions, indices, 40.0).source.size(), 4u);
  const std::vector<float> same = {1, 1, 1, 1, 1, 1};
  EXPECT_EQ(split_creases(positions, indices, 40.0, same, 1).source.size(), 4u);
  const std::vector<float> seam = {1, 1, 1, 2, 2, 2};  // the second triangle's corners differ
  const CreaseSplit split = split_creases(positions, indices, 40.0, seam, 1);
  EXPECT_EQ(split.source.size(), 6u);
  EXPECT_NE(split.indices[0], split.indices[3]);  // vertex 0 in each triangle
  EXPECT_NE(split.indices[2], split.indices[4]);  // vertex 2 in each triangle
}

}  // namespace
}  // namespace recoil::render
