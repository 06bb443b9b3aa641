// A mesh file's look (materials, textures, UVs, vertex colours) comes through
// import per triangle corner: welding, cleaning and mirroring keep it in step
// with the triangles, and a texture that cannot be read is a warning.
#include "sim/geometry/surface_look.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "sim/geometry/mesh_import.h"
#include "tests/test_support.h"

namespace recoil::sim {
namespace fs = std::filesystem;

namespace {

const fs::path kModels = "/usr/share/assimp/models";


// A unit square of two triangles in an OBJ whose two halves use two materials
// of `mtl`, with UVs split along the diagonal (a seam: the shared corners
// have different UVs in each triangle).
fs::path write_two_material_square(const fs::path& dir, const std::string& mtl) {
  test::write_file(dir / "square.mtl", mtl);
  test::write_file(dir / "square.obj",
             "mtllib square.mtl\n"
             "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
             "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
             "usemtl red\nf 1/1 2/2 3/3\n"
             "usemtl blue\nf 1/5 3/5 4/4\n");
  return dir / "square.obj";
}

TEST(SurfaceLook, TexturedGltfBringsItsUvsAndDecodedTexture) {
  const TriMesh box = import_surface(kModels / "glTF2/BoxTextured-glTF/BoxTextured.gltf");
  ASSERT_TRUE(box.look);
  const SurfaceLook& look = *box.look;
  EXPECT_EQ(look.num_triangles(), box.num_triangles());
  ASSERT_EQ(look.corner_uv.size(), 6u * static_cast<size_t>(box.num_triangles()));
  const std::set<int> used(look.triangle_material.begin(), look.triangle_material.end());
  ASSERT_EQ(used.size(), 1u);
  const LookMaterial& material = look.materials[static_cast<size_t>(*used.begin())];
  ASSERT_TRUE(material.texture);
  // CesiumLogoFlat.png is 211 x 211.
  EXPECT_EQ(material.texture->width, 211);
  EXPECT_EQ(material.texture->height, 211);
  EXPECT_EQ(material.texture->rgba.size(), 211u * 211u * 4u);
  // Welded: the box's 24 split vertices are its 8 corners again, the UVs kept per corner.
  EXPECT_EQ(box.num_vertices(), 8);
  std::set<std::pair<float, float>> distinct;
  for (size_t c = 0; c < look.corner_uv.size(); c += 2) distinct.insert({look.corner_uv[c], look.corner_uv[c + 1]});
  EXPECT_GT(distinct.size(), 8u);
  EXPECT_TRUE(look.warnings.empty());
}

TEST(SurfaceLook, ColladaTgaTextureIsDecoded) {
  const TriMesh duck = import_surface(kModels / "Collada/duck.dae");
  ASSERT_TRUE(duck.look);
  bool textured = false;
  for (const LookMaterial& m : duck.look->materials) textured |= m.texture && m.texture->width > 0;
  EXPECT_TRUE(textured);
  EXPECT_FALSE(duck.look->corner_uv.empty());
}

TEST(SurfaceLook, EveryMaterialOfAMultiMaterialGlbKeepsItsColour) {
  const TriMesh engine = import_surface(kModels / "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
  ASSERT_TRUE(engine.look);
  std::set<std::array<float, 3>> colours;
  std::set<int> used(engine.look->triangle_material.begin(), engine.look->triangle_material.end());
  for (int m : used) {
    const LookMaterial& material = engine.look->materials[static_cast<size_t>(m)];
    if (material.has_color) colours.insert(material.color);
  }
  EXPECT_GE(colours.size(), 3u);
}

TEST(SurfaceLook, GltfMetallicRoughnessFactorsAreRead) {
  // ClearCoatTest's materials: dielectrics of roughness 0.44, 0.03, 0.6, 0.9
  // and 1, and one whose factors scale a metallic-roughness map.
  const TriMesh spheres = import_surface(kModels / "glTF2/ClearCoat-glTF/ClearCoatTest.gltf");
  ASSERT_TRUE(spheres.look);
  std::set<float> roughness;
  int with_factors = 0;
  for (int m : std::set<int>(spheres.look->triangle_material.begin(), spheres.look->triangle_material.end())) {
    const LookMaterial& material = spheres.look->materials[static_cast<size_t>(m)];
    if (!material.has_surface) continue;
    ++with_factors;
    EXPECT_EQ(material.metallic, 0.0f) << material.name;
    roughness.insert(material.roughness);
  }
  EXPECT_GE(with_factors, 15);
  EXPECT_TRUE(roughness.count(0.03f)) << "the glossiest coat";
  EXPECT_TRUE(roughness.count(0.44f));
  // The mapped material (not drawn, so its factors would mislead) keeps the studio's surface.
  for (const LookMaterial& m : spheres.look->materials) {
    if (m.name == "RoughVariations_Coating") {
      EXPECT_FALSE(m.has_surface);
    }
  }
  // A format without the factors leaves them to the renderer.
  const TriMesh duck = import_surface(kModels / "Collada/duck.dae");
  ASSERT_TRUE(duck.look);
  for (const LookMaterial& m : duck.look->materials) EXPECT_FALSE(m.has_surface) << m.name;
}

TEST(SurfaceLook, PlyVertexColoursArePerCorner) {
  const TriMesh triangle = import_surface(kModels / "PLY/float-color.ply");
  ASSERT_TRUE(triangle.look);
  ASSERT_EQ(triangle.look->corner_color.size(), 9u);
  for (int corner = 0; corner < 3; ++corner) {  // the file's colour is pure blue
    EXPECT_FLOAT_EQ(triangle.look->corner_color[3 * corner + 0], 0.0f);
    EXPECT_FLOAT_EQ(triangle.look->corner_color[3 * corner + 2], 1.0f);
  }
}

TEST(SurfaceLook, PlainMeshesHaveNone) {
  EXPECT_FALSE(import_surface(recoil::test::source_path("assets/meshes/bunny.obj")).look);
  EXPECT_FALSE(import_surface(kModels / "STL/Spider_ascii.stl").look);
  // assimp gives these formats a grey or white material of its own.
  EXPECT_FALSE(import_surface(kModels / "OFF/Cube.off").look);
  EXPECT_FALSE(import_surface(kModels / "PLY/cube.ply").look);
}

TEST(SurfaceLook, MaterialsUvSeamsAndAMissingTexture) {
  const fs::path dir = recoil::test::scratch_dir("surface_look_square");
  const fs::path obj = write_two_material_square(dir, "newmtl red\nKd 1 0 0\nmap_Kd missing.png\nnewmtl blue\nKd 0 0 1\n");
  const TriMesh square = import_surface(obj);
  ASSERT_TRUE(square.look);
  const SurfaceLook& look = *square.look;
  EXPECT_EQ(square.num_vertices(), 4);  // welded across the seam
  ASSERT_EQ(look.num_triangles(), 2);
  const LookMaterial& first = look.materials[static_cast<size_t>(look.triangle_material[0])];
  const LookMaterial& second = look.materials[static_cast<size_t>(look.triangle_material[1])];
  EXPECT_EQ(first.color, (std::array<float, 3>{1, 0, 0}));
  EXPECT_EQ(second.color, (std::array<float, 3>{0, 0, 1}));
  EXPECT_FALSE(first.texture);  // missing: not drawn, and said
  ASSERT_EQ(look.warnings.size(), 1u);
  EXPECT_NE(look.warnings[0].find("missing.png"), std::string::npos) << look.warnings[0];
  // The second triangle's corners keep their own UVs: (0.5 0.5), (0.5 0.5), (0 1).
  ASSERT_EQ(look.corner_uv.size(), 12u);
  EXPECT_FLOAT_EQ(look.corner_uv[6], 0.5f);
  EXPECT_FLOAT_EQ(look.corner_uv[10], 0.0f);
  EXPECT_FLOAT_EQ(look.corner_uv[11], 1.0f);
}

TEST(SurfaceLook, MirroringSwapsTheCornersWithTheTriangles) {
  const fs::path dir = recoil::test::scratch_dir("surface_look_mirror");
  TriMesh square = import_surface(write_two_material_square(dir, "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n"));
  const TriMesh before = square;
  transform_in_place(square, Eigen::Matrix3d::Identity(), Eigen::Vector3d(-1, 1, 1), Eigen::Vector3d::Zero());
  ASSERT_TRUE(square.look);
  for (int f = 0; f < square.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int was = k == 0 ? 0 : 3 - k;  // corners 1 and 2 swapped
      EXPECT_EQ(square.triangles(f, k), before.triangles(f, was));
      for (int i = 0; i < 2; ++i)
        EXPECT_EQ(square.look->corner_uv[static_cast<size_t>(6 * f + 2 * k + i)],
                  before.look->corner_uv[static_cast<size_t>(6 * f + 2 * was + i)]);
    }
}

TEST(SurfaceLook, BytesRoundTripWithoutTextures) {
  SurfaceLook look;
  LookMaterial m;
  m.name = "m";
  m.has_color = true;
  m.has_uvs = true;
  m.color = {0.25f, 0.5f, 0.75f};
  m.has_surface = true;
  m.metallic = 0.75f;
  m.roughness = 0.125f;
  m.texture = std::make_shared<RgbaImage>(2, 1);  // decoded apart, in a child of its own
  look.materials = {m, LookMaterial{}};
  look.triangle_material = {1, 0};
  look.corner_uv = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  look.warnings = {"w"};
  std::string bytes = "x";
  encode_look(look, bytes);
  size_t offset = 1;
  const SurfaceLook back = decode_look(bytes, offset);
  EXPECT_EQ(offset, bytes.size());
  EXPECT_EQ(back.triangle_material, look.triangle_material);
  EXPECT_EQ(back.corner_uv, look.corner_uv);
  EXPECT_TRUE(back.corner_color.empty());
  EXPECT_EQ(back.warnings, look.warnings);
  ASSERT_EQ(back.materials.size(), 2u);
  EXPECT_EQ(back.materials[0].color, m.color);
  EXPECT_TRUE(back.materials[0].has_uvs);
  EXPECT_FALSE(back.materials[0].vertex_colored);
  EXPECT_FALSE(back.materials[0].texture);
  EXPECT_TRUE(back.materials[0].has_surface);
  EXPECT_EQ(back.materials[0].metallic, 0.75f);
  EXPECT_EQ(back.materials[0].roughness, 0.125f);
  EXPECT_FALSE(back.materials[1].has_surface);
}

TEST(SurfaceLook, TextFromFilesIsPrintable) {
  EXPECT_EQ(printable("wood\x1b[31m\n"), "wood?[31m?");
  EXPECT_EQ(printable("caf\xc3\xa9"), "caf\xc3\xa9");  // UTF-8 kept
  EXPECT_EQ(printable("a\xe9" "b"), "a?b");            // a Latin-1 byte is not UTF-8
  EXPECT_EQ(printable("t\xc0\xaf.png"), "t??.png");      // an overlong '/' is no character either
  EXPECT_EQ(printable("\xed\xa0\x80"), "???");           // nor is a surrogate
  EXPECT_EQ(printable(std::string(500, 'x'), 10), std::string(10, 'x') + "...");
}

TEST(SurfaceLook, TextureNamedInAnotherCaseOrPathIsFoundBesideTheMesh) {
  const fs::path dir = recoil::test::scratch_dir("surface_look_case");
  // The Cesium logo copied in under a name in capitals, named in the MTL in lower
  // case behind a Windows path from the machine it was made on.
  fs::copy_file(kModels / "glTF2/BoxTextured-glTF/CesiumLogoFlat.png", dir / "LOGO.PNG");
  const fs::path obj = write_two_material_square(dir, "newmtl red\nKd 1 1 1\nmap_Kd C:\\art\\textures\\logo.png\nnewmtl blue\nKd 0 0 1\n");
  const TriMesh square = import_surface(obj);
  ASSERT_TRUE(square.look);
  EXPECT_TRUE(square.look->warnings.empty()) << square.look->warnings.front();
  const LookMaterial& red = square.look->materials[static_cast<size_t>(square.look->triangle_material[0])];
  ASSERT_TRUE(red.texture);
  EXPECT_EQ(red.texture->width, 211);
}

TEST(SurfaceLook, ABrokenTextureCostsOnlyItself) {
  const fs::path dir = recoil::test::scratch_dir("surface_look_broken");
  test::write_file(dir / "broken.png", "\x89PNG\r\n\x1a\n not really");
  const fs::path obj = write_two_material_square(dir, "newmtl red\nKd 1 0 0\nmap_Kd broken.png\nnewmtl blue\nKd 0 0 1\n");
  const TriMesh square = import_surface(obj);
  ASSERT_TRUE(square.look);
  EXPECT_EQ(square.num_triangles(), 2);
  ASSERT_EQ(square.look->warnings.size(), 1u);
  EXPECT_NE(square.look->warnings[0].find("broken.png"), std::string::npos) << square.look->warnings[0];
  EXPECT_NE(square.look->warnings[0].find("stb_image"), std::string::npos) << square.look->warnings[0];
}

}  // namespace
}  // namespace recoil::sim
