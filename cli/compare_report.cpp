#include "cli/compare_report.h"

#include <algorithm>
#include <cstdio>
#include <ostream>

#include "cli/file_io.h"
#include "cli/format_number.h"
#include "core/check.h"
#include "render/png.h"

namespace recoil::cli {
namespace fs = std::filesystem;
namespace {

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

const char* style_sheet = R"(
body { font-family: system-ui, sans-serif; margin: 1.5em; background: #1e1e1e; color: #ddd; }
h1 { font-size: 1.4em; margin-bottom: 0.2em; }
.summary { margin: 0.5em 0 1.5em; }
.verdict { font-weight: bold; padding: 0.1em 0.5em; border-radius: 4px; }
.pass .verdict, .verdict.pass { background: #2e7d32; color: #fff; }
.fail .verdict, .verdict.fail { background: #c62828; color: #fff; }
section.pair { border-top: 1px solid #444; padding: 0.8em 0 1.2em; }
section.pair h2 { font-size: 1.1em; margin: 0 0 0.3em; }
.metrics { font-family: ui-monospace, monospace; font-size: 0.9em; color: #bbb; margin-bottom: 0.6em; }
.images { display: grid; grid-template-columns: repeat(3, 1fr); gap: 0.8em; }
figure { margin: 0; }
figcaption { font-size: 0.85em; color: #aaa; margin-bottom: 0.2em; }
figure img { width: 100%; height: auto; image-rendering: pixelated; background: #000; border: 1px solid #333; }
ul.files { font-family: ui-monospace, monospace; font-size: 0.9em; }
table.index { border-collapse: collapse; font-family: ui-monospace, monospace; font-size: 0.85em; margin-bottom: 1em; }
table.index td, table.index th { padding: 0.1em 0.8em; text-align: right; }
table.index td:last-child, table.index th:last-child { text-align: left; }
a { color: #8ab4f8; }
.legend { display: flex; align-items: center; gap: 0.6em; font-size: 0.85em; color: #aaa; margin-bottom: 1em; }
.ramp { width: 16em; height: 0.9em; border: 1px solid #444;
        background: linear-gradient(to right, #000 0%, #800000 35%, #ff0000 35%, #ffff00 67%, #fff 100%); }
)";

void write_figure(std::ostream& out, const std::string& caption, const std::vector<std::uint8_t>& png) {
  out << "<figure><figcaption>" << html_escape(caption) << "</figcaption><img alt=\"" << html_escape(caption)
      << "\" src=\"data:image/png;base64," << base64_encode(png) << "\"></figure>\n";
}

void write_file_list(std::ostream& out, const std::string& title, const std::vector<fs::path>& files) {
  if (files.empty()) return;
  out << "<h2>" << html_escape(title) << " (" << files.size() << ")</h2>\n<ul class=\"files\">\n";
  for (const fs::path& f : files) out << "<li>" << html_escape(f.string()) << "</li>\n";
  out << "</ul>\n";
}

// One line per pair, worst first, each linking to its images below.
void write_index(std::ostream& out, const std::vector<PairResult>& results, bool directory_mode) {
  out << "<table class=\"index\">\n<tr><th>status</th><th>failing %</th><th>max diff</th><th>PSNR dB</th>"
         "<th>SSIM</th><th>frame</th></tr>\n";
  for (size_t index = 0; index < results.size(); ++index) {
    const PairResult& r = results[index];
    const render::ImageComparison& m = r.metrics;
    if (!r.error.empty()) {
      out << "<tr class=\"fail\"><td><span class=\"verdict\">ERROR</span></td><td colspan=\"4\">"
          << html_escape(r.error) << "</td><td><a href=\"#pair-" << index << "\">"
          << html_escape(pair_label(r, directory_mode)) << "</a></td></tr>\n";
      continue;
    }
    out << "<tr class=\"" << (r.pass ? "pass" : "fail") << "\"><td><span class=\"verdict\">"
        << (r.pass ? "pass" : "FAIL") << "</span></td><td>" << format_number("%.4f", m.failing_fraction * 100.0)
        << "</td><td>" << format_number("%.4f", m.max_difference) << "</td><td>"
        << (m.psnr ? format_number("%.2f", *m.psnr) : std::string("&infin;")) << "</td><td>" << format_number("%.5f", m.ssim)
        << "</td><td><a href=\"#pair-" << index << "\">" << html_escape(pair_label(r, directory_mode))
        << "</a></td></tr>\n";
  }
  out << "</table>\n";
}

}  // namespace

render::Image downscale_to_width(const render::Image& image, int max_width) {
  const int factor = (image.width + max_width - 1) / max_width;
  if (factor <= 1) return image;
  render::Image small((image.width + factor - 1) / factor, (image.height + factor - 1) / factor);
  for (int y = 0; y < small.height; ++y)
    for (int x = 0; x < small.width; ++x) {
      int sum[4] = {0, 0, 0, 0};
      int count = 0;
      for (int sy = y * factor; sy < std::min(image.height, (y + 1) * factor); ++sy)
        for (int sx = x * factor; sx < std::min(image.width, (x + 1) * factor); ++sx) {
          const std::uint8_t* p = image.pixel(sx, sy);
          for (int c = 0; c < 4; ++c) sum[c] += p[c];
          ++count;
        }
      std::uint8_t* q = small.pixel(x, y);
      for (int c = 0; c < 4; ++c) q[c] = static_cast<std::uint8_t>((sum[c] + count / 2) / count);
    }
  return small;
}

void prepare_report_images(PairResult& result, const render::Image& actual, const render::Image& reference,
                           const render::Image& heat) {
  result.thumbnails.clear();
  for (const render::Image* image : {&reference, &actual, &heat})
    result.thumbnails.push_back(render::encode_png(downscale_to_width(*image, report_thumbnail_width)));
  if (!result.pass) result.diff_png = render::encode_png(heat);
}

std::string base64_encode(const std::vector<std::uint8_t>& bytes) {
  static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const std::uint32_t v = (std::uint32_t(bytes[i]) << 16) | (std::uint32_t(bytes[i + 1]) << 8) | bytes[i + 2];
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += alphabet[(v >> 6) & 63];
    out += alphabet[v & 63];
  }
  const size_t rest = bytes.size() - i;
  if (rest > 0) {
    std::uint32_t v = std::uint32_t(bytes[i]) << 16;
    if (rest == 2) v |= std::uint32_t(bytes[i + 1]) << 8;
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += rest == 2 ? alphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

void write_html_report(const fs::path& path, const std::vector<PairResult>& results, const PairPlan& plan,
                       const ReportSettings& settings) {
  size_t failing = 0;
  for (const PairResult& r : results) failing += r.pass ? 0 : 1;
  const bool pass = failing == 0 && plan.missing.empty();

  AtomicFile file(path);
  std::ostream& out = file.stream();
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<title>recoil compare: " << (pass ? "pass" : "FAIL") << "</title>\n<style>" << style_sheet
      << "</style>\n</head>\n<body>\n";
  out << "<h1>recoil compare <span class=\"verdict " << (pass ? "pass\">PASS" : "fail\">FAIL") << "</span></h1>\n";
  out << "<div class=\"summary\">actual: <code>" << html_escape(settings.actual_root.string())
      << "</code><br>reference: <code>" << html_escape(settings.reference_root.string()) << "</code><br>"
      << results.size() << " pair(s), " << failing << " beyond tolerance, " << plan.missing.size() << " missing, "
      << plan.extra.size() << " extra &mdash; a pixel fails when its largest channel difference exceeds "
      << format_number("%g", settings.threshold) << "; a pair fails when more than "
      << format_number("%g", settings.max_failing * 100.0) << "% of its pixels fail. Worst first; the "
      << report_full_size_pairs << " worst failing pairs at full size, the others as thumbnails.</div>\n";
  out << "<div class=\"legend\">heat map: <span>identical</span><span class=\"ramp\"></span><span>difference 1"
      << "</span>&mdash; dim scene with a red tint up to the threshold, then bright red, yellow, white when "
         "failing</div>\n";
  write_file_list(out, "Missing from actual", plan.missing);
  write_file_list(out, "Extra in actual", plan.extra);
  write_index(out, results, settings.directory_mode);

  size_t shown_full = 0;
  for (size_t index = 0; index < results.size(); ++index) {
    const PairResult& r = results[index];
    const render::ImageComparison& m = r.metrics;
    if (!r.error.empty()) {
      out << "<section class=\"pair fail\" id=\"pair-" << index << "\">\n<h2><span class=\"verdict\">ERROR</span> "
          << html_escape(pair_label(r, settings.directory_mode)) << "</h2>\n<div class=\"metrics\">"
          << html_escape(r.error) << "</div>\n</section>\n";
      continue;
    }
    out << "<section class=\"pair " << (r.pass ? "pass" : "fail") << "\" id=\"pair-" << index
        << "\">\n<h2><span class=\"verdict\">"
        << (r.pass ? "pass" : "FAIL") << "</span> " << html_escape(pair_label(r, settings.directory_mode))
        << "</h2>\n<div class=\"metrics\">" << m.width << "x" << m.height << " &middot; failing "
        << format_number("%.4f", m.failing_fraction * 100.0) << "% (" << m.failing_pixels << " px) &middot; max difference "
        << format_number("%.4f", m.max_difference) << " &middot; PSNR "
        << (m.psnr ? format_number("%.2f", *m.psnr) + " dB" : std::string("&infin; (identical)")) << " &middot; SSIM "
        << format_number("%.5f", m.ssim) << "</div>\n<div class=\"images\">\n";
    const bool full_size = !r.pass && shown_full < report_full_size_pairs;
    RECOIL_CHECK(r.thumbnails.size() == 3 && (!full_size || !r.diff_png.empty()), "report images not prepared");
    if (full_size) {
      ++shown_full;
      write_figure(out, "reference: " + r.reference.string(), read_file_bytes(r.reference));
      write_figure(out, "actual: " + r.actual.string(), read_file_bytes(r.actual));
      write_figure(out, "difference (red to white: failing)", r.diff_png);
    } else {
      write_figure(out, "reference (thumbnail): " + r.reference.string(), r.thumbnails[0]);
      write_figure(out, "actual (thumbnail): " + r.actual.string(), r.thumbnails[1]);
      write_figure(out, "difference (thumbnail; red to white: failing)", r.thumbnails[2]);
    }
    out << "</div>\n</section>\n";
  }
  out << "</body>\n</html>\n";
  file.commit();
}

}  // namespace recoil::cli
