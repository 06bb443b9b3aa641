#pragma once
// The self-contained HTML page of `recoil compare --report`: one file a reviewer can open or attach to a CI run, with every image
// embedded as a base64 data URI so nothing else needs to travel with it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/compare_pairs.h"
#include "render/image.h"

namespace recoil::cli {

struct ReportSettings {
  double threshold = 0.0;
  double max_failing = 0.0;
  bool directory_mode = false;
  std::filesystem::path actual_root;     // the ACTUAL and REF arguments, shown in the title
  std::filesystem::path reference_root;
};

// A page of 300 full-size frame triples would run to gigabytes, which no
// browser opens. So the worst failing pairs (up to this many) are embedded at
// full resolution, the original PNG bytes; every other pair as thumbnails at
// most this wide. Every pair keeps its three images.
inline constexpr size_t report_full_size_pairs = 50;
inline constexpr int report_thumbnail_width = 320;

// Fills result.thumbnails (and result.diff_png when the pair fails) from the
// decoded images; called once per pair while its images are in memory.
void prepare_report_images(PairResult& result, const render::Image& actual, const render::Image& reference,
                           const render::Image& heat);

// Box-filter downscale by the smallest integer factor that brings the width
// to at most `max_width` (no change when it already fits).
render::Image downscale_to_width(const render::Image& image, int max_width);

// Standard base64 (RFC 4648, with padding).
std::string base64_encode(const std::vector<std::uint8_t>& bytes);

// Writes the page atomically (temporary file, then rename). `results` must be
// sorted worst first and prepared by prepare_report_images. Throws recoil::Error(output_failed) naming the
// path when it cannot be written, bad_input when an input file vanished.
void write_html_report(const std::filesystem::path& path, const std::vector<PairResult>& results,
                       const PairPlan& plan, const ReportSettings& settings);

}  // namespace recoil::cli
