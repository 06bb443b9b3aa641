// `recoil compare ACTUAL REF`: visual regression of frames against references
//. Exit 0 within tolerance, 1 beyond it, 2 bad input.

#include <algorithm>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <system_error>

#include "cli/commands.h"
#include "cli/file_io.h"
#include "cli/format_number.h"
#include "cli/number_range.h"
#include "cli/output_dir.h"
#include "cli/compare_pairs.h"
#include "cli/compare_report.h"
#include "cli/progress.h"
#include "core/error.h"

namespace recoil::cli {
namespace fs = std::filesystem;
namespace {

struct CompareOptions {
  std::string actual;
  std::string reference;
  double threshold = render::default_compare_threshold;
  double max_failing = 0.001;
  std::string diff_dir;
  std::string report;
  bool json = false;
  bool update = false;
};

void print_table(const std::vector<PairResult>& results, const PairPlan& plan, const CompareOptions& options,
                 bool pass) {
  std::printf("%-7s %10s %9s %8s %8s  %s\n", "status", "failing", "max diff", "PSNR dB", "SSIM", "frame");
  for (const PairResult& r : results) {
    const render::ImageComparison& m = r.metrics;
    if (!r.error.empty()) {
      std::printf("%-7s %48s  %s (%s)\n", "ERROR", "", pair_label(r, plan.directory_mode).c_str(), r.error.c_str());
      continue;
    }
    std::printf("%-7s %9.4f%% %9.4f %8s %8.5f  %s\n", r.pass ? "pass" : "FAIL", m.failing_fraction * 100.0,
                m.max_difference, m.psnr ? format_number("%.2f", *m.psnr).c_str() : "inf", m.ssim,
                pair_label(r, plan.directory_mode).c_str());
  }
  for (const fs::path& p : plan.missing) std::printf("%-7s %48s  %s\n", "MISSING", "", p.filename().c_str());
  for (const fs::path& p : plan.extra) std::printf("%-7s %48s  %s\n", "extra", "", p.filename().c_str());
  const size_t failing = static_cast<size_t>(std::count_if(results.begin(), results.end(),
                                                           [](const PairResult& r) { return !r.pass; }));
  const size_t errors = static_cast<size_t>(std::count_if(results.begin(), results.end(),
                                                          [](const PairResult& r) { return !r.error.empty(); }));
  std::printf("%s: %zu of %zu pair(s) beyond tolerance%s, %zu missing, %zu extra (threshold %g, max failing %g)\n",
              pass ? "PASS" : "FAIL", failing - errors, results.size(),
              errors > 0 ? (", " + std::to_string(errors) + " could not be compared").c_str() : "",
              plan.missing.size(), plan.extra.size(), options.threshold, options.max_failing);
}

nlohmann::ordered_json to_json(const std::vector<PairResult>& results, const PairPlan& plan, bool pass,
                               const CompareOptions& options) {
  nlohmann::ordered_json pairs = nlohmann::ordered_json::array();
  for (const PairResult& r : results) {
    const render::ImageComparison& m = r.metrics;
    nlohmann::ordered_json pair = {
        {"actual", r.actual.string()}, {"reference", r.reference.string()}, {"pass", r.pass}};
    if (!r.error.empty()) {
      pair["error"] = r.error;
      for (const char* metric : {"failing_fraction", "max_difference", "psnr", "ssim"}) pair[metric] = nullptr;
    } else {
      pair["failing_fraction"] = m.failing_fraction;
      pair["max_difference"] = m.max_difference;
      pair["psnr"] = m.psnr ? nlohmann::ordered_json(*m.psnr) : nlohmann::ordered_json(nullptr);
      pair["ssim"] = m.ssim;
    }
    pairs.push_back(pair);
  }
  auto paths = [](const std::vector<fs::path>& list) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const fs::path& p : list) out.push_back(p.string());
    return out;
  };
  return {{"pass", pass},
          {"pairs", pairs},
          {"missing", paths(plan.missing)},
          {"extra", paths(plan.extra)},
          {"threshold", options.threshold},
          {"max_failing", options.max_failing}};
}

