// The camera from the command line: --azimuth, --fov, --camera-position and
// --camera-target reach the scene (and so its rerun), an option the scene's
// camera cannot take is exit 2 naming it, a turntable starts at a
// three-quarter view, and --no-ground leaves the floor undrawn.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;

namespace {

std::string bunny() { return shell_quote(source_path("assets/meshes/bunny.obj")); }

nlohmann::json camera_of(const fs::path& out) { return nlohmann::json::parse(file_bytes(out / "scene.json"))["render"]["camera"]; }

TEST(CameraOptions, PositionTargetAndFovReachTheScene) {
  const fs::path dir = scratch_dir("camera_options");
  const CommandResult r = run_recoil("drop " + bunny() +
                                     " --camera-position 0.8,0.6,0.8 --camera-target 0,0.1,0 --fov 30 --seconds 0.1"
                                     " --frames 1 --resolution 96x64 -q -o " + shell_quote(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json camera = camera_of(dir / "out");
  EXPECT_EQ(camera["position"], nlohmann::json::parse("[0.8, 0.6, 0.8]"));
  EXPECT_EQ(camera["target"], nlohmann::json::parse("[0.0, 0.1, 0.0]"));
  EXPECT_EQ(camera["fov"], 30.0);
}

TEST(CameraOptions, NoGroundReachesTheSceneAndDrawsNoFloor) {
  const fs::path dir = scratch_dir("no_ground");
  for (const char* flag : {"", "--no-ground"}) {
    const fs::path out = dir / (flag[0] ? "without" : "with");
    const CommandResult r = run_recoil("turntable " + bunny() + " " + flag +
                                       " --turn-frames 2 --frames 1 --resolution 96x64 -q -o " + shell_quote(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const nlohmann::json scene = nlohmann::json::parse(file_bytes(dir / "without/scene.json"));
  EXPECT_EQ(scene["render"]["ground"]["visible"], false);
  EXPECT_NE(file_bytes(dir / "with/frame_0001.png"), file_bytes(dir / "without/frame_0001.png"));
}

TEST(CameraOptions, TurntablesStartAtAThreeQuarterViewThatAzimuthTurns) {
  const fs::path dir = scratch_dir("camera_azimuth");
  for (const char* azimuth : {"", "--azimuth 90"}) {
    const fs::path out = dir / (azimuth[0] ? "turned" : "default");
    const CommandResult r = run_recoil("turntable " + bunny() + " " + azimuth +
                                       " --turn-frames 2 --frames 1 --resolution 96x64 -q -o " + shell_quote(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  EXPECT_EQ(camera_of(dir / "default")["azimuth"], 30.0);
  EXPECT_EQ(camera_of(dir / "turned")["azimuth"], 90.0);
  EXPECT_NE(file_bytes(dir / "default/frame_0001.png"), file_bytes(dir / "turned/frame_0001.png"));
}

TEST(CameraOptions, AnOptionTheCameraCannotTakeIsRefused) {
  const fs::path out = scratch_dir("camera_refused") / "out";
  struct Case {
    std::string args, named;
  };
  for (const Case& c : {Case{"turntable " + bunny() + " --camera-position 1,1,1", "--camera-position"},
                        Case{"drop " + bunny() + " --camera-position 1,0.5,1 --azimuth 10", "--azimuth"},
                        Case{"drop " + bunny() + " --camera-position 1,0.5,1 --camera-distance 2", "--camera-distance"},
                        Case{"drop " + bunny() + " --camera-position 1,a,1", "--camera-position"},
                        Case{"drop " + bunny() + " --camera-position 0,0,0 --camera-target 0,0,0", "--camera-position"}}) {
    const CommandResult r = run_recoil(c.args + " -o " + shell_quote(out));
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.named), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out / "frame_0001.png"));
  }
}

}  // namespace
}  // namespace recoil::test
