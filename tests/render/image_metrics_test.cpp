// The compare metrics on synthetic images whose values are known in
// closed form.
#include "render/image_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "core/error.h"
#include "render/diff_heatmap.h"

namespace recoil::render {
namespace {

// Opaque image with varied content: gradients plus seeded noise.
Image textured(int width, int height, unsigned seed = 3) {
  Image image(width, height);
  std::mt19937 rng(seed);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(30 + (x * 7 + y * 3) % 150 + rng() % 20);
      p[1] = static_cast<std::uint8_t>(40 + (x * y) % 120 + rng() % 20);
      p[2] = static_cast<std::uint8_t>(50 + ((x / 8 + y / 8) % 2) * 100 + rng() % 20);
      p[3] = 255;
    }
  return image;
}

Image constant(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a = 255) {
  Image image(width, height);
  for (int i = 0; i < width * height; ++i) {
    image.rgba[4 * i + 0] = r;
    image.rgba[4 * i + 1] = g;
    image.rgba[4 * i + 2] = b;
    image.rgba[4 * i + 3] = a;
  }
  return image;
}

TEST(ImageMetrics, IdenticalImagesHaveSsimOneAndNoPsnr) {
  const Image a = textured(40, 30);
  const ImageComparison c = compare_images(a, a);
  EXPECT_EQ(c.failing_pixels, 0);
  EXPECT_EQ(c.failing_fraction, 0.0);
  EXPECT_EQ(c.max_difference, 0.0);
  EXPECT_FALSE(c.psnr.has_value());
  EXPECT_EQ(c.ssim, 1.0);
  // The SSIM kernel itself (not only the identical-image shortcut) gives 1.
  const std::vector<double> luma = composited_luma(a);
  EXPECT_NEAR(ssim_luma(luma, luma, a.width, a.height), 1.0, 1e-15);
}

TEST(ImageMetrics, ConstantOffsetGivesClosedFormPsnr) {
  // Every channel of every pixel differs by k/255: MSE = (k/255)^2, so
  // PSNR = -20 log10(k/255) exactly.
  for (int k : {1, 5, 51}) {
    const Image a = textured(32, 24);
    Image b = a;
    for (size_t i = 0; i < b.rgba.size(); ++i)
      if (i % 4 != 3) b.rgba[i] = static_cast<std::uint8_t>(b.rgba[i] + k);  // textured stays below 200
    const ImageComparison c = compare_images(b, a, 0.02);
    const double delta = k / 255.0;
    ASSERT_TRUE(c.psnr.has_value());
    std::cout << "offset " << k << "/255: psnr " << *c.psnr << " expected " << -20.0 * std::log10(delta)
              << " ssim " << c.ssim << "\n";
    EXPECT_NEAR(*c.psnr, -20.0 * std::log10(delta), 1e-9);
    EXPECT_NEAR(c.max_difference, delta, 1e-15);
    EXPECT_EQ(c.failing_fraction, delta > 0.02 ? 1.0 : 0.0);
  }
}

TEST(ImageMetrics, ConstantImagesHaveClosedFormSsim) {
  // Flat images: all variances vanish, so SSIM = (2 mx my + C1) / (mx^2 + my^2 + C1)
  // with mx, my the luma values.
  const Image a = constant(20, 16, 100, 100, 100);
  const Image b = constant(20, 16, 120, 120, 120);
  const double mx = 100.0 / 255.0, my = 120.0 / 255.0, c1 = 1e-4;
  const double expected = (2 * mx * my + c1) / (mx * mx + my * my + c1);
  const ImageComparison c = compare_images(a, b);
  std::cout << "flat ssim " << c.ssim << " expected " << expected << "\n";
  EXPECT_NEAR(c.ssim, expected, 1e-12);
}

TEST(ImageMetrics, OnePixelChangeFailsExactlyOnePixel) {
  const Image a = textured(64, 48);
  Image b = a;
  b.pixel(17, 9)[1] = static_cast<std::uint8_t>(b.pixel(17, 9)[1] + 40);
  const ImageComparison c = compare_images(b, a);
  EXPECT_EQ(c.failing_pixels, 1);
  EXPECT_DOUBLE_EQ(c.failing_fraction, 1.0 / (64 * 48));
  EXPECT_DOUBLE_EQ(c.max_difference, 40.0 / 255.0);
  EXPECT_LT(c.ssim, 1.0);
  EXPECT_GT(c.ssim, 0.99);
}

TEST(ImageMetrics, ThresholdIsExclusive) {
  // A difference equal to the threshold passes; one level more fails.
  const Image a = constant(16, 16, 100, 100, 100);
  const Image same_level = constant(16, 16, 105, 100, 100);
  const Image next_level = constant(16, 16, 106, 100, 100);
  const double threshold = 5.0 / 255.0;
  EXPECT_EQ(compare_images(same_level, a, threshold).failing_pixels, 0);
  EXPECT_EQ(compare_images(next_level, a, threshold).failing_pixels, 256);
  EXPECT_EQ(compare_images(next_level, a, 6.0 / 255.0).failing_pixels, 0);
}

TEST(ImageMetrics, AlphaIsCompositedOverBlack) {
  // Fully transparent pixels are black whatever their colour; half-transparent
  // white equals opaque grey 255*128/255 = 128 / 255.
  const Image transparent_red = constant(16, 16, 255, 0, 0, 0);
  const Image black = constant(16, 16, 0, 0, 0, 255);
  const ImageComparison t = compare_images(transparent_red, black);
  EXPECT_EQ(t.max_difference, 0.0);
  EXPECT_FALSE(t.psnr.has_value());

  const Image half_white = constant(16, 16, 255, 255, 255, 128);
  const Image grey = constant(16, 16, 128, 128, 128, 255);
  const ImageComparison h = compare_images(half_white, grey);
  EXPECT_EQ(h.max_difference, 0.0);
  EXPECT_EQ(h.ssim, 1.0);

  const Image half_red = constant(16, 16, 200, 0, 0, 100);
  const ImageComparison r = compare_images(half_red, black);
  EXPECT_DOUBLE_EQ(r.max_difference, 200.0 * 100.0 / (255.0 * 255.0));
}

TEST(ImageMetrics, SizeMismatchAndTinyImagesAreBadInput) {
  try {
    compare_images(textured(20, 20), textured(21, 20));
    FAIL() << "expected a size mismatch";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::bad_input);
    EXPECT_NE(std::string(e.what()).find("20x20"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("21x20"), std::string::npos);
  }
  EXPECT_THROW(compare_images(textured(10, 30), textured(10, 30)), Error);
  EXPECT_NO_THROW(compare_images(textured(11, 11), textured(11, 11, 4)));
}

// Direct 2-D evaluation of the definition: for every centre whose 11x11
// window lies inside, Gaussian-weighted means, population (co)variances and
// the SSIM formula; then the plain mean. Independent of the separable,
// row-streamed implementation.
double brute_force_ssim(const std::vector<double>& x, const std::vector<double>& y, int width, int height) {
  double w[11], sum = 0.0;
  for (int k = 0; k < 11; ++k) sum += w[k] = std::exp(-0.5 * (k - 5) * (k - 5) / 2.25);
  double total = 0.0;
  int count = 0;
  for (int cy = 5; cy < height - 5; ++cy)
    for (int cx = 5; cx < width - 5; ++cx) {
      double ux = 0, uy = 0, uxx = 0, uyy = 0, uxy = 0;
      for (int j = -5; j <= 5; ++j)
        for (int i = -5; i <= 5; ++i) {
          const double wij = w[j + 5] * w[i + 5] / (sum * sum);
          const double a = x[(cy + j) * width + cx + i], b = y[(cy + j) * width + cx + i];
          ux += wij * a;
          uy += wij * b;
          uxx += wij * a * a;
          uyy += wij * b * b;
          uxy += wij * a * b;
        }
      const double vx = uxx - ux * ux, vy = uyy - uy * uy, vxy = uxy - ux * uy;
      total += (2 * ux * uy + 1e-4) * (2 * vxy + 9e-4) / ((ux * ux + uy * uy + 1e-4) * (vx + vy + 9e-4));
      ++count;
    }
  return total / count;
}

TEST(ImageMetrics, SsimMatchesDirectEvaluationOfTheDefinition) {
  for (auto [w, h] : {std::pair{11, 11}, std::pair{25, 19}, std::pair{13, 40}}) {
    const std::vector<double> x = composited_luma(textured(w, h, 1));
    const std::vector<double> y = composited_luma(textured(w, h, 2));
    const double fast = ssim_luma(x, y, w, h);
    const double direct = brute_force_ssim(x, y, w, h);
    std::cout << w << "x" << h << ": ssim " << fast << " direct " << direct << "\n";
    EXPECT_NEAR(fast, direct, 1e-12);
  }
}

TEST(ImageMetrics, SsimSeesOnlyPixelsInsideSomeWindow) {
  // Corner pixel (0,0) is inside the window of the first valid centre (5,5).
  const Image a = textured(30, 30);
  Image corner = a;
  corner.pixel(0, 0)[0] = static_cast<std::uint8_t>(corner.pixel(0, 0)[0] + 60);
  EXPECT_LT(compare_images(corner, a).ssim, 1.0);
}

TEST(DiffHeatmap, FailingPixelsStandOut) {
  const Image a = textured(32, 32);
  Image b = a;
  b.pixel(5, 7)[2] = static_cast<std::uint8_t>(b.pixel(5, 7)[2] + 50);
  const Image heat = difference_heatmap(b, a, 0.02);
  ASSERT_EQ(heat.width, 32);
  ASSERT_EQ(heat.height, 32);
  EXPECT_EQ(heat.pixel(5, 7)[0], 255);  // failing: full red at least
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      EXPECT_EQ(heat.pixel(x, y)[3], 255);
      if (x != 5 || y != 7) {
        EXPECT_LE(heat.pixel(x, y)[0], 64) << x << "," << y;  // dim context only
      }
    }
  // The ramp rises with the difference: a larger failure is brighter.
  Image c = a;
  c.pixel(5, 7)[2] = 255;
  c.pixel(5, 7)[1] = 0;
  const Image hotter = difference_heatmap(c, a, 0.02);
  EXPECT_GT(int(hotter.pixel(5, 7)[1]) + hotter.pixel(5, 7)[2], int(heat.pixel(5, 7)[1]) + heat.pixel(5, 7)[2]);
  EXPECT_THROW(difference_heatmap(a, textured(31, 32), 0.02), Error);
}

}  // namespace
}  // namespace recoil::render
