// --ao reaches the scene written beside the frames, so a rerun of that scene
// draws the same frame, and it changes what is drawn; --no-ao undoes it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;
namespace {

TEST(AmbientOcclusionOption, ReachesTheSceneAndItsRerun) {
  const fs::path dir = scratch_dir("ambient_occlusion_option");
  const std::string bunny = shell_quote(source_path("assets/meshes/bunny.obj"));
  for (const char* flag : {"", "--ao"}) {
    const fs::path out = dir / (flag[0] ? "with" : "without");
    const CommandResult r = run_recoil("turntable " + bunny + " " + flag +
                                       " --turn-frames 2 --frames 1 --resolution 96x64 -q -o " + shell_quote(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const auto scene_of = [&](const char* name) {
    return nlohmann::json::parse(file_bytes(dir / name / "scene.json"))["render"]["ambient_occlusion"];
  };
  EXPECT_EQ(scene_of("with"), true);
  EXPECT_EQ(scene_of("without"), false);
  EXPECT_NE(file_bytes(dir / "with/frame_0001.png"), file_bytes(dir / "without/frame_0001.png"));
  const CommandResult rerun = run_recoil("run " + shell_quote(dir / "with/scene.json") + " --frames 1 -q -o " +
                                         shell_quote(dir / "rerun"));
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  EXPECT_EQ(file_bytes(dir / "rerun/frame_0001.png"), file_bytes(dir / "with/frame_0001.png"));
  // --no-ao turns it off over the scene file, and contradicts --ao.
  const CommandResult off = run_recoil("run " + shell_quote(dir / "with/scene.json") + " --no-ao --frames 1 -q -o " +
                                       shell_quote(dir / "off"));
  ASSERT_EQ(off.exit_code, 0) << off.err;
  EXPECT_EQ(file_bytes(dir / "off/frame_0001.png"), file_bytes(dir / "without/frame_0001.png"));
  EXPECT_EQ(nlohmann::json::parse(file_bytes(dir / "off/scene.json"))["render"]["ambient_occlusion"], false);
  const CommandResult both =
      run_recoil("turntable " + bunny + " --ao --no-ao --turn-frames 2 -q -o " + shell_quote(dir / "both"));
  EXPECT_EQ(both.exit_code, 2) << both.err;
}

}  // namespace
}  // namespace recoil::test
