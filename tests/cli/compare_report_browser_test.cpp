// The --report page renders in a real browser: headless Chromium takes a
// screenshot and the three embedded images must show up in it with their
// colours. Skips when no chromium is installed (Debian: apt-get install chromium).
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>

#include "render/png.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace {
namespace fs = std::filesystem;

std::string find_chromium() {
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    const std::string probe = std::string("command -v ") + name + " >/dev/null 2>&1";
    if (std::system(probe.c_str()) == 0) return name;
  }
  return "";
}

render::Image flat(int size, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  render::Image image(size, size);
  for (int i = 0; i < size * size; ++i) {
    image.rgba[4 * i] = r;
    image.rgba[4 * i + 1] = g;
    image.rgba[4 * i + 2] = b;
    image.rgba[4 * i + 3] = 255;
  }
  return image;
}

int count_near(const render::Image& shot, int r, int g, int b) {
  int n = 0;
  for (size_t i = 0; i < shot.rgba.size(); i += 4)
    if (std::abs(shot.rgba[i] - r) < 12 && std::abs(shot.rgba[i + 1] - g) < 12 && std::abs(shot.rgba[i + 2] - b) < 12)
      ++n;
  return n;
}

TEST(CompareReportBrowser, ChromiumShowsReferenceActualAndDiff) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) GTEST_SKIP() << "no chromium on PATH";
  const fs::path dir = scratch_dir("compare_report_browser");
  // Reference pure blue, actual with red +128: every pixel fails by 128/255,
  // which the heat map shows as yellow (255, 251, 0).
  render::write_png(dir / "ref.png", flat(64, 0, 0, 255));
  render::write_png(dir / "actual.png", flat(64, 128, 0, 255));
  const CommandResult r = run_recoil("-q compare '" + (dir / "actual.png").string() + "' '" +
                                     (dir / "ref.png").string() + "' --report '" + (dir / "report.html").string() +
                                     "'");
  ASSERT_EQ(r.exit_code, 1) << r.err;

  const fs::path shot_path = dir / "shot.png";
  const std::string command = "timeout 90 " + chromium +
                              " --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1200,800"
                              " --user-data-dir='" + (dir / "profile").string() + "' --screenshot='" +
                              shot_path.string() + "' 'file://" + (dir / "report.html").string() +
                              "' >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  if (!fs::exists(shot_path)) GTEST_SKIP() << "chromium could not take a screenshot here (status " << status << ")";
  const render::Image shot = render::read_png(shot_path);
  const int blue = count_near(shot, 0, 0, 255);
  const int violet = count_near(shot, 128, 0, 255);
  const int yellow = count_near(shot, 255, 251, 0);
  std::cout << "screenshot " << shot.width << "x" << shot.height << ": reference-blue px " << blue
            << ", actual-violet px " << violet << ", heat-map-yellow px " << yellow << "\n";
  // Each image is drawn a third of the page wide (~380 px square): far more
  // than 10^4 pixels of its colour when it rendered.
  EXPECT_GT(blue, 10000);
  EXPECT_GT(violet, 10000);
  EXPECT_GT(yellow, 10000);
}

}  // namespace
}  // namespace recoil::test
