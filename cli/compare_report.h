#pragma once
// The self-contained HTML page of `recoil compare --report` (SPEC.md section
// 6): one file a reviewer can open or attach to a CI run, with every image
// embedded as a base64 data URI so nothing else needs to travel with it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/compare_pairs.h"

namespace recoil::cli {

struct ReportSettings {
  double threshold = 0.0;
  double max_failing = 0.0;
  bool directory_mode = false;
  std::filesystem::path actual_root;     // the ACTUAL and REF arguments, shown in the title
  std::filesystem::path reference_root;
};

// Standard base64 (RFC 4648, with padding).
std::string base64_encode(const std::vector<std::uint8_t>& bytes);

// Writes the page atomically (temporary file, then rename). `results` must be
// sorted worst first and carry diff_png; reference and actual images are the
// original PNG files' bytes. Throws recoil::Error(output_failed) naming the
// path when it cannot be written, bad_input when an input file vanished.
void write_html_report(const std::filesystem::path& path, const std::vector<PairResult>& results,
                       const PairPlan& plan, const ReportSettings& settings);

}  // namespace recoil::cli
