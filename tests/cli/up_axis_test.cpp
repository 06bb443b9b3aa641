// `--up` and a body's "up" end to end: a Z-up tall box stands along world Y
// with --up +Z and lies without it, behaves exactly like the same box modelled
// Y-up, is recorded in the saved and resolved scenes, and bad values are
// exit 2 naming the option.
#include <gtest/gtest.h>

#include <Eigen/LU>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/up_axis.h"
#include "tests/cli/box_mesh_file.h"
#include "tests/cli/json_lines.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A 0.1 x 0.1 x 0.4 m box standing on z = 0, long side along Z (a CAD export).
fs::path write_tall_z(const fs::path& dir) {
  return write_box_off(dir / "tall_z.off", Eigen::Vector3d(-0.05, -0.05, 0.0), Eigen::Vector3d(0.05, 0.05, 0.4));
}

// The same box modelled Y-up: every vertex turned as --up +Z turns it.
fs::path write_tall_y(const fs::path& dir) {
  const Eigen::Matrix3d r = cli::up_rotation(cli::UpAxis::pos_z);
  return write_box_off(dir / "tall_y.off", Eigen::Vector3d(-0.05, -0.05, 0.0), Eigen::Vector3d(0.05, 0.05, 0.4), false,
                       [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(r * p); });
}

std::vector<json> up_test_stats(const fs::path& path) { return json_lines(file_bytes(path)); }

}  // namespace

TEST(UpAxis, RotationsTakeEachAxisToPlusY) {
  using cli::UpAxis;
  const std::vector<std::pair<UpAxis, Eigen::Vector3d>> cases = {
      {UpAxis::pos_x, Eigen::Vector3d::UnitX()},  {UpAxis::neg_x, -Eigen::Vector3d::UnitX()},
      {UpAxis::pos_y, Eigen::Vector3d::UnitY()},  {UpAxis::neg_y, -Eigen::Vector3d::UnitY()},
      {UpAxis::pos_z, Eigen::Vector3d::UnitZ()},  {UpAxis::neg_z, -Eigen::Vector3d::UnitZ()}};
  for (const auto& [axis, v] : cases) {
    const Eigen::Matrix3d r = cli::up_rotation(axis);
    EXPECT_EQ(r * v, Eigen::Vector3d::UnitY()) << cli::to_string(axis);
    EXPECT_EQ(r.determinant(), 1.0) << cli::to_string(axis);
    EXPECT_EQ(cli::parse_up_axis(cli::to_string(axis)), axis);
  }
  // Blender's Y-up export of a Z-up model: (x, y, z) -> (x, z, -y).
  EXPECT_EQ(cli::up_rotation(UpAxis::pos_z) * Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1, 3, -2));
  EXPECT_EQ(cli::parse_up_axis("z"), UpAxis::pos_z);
  EXPECT_EQ(cli::parse_up_axis("-x"), UpAxis::neg_x);
  EXPECT_FALSE(cli::parse_up_axis("up"));
  EXPECT_FALSE(cli::parse_up_axis("+W"));
  EXPECT_FALSE(cli::parse_up_axis(""));
}

