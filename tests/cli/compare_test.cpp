// `recoil compare` as a user runs it.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/compare_report.h"
#include "render/png.h"
#include "tests/test_support.h"

namespace recoil::test {
namespace {
namespace fs = std::filesystem;

render::Image frame(int width, int height, int seed) {
  render::Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = static_cast<std::uint8_t>((x * 9 + seed * 31) % 200);
      p[1] = static_cast<std::uint8_t>((y * 5 + x) % 180);
      p[2] = static_cast<std::uint8_t>(((x / 4 + y / 4) % 2) * 120 + seed);
      p[3] = 255;
    }
  return image;
}

// `base` with a square of side `side` at (2,2) brightened by `amount` levels.
render::Image changed(const render::Image& base, int side, int amount) {
  render::Image image = base;
  for (int y = 2; y < 2 + side; ++y)
    for (int x = 2; x < 2 + side; ++x) image.pixel(x, y)[0] = static_cast<std::uint8_t>(image.pixel(x, y)[0] + amount);
  return image;
}

std::string numbered(int i) {
  std::string name(1, 'f');
  name += std::to_string(i);
  name += ".png";
  return name;
}

size_t count(const std::string& text, const std::string& needle) {
  size_t n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

TEST(CompareCli, ExitCodesForFiles) {
  const fs::path dir = scratch_dir("compare_files");
  const render::Image a = frame(32, 24, 1);
  render::write_png(dir / "a.png", a);
  render::write_png(dir / "same.png", a);
  render::write_png(dir / "changed.png", changed(a, 4, 50));
  render::write_png(dir / "small.png", frame(30, 24, 1));
  std::ofstream(dir / "not_png.png") << "hello";

  EXPECT_EQ(run_recoil("compare " + shell_quote(dir / "same.png") + " " + shell_quote(dir / "a.png")).exit_code, 0);
  const CommandResult differ = run_recoil("compare " + shell_quote(dir / "changed.png") + " " + shell_quote(dir / "a.png"));
  EXPECT_EQ(differ.exit_code, 1);
  EXPECT_NE(differ.out.find("FAIL"), std::string::npos) << differ.out;

  const CommandResult size = run_recoil("compare " + shell_quote(dir / "small.png") + " " + shell_quote(dir / "a.png"));
  EXPECT_EQ(size.exit_code, 2);
  EXPECT_NE(size.err.find("small.png"), std::string::npos) << size.err;
  EXPECT_NE(size.err.find("a.png"), std::string::npos) << size.err;
  EXPECT_NE(size.err.find("recoil: error:"), std::string::npos) << size.err;

  const CommandResult unreadable = run_recoil("compare " + shell_quote(dir / "not_png.png") + " " + shell_quote(dir / "a.png"));
  EXPECT_EQ(unreadable.exit_code, 2);
  EXPECT_NE(unreadable.err.find("not_png.png"), std::string::npos) << unreadable.err;
  EXPECT_EQ(run_recoil("compare " + shell_quote(dir) + " " + shell_quote(dir / "a.png")).exit_code, 2);
  EXPECT_EQ(run_recoil("compare " + shell_quote(dir / "nope.png") + " " + shell_quote(dir / "a.png")).exit_code, 2);
  EXPECT_EQ(run_recoil("compare " + shell_quote(dir / "a.png") + " " + shell_quote(dir / "a.png") + " --threshold 2").exit_code, 2);
}

TEST(CompareCli, ThresholdAndMaxFailing) {
  const fs::path dir = scratch_dir("compare_tolerance");
  const render::Image a = frame(16, 16, 2);
  render::write_png(dir / "ref.png", a);
  render::write_png(dir / "one.png", changed(a, 1, 10));  // one pixel 10/255 = 0.039 off
  const std::string args = "compare " + shell_quote(dir / "one.png") + " " + shell_quote(dir / "ref.png");
  EXPECT_EQ(run_recoil(args).exit_code, 1);                          // 1/256 > 0.001
  EXPECT_EQ(run_recoil(args + " --max-failing 0.004").exit_code, 0);  // 1/256 = 0.0039
  EXPECT_EQ(run_recoil(args + " --threshold 0.04").exit_code, 0);     // 0.039 is within
}

TEST(CompareCli, JsonLayoutInDirectoryMode) {
  const fs::path dir = scratch_dir("compare_json");
  fs::create_directories(dir / "actual");
  fs::create_directories(dir / "ref");
  const render::Image f1 = frame(24, 20, 1), f2 = frame(24, 20, 2), f3 = frame(24, 20, 3);
  render::write_png(dir / "ref/frame_0001.png", f1);
  render::write_png(dir / "ref/frame_0002.png", f2);
  render::write_png(dir / "ref/frame_0003.png", f3);
  render::write_png(dir / "actual/frame_0001.png", f1);
  render::write_png(dir / "actual/frame_0002.png", changed(f2, 6, 40));
  render::write_png(dir / "actual/frame_0004.png", f3);
  std::ofstream(dir / "actual/notes.txt") << "not a frame";

  const CommandResult r = run_recoil("compare " + shell_quote(dir / "actual") + " " + shell_quote(dir / "ref") + " --json");
  EXPECT_EQ(r.exit_code, 1);
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(r.out);
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"pass", "pairs", "missing", "extra", "threshold", "max_failing"}));
  EXPECT_EQ(j["threshold"], 0.02);
  EXPECT_EQ(j["max_failing"], 0.001);
  EXPECT_EQ(j["pass"], false);
  ASSERT_EQ(j["pairs"].size(), 2u);
  const auto& worst = j["pairs"][0];
  std::vector<std::string> pair_keys;
  for (const auto& item : worst.items()) pair_keys.push_back(item.key());
  EXPECT_EQ(pair_keys, (std::vector<std::string>{"actual", "reference", "pass", "failing_fraction",
                                                 "max_difference", "psnr", "ssim"}));
  // Worst first: the changed frame, failing 36 of 480 pixels by 40/255.
  EXPECT_EQ(fs::path(worst["actual"].get<std::string>()).filename(), "frame_0002.png");
  EXPECT_EQ(fs::path(worst["reference"].get<std::string>()), dir / "ref/frame_0002.png");
  EXPECT_EQ(worst["pass"], false);
  EXPECT_DOUBLE_EQ(worst["failing_fraction"].get<double>(), 36.0 / 480.0);
  EXPECT_DOUBLE_EQ(worst["max_difference"].get<double>(), 40.0 / 255.0);
  EXPECT_TRUE(worst["psnr"].is_number());
  EXPECT_LT(worst["ssim"].get<double>(), 1.0);
  const auto& best = j["pairs"][1];
  EXPECT_EQ(best["pass"], true);
  EXPECT_TRUE(best["psnr"].is_null());
  EXPECT_EQ(best["ssim"].get<double>(), 1.0);
  ASSERT_EQ(j["missing"].size(), 1u);
  EXPECT_EQ(fs::path(j["missing"][0].get<std::string>()).filename(), "frame_0003.png");
  ASSERT_EQ(j["extra"].size(), 1u);
  EXPECT_EQ(fs::path(j["extra"][0].get<std::string>()).filename(), "frame_0004.png");
}

