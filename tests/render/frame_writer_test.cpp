#include "render/frame_writer.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "tests/test_support.h"

namespace recoil::render {

static Image numbered_image(int n) {
  Image image(24, 16);
  for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = static_cast<std::uint8_t>(n * 31 + i);
  return image;
}

TEST(FrameWriter, WritesEveryFrameWithItsOwnContent) {
  const auto dir = recoil::test::scratch_dir("frame_writer");
  {
    FrameWriter writer(PngOptions{}, 3, 2);
    for (int n = 0; n < 20; ++n) writer.submit(dir / ("f" + std::to_string(n) + ".png"), numbered_image(n));
    writer.finish();
    EXPECT_GT(writer.encode_ms(), 0.0);
  }
  for (int n = 0; n < 20; ++n) EXPECT_EQ(read_png(dir / ("f" + std::to_string(n) + ".png")).rgba, numbered_image(n).rgba);
}

TEST(FrameWriter, ReportsAWriteFailure) {
  FrameWriter writer(PngOptions{}, 1, 1);
  writer.submit("/nonexistent-folder/a.png", numbered_image(0));
  try {
    writer.finish();
    FAIL() << "the failed write was not reported";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::output_failed);
  }
}

}  // namespace recoil::render
