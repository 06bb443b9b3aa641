#pragma once
// `recoil compare` building blocks: which files to pair, and the outcome of
// one pair. Kept apart from the command so the report writer shares them.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "render/image_metrics.h"

namespace recoil::cli {

// What to compare: two files (one pair), or two directories whose *.png files
// pair by file name. Sorted by name so every run lists them in the same order.
struct PairPlan {
  bool directory_mode = false;
  std::filesystem::path reference_root;          // REF as given: where --update puts extra frames
  std::vector<std::filesystem::path> actual;     // pairs[i] = (actual[i], reference[i])
  std::vector<std::filesystem::path> reference;
  std::vector<std::filesystem::path> missing;    // in REF but not in ACTUAL (reference paths)
  std::vector<std::filesystem::path> extra;      // in ACTUAL but not in REF (actual paths)
};

// Throws recoil::Error(bad_input) naming the path when one does not exist,
// when a file is mixed with a directory, or when REF holds no *.png file.
// `creating_references` (--update) lets REF be missing or hold no *.png:
// every actual frame is then extra, for the update to copy into REF.
PairPlan plan_pairs(const std::filesystem::path& actual, const std::filesystem::path& reference,
                    bool creating_references = false);

struct PairResult {
  std::filesystem::path actual;
  std::filesystem::path reference;
  render::ImageComparison metrics;
  bool pass = true;
  // Why the pair could not be compared (sizes differ, a PNG cannot be read):
  // the pair fails, with no metrics, and the command exits 2 once every
  // pair is reported.
  std::string error;
  // Only when a report is written (see compare_report.h): the full-size heat
  // map as PNG for failing pairs, and small PNGs of reference, actual and heat map.
  std::vector<std::uint8_t> diff_png;
  std::vector<std::vector<std::uint8_t>> thumbnails;
};

struct CompareSettings {
  double threshold = render::default_compare_threshold;  // per-pixel difference that fails a pixel
  double max_failing = 0.001;                            // fraction of failing pixels that fails a pair
  std::filesystem::path diff_dir;                        // heat maps go here when not empty
  bool report_images = false;                            // fill diff_png / thumbnails for the HTML page
  int threads = 0;                                       // 0: one per core (at most 16)
  // Called after each pair with (pairs done, total), one call at a time and
  // with `done` rising by one per call; for progress display only.
  std::function<void(size_t, size_t)> on_progress;
};

// Decodes and compares every planned pair, several at once, in plan order.
// Each result lands at its own index, so nothing depends on scheduling. A
// pair that cannot be compared (bad input) records why in its `error`; any
// other failure (a heat map that cannot be written) is rethrown, the first
// by pair index.
std::vector<PairResult> compare_pairs(const PairPlan& plan, const CompareSettings& settings);

// Whether the file at `path` decodes as a PNG.
bool readable_png(const std::filesystem::path& path);

// Worst first: failing pairs before passing ones, those that could not be
// compared first among them, then larger failing fraction, then larger max
// difference, then lower SSIM, then by path (so ties keep a fixed order).
void sort_worst_first(std::vector<PairResult>& results);

// The label of a pair in tables and reports: the file name in directory mode,
// the actual path for a single pair.
std::string pair_label(const PairResult& result, bool directory_mode);

}  // namespace recoil::cli