TEST(CompareCli, MissingFramesFailExtraFramesDoNot) {
  const fs::path dir = scratch_dir("compare_missing");
  fs::create_directories(dir / "actual");
  fs::create_directories(dir / "ref");
  render::write_png(dir / "ref/a.png", frame(16, 16, 1));
  render::write_png(dir / "actual/a.png", frame(16, 16, 1));
  render::write_png(dir / "actual/b.png", frame(16, 16, 2));
  const CommandResult extra = run_recoil("compare " + shell_quote(dir / "actual") + " " + shell_quote(dir / "ref"));
  EXPECT_EQ(extra.exit_code, 0) << extra.out;
  EXPECT_NE(extra.out.find("b.png"), std::string::npos);
  const CommandResult missing = run_recoil("compare " + shell_quote(dir / "ref") + " " + shell_quote(dir / "actual"));
  EXPECT_EQ(missing.exit_code, 1) << missing.out;
  EXPECT_NE(missing.out.find("MISSING"), std::string::npos) << missing.out;
  // Nothing rendered at all: every reference frame is missing.
  fs::create_directories(dir / "empty");
  const CommandResult none = run_recoil("compare " + shell_quote(dir / "empty") + " " + shell_quote(dir / "actual") + " --json");
  EXPECT_EQ(none.exit_code, 1) << none.err;
  const nlohmann::json j = nlohmann::json::parse(none.out);
  EXPECT_EQ(j["pairs"].size(), 0u);
  EXPECT_EQ(j["missing"].size(), 2u);
  // An empty reference directory is a wrong path, not a pass.
  EXPECT_EQ(run_recoil("compare " + shell_quote(dir / "actual") + " " + shell_quote(dir / "empty")).exit_code, 2);
}

