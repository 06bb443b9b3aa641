// read_png refuses what is not a regular file and headers declaring more
// pixels than the file can hold, as bad_input naming the file.
#include <gtest/gtest.h>

#include "render/png.h"
#include "tests/hostile_files.h"
#include "tests/test_support.h"

namespace recoil::render {
namespace {

TEST(Png, FifoAndDeviceAreRefused) {
  const auto dir = recoil::test::scratch_dir("png_hostile");
  recoil::test::make_fifo(dir / "pipe.png");
  const std::string e1 =
      recoil::test::bad_input_within_a_second([&] { read_png(dir / "pipe.png"); }, dir / "pipe.png");
  EXPECT_NE(e1.find((dir / "pipe.png").string()), std::string::npos) << e1;
  recoil::test::link_to_dev_zero(dir / "zero.png");
  const std::string e2 = recoil::test::bad_input_within_a_second([&] { read_png(dir / "zero.png"); });
  EXPECT_NE(e2.find((dir / "zero.png").string()), std::string::npos) << e2;
}

// The fuzz seed declares 100000 x 100000 pixels (40 GB as RGBA) in 66 bytes.
TEST(Png, DeclaredSizeBeyondTheFileIsRefusedBeforeAllocating) {
  const auto path = recoil::test::source_path("fuzz/corpus/png/huge-dims.png");
  const std::string e = recoil::test::bad_input_within_a_second([&] { read_png(path); });
  EXPECT_NE(e.find(path.string()), std::string::npos) << e;
  EXPECT_NE(e.find("100000 x 100000"), std::string::npos) << e;
}

}  // namespace
}  // namespace recoil::render
