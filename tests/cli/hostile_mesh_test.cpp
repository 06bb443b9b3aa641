// What the readers refuse ends the CLI with exit code 2 and one error line
// naming the file: a FIFO (at once, not blocked) and /dev/zero behind a symlink.
#include <gtest/gtest.h>

#include "tests/hostile_files.h"
#include "tests/test_support.h"

namespace recoil::test {

TEST(MeshImportCli, FifoAndDeviceExitWithCode2) {
  const auto dir = scratch_dir("cli_hostile_mesh");
  make_fifo(dir / "pipe.obj");
  link_to_dev_zero(dir / "zero.obj");
  for (const char* name : {"pipe.obj", "zero.obj"}) {
    const CommandResult r = run_recoil("info " + shell_quote(dir / name));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("recoil: error: " + (dir / name).string(), 0), 0u) << r.err;
  }
}

}  // namespace recoil::test