TEST(CompareCli, DiffWritesOneHeatMapPerPair) {
  const fs::path dir = scratch_dir("compare_diff");
  fs::create_directories(dir / "actual");
  fs::create_directories(dir / "ref");
  for (int i = 1; i <= 3; ++i) {
    const std::string name = numbered(i);
    render::write_png(dir / "ref" / name, frame(20, 12, i));
    render::write_png(dir / "actual" / name, i == 2 ? changed(frame(20, 12, i), 3, 60) : frame(20, 12, i));
  }
  const CommandResult r =
      run_recoil("compare " + shell_quote(dir / "actual") + " " + shell_quote(dir / "ref") + " --diff " + shell_quote(dir / "diffs"));
  EXPECT_EQ(r.exit_code, 1);
  for (int i = 1; i <= 3; ++i) {
    const render::Image heat = render::read_png(dir / "diffs" / numbered(i));
    EXPECT_EQ(heat.width, 20);
    EXPECT_EQ(heat.height, 12);
    // Failing pixels of f2 are bright red or hotter; f1 and f3 have none.
    EXPECT_EQ(heat.pixel(3, 3)[0] == 255, i == 2);
  }
  // Heat maps named like the frames must not land among the inputs.
  EXPECT_EQ(run_recoil("compare " + shell_quote(dir / "actual") + " " + shell_quote(dir / "ref") + " --diff " + shell_quote(dir / "ref")).exit_code,
            2);
  // A file where the folder should be is a mistake in the command (2), not an output failure (4).
  std::ofstream(dir / "a_file") << "x";
  const CommandResult onto_file = run_recoil("compare " + shell_quote(dir / "actual") + " " + shell_quote(dir / "ref") +
                                             " --diff " + shell_quote(dir / "a_file"));
  EXPECT_EQ(onto_file.exit_code, 2) << onto_file.err;
  EXPECT_NE(onto_file.err.find("--diff: " + (dir / "a_file").string() + " is a file, not a folder"), std::string::npos)
      << onto_file.err;
}

TEST(CompareCli, UpdateTouchesOnlyFailingPairs) {
  const fs::path dir = scratch_dir("compare_update");
  fs::create_directories(dir / "actual");
  fs::create_directories(dir / "ref");
  const render::Image base = frame(16, 16, 5);
  render::write_png(dir / "ref/pass.png", base);
  render::write_png(dir / "actual/pass.png", changed(base, 2, 2));  // 2/255 < 0.02: passes, bytes differ
  render::write_png(dir / "ref/fail.png", base);
  render::write_png(dir / "actual/fail.png", changed(base, 8, 80));
  const std::string pass_before = file_bytes(dir / "ref/pass.png");
  ASSERT_NE(pass_before, file_bytes(dir / "actual/pass.png"));

  const CommandResult r = run_recoil("compare " + shell_quote(dir / "actual") + " " + shell_quote(dir / "ref") + " --update");
  EXPECT_EQ(r.exit_code, 1) << "the comparison itself failed; --update does not change the verdict";
  EXPECT_EQ(file_bytes(dir / "ref/pass.png"), pass_before);
  EXPECT_EQ(file_bytes(dir / "ref/fail.png"), file_bytes(dir / "actual/fail.png"));
  EXPECT_EQ(run_recoil("compare " + shell_quote(dir / "actual") + " " + shell_quote(dir / "ref")).exit_code, 0);
  for (const auto& entry : fs::directory_iterator(dir / "ref"))
    EXPECT_EQ(entry.path().extension(), ".png") << "temporary left behind: " << entry.path();
}

