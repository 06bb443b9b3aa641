#include "cli/compare_pairs.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <map>
#include <mutex>
#include <system_error>
#include <thread>
#include <tuple>

#include "cli/compare_report.h"
#include "core/error.h"
#include "render/diff_heatmap.h"
#include "render/png.h"

namespace recoil::cli {
namespace fs = std::filesystem;
namespace {

enum class PathKind { missing, file, directory, other };

PathKind kind_of(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) return PathKind::missing;
  if (fs::is_directory(status)) return PathKind::directory;
  if (fs::is_regular_file(status)) return PathKind::file;
  return PathKind::other;
}

// *.png regular files directly inside `dir` (not recursive), by file name.
std::map<std::string, fs::path> png_files(const fs::path& dir) {
  std::map<std::string, fs::path> files;
  std::error_code ec;
  fs::directory_iterator it(dir, ec);
  if (ec) throw bad_input("cannot list directory " + dir.string() + ": " + ec.message());
  for (const fs::directory_entry& entry : it) {
    const fs::path& p = entry.path();
    if (p.extension() != ".png" || !entry.is_regular_file()) continue;
    files.emplace(p.filename().string(), p);
  }
  return files;
}

}  // namespace

bool readable_png(const fs::path& path) {
  try {
    render::read_png(path);
    return true;
  } catch (const Error&) {
    return false;
  }
}

PairPlan plan_pairs(const fs::path& actual, const fs::path& reference, bool creating_references) {
  const PathKind actual_kind = kind_of(actual);
  PathKind reference_kind = kind_of(reference);
  // References to be created take the form of what they are made from.
  if (creating_references && reference_kind == PathKind::missing) reference_kind = actual_kind;
  for (const auto& [path, kind, role] : {std::tuple{actual, actual_kind, "ACTUAL"},
                                         std::tuple{reference, reference_kind, "REF"}}) {
    if (kind == PathKind::missing) throw bad_input(std::string(role) + " " + path.string() + " does not exist");
    if (kind == PathKind::other)
      throw bad_input(std::string(role) + " " + path.string() + " is neither a file nor a directory");
  }
  if (actual_kind != reference_kind)
    throw bad_input("cannot compare a " + std::string(actual_kind == PathKind::file ? "file" : "directory") + " (" +
                    actual.string() + ") with a " + (reference_kind == PathKind::file ? "file" : "directory") +
                    " (" + reference.string() + "): give two PNG files or two directories");

  PairPlan plan;
  plan.reference_root = reference;
  std::error_code ec;
  const bool reference_exists = fs::exists(reference, ec);
  if (actual_kind == PathKind::file) {
    if (reference_exists) {
      plan.actual.push_back(actual);
      plan.reference.push_back(reference);
    } else {
      plan.extra.push_back(actual);
    }
    return plan;
  }
  plan.directory_mode = true;
  const std::map<std::string, fs::path> actual_files = png_files(actual);
  const std::map<std::string, fs::path> reference_files =
      reference_exists ? png_files(reference) : std::map<std::string, fs::path>{};
  if (reference_files.empty() && !creating_references)
    throw bad_input("reference directory " + reference.string() + " holds no *.png files (--update creates them)");
  if (reference_files.empty() && actual_files.empty())
    throw bad_input("ACTUAL " + actual.string() + " holds no *.png files: no references to make of it");
  for (const auto& [name, path] : reference_files) {
    const auto match = actual_files.find(name);
    if (match == actual_files.end()) {
      plan.missing.push_back(path);
    } else {
      plan.actual.push_back(match->second);
      plan.reference.push_back(path);
    }
  }
  for (const auto& [name, path] : actual_files)
    if (!reference_files.count(name)) plan.extra.push_back(path);
  return plan;
}

std::vector<PairResult> compare_pairs(const PairPlan& plan, const CompareSettings& settings) {
  const size_t n = plan.actual.size();
  std::vector<PairResult> results(n);
  std::vector<std::exception_ptr> errors(n);
  std::atomic<size_t> next{0};
  std::mutex progress_mutex;
  size_t done = 0;
  auto worker = [&] {
    for (size_t i = next++; i < n; i = next++) {
      try {
        PairResult& r = results[i];
        r.actual = plan.actual[i];
        r.reference = plan.reference[i];
        const render::LoadedComparison loaded =
            render::compare_image_files(r.actual, r.reference, settings.threshold);
        r.metrics = loaded.metrics;
        r.pass = r.metrics.failing_fraction <= settings.max_failing;
        if (!settings.diff_dir.empty() || settings.report_images) {
          const render::Image heat =
              render::difference_heatmap(loaded.actual, loaded.reference, settings.threshold);
          if (!settings.diff_dir.empty()) render::write_png(settings.diff_dir / r.actual.filename(), heat);
          if (settings.report_images) prepare_report_images(r, loaded.actual, loaded.reference, heat);
        }
      } catch (const Error& e) {
        if (e.kind() != ErrorKind::bad_input) {
          errors[i] = std::current_exception();
        } else {
          PairResult& r = results[i];
          r.error = e.what();
          r.pass = false;
          r.metrics = render::ImageComparison{};
        }
      } catch (...) {
        errors[i] = std::current_exception();
      }
      if (settings.on_progress) {
        const std::lock_guard<std::mutex> lock(progress_mutex);
        settings.on_progress(++done, n);
      }
    }
  };
  const size_t wanted = settings.threads > 0 ? static_cast<size_t>(settings.threads)
                                             : std::max(1u, std::thread::hardware_concurrency());
  const size_t threads = std::min({wanted, n, size_t(16)});
  std::vector<std::thread> pool;
  for (size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  return results;
}

void sort_worst_first(std::vector<PairResult>& results) {
  std::stable_sort(results.begin(), results.end(), [](const PairResult& a, const PairResult& b) {
    const render::ImageComparison& ma = a.metrics;
    const render::ImageComparison& mb = b.metrics;
    return std::tuple(a.pass, a.error.empty(), -ma.failing_fraction, -ma.max_difference, ma.ssim, a.actual.string()) <
           std::tuple(b.pass, b.error.empty(), -mb.failing_fraction, -mb.max_difference, mb.ssim, b.actual.string());
  });
}

std::string pair_label(const PairResult& result, bool directory_mode) {
  return directory_mode ? result.actual.filename().string() : result.actual.string();
}

}  // namespace recoil::cli
