// The options `drop` and `turntable` share for a mesh: the collision budget
// (checked as the scene would check it, and reaching a settling turntable),
// the build stage a long build shows, the summary's frame count, and the
// lattice cells `info MESH` gives at the size `drop` scales a mesh to.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/cli/box_mesh_file.h"
#include "tests/cli/json_lines.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;
using nlohmann::json;

TEST(MeshCommandOptions, CollisionTrianglesTakeWhatTheSceneTakes) {
  const fs::path dir = scratch_dir("collision_budget_range");
  const fs::path box = write_box_off(dir / "box.off", Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.1, 0.1, 0.1));
  for (const char* count : {"2", "-1", "100000001"}) {
    const CommandResult r = run_recoil("drop " + shell_quote(box) + " --collision-triangles " + count +
                                       " --seconds 0.01 --no-render -o " + shell_quote(dir / "out"));
    EXPECT_EQ(r.exit_code, 2) << count << ": " << r.err;
    EXPECT_NE(r.err.find("--collision-triangles: must be 0 (the mesh itself) or 4 to 100000000 triangles"),
              std::string::npos)
        << r.err;
  }
  // What the option takes, the scene takes: 4 and 0 both run.
  for (const char* count : {"4", "0"}) {
    const CommandResult r = run_recoil("drop " + shell_quote(box) + " --collision-triangles " + count +
                                       " --seconds 0.01 --no-render -q -o " + shell_quote(dir / "out"));
    EXPECT_EQ(r.exit_code, 0) << count << ": " << r.err;
  }
  const CommandResult help = run_recoil("drop --help");
  EXPECT_NE(help.out.find("0 or 4-100000000"), std::string::npos) << help.out;
}

TEST(MeshCommandOptions, ASettlingTurntableTakesTheCollisionBudget) {
  const fs::path dir = scratch_dir("turntable_collision_budget");
  const fs::path box = write_box_off(dir / "box.off", Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.1, 0.1, 0.1));
  const fs::path scene = dir / "settle.json";
  const CommandResult r = run_recoil("turntable " + shell_quote(box) +
                                     " --settle --settle-seconds 0.01 --collision-edge 0.05 --turn-frames 1 --no-render -q -o " +
                                     shell_quote(dir / "out") + " --save-scene " + shell_quote(scene));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json saved = json::parse(file_bytes(scene));
  EXPECT_EQ(saved["bodies"][1]["collision"], json({{"edge_length", 0.05}})) << saved.dump();
  // A static turntable's mesh collides with nothing: the option cannot apply.
  const CommandResult fixed = run_recoil("turntable " + shell_quote(box) + " --collision-triangles 400 --turn-frames 1 --no-render -o " +
                                         shell_quote(dir / "fixed"));
  EXPECT_EQ(fixed.exit_code, 2) << fixed.err;
  EXPECT_NE(fixed.err.find("--collision-triangles requires --settle"), std::string::npos) << fixed.err;
}

TEST(MeshCommandOptions, TheBuildIsAStageAndOneFrameIsOneFrame) {
  const fs::path dir = scratch_dir("build_stage");
  const fs::path box = write_box_off(dir / "box.off", Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.1, 0.1, 0.1));
  const CommandResult logged = run_recoil("drop " + shell_quote(box) + " --seconds 0.01 --no-render --log-json -o " +
                                          shell_quote(dir / "logged"));
  ASSERT_EQ(logged.exit_code, 0) << logged.err;
  std::vector<std::string> events;
  for (const json& j : json_lines(logged.err)) {
    if (j.is_object() && j.contains("event")) events.push_back(j["event"]);
    if (j.value("event", "") == "stage") {
      EXPECT_EQ(j["stage"], "building 1 body, 12 triangles");
    }
  }
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.front(), "stage");  // before any frame
  const CommandResult one = run_recoil("drop " + shell_quote(box) + " --seconds 0.1 --frames 3 --resolution 64x64 -o " +
                                       shell_quote(dir / "one"));
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_NE(one.err.find(", wrote 1 frame to "), std::string::npos) << one.err;
}

TEST(MeshCommandOptions, InfoGivesTheCellsAtTheSizeDropScalesTo) {
  const fs::path dir = scratch_dir("info_scaled_cells");
  // 40 units long: taken for another unit and scaled to 0.3 m by `drop`.
  const fs::path big = write_box_off(dir / "big.off", Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(40, 10, 10));
  const CommandResult text = run_recoil("info " + shell_quote(big));
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("(cells of 5 file units; 0.0375 m once `drop` or `turntable` scale it to 0.3 m)"),
            std::string::npos)
      << text.out;
  const CommandResult j = run_recoil("info --json " + shell_quote(big));
  ASSERT_EQ(j.exit_code, 0) << j.err;
  EXPECT_DOUBLE_EQ(json::parse(j.out)["tetrahedra"]["drop_scale"].get<double>(), 0.3 / 40);
  // A mesh in metres keeps its size, and its cells are in metres.
  const fs::path box = write_box_off(dir / "box.off", Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.4, 0.1, 0.1));
  const CommandResult metres = run_recoil("info " + shell_quote(box));
  EXPECT_NE(metres.out.find("(cells of 0.05 m)"), std::string::npos) << metres.out;
}

}  // namespace recoil::test