TEST(UpAxis, ZUpBoxStandsTallWithUpZAndLiesWithout) {
  const fs::path dir = scratch_dir("up_drop");
  const fs::path tall_z = write_tall_z(dir), tall_y = write_tall_y(dir);
  const std::string common = " --material stiff --seconds 0.1 --frames 1-2 --no-render -q";
  const CommandResult up = run_recoil("drop " + shell_quote(tall_z) + " --up +Z" + common + " -o " +
                                      shell_quote(dir / "up") + " --save-scene " + shell_quote(dir / "up.json"));
  ASSERT_EQ(up.exit_code, 0) << up.err;
  const CommandResult flat = run_recoil("drop " + shell_quote(tall_z) + common + " -o " + shell_quote(dir / "flat"));
  ASSERT_EQ(flat.exit_code, 0) << flat.err;
  const CommandResult twin = run_recoil("drop " + shell_quote(tall_y) + common + " -o " + shell_quote(dir / "twin"));
  ASSERT_EQ(twin.exit_code, 0) << twin.err;

  // drop rests the lowest point 0.3 m above the ground: the centre of mass is
  // half the box's vertical extent above that, 0.2 m standing, 0.05 m lying.
  const std::vector<json> s_up = up_test_stats(dir / "up" / "stats.jsonl");
  const std::vector<json> s_flat = up_test_stats(dir / "flat" / "stats.jsonl");
  const std::vector<json> s_twin = up_test_stats(dir / "twin" / "stats.jsonl");
  ASSERT_EQ(s_up.size(), 2u);
  ASSERT_EQ(s_flat.size(), 2u);
  ASSERT_EQ(s_twin.size(), 2u);
  EXPECT_NEAR(s_up[0]["bodies"][0]["com"][1].get<double>(), 0.3 + 0.2, 1e-6);
  EXPECT_NEAR(s_flat[0]["bodies"][0]["com"][1].get<double>(), 0.3 + 0.05, 1e-6);
  // Standing as modelled: the Z-up file with --up +Z is the Y-up file, bit for bit.
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(s_up[i]["bodies"][0]["com"], s_twin[i]["bodies"][0]["com"]) << "frame " << i + 1;
    EXPECT_EQ(s_up[i]["bodies"][0]["velocity"], s_twin[i]["bodies"][0]["velocity"]) << "frame " << i + 1;
  }

  // Recorded: in the saved scene, in the resolved one (default +Y filled in),
  // and a rerun of the saved scene is the run that was saved.
  EXPECT_EQ(json::parse(file_bytes(dir / "up.json"))["bodies"][1]["up"], "+Z");
  EXPECT_EQ(json::parse(file_bytes(dir / "up" / "scene.json"))["bodies"][1]["up"], "+Z");
  EXPECT_EQ(json::parse(file_bytes(dir / "flat" / "scene.json"))["bodies"][1]["up"], "+Y");
  const CommandResult rerun = run_recoil("run " + shell_quote(dir / "up.json") + " --frames 1-2 --no-render -q -o " +
                                         shell_quote(dir / "rerun"));
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  const std::vector<json> s_rerun = up_test_stats(dir / "rerun" / "stats.jsonl");
  ASSERT_EQ(s_rerun.size(), 2u);
  EXPECT_EQ(s_rerun[1]["bodies"], s_up[1]["bodies"]);
}

TEST(UpAxis, TurntableOfZUpBoxWithUpZDrawsTheYUpBox) {
  const fs::path dir = scratch_dir("up_turntable");
  const fs::path tall_z = write_tall_z(dir), tall_y = write_tall_y(dir);
  const std::string common = " --turn-frames 2 --resolution 48x32 --msaa 0 -q -o ";
  const CommandResult up = run_recoil("turntable " + shell_quote(tall_z) + " --up +Z" + common + shell_quote(dir / "up"));
  ASSERT_EQ(up.exit_code, 0) << up.err;
  const CommandResult twin = run_recoil("turntable " + shell_quote(tall_y) + common + shell_quote(dir / "twin"));
  ASSERT_EQ(twin.exit_code, 0) << twin.err;
  const CommandResult flat = run_recoil("turntable " + shell_quote(tall_z) + common + shell_quote(dir / "flat"));
  ASSERT_EQ(flat.exit_code, 0) << flat.err;
  const std::string frame = file_bytes(dir / "up" / "frame_0002.png");
  ASSERT_FALSE(frame.empty());
  EXPECT_EQ(frame, file_bytes(dir / "twin" / "frame_0002.png"));
  EXPECT_NE(frame, file_bytes(dir / "flat" / "frame_0002.png"));
}

TEST(UpAxis, BadUpIsExit2NamingTheOption) {
  const fs::path dir = scratch_dir("up_bad");
  const fs::path tall_z = write_tall_z(dir);
  for (const std::string command : {"drop", "turntable"}) {
    const CommandResult r = run_recoil(command + " " + shell_quote(tall_z) + " --up sideways -o " + shell_quote(dir));
    EXPECT_EQ(r.exit_code, 2) << command;
    EXPECT_NE(r.err.find("--up: unknown up axis \"sideways\""), std::string::npos) << r.err;
  }
  const CommandResult help = run_recoil("drop --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--up +Z"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("glTF is +Y"), std::string::npos) << help.out;
}

}  // namespace recoil::test
