// `recoil batch MANIFEST|DIR`: many runs, turntables and drops, restartable,
// shardable across a farm, gathered into a contact sheet.
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/batch_manifest.h"
#include "cli/batch_record.h"
#include "cli/batch_runner.h"
#include "cli/batch_shard.h"
#include "cli/commands.h"
#include "cli/json_cursor.h"
#include "cli/number_range.h"
#include "cli/output_dir.h"
#include "cli/utf8_arguments.h"
#include "core/error.h"
#include "render/contact_sheet.h"
#include "render/png.h"

namespace recoil::cli {
namespace fs = std::filesystem;
namespace {

struct BatchOptions {
  std::string source;
  std::string output;
  std::string shard;
  int shard_count = 0;
  int jobs = 1;
  std::vector<std::string> settings;  // --set KEY=VALUE
  std::string contact_sheet;
  bool contact_sheet_only = false;
  bool list = false;
};

// --set KEY=VALUE pairs as an object; a VALUE that is JSON (24, true, "x") is taken as such, else as a string.
nlohmann::json parse_settings(const std::vector<std::string>& settings) {
  nlohmann::json defaults = nlohmann::json::object();
  for (const std::string& s : settings) {
    const size_t eq = s.find('=');
    if (eq == std::string::npos || eq == 0) throw bad_input("--set \"" + s + "\": expected KEY=VALUE, e.g. frames=24");
    const std::string value = s.substr(eq + 1);
    const nlohmann::json parsed = nlohmann::json::parse(value, nullptr, false);
    defaults[s.substr(0, eq)] = parsed.is_discarded() || parsed.is_object() ? nlohmann::json(value) : parsed;
  }
  return defaults;
}

// The last frame an item wrote (a drop's settled pose, a turntable's closing view).
fs::path last_frame(const fs::path& dir) {
  fs::path best;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("frame_", 0) == 0 && e.path().extension() == ".png" && (best.empty() || e.path() > best))
      best = e.path();
  }
  return best;
}

void write_contact_sheet(const fs::path& target, const fs::path& output, const std::vector<ItemRecord>& records) {
  std::vector<render::SheetTile> tiles;
  for (const ItemRecord& r : records) {
    render::SheetTile tile;
    tile.label = r.name;
    if (r.status == "pending") {
      tile.note = "not run";
    } else {
      tile.state = r.succeeded() ? render::SheetTile::State::done : render::SheetTile::State::failed;
      tile.image = last_frame(output / r.name);
      tile.note = r.succeeded() ? "no frames (--no-render)" : "failed, exit " + std::to_string(r.exit_code);
      // The message without the file it names: the label already says which item it is.
      const size_t colon = r.message.find(": ");
      tile.detail = colon != std::string::npos && r.message.find_first_of("/.") < colon ? r.message.substr(colon + 2)
                                                                                        : r.message;
    }
    tiles.push_back(tile);
  }
  if (target.has_parent_path()) ensure_output_dir(target.parent_path());
  render::write_png(target, render::compose_contact_sheet(tiles));
}

int run_batch(const BatchOptions& options, const GlobalOptions& global) {
  const fs::path source = options.source;
  const std::vector<BatchItem> items = load_batch_items(source, parse_settings(options.settings));
  const Shard shard = choose_shard(options.shard, options.shard_count);
  // "meshes/" names its folder as "meshes" does: the trailing slash leaves an empty file name.
  const fs::path named = source.filename().empty() ? source.parent_path() : source;
  const fs::path output = options.output.empty() ? default_output_dir(named.stem().string()) : fs::path(options.output);
  if (options.list) {
    for (const BatchItem& item : items) {
      std::cout << item.index << "\t" << item.name << "\t" << (shard.keeps(item.index) ? "" : "(other shard)\t")
                << "recoil";
      for (const std::string& a : item.args) std::cout << " " << a;
      std::cout << " -o " << (output / item.name).string() << "\n";
    }
    return 0;
  }
  int code = 0;
  std::vector<ItemRecord> mine;
  if (!options.contact_sheet_only) {
    mine = run_batch_items(items, {output, options.jobs, shard}, global);
    code = batch_exit_code(mine);
  } else {
    ensure_output_dir(output);
  }
  const std::vector<ItemRecord> all = write_batch_summary(output, source, items);
  if (!options.contact_sheet.empty()) write_contact_sheet(options.contact_sheet, output, all);
  int ok = 0, failed = 0, reused = 0;
  for (const ItemRecord& r : mine) {
    (r.succeeded() ? ok : failed)++;
    reused += r.reused;
  }
  if (global.log_json) {
    nlohmann::json line = {{"command", "batch"}, {"event", "summary"}, {"summary", (output / "batch.json").string()},
                           {"shard", shard.text()}};
    if (!options.contact_sheet_only) line.update({{"succeeded", ok}, {"failed", failed}, {"reused", reused}});
    if (!options.contact_sheet.empty()) line["contact_sheet"] = options.contact_sheet;
    std::cerr << line.dump() << std::endl;
  } else if (!global.quiet) {
    if (!options.contact_sheet_only)
      std::cerr << "recoil: batch: " << ok << " succeeded"
                << (reused > 0 ? " (" + std::to_string(reused) + " finished by an earlier run)" : "") << ", "
                << failed << " failed"
                << (shard.count > 1 ? " in shard " + shard.text() : "") << "; summary in "
                << (output / "batch.json").string() << "\n";
    if (!options.contact_sheet.empty()) std::cerr << "recoil: wrote contact sheet " << options.contact_sheet << "\n";
  }
  return code;
}

}  // namespace

