// Outputs named by the user that are not plain files: a FIFO given to
// --save-scene receives the scene and stays a FIFO (a device such as
// /dev/null or /dev/stdout is handled the same way); --video, which is
// encoded beside its path and renamed into place, refuses one before
// anything is simulated.
#include <fcntl.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "tests/cli/box_mesh_file.h"
#include "tests/hostile_files.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;

TEST(SpecialFiles, ASavedSceneIsWrittenIntoAFifoAndTheFifoStays) {
  const fs::path dir = scratch_dir("special_files_save_scene");
  const fs::path box = write_box_off(dir / "box.off", Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.1, 0.1, 0.1));
  const fs::path fifo = dir / "scene.json";
  make_fifo(fifo);
  // Open for reading first, without blocking, so that recoil's open for
  // writing finds a reader; the scene (a few KB) fits the pipe's buffer.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  const CommandResult r = run_recoil("drop " + shell_quote(box) + " --seconds 0.004 --no-render -q -o " +
                                     shell_quote(dir / "out") + " --save-scene " + shell_quote(fifo));
  std::string received;
  char buffer[4096];
  for (ssize_t n; (n = ::read(reader, buffer, sizeof buffer)) > 0;) received.append(buffer, static_cast<size_t>(n));
  ::close(reader);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo))) << "the FIFO was replaced by a file";
  EXPECT_NE(received.find("\"recoil\": 1"), std::string::npos) << received;
}

TEST(SpecialFiles, AVideoPathThatIsAFifoIsRefusedBeforeTheRun) {
  const fs::path dir = scratch_dir("special_files_video");
  const fs::path box = write_box_off(dir / "box.off", Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.1, 0.1, 0.1));
  const fs::path fifo = dir / "video.mp4";
  make_fifo(fifo);
  const CommandResult r = run_recoil("drop " + shell_quote(box) + " --seconds 0.004 --resolution 32x32 -q -o " +
                                     shell_quote(dir / "out") + " --video " + shell_quote(fifo));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--video " + fifo.string() + ": not a regular file"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace recoil::test