// In directory mode a pair that cannot be compared (another size, a PNG that
// does not read) is reported with the rest, not in place of them, and the
// command then exits 2; --update accepts a new size, never an unreadable
// frame, adds the extra frames and keeps the missing ones.
TEST(CompareCli, PairsThatCannotBeComparedAreReportedWithTheRestAndUpdateAcceptsANewSize) {
  const fs::path dir = scratch_dir("compare_sizes");
  fs::create_directories(dir / "actual");
  fs::create_directories(dir / "ref");
  for (int i = 1; i <= 3; ++i) render::write_png(dir / "ref" / numbered(i), frame(16, 16, i));
  render::write_png(dir / "ref/gone.png", frame(16, 16, 9));
  render::write_png(dir / "actual" / numbered(1), frame(16, 16, 1));
  render::write_png(dir / "actual" / numbered(2), frame(20, 16, 2));  // resized
  std::ofstream(dir / "actual" / numbered(3)) << "cut short";         // unreadable
  render::write_png(dir / "actual/new.png", frame(16, 16, 7));
  const std::string args = "compare " + shell_quote(dir / "actual") + " " + shell_quote(dir / "ref");

  const CommandResult table = run_recoil(args);
  EXPECT_EQ(table.exit_code, 2) << table.err;
  EXPECT_NE(table.out.find("pass       0.0000%"), std::string::npos) << table.out;
  EXPECT_EQ(count(table.out, "ERROR"), 2u) << table.out;
  EXPECT_NE(table.out.find("image size mismatch: actual is 20x16, reference is 16x16"), std::string::npos) << table.out;
  EXPECT_NE(table.err.find("recoil: error: 2 frames could not be compared or taken"), std::string::npos) << table.err;
  const CommandResult json = run_recoil(args + " --json");
  EXPECT_EQ(json.exit_code, 2);
  const nlohmann::json j = nlohmann::json::parse(json.out);
  ASSERT_EQ(j["pairs"].size(), 3u);
  EXPECT_FALSE(j["pass"].get<bool>());
  EXPECT_TRUE(j["pairs"][0].contains("error")) << j;  // worst first
  EXPECT_TRUE(j["pairs"][0]["ssim"].is_null()) << j;
  EXPECT_FALSE(j["pairs"][2].contains("error")) << j;
  EXPECT_EQ(j["pairs"][2]["ssim"], 1.0) << j;
  EXPECT_EQ(run_recoil(args + " --report " + shell_quote(dir / "reports/today/report.html")).exit_code, 2);
  EXPECT_EQ(count(file_bytes(dir / "reports/today/report.html"), "image size mismatch"), 2u)
      << "index line and section, in a folder the report made";

  const CommandResult update = run_recoil(args + " --update");
  EXPECT_EQ(update.exit_code, 2) << "the comparison itself failed; --update does not change the verdict";
  EXPECT_NE(update.err.find("updated 1 reference frame(s), added 1 new one(s)"), std::string::npos) << update.err;
  EXPECT_EQ(file_bytes(dir / "ref" / numbered(2)), file_bytes(dir / "actual" / numbered(2)));
  EXPECT_EQ(render::read_png(dir / "ref" / numbered(3)).width, 16) << "an unreadable frame is never accepted";
  EXPECT_EQ(file_bytes(dir / "ref/new.png"), file_bytes(dir / "actual/new.png"));
  EXPECT_TRUE(fs::exists(dir / "ref/gone.png"));
  EXPECT_NE(update.err.find("kept 1 with no actual frame (missing)"), std::string::npos) << update.err;

  // References made from nothing: a REF that is not there yet is created.
  fs::remove(dir / "actual" / numbered(3));
  const CommandResult created = run_recoil("compare " + shell_quote(dir / "actual") + " " +
                                           shell_quote(dir / "fresh/golden") + " --update");
  EXPECT_EQ(created.exit_code, 0) << created.err;
  for (const char* name : {"f1.png", "f2.png", "new.png"})
    EXPECT_EQ(file_bytes(dir / "fresh/golden" / name), file_bytes(dir / "actual" / name)) << name;
  const CommandResult one = run_recoil("compare " + shell_quote(dir / "actual/new.png") + " " +
                                       shell_quote(dir / "single/deeper/one.png") + " --update");
  EXPECT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(file_bytes(dir / "single/deeper/one.png"), file_bytes(dir / "actual/new.png"));
  // An extra frame that is no PNG is never taken as a reference; an
  // unreadable reference is reported, and replaced by a readable frame.
  std::ofstream(dir / "actual/junk.png") << "junk";
  std::ofstream(dir / "fresh/golden/f1.png") << "broken reference";
  const CommandResult junk = run_recoil("compare " + shell_quote(dir / "actual") + " " +
                                        shell_quote(dir / "fresh/golden") + " --update");
  EXPECT_EQ(junk.exit_code, 2) << junk.err;
  EXPECT_NE(junk.err.find("junk.png does not read as a PNG; not added"), std::string::npos) << junk.err;
  EXPECT_NE(junk.out.find("ERROR"), std::string::npos) << junk.out;
  EXPECT_FALSE(fs::exists(dir / "fresh/golden/junk.png"));
  EXPECT_EQ(file_bytes(dir / "fresh/golden/f1.png"), file_bytes(dir / "actual/f1.png"));
  fs::create_directories(dir / "nothing");
  EXPECT_EQ(run_recoil("compare " + shell_quote(dir / "nothing") + " " + shell_quote(dir / "nowhere") + " --update")
                .exit_code,
            2)
      << "no references to make of an empty folder";
  EXPECT_EQ(run_recoil("compare " + shell_quote(dir / "actual") + " " + shell_quote(dir / "nowhere")).exit_code, 2)
      << "without --update a missing REF is a wrong path";
}

