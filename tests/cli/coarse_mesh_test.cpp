// A deformable body from a mesh far coarser than its lattice (an exported
// box is 12 triangles): contact on the corners alone let the cells between
// them sag through the ground until the elements inverted (exit 3). Its
// collision surface is refined to the lattice, so it lands and stands.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli/box_mesh_file.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;

namespace {

TEST(CoarseMesh, ASoftBoxOfTwelveTrianglesLandsAndStands) {
  const fs::path dir = scratch_dir("coarse_box");
  const fs::path box = write_box_off(dir / "box.off", Eigen::Vector3d::Constant(-0.5), Eigen::Vector3d::Constant(0.5));
  const CommandResult r = run_recoil("drop " + shell_quote(box) + " --seconds 1.5 --no-render -q -o " + shell_quote(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream stats(dir / "out/stats.jsonl");
  std::string line;
  double lowest_volume_ratio = 1.0, last_height = 0.0;
  while (std::getline(stats, line)) {
    const nlohmann::json body = nlohmann::json::parse(line)["bodies"][0];
    lowest_volume_ratio = std::min(lowest_volume_ratio, body["min_volume_ratio"].get<double>());
    last_height = body["com"][1].get<double>();
  }
  EXPECT_GT(lowest_volume_ratio, 0.5);  // squashed on landing, never inverted
  // At the end the 1 m cube stands on the ground: its centre near 0.5 m, less
  // its sag under its own weight (rho g L / E = 1000 * 9.81 * 1 / 1e5, about 10 %).
  EXPECT_GT(last_height, 0.40);
  EXPECT_LT(last_height, 0.52);
  const CommandResult info = run_recoil("info --json " + shell_quote(dir / "out/scene.json"));
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const nlohmann::json body = nlohmann::json::parse(info.out)["bodies"][1];
  EXPECT_GT(body["collision_triangles"].get<int>(), 12 * 16) << body.dump();
}

}  // namespace
}  // namespace recoil::test
