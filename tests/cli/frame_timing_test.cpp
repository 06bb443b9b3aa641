// When a run takes its frames and steps: a settle before frame 1 with
// kinematic bodies held, each frame's statistics at the frame's own time,
// and the time step --dt sets.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli/json_lines.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A scene settles as it is set up: a kinematic paddle waits while the box
// comes to rest and starts pushing with frame 1 (moving while settling, it had
// pushed the box 0.375 m before the first frame, and the settle never ended).
TEST(RunCommand, KinematicBodiesHoldStillWhileTheSceneSettles) {
  const fs::path dir = scratch_dir("run_settle_kinematic");
  const fs::path scene = dir / "paddle.json";
  std::ofstream(scene) << R"({"recoil": 1, "name": "paddle",
    "simulation": {"dt": 0.002, "duration": 0.5, "settle": 1.0},
    "bodies": [{"name": "floor", "type": "plane"},
      {"name": "paddle", "type": "kinematic", "primitive": {"box": [0.05, 0.2, 0.4]},
       "transform": {"position": [-0.2, 0.1005, 0]}, "motion": {"velocity": [0.5, 0, 0]}},
      {"name": "box", "type": "rigid", "primitive": {"box": [0.1, 0.1, 0.1]},
       "transform": {"position": [0, 0.0505, 0]}}]})";
  const CommandResult r = run_recoil("run " + shell_quote(scene) + " --no-render -q -o " + shell_quote(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("still moving"), std::string::npos) << r.err;
  const json run = json::parse(file_bytes(dir / "out" / "run.json"));
  EXPECT_TRUE(run["settle"]["at_rest"].get<bool>()) << run["settle"];
  const std::vector<json> frames = json_lines(file_bytes(dir / "out" / "stats.jsonl"));
  ASSERT_GE(frames.size(), 2u);
  // Frame 1: the box where it was put. The paddle's face, 0.125 m behind the
  // box's at frame 1, reaches it at 0.25 s and pushes it 0.125 m by 0.5 s.
  EXPECT_NEAR(frames.front()["bodies"][0]["com"][0].get<double>(), 0.0, 1e-6);
  EXPECT_NEAR(frames.back()["bodies"][0]["com"][0].get<double>(), 0.125, 0.002);
}

// stats.jsonl gives each frame's state at the frame's time, between the two
// steps around it: at 30 fps and dt 4 ms, frame 2 (0.0333 s) lies between
// steps 8 and 9. It was taken at the nearer step, 8, and extrapolated past
// it (a ball's kinetic energy came out negative after a bounce).
TEST(RunCommand, FrameStatisticsLieBetweenTheStepsAroundTheFrameTime) {
  const fs::path dir = scratch_dir("run_frame_times");
  const fs::path scene = dir / "fall.json";
  std::ofstream(scene) << R"({"recoil": 1, "name": "fall", "simulation": {"dt": 0.004, "duration": 0.3},
    "render": {"fps": 30},
    "bodies": [{"name": "box", "type": "rigid", "primitive": {"box": [0.1, 0.1, 0.1]},
                "transform": {"position": [0, 5, 0]}}]})";
  const CommandResult r = run_recoil("run " + shell_quote(scene) + " --no-render -q -o " + shell_quote(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<json> frames = json_lines(file_bytes(dir / "out" / "stats.jsonl"));
  ASSERT_EQ(frames.size(), 10u);
  for (const json& f : frames) {
    const double time = f["time"].get<double>(), shown = f["sim_time"].get<double>();
    EXPECT_GE(shown, time - 1e-12) << f.dump();
    EXPECT_LT(shown - time, 0.004) << f.dump();
    // In free fall v = -g t at every step, so the interpolated velocity is exact.
    EXPECT_NEAR(f["bodies"][0]["velocity"][1].get<double>(), -9.81 * time, 1e-9) << f.dump();
  }
}

// --dt overrides the scene's time step, and the record says so: the run
// takes duration / dt steps and scene.json holds the step it ran with.
TEST(RunCommand, TimeStepOptionOverridesTheScene) {
  const fs::path dir = scratch_dir("run_dt_option");
  const fs::path scene = dir / "fall.json";
  std::ofstream(scene) << R"({"recoil": 1, "name": "fall", "simulation": {"dt": 0.004, "duration": 0.2},
    "bodies": [{"name": "box", "type": "rigid", "primitive": {"box": [0.1, 0.1, 0.1]},
                "transform": {"position": [0, 5, 0]}}]})";
  const CommandResult r =
      run_recoil("run " + shell_quote(scene) + " --dt 0.001 --no-render -q -o " + shell_quote(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json run = json::parse(file_bytes(dir / "out" / "run.json"));
  EXPECT_EQ(run["dt"].get<double>(), 0.001);
  EXPECT_EQ(run["steps"].get<long>(), 200);
  const json resolved = json::parse(file_bytes(dir / "out" / "scene.json"));
  EXPECT_EQ(resolved["simulation"]["dt"].get<double>(), 0.001);
  const CommandResult refused = run_recoil("run " + shell_quote(scene) + " --dt 0 --no-render -q -o " +
                                           shell_quote(dir / "refused"));
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("--dt"), std::string::npos) << refused.err;
}

}  // namespace
}  // namespace recoil::test