void add_batch_command(CLI::App& app, const GlobalOptions& global, Action& action) {
  auto options = std::make_shared<BatchOptions>();
  CLI::App* cmd = app.add_subcommand("batch", "Run many scenes or meshes (a manifest, or every mesh in a folder)");
  cmd->add_option("SOURCE", options->source, "Manifest (a JSON list of items) or a folder of mesh files")->required();
  cmd->add_option("-o,--output", options->output, "Output folder: one sub-folder per item (default: output/<source name>/)");
  cmd->add_option("--shard", options->shard, "Run only shard I of N (0-based): the items whose index mod N is I");
  cmd->add_option("--shard-count", options->shard_count, "Shards in all, with the index from JOB_COMPLETION_INDEX")
      ->check(WholeNumberIn(1, 1000000));
  CLI::Option* jobs = cmd->add_option("--jobs", options->jobs, "Items run at once (the cores are shared out among them)")
                          ->check(WholeNumberIn(1, 256))
                          ->capture_default_str();
  cmd->add_option("--set", options->settings, "KEY=VALUE given to every item that does not set KEY (repeatable)");
  CLI::Option* sheet =
      cmd->add_option("--contact-sheet", options->contact_sheet, "Also write a PNG grid of every item's last frame");
  CLI::Option* sheet_only = cmd->add_flag("--contact-sheet-only", options->contact_sheet_only,
                                          "Run nothing: rebuild batch.json and the contact sheet from the outputs there");
  // What runs nothing takes no option that only shapes a run or its outputs.
  sheet_only->excludes(jobs);
  cmd->add_flag("--list", options->list, "Print each item's folder and command line, and run nothing")
      ->excludes(jobs)
      ->excludes(sheet)
      ->excludes(sheet_only);
  cmd->footer(
      "A manifest is a JSON list; each item names a \"scene\" (run) or a \"mesh\" with \"mode\"\n"
      "\"turntable\" (default) or \"drop\", and any options of that command by their long name:\n"
      "  [{\"scene\": \"scenes/stack.json\", \"frames\": \"1-48\"},\n"
      "   {\"mesh\": \"statue.glb\", \"turn-frames\": 60, \"up\": \"+Z\"},\n"
      "   {\"mesh\": \"bunny.obj\", \"mode\": \"drop\", \"material\": \"jelly\", \"no-render\": true,\n"
      "    \"name\": \"bunny-jelly\"}]\n"
      "An item's \"name\" is its folder's (default: its file's stem).\n"
      "Every path in an item (scene, mesh, video, stats, save-scene) is relative to the manifest,\n"
      "and every item is checked before the first runs. A folder means every mesh file in it, as\n"
      "turntables.\n"
      "Each item writes into OUT/NAME/ (NAME from its file, made unique: cube, cube-2) and is\n"
      "complete once OUT/NAME/item.json says \"succeeded\" for its command line and its input\n"
      "files: a rerun skips complete items and redoes the rest (an item whose entry or --set\n"
      "changed, or whose scene, mesh or tet files changed size or time since, included), so a\n"
      "killed batch loses at most the items in flight. A folder OUT/NAME that batch did not write\n"
      "(no item.json) is never replaced: the batch stops before running anything. A failed item\n"
      "is recorded (exit code, message) and never stops the others. --max-memory before `batch`\n"
      "(its default too) is shared out among the items running at once (--jobs), as the cores\n"
      "are. OUT/batch.json lists every item; the exit code is 0 when all succeeded, else the\n"
      "largest item exit code, an item killed from outside (SIGKILL, as the out-of-memory\n"
      "killer sends, or SIGTERM) counting as 4, retryable, and one that crashed as 5.\n\n"
      "On a farm, each array task runs one shard: Slurm's SLURM_ARRAY_TASK_ID/COUNT are read\n"
      "without options; a Kubernetes Indexed Job gives JOB_COMPLETION_INDEX, with --shard-count.\n\n"
      "Examples:\n"
      "  recoil batch assets/meshes/ --set turn-frames=48 --set resolution=640x360 --contact-sheet sheet.png\n"
      "  recoil batch manifest.json -o previews/ --jobs 2\n"
      "  recoil batch manifest.json -o previews/ --shard 1/4\n"
      "  recoil batch manifest.json -o previews/ --contact-sheet-only --contact-sheet sheet.png\n");
  cmd->callback([options, &global, &action] {
    action = [options, &global] {
      require_utf8_arguments(global);
      return run_batch(*options, global);
    };
  });
}

}  // namespace recoil::cli
