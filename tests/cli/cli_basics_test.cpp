#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/test_support.h"

namespace recoil::test {

namespace fs = std::filesystem;

TEST(Cli, HelpAndVersion) {
  const CommandResult help = run_recoil("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("turntable"), std::string::npos);
  const CommandResult version = run_recoil("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.out.find("recoil"), std::string::npos);
}

TEST(Cli, UnknownCommandIsBadUsage) {
  const CommandResult r = run_recoil("frobnicate");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "recoil: error: unknown command \"frobnicate\"; the commands are run, drop, turntable, info, "
                   "compare, batch (see --help)\n");
}

// A word that names no command is the mistake even when --help follows it:
// printing the top-level help and exiting 0 read as though it were one.
TEST(Cli, HelpAfterAnUnknownCommandNamesTheWord) {
  const CommandResult r = run_recoil("settle --help");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "recoil: error: unknown command \"settle\"; the commands are run, drop, turntable, info, "
                   "compare, batch (see --help)\n");
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(run_recoil("run --help").exit_code, 0);
  EXPECT_EQ(run_recoil("-q --help").exit_code, 0);
}

// One line each, with the closest command or option named.
TEST(Cli, TyposGetADidYouMean) {
  const CommandResult command = run_recoil("runn scene.json");
  EXPECT_EQ(command.exit_code, 2);
  EXPECT_EQ(command.err, "recoil: error: unknown command \"runn\"; did you mean \"run\"? (see --help)\n");
  const CommandResult option = run_recoil("run scene.json --framez 1-3");
  EXPECT_EQ(option.exit_code, 2);
  EXPECT_EQ(option.err, "recoil: error: unknown option --framez; did you mean --frames? (see recoil run --help)\n");
  const CommandResult global = run_recoil("--max-memory 5 drp mesh.obj");
  EXPECT_EQ(global.err, "recoil: error: unknown command \"drp\"; did you mean \"drop\"? (see --help)\n");
  const CommandResult missing = run_recoil("drop");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.err, "recoil: error: MESH is required (see recoil drop --help)\n");
}

// A number out of its range, or a word where a number goes, is refused in
// the scene file's words, with the range as the user can type it.
TEST(Cli, NumbersOutOfRangeSayTheRange) {
  const std::string bunny = shell_quote(source_path("assets/meshes/bunny.obj"));
  const CommandResult word = run_recoil("turntable " + bunny + " --turn-frames many");
  EXPECT_EQ(word.exit_code, 2);
  EXPECT_EQ(word.err,
            "recoil: error: --turn-frames: must be a whole number in [1, 1000000], got 'many' (see recoil turntable "
            "--help)\n");
  const CommandResult low = run_recoil("turntable " + bunny + " --fov 0");
  EXPECT_EQ(low.exit_code, 2);
  EXPECT_EQ(low.err, "recoil: error: --fov: must be in [1, 170], got 0 (see recoil turntable --help)\n");
  EXPECT_NE(run_recoil("turntable --help").out.find("--fov FLOAT:in [1, 170]"), std::string::npos);
  const CommandResult part = run_recoil("turntable " + bunny + " --turn-frames 1.5");
  EXPECT_EQ(part.exit_code, 2);
  EXPECT_NE(part.err.find("--turn-frames: must be a whole number in [1, 1000000], got '1.5'"), std::string::npos)
      << part.err;
  const CommandResult budget = run_recoil("drop " + bunny + " --collision-triangles many");
  EXPECT_EQ(budget.exit_code, 2) << budget.err;
  EXPECT_NE(budget.err.find("--collision-triangles: must be 0 (the mesh itself) or 4 to"), std::string::npos)
      << budget.err;
}

// `run` given a mesh or a folder says which command to use instead.
TEST(Cli, RunOnAMeshOrAFolderSaysWhatToRun) {
  const std::string bunny = source_path("assets/meshes/bunny.obj").string();
  const CommandResult mesh = run_recoil("run " + shell_quote(bunny));
  EXPECT_EQ(mesh.exit_code, 2);
  EXPECT_NE(mesh.err.find("`recoil drop " + bunny + "` builds a scene of it and `recoil turntable " + bunny + "`"),
            std::string::npos)
      << mesh.err;
  const fs::path dir = scratch_dir("run_on_folder");
  const CommandResult empty = run_recoil("run " + shell_quote(dir));
  EXPECT_EQ(empty.exit_code, 2);
  EXPECT_NE(empty.err.find("a folder, not a scene file"), std::string::npos) << empty.err;
  std::ofstream(dir / "scene.json") << "{}";
  const CommandResult saved = run_recoil("run " + shell_quote(dir));
  EXPECT_NE(saved.err.find("`recoil run " + (dir / "scene.json").string() + "` reruns the scene saved there"),
            std::string::npos)
      << saved.err;
}

}  // namespace recoil::test