TEST(CompareCli, ReportEmbedsThreeImagesPerPairWorstFirst) {
  const fs::path dir = scratch_dir("compare_report");
  fs::create_directories(dir / "actual");
  fs::create_directories(dir / "ref");
  render::write_png(dir / "ref/aaa_good.png", frame(16, 16, 1));
  render::write_png(dir / "actual/aaa_good.png", frame(16, 16, 1));
  render::write_png(dir / "ref/zzz_bad.png", frame(16, 16, 2));
  render::write_png(dir / "actual/zzz_bad.png", changed(frame(16, 16, 2), 5, 70));
  const CommandResult r = run_recoil("compare " + shell_quote(dir / "actual") + " " + shell_quote(dir / "ref") + " --report " +
                                     shell_quote(dir / "report.html") + " -q");
  EXPECT_EQ(r.exit_code, 1);
  const std::string html = file_bytes(dir / "report.html");
  EXPECT_EQ(count(html, "src=\"data:image/png;base64,"), 6u);
  EXPECT_NE(html.find("<!DOCTYPE html>"), std::string::npos);
  EXPECT_LT(html.find("zzz_bad.png"), html.find("aaa_good.png")) << "failing pair first";
  // The failing pair embeds the original files; the passing one thumbnails.
  const std::string bad_reference = file_bytes(dir / "ref/zzz_bad.png");
  EXPECT_NE(html.find(cli::base64_encode(std::vector<std::uint8_t>(bad_reference.begin(), bad_reference.end()))),
            std::string::npos);
  EXPECT_EQ(count(html, "<figcaption>reference (thumbnail)"), 1u);
  EXPECT_EQ(count(html, "<figcaption>actual (thumbnail)"), 1u);
  EXPECT_EQ(count(html, "<figcaption>difference (thumbnail"), 1u);
  EXPECT_EQ(count(html, "<figcaption>reference: "), 1u);
  EXPECT_EQ(html.find("src=\"file:"), std::string::npos);
  EXPECT_EQ(html.find("src=\"/"), std::string::npos) << "self-contained: no links to files";
}

TEST(CompareCli, LogJsonReportsProgressPerPair) {
  const fs::path dir = scratch_dir("compare_progress");
  fs::create_directories(dir / "actual");
  fs::create_directories(dir / "ref");
  for (int i = 1; i <= 3; ++i) {
    render::write_png(dir / "ref" / numbered(i), frame(12, 12, i));
    render::write_png(dir / "actual" / numbered(i), frame(12, 12, i));
  }
  const CommandResult r = run_recoil("--log-json compare " + shell_quote(dir / "actual") + " " + shell_quote(dir / "ref"));
  EXPECT_EQ(r.exit_code, 0);
  std::istringstream lines(r.err);
  std::string line;
  size_t expected_done = 0;
  while (std::getline(lines, line)) {
    const nlohmann::json event = nlohmann::json::parse(line);
    EXPECT_EQ(event["command"], "compare");
    EXPECT_EQ(event["done"].get<size_t>(), ++expected_done);
    EXPECT_EQ(event["total"].get<size_t>(), 3u);
  }
  EXPECT_EQ(expected_done, 3u);
  // Without --log-json and with stderr not a terminal: no progress at all.
  EXPECT_EQ(run_recoil("compare " + shell_quote(dir / "actual") + " " + shell_quote(dir / "ref")).err, "");
}

TEST(CompareCli, HelpTeaches) {
  const CommandResult r = run_recoil("compare --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* word : {"--threshold", "--max-failing", "--diff", "--report", "--json", "--update", "Examples"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

}  // namespace
}  // namespace recoil::test
