#include <gtest/gtest.h>

#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "core/utf8.h"
#include "tests/cli/box_mesh_file.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;

TEST(Utf8, WellFormedTextPassesAndEachKindOfMalformedSequenceIsFound) {
  EXPECT_EQ(first_invalid_utf8("plain ascii"), std::string::npos);
  EXPECT_EQ(first_invalid_utf8("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x99\x82 \xF4\x8F\xBF\xBF"), std::string::npos);
  EXPECT_EQ(first_invalid_utf8("caf\xE9.off"), 3u);            // Latin-1
  EXPECT_EQ(first_invalid_utf8("a\x80"), 1u);                  // a stray continuation byte
  EXPECT_EQ(first_invalid_utf8("ab\xE2\x82"), 2u);             // cut short
  EXPECT_EQ(first_invalid_utf8("\xC0\xAF"), 0u);               // overlong '/'
  EXPECT_EQ(first_invalid_utf8("x\xE0\x80\xAF"), 1u);          // overlong, three bytes
  EXPECT_EQ(first_invalid_utf8("\xED\xA0\x80"), 0u);           // a surrogate
  EXPECT_EQ(first_invalid_utf8("\xF4\x90\x80\x80"), 0u);       // past U+10FFFF
  EXPECT_EQ(first_invalid_utf8("\xC3\xA9\xFF"), 2u);
  EXPECT_EQ(escape_invalid_utf8("caf\xE9.off \xC3\xA9"), "caf\\xE9.off \xC3\xA9");
}

// A Latin-1 file name cannot go into the JSON records (run.json, scene.json,
// batch.json): the commands that write them refuse it up front, naming it,
// and write nothing; `info`, which writes no record, reads the file.
TEST(NonUtf8Names, AreRefusedBeforeAnythingIsWrittenByTheCommandsThatRecordThem) {
  const fs::path dir = scratch_dir("non_utf8_names");
  const fs::path meshes = dir / "meshes";
  fs::create_directories(meshes);
  write_box_off(meshes / "plain.off", Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(0.2));
  const fs::path latin1 =
      write_box_off(meshes / "caf\xE9.off", Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(0.2));
  const std::string quick = " --frames 1 --resolution 32x32 -q -o ";
  for (const std::string command : {"turntable", "drop"}) {
    const CommandResult r = run_recoil(command + " " + shell_quote(latin1) + quick + shell_quote(dir / command));
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("argument '" + (meshes / "caf\\xE9.off").string() + "' is not UTF-8 text"), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / command)) << command;
  }
  const CommandResult out = run_recoil("turntable " + shell_quote(meshes / "plain.off") + quick +
                                       shell_quote(dir / "out\xE9"));
  EXPECT_EQ(out.exit_code, 2) << out.err;
  EXPECT_FALSE(fs::exists(dir / "out\xE9"));
  const std::string items = " --set turn-frames=1 --set resolution=32x32 -q -o ";
  const CommandResult batch = run_recoil("batch " + shell_quote(meshes) + items + shell_quote(dir / "batch"));
  EXPECT_EQ(batch.exit_code, 2) << batch.err;
  EXPECT_NE(batch.err.find("mesh file '" + (meshes / "caf\\xE9.off").string() + "' is not UTF-8 text"),
            std::string::npos)
      << batch.err;
  EXPECT_FALSE(fs::exists(dir / "batch"));
  const CommandResult info = run_recoil("info " + shell_quote(latin1));
  EXPECT_EQ(info.exit_code, 0) << info.err;
  // Relative paths are recorded made absolute: a working directory that is
  // not UTF-8 is refused as an argument is.
  fs::create_directories(dir / "caf\xE9");
  const CommandResult here = run_recoil("turntable " + shell_quote(meshes / "plain.off") + quick + "out",
                                        "-C " + shell_quote(dir / "caf\xE9"));
  EXPECT_EQ(here.exit_code, 2) << here.err;
  EXPECT_NE(here.err.find("the working directory '"), std::string::npos) << here.err;
  EXPECT_FALSE(fs::exists(dir / "caf\xE9" / "out"));
  // An error about such a name is still one JSON line under --log-json.
  const CommandResult logged = run_recoil("--log-json info " + shell_quote(meshes / "gone\xE9.off"));
  EXPECT_EQ(logged.exit_code, 2) << logged.err;
  EXPECT_EQ(nlohmann::json::parse(logged.err)["event"], "error") << logged.err;
}

}  // namespace recoil::test