// Creates the folder an option writes into, its errors naming the option.
void ensure_option_folder(const fs::path& folder, const std::string& option) {
  try {
    ensure_output_dir(folder);
  } catch (const Error& e) {
    throw Error(e.kind(), option + ": " + std::string(e.what()));
  }
}

// --diff must not be a folder of the inputs: heat maps are named like the
// frames and would overwrite them.
void check_diff_dir(const CompareOptions& options, const PairPlan& plan) {
  if (options.diff_dir.empty()) return;
  ensure_option_folder(options.diff_dir, "--diff");
  std::error_code ec;
  for (const auto* list : {&plan.actual, &plan.reference})
    for (const fs::path& p : *list) {
      const fs::path parent = p.parent_path().empty() ? fs::path(".") : p.parent_path();
      if (fs::equivalent(parent, options.diff_dir, ec))
        throw bad_input("--diff " + options.diff_dir + " holds the input " + p.string() +
                        "; heat maps would overwrite it: choose another directory");
    }
}

// --update: the actual frame replaces the reference of every failing pair
// (one of another size too), and extra frames are added to REF (created if
// need be), each only when it reads as a PNG (a compared pair's did); a
// reference with no actual frame (missing) is kept. Returns why an extra
// frame was not added.
std::vector<std::string> update_references(const std::vector<PairResult>& results, const PairPlan& plan,
                                           const GlobalOptions& global) {
  size_t updated = 0, added = 0;
  for (const PairResult& r : results)
    if (!r.pass && (r.error.empty() || readable_png(r.actual))) {
      copy_file_atomically(r.actual, r.reference);
      ++updated;
    }
  std::vector<std::string> refused;
  for (const fs::path& frame : plan.extra) {
    if (!readable_png(frame)) {
      refused.push_back("--update: " + frame.string() + " does not read as a PNG; not added to the references");
      continue;
    }
    const fs::path reference = plan.directory_mode ? plan.reference_root / frame.filename() : plan.reference_root;
    if (reference.has_parent_path()) ensure_output_dir(reference.parent_path());
    copy_file_atomically(frame, reference);
    ++added;
  }
  if (!global.quiet) {
    std::cerr << "recoil: updated " << updated << " reference frame(s), added " << added << " new one(s)";
    if (!plan.missing.empty())
      std::cerr << "; kept " << plan.missing.size()
                << " with no actual frame (missing), which fail every comparison until removed from REF";
    std::cerr << "\n";
  }
  return refused;
}

int run_compare(const CompareOptions& options, const GlobalOptions& global) {
  const PairPlan plan = plan_pairs(options.actual, options.reference, options.update);
  check_diff_dir(options, plan);
  // The report's folder is made before the comparison, as --diff's is: a path
  // that cannot be written fails at once, not after every pair is compared.
  if (const fs::path folder = fs::path(options.report).parent_path(); !options.report.empty() && !folder.empty())
    ensure_option_folder(folder, "--report");
  CompareSettings settings;
  settings.threshold = options.threshold;
  settings.max_failing = options.max_failing;
  settings.diff_dir = options.diff_dir;
  settings.report_images = !options.report.empty();
  Progress progress(global, "compare", static_cast<int>(plan.actual.size()));
  settings.on_progress = [&progress](size_t done, size_t) { progress.update(static_cast<int>(done)); };
  std::vector<PairResult> results = compare_pairs(plan, settings);
  sort_worst_first(results);
  const bool pass = plan.missing.empty() &&
                    std::all_of(results.begin(), results.end(), [](const PairResult& r) { return r.pass; });

  if (options.json) {
    // Paths are bytes; a name that is not UTF-8 is shown with U+FFFD rather than aborting.
    std::cout << to_json(results, plan, pass, options)
                     .dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace)
              << std::endl;
  } else if (!global.quiet) {
    print_table(results, plan, options, pass);
    std::fflush(stdout);
  }
  if (!options.report.empty()) {
    const ReportSettings report{options.threshold, options.max_failing, plan.directory_mode, options.actual,
                                options.reference};
    write_html_report(options.report, results, plan, report);
    if (!global.quiet) std::cerr << "recoil: wrote report " << options.report << "\n";
  }
  // A pair that could not be compared, or a frame --update could not take,
  // is an error (exit 2), raised once every pair is reported.
  std::vector<std::string> errors;
  for (const PairResult& r : results)
    if (!r.error.empty()) errors.push_back(r.error);
  if (options.update)
    for (std::string& refused : update_references(results, plan, global)) errors.push_back(std::move(refused));
  if (errors.size() == 1) throw bad_input(errors.front());
  if (errors.size() > 1) {
    std::string message = std::to_string(errors.size()) + " frames could not be compared or taken: ";
    for (size_t i = 0; i < std::min<size_t>(errors.size(), 3); ++i) message += (i > 0 ? "; " : "") + errors[i];
    throw bad_input(message + (errors.size() > 3 ? "; and " + std::to_string(errors.size() - 3) + " more" : ""));
  }
  return pass ? 0 : 1;
}

}  // namespace

