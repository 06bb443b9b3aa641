// The progress bar's rate reads as items per second, or as seconds per item
// once an item takes longer than a second.
#include "cli/progress.h"

#include <gtest/gtest.h>

namespace recoil::cli {
namespace {

TEST(Progress, SlowRatesReadAsSecondsPerItem) {
  EXPECT_EQ(format_rate(3.25, "frame"), "3.2/s");
  EXPECT_EQ(format_rate(1.0, "frame"), "1.0/s");
  EXPECT_EQ(format_rate(0.25, "frame"), "4.0 s/frame");
  EXPECT_EQ(format_rate(0.0, "frame"), "-");
}

}  // namespace
}  // namespace recoil::cli
