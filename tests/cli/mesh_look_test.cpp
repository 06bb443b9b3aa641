// An asset's own look through the commands: a textured body keeps its
// texture while it deforms, --color still overrides it, and a texture that
// cannot be read is a warning, never a failed run.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "render/png.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;

namespace {

const fs::path kBoxTextured = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf";

// Pixels of the Cesium logo's blue (its sky), which no grey floor or orange body has.
int logo_blue_pixels(const fs::path& png) {
  const render::Image image = render::read_png(png);
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      count += p[2] > 110 && p[2] > p[0] + 50 && p[2] > p[1] + 10;
    }
  return count;
}

TEST(MeshLookCommand, TexturedJellyKeepsItsTextureWhileItDeforms) {
  const fs::path dir = scratch_dir("look_jelly");
  // Frame 10 (0.3 s): the jelly box landed at 0.25 s and is squashed.
  const CommandResult r = run_recoil("drop " + shell_quote(kBoxTextured) +
                                     " --material jelly --seconds 0.3 --resolution 160x120 --frames 10 -q -o " +
                                     shell_quote(dir / "own"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const int own = logo_blue_pixels(dir / "own/frame_0010.png");
  EXPECT_GT(own, 150);
  const CommandResult plain = run_recoil("drop " + shell_quote(kBoxTextured) +
                                         " --material jelly --seconds 0.3 --resolution 160x120 --frames 10 -q "
                                         "--color '#d9a066' -o " + shell_quote(dir / "plain"));
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(logo_blue_pixels(dir / "plain/frame_0010.png"), 0);
  // The body did deform: its most squashed tetrahedron has lost a tenth of its volume or more.
  std::ifstream stats(dir / "own/stats.jsonl");
  std::string line;
  ASSERT_TRUE(std::getline(stats, line));
  const nlohmann::json frame = nlohmann::json::parse(line);
  EXPECT_LT(frame["bodies"][0]["min_volume_ratio"].get<double>(), 0.9);
}

TEST(MeshLookCommand, AMissingTextureWarnsAndTheRunSucceeds) {
  const fs::path dir = scratch_dir("look_missing_texture");
  std::ofstream(dir / "part.mtl") << "newmtl skin\nKd 0.2 0.4 0.8\nmap_Kd nowhere.png\n";
  std::ofstream(dir / "part.obj") << "mtllib part.mtl\nusemtl skin\n"
                                     "v 0 0 0\nv 0.2 0 0\nv 0 0.2 0\nv 0 0 0.2\n"
                                     "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const CommandResult r = run_recoil("turntable " + shell_quote(dir / "part.obj") +
                                     " --resolution 96x64 --turn-frames 2 -o " + shell_quote(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nowhere.png"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out/frame_0002.png"));
}

TEST(MeshLookCommand, InfoTellsTheLook) {
  const CommandResult duck = run_recoil("info --json /usr/share/assimp/models/Collada/duck.dae");
  ASSERT_EQ(duck.exit_code, 0) << duck.err;
  const nlohmann::json look = nlohmann::json::parse(duck.out)["look"];
  ASSERT_TRUE(look.is_object()) << duck.out;
  ASSERT_EQ(look["materials"].size(), 1u);
  EXPECT_GT(look["materials"][0]["texture"]["width"].get<int>(), 0);
  EXPECT_TRUE(look["uvs"].get<bool>());
  const CommandResult bunny = run_recoil("info " + shell_quote(source_path("assets/meshes/bunny.obj")));
  ASSERT_EQ(bunny.exit_code, 0) << bunny.err;
  EXPECT_NE(bunny.out.find("look         none"), std::string::npos) << bunny.out;
}

}  // namespace
}  // namespace recoil::test
