#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "render/png.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace fs = std::filesystem;

static std::string bunny() { return shell_quote(source_path("assets/meshes/bunny.obj")); }

TEST(TurntableCommand, WritesEveryFrameAtTheAskedSizeByteIdenticalAcrossRuns) {
  const fs::path a = scratch_dir("turntable_a"), b = scratch_dir("turntable_b");
  for (const fs::path& dir : {a, b}) {
    const CommandResult r = run_recoil("turntable " + bunny() + " --frames 4 --resolution 96x64 -o " + shell_quote(dir));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  int frames = 0;
  for (const auto& entry : fs::directory_iterator(a)) {
    ++frames;
    EXPECT_EQ(entry.path().extension(), ".png") << entry.path();  // no temporary files left
  }
  EXPECT_EQ(frames, 4);
  const render::Image first = render::read_png(a / "frame_0001.png");
  EXPECT_EQ(first.width, 96);
  EXPECT_EQ(first.height, 64);
  for (const char* name : {"frame_0001.png", "frame_0004.png"})
    EXPECT_EQ(file_bytes(a / name), file_bytes(b / name)) << name << " differs between two identical runs";
  // The camera moves: consecutive frames differ.
  EXPECT_NE(file_bytes(a / "frame_0001.png"), file_bytes(a / "frame_0002.png"));
}

TEST(TurntableCommand, TransparentBackgroundAndColour) {
  const fs::path dir = scratch_dir("turntable_transparent");
  const CommandResult r = run_recoil("turntable " + bunny() +
                                     " --frames 1 --resolution 64x64 --background transparent --color '#ff0000' -o " +
                                     shell_quote(dir));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const render::Image image = render::read_png(dir / "frame_0001.png");
  // The bunny sits in the middle; it is reddish and opaque there.
  const std::uint8_t* centre = image.pixel(32, 36);
  EXPECT_EQ(centre[3], 255);
  EXPECT_GT(centre[0], centre[1] + 40);
}

TEST(TurntableCommand, BadInputIsExit2AndUnwritableOutputIsExit4) {
  const fs::path dir = scratch_dir("turntable_bad");
  EXPECT_EQ(run_recoil("turntable /nonexistent.obj -o " + shell_quote(dir)).exit_code, 2);
  const CommandResult resolution = run_recoil("turntable " + bunny() + " --resolution 12by9 -o " + shell_quote(dir));
  EXPECT_EQ(resolution.exit_code, 2);
  EXPECT_NE(resolution.err.find("--resolution"), std::string::npos) << resolution.err;
  const CommandResult color = run_recoil("turntable " + bunny() + " --color red -o " + shell_quote(dir));
  EXPECT_EQ(color.exit_code, 2);
  EXPECT_NE(color.err.find("--color"), std::string::npos) << color.err;
  EXPECT_EQ(run_recoil("turntable " + bunny() + " --msaa 3").exit_code, 2);
  std::ofstream(dir / "a_file") << "x";
  const CommandResult blocked =
      run_recoil("turntable " + bunny() + " --frames 1 --resolution 32x32 -o " + shell_quote(dir / "a_file" / "sub"));
  EXPECT_EQ(blocked.exit_code, 4) << blocked.err;
}

}  // namespace recoil::test
