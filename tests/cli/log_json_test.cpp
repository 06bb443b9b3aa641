// --log-json end to end: every stderr line of a run is one JSON object, a
// failure included, and a long settle shows life as "working" lines.
#include <gtest/gtest.h>

#include "tests/cli/box_mesh_file.h"
#include "tests/cli/json_lines.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Every line of `err` parsed; a line that is not a JSON object fails the test.
std::vector<json> objects(const std::string& err) {
  std::vector<json> lines = json_lines(err);
  for (const json& line : lines) EXPECT_TRUE(line.is_object()) << "not a JSON object line in:\n" << err;
  return lines;
}

}  // namespace

TEST(LogJson, AFailureIsAJsonLineWithItsExitCode) {
  const fs::path dir = scratch_dir("log_json_failure");
  const CommandResult r = run_recoil("--log-json drop " + shell_quote(dir / "missing.obj") + " -o " + shell_quote(dir / "out"));
  EXPECT_EQ(r.exit_code, 2);
  const std::vector<json> lines = objects(r.err);
  ASSERT_FALSE(lines.empty()) << r.err;
  EXPECT_EQ(lines.back()["event"], "error");
  EXPECT_EQ(lines.back()["exit_code"], 2);
  EXPECT_NE(lines.back()["message"].get<std::string>().find("missing.obj"), std::string::npos) << r.err;
}

// The first step of a settle reports at once; later ones at most once a second.
TEST(LogJson, SettlingReportsWorkingLines) {
  const fs::path dir = scratch_dir("log_json_settle");
  const fs::path box = write_box_off(dir / "box.off", Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.1, 0.1, 0.1));
  const CommandResult r = run_recoil("turntable " + shell_quote(box) + " --settle --turn-frames 1 --resolution 32x32 " +
                                     "--msaa 0 --log-json -o " + shell_quote(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  bool settling = false;
  for (const json& line : objects(r.err))
    if (line.value("event", "") == "working")
      settling = settling || line["detail"].get<std::string>().find("settling") != std::string::npos;
  EXPECT_TRUE(settling) << r.err;
}

}  // namespace recoil::test
