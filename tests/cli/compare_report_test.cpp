// Pieces of the --report page: base64 and the thumbnails of passing pairs.
#include "cli/compare_report.h"

#include <gtest/gtest.h>

namespace recoil::cli {
namespace {

std::string encode(const std::string& text) {
  return base64_encode(std::vector<std::uint8_t>(text.begin(), text.end()));
}

TEST(CompareReport, Base64MatchesRfc4648Vectors) {
  EXPECT_EQ(encode(""), "");
  EXPECT_EQ(encode("f"), "Zg==");
  EXPECT_EQ(encode("fo"), "Zm8=");
  EXPECT_EQ(encode("foo"), "Zm9v");
  EXPECT_EQ(encode("foob"), "Zm9vYg==");
  EXPECT_EQ(encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(encode("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64_encode({0xff, 0xfe, 0x00}), "//4A");
}

TEST(CompareReport, ThumbnailsAverageBoxes) {
  render::Image image(7, 4);  // factor 3 for width 3: 7 -> 3 columns, 4 -> 2 rows
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 7; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(10 * x);
      p[1] = static_cast<std::uint8_t>(20 * y);
      p[2] = 77;
      p[3] = 255;
    }
  const render::Image small = downscale_to_width(image, 3);
  ASSERT_EQ(small.width, 3);
  ASSERT_EQ(small.height, 2);
  EXPECT_EQ(small.pixel(0, 0)[0], 10);  // mean of x = 0,1,2 times 10
  EXPECT_EQ(small.pixel(0, 0)[1], 20);  // mean of y = 0,1,2 times 20
  EXPECT_EQ(small.pixel(2, 1)[0], 60);  // the partial box x = 6 only
  EXPECT_EQ(small.pixel(2, 1)[1], 60);  // the partial box y = 3 only
  EXPECT_EQ(small.pixel(1, 1)[2], 77);
  const render::Image same = downscale_to_width(image, 7);
  EXPECT_EQ(same.rgba, image.rgba);
}

}  // namespace
}  // namespace recoil::cli
