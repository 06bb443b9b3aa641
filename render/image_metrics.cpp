#include "render/image_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string>

#include "core/check.h"
#include "core/error.h"
#include "render/png.h"

namespace recoil::render {
namespace {

// A composited channel is channel * alpha / 255^2; working on the integer
// numerator channel * alpha keeps differences exact, and dividing (not
// multiplying by a rounded reciprocal) rounds once, so k/255 differences
// equal the threshold k/255.0 exactly at the edge.
constexpr double composite_denominator = 255.0 * 255.0;

int composited_numerator(const std::uint8_t* p, int channel) { return int(p[channel]) * int(p[3]); }

std::string size_text(const Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

// SSIM window: sigma 1.5 truncated at 3.5 sigma; scipy's
// gaussian_filter uses radius int(truncate * sigma + 0.5) = 5.
constexpr double ssim_sigma = 1.5;
constexpr int ssim_radius = ssim_window / 2;
static_assert(ssim_radius == int(3.5 * ssim_sigma + 0.5));

std::array<double, ssim_window> gaussian_weights() {
  std::array<double, ssim_window> w{};
  double sum = 0.0;
  for (int k = 0; k < ssim_window; ++k) {
    const double x = k - ssim_radius;
    w[k] = std::exp(-0.5 * x * x / (ssim_sigma * ssim_sigma));
    sum += w[k];
  }
  for (double& v : w) v /= sum;
  return w;
}

// The five filtered quantities SSIM needs: x, y, x^2, y^2, xy.
constexpr int n_moments = 5;

}  // namespace

std::vector<double> pixel_differences(const Image& actual, const Image& reference) {
  RECOIL_CHECK(actual.width == reference.width && actual.height == reference.height,
               "sizes " << size_text(actual) << " vs " << size_text(reference));
  const size_t n = static_cast<size_t>(actual.width) * actual.height;
  std::vector<double> diff(n);
  for (size_t i = 0; i < n; ++i) {
    const std::uint8_t* a = actual.rgba.data() + 4 * i;
    const std::uint8_t* b = reference.rgba.data() + 4 * i;
    int largest = 0;
    for (int c = 0; c < 3; ++c)
      largest = std::max(largest, std::abs(composited_numerator(a, c) - composited_numerator(b, c)));
    diff[i] = largest / composite_denominator;
  }
  return diff;
}

std::vector<double> composited_luma(const Image& image) {
  const size_t n = static_cast<size_t>(image.width) * image.height;
  std::vector<double> luma(n);
  for (size_t i = 0; i < n; ++i) {
    const std::uint8_t* p = image.rgba.data() + 4 * i;
    luma[i] = 0.2126 * (composited_numerator(p, 0) / composite_denominator) +
              0.7152 * (composited_numerator(p, 1) / composite_denominator) +
              0.0722 * (composited_numerator(p, 2) / composite_denominator);
  }
  return luma;
}

double ssim_luma(const std::vector<double>& x, const std::vector<double>& y, int width, int height) {
  RECOIL_CHECK(width >= ssim_window && height >= ssim_window, "width=" << width << " height=" << height);
  RECOIL_CHECK(x.size() == static_cast<size_t>(width) * height && y.size() == x.size(), "plane sizes");
  static const std::array<double, ssim_window> w = gaussian_weights();
  const double c1 = 0.01 * 0.01;  // (K1 * data range)^2
  const double c2 = 0.03 * 0.03;  // (K2 * data range)^2
  const int out_w = width - 2 * ssim_radius;

  // Separable filter, streamed by rows: `ring` keeps the horizontally
  // filtered moments of the last 11 input rows (11 x 5 x out_w), so memory
  // stays small and the vertical pass reads cache-resident rows.
  std::vector<double> ring(static_cast<size_t>(ssim_window) * n_moments * out_w);
  std::vector<double> products(static_cast<size_t>(n_moments) * width);
  std::vector<double> mu(static_cast<size_t>(n_moments) * out_w);  // filtered moments of one output row
  double total = 0.0;
  for (int row = 0; row < height; ++row) {
    const double* xr = x.data() + static_cast<size_t>(row) * width;
    const double* yr = y.data() + static_cast<size_t>(row) * width;
    double* px = products.data();
    double* py = px + width;
    double* pxx = py + width;
    double* pyy = pxx + width;
    double* pxy = pyy + width;
    for (int i = 0; i < width; ++i) {
      px[i] = xr[i];
      py[i] = yr[i];
      pxx[i] = xr[i] * xr[i];
      pyy[i] = yr[i] * yr[i];
      pxy[i] = xr[i] * yr[i];
    }
    double* slot = ring.data() + static_cast<size_t>(row % ssim_window) * n_moments * out_w;
    // Taps outermost, pixels innermost: contiguous loops the compiler
    // vectorises. The window is symmetric, so mirrored taps share one
    // multiply (about 30 % less time than 11 multiplies); every output sums
    // in the same fixed order, so results are reproducible bit for bit.
    for (int m = 0; m < n_moments; ++m) {
      const double* src = products.data() + static_cast<size_t>(m) * width;
      double* dst = slot + static_cast<size_t>(m) * out_w;
      const double* centre = src + ssim_radius;
      for (int i = 0; i < out_w; ++i) dst[i] = w[ssim_radius] * centre[i];
      for (int k = 0; k < ssim_radius; ++k) {
        const double wk = w[k];
        const double* left = src + k;
        const double* right = src + (ssim_window - 1 - k);
        for (int i = 0; i < out_w; ++i) dst[i] += wk * (left[i] + right[i]);
      }
    }
    if (row < ssim_window - 1) continue;

    // Vertical pass for output row (row - radius): input rows row-10 .. row.
    std::array<const double*, ssim_window> rows{};
    for (int k = 0; k < ssim_window; ++k)
      rows[k] = ring.data() + static_cast<size_t>((row - (ssim_window - 1) + k) % ssim_window) * n_moments * out_w;
    for (int m = 0; m < n_moments; ++m) {
      const size_t offset = static_cast<size_t>(m) * out_w;
      double* dst = mu.data() + offset;
      const double* centre = rows[ssim_radius] + offset;
      for (int i = 0; i < out_w; ++i) dst[i] = w[ssim_radius] * centre[i];
      for (int k = 0; k < ssim_radius; ++k) {
        const double wk = w[k];
        const double* above = rows[k] + offset;
        const double* below = rows[ssim_window - 1 - k] + offset;
        for (int i = 0; i < out_w; ++i) dst[i] += wk * (above[i] + below[i]);
      }
    }
    const double* mux = mu.data();
    const double* muy = mux + out_w;
    const double* muxx = muy + out_w;
    const double* muyy = muxx + out_w;
    const double* muxy = muyy + out_w;
    double row_sum = 0.0;
    for (int i = 0; i < out_w; ++i) {
      const double ux = mux[i], uy = muy[i];
      const double vx = muxx[i] - ux * ux;
      const double vy = muyy[i] - uy * uy;
      const double vxy = muxy[i] - ux * uy;
      row_sum += ((2.0 * ux * uy + c1) * (2.0 * vxy + c2)) / ((ux * ux + uy * uy + c1) * (vx + vy + c2));
    }
    total += row_sum;
  }
  const double count = static_cast<double>(out_w) * (height - 2 * ssim_radius);
  return total / count;
}

ImageComparison compare_images(const Image& actual, const Image& reference, double threshold) {
  if (actual.width != reference.width || actual.height != reference.height)
    throw bad_input("image size mismatch: actual is " + size_text(actual) + ", reference is " +
                    size_text(reference));
  if (actual.width < ssim_window || actual.height < ssim_window)
    throw bad_input("images are " + size_text(actual) + "; SSIM needs at least " + std::to_string(ssim_window) +
                    "x" + std::to_string(ssim_window) + " pixels");
  RECOIL_CHECK(threshold >= 0.0 && threshold <= 1.0, "threshold=" << threshold);

  ImageComparison result;
  result.width = actual.width;
  result.height = actual.height;
  result.threshold = threshold;
  const size_t n = static_cast<size_t>(actual.width) * actual.height;
  // Integer sums of squared numerators are exact, so the MSE does not depend
  // on summation order; numerator^2 < 2^32, so 3n terms fit 64 bits for n < 2^29.
  if (n >= (std::size_t(1) << 29)) throw bad_input("images of " + size_text(actual) + " are too large to compare");
  std::uint64_t squared = 0;
  int largest = 0;
  // A pixel fails when numerator / 65025 > threshold, computed exactly as
  // pixel_differences does so both agree at the threshold edge.
  for (size_t i = 0; i < n; ++i) {
    const std::uint8_t* a = actual.rgba.data() + 4 * i;
    const std::uint8_t* b = reference.rgba.data() + 4 * i;
    int pixel_largest = 0;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(composited_numerator(a, c) - composited_numerator(b, c));
      squared += static_cast<std::uint64_t>(d) * static_cast<std::uint64_t>(d);
      pixel_largest = std::max(pixel_largest, d);
    }
    largest = std::max(largest, pixel_largest);
    if (pixel_largest / composite_denominator > threshold) ++result.failing_pixels;
  }
  result.failing_fraction = static_cast<double>(result.failing_pixels) / static_cast<double>(n);
  result.max_difference = largest / composite_denominator;
  result.mse = static_cast<double>(squared) /
               (composite_denominator * composite_denominator * 3.0 * static_cast<double>(n));
  if (squared > 0) result.psnr = 10.0 * std::log10(1.0 / result.mse);
  result.ssim = squared == 0 ? 1.0
                             : ssim_luma(composited_luma(actual), composited_luma(reference), actual.width,
                                         actual.height);
  return result;
}

LoadedComparison compare_image_files(const std::filesystem::path& actual, const std::filesystem::path& reference,
                                     double threshold) {
  LoadedComparison loaded;
  loaded.actual = read_png(actual);
  loaded.reference = read_png(reference);
  try {
    loaded.metrics = compare_images(loaded.actual, loaded.reference, threshold);
  } catch (const Error& e) {
    throw Error(e.kind(), "comparing " + actual.string() + " with " + reference.string() + ": " + e.what());
  }
  return loaded;
}

}  // namespace recoil::render
