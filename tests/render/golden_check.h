#pragma once
// Compares a rendered image with its golden PNG under tests/render/golden/,
// with the tolerance of the project's visual-regression metric; writes the
// golden instead when RECOIL_UPDATE_GOLDEN=1.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "render/image.h"
#include "render/image_metrics.h"
#include "render/png.h"
#include "tests/test_support.h"

namespace recoil::render {

inline void check_golden(const std::string& name, const Image& actual) {
  const auto golden = recoil::test::source_path("tests/render/golden/" + name + ".png");
  const char* update = std::getenv("RECOIL_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    write_png(golden, actual);
    std::cout << "updated " << golden << "\n";
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " is missing; run with RECOIL_UPDATE_GOLDEN=1";
  const Image expected = read_png(golden);
  ASSERT_EQ(actual.width, expected.width) << name;
  ASSERT_EQ(actual.height, expected.height) << name;
  // The project's visual-regression metric (recoil compare): a pixel fails
  // when a channel differs by more than 2/255; at most 0.1 % may fail.
  const ImageComparison d = compare_images(actual, expected, 2.0 / 255.0);
  std::cout << name << ": " << d.failing_pixels << " pixels off by > 2/255 (" << 100.0 * d.failing_fraction
            << " %), max difference " << d.max_difference << ", SSIM " << d.ssim << "\n";
  if (d.failing_fraction > 0.001) {
    const auto dir = recoil::test::scratch_dir("golden_" + name);
    write_png(dir / (name + ".png"), actual);
    ADD_FAILURE() << name << ": " << 100.0 * d.failing_fraction << " % of pixels differ (limit 0.1 %); actual image in "
                  << (dir / (name + ".png"));
  }
}

}  // namespace recoil::render