void add_compare_command(CLI::App& app, const GlobalOptions& global, Action& action) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Visual regression: compare frames with reference frames; exit 1 when they differ beyond tolerance");
  cmd->fallthrough();  // -q and --log-json after the subcommand reach the main app
  cmd->add_option("ACTUAL", options->actual, "Rendered frame, or directory of frames")->required()->type_name("PATH");
  cmd->add_option("REF", options->reference, "Reference frame, or directory of reference frames")
      ->required()
      ->type_name("PATH");
  cmd->add_option("--threshold", options->threshold, "Per-pixel difference in [0,1] above which a pixel fails")
      ->type_name("T")
      ->check(NumberIn(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--max-failing", options->max_failing, "Largest fraction of failing pixels a pair may have")
      ->type_name("F")
      ->check(NumberIn(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--diff", options->diff_dir,
                  "Write a heat-map PNG per pair into DIR, named like the frame (red to white: failing)")
      ->type_name("DIR");
  cmd->add_option("--report", options->report,
                  "Write one self-contained HTML page: reference, actual and heat map side by side, worst first")
      ->type_name("FILE.html");
  cmd->add_flag("--json", options->json, "Print the metrics as JSON on stdout instead of a table");
  cmd->add_flag("--update", options->update,
                "After reporting, copy actual over reference for the failing pairs only, and add extra frames "
                "(accept new renders; creates REF)");
  cmd->footer(
      "Visual regression: compare an actual frame with a reference frame, or two directories\n"
      "of frames paired by file name (*.png). Images are composited over black; a pixel fails\n"
      "when its largest channel difference exceeds --threshold, and a pair fails when more\n"
      "than --max-failing of its pixels fail. Reports failing fraction, max difference, PSNR\n"
      "and SSIM (as scikit-image's, Gaussian window), worst first.\n"
      "Exit 0 within tolerance, 1 beyond it or frames missing, 2 on bad input (a file compared\n"
      "with a directory; a pair of different sizes or an unreadable PNG, reported with the rest).\n\n"
      "Examples:\n"
      "  recoil compare out/frame_0001.png golden/frame_0001.png\n"
      "  recoil compare out/ golden/ --diff diffs/ --report report.html\n"
      "  recoil compare out/ golden/ --threshold 0.05 --max-failing 0.01 --json > metrics.json\n"
      "  recoil compare out/ golden/ --update      # accept the new look of the frames that changed\n"
      "Missing frames (in REF, not in ACTUAL) fail the comparison; extra frames are listed only.\n"
      "--update replaces the reference of each failing pair (one of another size too), adds the\n"
      "extra frames to REF, creating REF when it is not there yet, and keeps missing ones.");
  cmd->callback([options, &global, &action] {
    action = [options, &global] { return run_compare(*options, global); };
  });
}

}  // namespace recoil::cli
