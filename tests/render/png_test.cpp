#include "render/png.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "tests/test_support.h"

namespace recoil::render {

TEST(Png, RoundTripIsLosslessAtEveryLevel) {
  Image image(37, 23);  // odd sizes catch stride mistakes
  for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = static_cast<std::uint8_t>((i * 7919) % 251);
  const auto dir = recoil::test::scratch_dir("png_round_trip");
  for (int level : {0, 1, 6, 9}) {
    for (bool fast : {true, false}) {
      const auto path = dir / ("img_" + std::to_string(level) + (fast ? "f" : "a") + ".png");
      write_png(path, image, PngOptions{level, fast});
      const Image back = read_png(path);
      ASSERT_EQ(back.width, image.width);
      ASSERT_EQ(back.height, image.height);
      EXPECT_EQ(back.rgba, image.rgba) << "level " << level;
    }
  }
  // Atomic writes leave no temporary files behind.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 8);
}

// The colour type byte of a PNG's header chunk (2: RGB, 6: RGBA).
int colour_type(const std::vector<std::uint8_t>& png) { return png.at(25); }

TEST(Png, WithoutAlphaTheImageIsWrittenAsRgbAndReadBackOpaque) {
  Image image(19, 11);
  for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = i % 4 == 3 ? 255 : static_cast<std::uint8_t>(i * 31);
  PngOptions rgb;
  rgb.alpha = false;
  const std::vector<std::uint8_t> without = encode_png(image, rgb);
  const std::vector<std::uint8_t> with = encode_png(image);
  EXPECT_EQ(colour_type(without), 2);
  EXPECT_EQ(colour_type(with), 6);
  EXPECT_LT(without.size(), with.size());
  // An opaque image reads back the same either way; RGBA keeps every alpha,
  // even of an image whose pixels are all opaque but one.
  const auto dir = recoil::test::scratch_dir("png_colour_type");
  write_png(dir / "rgb.png", image, rgb);
  EXPECT_EQ(read_png(dir / "rgb.png").rgba, image.rgba);
  image.pixel(18, 10)[3] = 254;
  write_png(dir / "rgba.png", image);
  EXPECT_EQ(read_png(dir / "rgba.png").rgba, image.rgba);
}

TEST(Png, RejectsNonPngAndTruncatedFiles) {
  const auto dir = recoil::test::scratch_dir("png_bad");
  std::ofstream(dir / "text.png") << "hello";
  EXPECT_THROW(read_png(dir / "text.png"), Error);
  Image image(16, 16);
  const auto bytes = encode_png(image);
  std::ofstream out(dir / "cut.png", std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size() / 2));
  out.close();
  try {
    read_png(dir / "cut.png");
    FAIL() << "truncated PNG was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::bad_input);
    EXPECT_NE(std::string(e.what()).find("cut.png"), std::string::npos);
  }
  EXPECT_THROW(read_png(dir / "missing.png"), Error);
}

TEST(Png, UnwritableFolderIsAnOutputError) {
  try {
    write_png("/nonexistent-folder/x.png", Image(2, 2));
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::output_failed);
  }
}

}  // namespace recoil::render
