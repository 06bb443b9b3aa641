#pragma once
// Image difference metrics for visual regression.
//
// Both images are first composited over black (straight alpha, so a pixel's
// encoded value becomes channel/255 * alpha/255 in [0,1]); every metric below
// works on those composited, still sRGB-encoded values.
#include <cstddef>  // before render/image.h, which uses size_t
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "render/image.h"

namespace recoil::render {

inline constexpr double default_compare_threshold = 0.02;

struct ImageComparison {
  int width = 0;
  int height = 0;
  double threshold = default_compare_threshold;
  std::int64_t failing_pixels = 0;   // pixels whose difference is > threshold
  double failing_fraction = 0.0;     // failing_pixels / (width * height)
  double max_difference = 0.0;       // largest per-pixel difference, in [0,1]
  double mse = 0.0;                  // mean squared error over R, G and B
  std::optional<double> psnr;        // dB over RGB, data range 1; empty when identical
  double ssim = 1.0;                 // SSIM of the luma planes (see ssim_luma)
};

// Smallest side SSIM accepts: the 11x11 Gaussian window must fit at least once.
inline constexpr int ssim_window = 11;

// Per-pixel difference: the largest absolute channel difference of R, G, B in
// [0,1] after compositing over black. Returns width*height values, row-major.
std::vector<double> pixel_differences(const Image& actual, const Image& reference);

// Luma Y' = 0.2126 R' + 0.7152 G' + 0.0722 B' of the composited, encoded
// values in [0,1]: width*height values, row-major.
std::vector<double> composited_luma(const Image& image);

// SSIM as scikit-image's structural_similarity(gaussian_weights=True,
// sigma=1.5, use_sample_covariance=False, data_range=1): Gaussian window of
// radius int(3.5*1.5+0.5) = 5 (11x11), K1 = 0.01, K2 = 0.03, population
// (co)variances, averaged over the pixels whose whole window lies inside the
// image. `x` and `y` are width*height planes. Requires both sides >= 11.
double ssim_luma(const std::vector<double>& x, const std::vector<double>& y, int width, int height);

// All metrics of one pair. Throws recoil::Error(bad_input) when the sizes
// differ or an image is smaller than 11x11 (SSIM is undefined there).
ImageComparison compare_images(const Image& actual, const Image& reference,
                               double threshold = default_compare_threshold);

// Both decoded images and their metrics (the images feed heat maps, reports).
struct LoadedComparison {
  Image actual;
  Image reference;
  ImageComparison metrics;
};

// Reads both PNGs and compares them; errors (unreadable file, size mismatch)
// are recoil::Error(bad_input) naming both files.
LoadedComparison compare_image_files(const std::filesystem::path& actual, const std::filesystem::path& reference,
                                    double threshold = default_compare_threshold);

}  // namespace recoil::render
