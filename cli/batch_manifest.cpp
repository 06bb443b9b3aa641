// Manifest items become recoil command lines: each key is the long option of
// the same name, and the whole line goes through the command's own CLI11
// parser and the parsers its run applies once here, so a bad value is
// reported before the first item runs.
#include "cli/batch_manifest.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "cli/batch_check.h"
#include "cli/commands.h"
#include "cli/file_io.h"
#include "cli/input_file.h"
#include "cli/json_cursor.h"
#include "cli/utf8_arguments.h"
#include "core/error.h"
#include "core/lower_case.h"
#include "sim/geometry/mesh_import.h"

namespace recoil::cli {
namespace fs = std::filesystem;
namespace {

// Keys that are not options of the command: what to run and what to call it.
const std::vector<std::string> kItemKeys = {"scene", "mesh", "mode", "name"};
// Options given before the command, for every item alike.
const std::vector<std::string> kGlobalOptions = {"max-memory", "log-json", "quiet"};

// Options whose value is a file the item writes: like its inputs, relative to the manifest.
const std::vector<std::string> kPathOptions = {"video", "stats", "save-scene"};

// A folder name from a file stem: letters, digits, '.', '-' and '_' kept, anything else '_'.
std::string folder_name(const std::string& stem) {
  std::string name;
  for (const char c : stem) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                       c == '-' || c == '_';
    name += plain ? c : '_';
  }
  if (name.empty() || name.front() == '.') name.insert(0, "item");
  return name;
}

// A command-line value for one JSON scalar ("0.5", "256x256", "3").
std::string option_value(const JsonCursor& field) {
  const nlohmann::json& v = field.value();
  if (v.is_string()) return v.get<std::string>();
  // 10.0 is the whole number an integer option takes (JSON writers print floats so).
  if (v.is_number_float() && std::abs(v.get<double>()) < 1e15 && std::floor(v.get<double>()) == v.get<double>())
    return std::to_string(static_cast<long long>(v.get<double>()));
  if (v.is_number()) return v.dump();
  field.fail("expected a string or a number, got " + std::string(v.type_name()));
}

// Checks `args` with the real parser of their command; a refusal is reported
// at the field whose option it names.
void check_with_command_parser(const std::vector<std::string>& args, const JsonCursor& item) {
  CLI::App app;
  GlobalOptions global;
  Action action;
  add_run_command(app, global, action);
  add_drop_command(app, global, action);
  add_turntable_command(app, global, action);
  // CLI11 takes the arguments last first; batch gives every item its own -o.
  std::vector<std::string> line = args;
  line.insert(line.end(), {"-o", "-"});
  std::reverse(line.begin(), line.end());
  try {
    app.parse(line);
  } catch (const CLI::ParseError& e) {
    fail_at_option(item, e.what());
  }
}

// Turns one manifest entry (with `defaults` under it) into an item.
BatchItem to_item(const JsonCursor& entry, const nlohmann::json& defaults, const fs::path& base, int index) {
  nlohmann::json merged = defaults;
  if (!entry.value().is_object()) entry.fail("expected an object with \"scene\" or \"mesh\", got " +
                                             std::string(entry.value().type_name()));
  for (const auto& [key, value] : entry.value().items()) merged[key] = value;
  const JsonCursor item(merged, entry.file(), entry.pointer());
  const bool has_scene = merged.contains("scene"), has_mesh = merged.contains("mesh");
  if (has_scene == has_mesh) item.fail("an item names exactly one of \"scene\" or \"mesh\"");

  BatchItem out;
  out.index = index;
  std::vector<std::string> inputs;
  const JsonCursor source = item.child(has_scene ? "scene" : "mesh");
  const auto resolve = [&](const JsonCursor& path) {
    if (!path.value().is_string() || path.value().get<std::string>().empty())
      path.fail("expected a file name (a non-empty string)");
    return (base / path.value().get<std::string>()).lexically_normal().string();
  };
  const auto input = [&](const JsonCursor& path) {
    const std::string file = resolve(path);
    require_regular_file(path, file);
    return file;
  };
  if (source.value().is_array() && has_mesh) {
    for (const JsonCursor& mesh : source.elements()) inputs.push_back(input(mesh));
    if (inputs.empty()) source.fail("expected at least one mesh file");
  } else {
    inputs.push_back(input(source));
  }
  out.mode = has_scene ? "run" : "turntable";
  if (merged.contains("mode")) {
    const JsonCursor mode = item.child("mode");
    const std::vector<std::string> allowed = has_scene ? std::vector<std::string>{"run"}
                                                       : std::vector<std::string>{"turntable", "drop"};
    if (!mode.value().is_string() ||
        std::find(allowed.begin(), allowed.end(), mode.value().get<std::string>()) == allowed.end())
      mode.fail("expected " + std::string(has_scene ? "\"run\" for a scene" : "\"turntable\" or \"drop\""));
    out.mode = mode.value().get<std::string>();
  }
  if (out.mode == "turntable" && inputs.size() > 1) source.fail("a turntable takes one mesh; use \"mode\": \"drop\"");
  out.name = merged.contains("name") ? option_value(item.child("name")) : fs::path(inputs.front()).stem().string();
  out.name = folder_name(out.name);

  // The command's own options, from every other key.
  CLI::App app;
  GlobalOptions global;
  Action action;
  if (out.mode == "run") add_run_command(app, global, action);
  if (out.mode == "drop") add_drop_command(app, global, action);
  if (out.mode == "turntable") add_turntable_command(app, global, action);
  CLI::App* command = app.get_subcommand(out.mode);
  std::vector<std::string> known;
  for (const CLI::Option* option : command->get_options())
    for (const std::string& name : option->get_lnames())
      if (name != "help" && name != "output") known.push_back(name);

  out.args = {out.mode};
  out.args.insert(out.args.end(), inputs.begin(), inputs.end());
  out.inputs = inputs;
  for (const auto& [key, value] : merged.items()) {
    if (std::find(kItemKeys.begin(), kItemKeys.end(), key) != kItemKeys.end()) continue;
    const JsonCursor field = item.child(key);
    if (key == "output" || key == "o") field.fail("batch writes every item into its own folder under -o");
    const CLI::Option* option = std::find(known.begin(), known.end(), key) == known.end()
                                    ? nullptr
                                    : command->get_option_no_throw("--" + key);
    if (!option && std::find(kGlobalOptions.begin(), kGlobalOptions.end(), key) != kGlobalOptions.end())
      (entry.has(key) ? field : item)
          .fail("--" + key + " is an option of recoil itself, not of `recoil " + out.mode +
                "`: give it before the command, `recoil --" + key + " ... batch ...`");
    if (!option) {
      std::vector<std::string> candidates = known;
      candidates.insert(candidates.end(), kItemKeys.begin(), kItemKeys.end());
      const std::string suggestion = near_miss(key, candidates);
      // A key the entry does not set came from --set, which is where the mistake is.
      if (!entry.has(key))
        item.fail("--set " + key + ": `recoil " + out.mode + "` has no option --" + key +
                  "; set it in the manifest on the items that take it");
      field.fail("`recoil " + out.mode + "` has no option --" + key +
                 (suggestion.empty() ? "" : "; did you mean \"" + suggestion + "\"?"));
    }
    const bool flag = option->get_expected_max() == 0;  // a switch takes no value
    if (flag) {
      if (!value.is_boolean()) field.fail("--" + key + " is a switch: expected true or false");
      if (value.get<bool>()) out.args.push_back("--" + key);
      continue;
    }
    if (value.is_boolean()) field.fail("--" + key + " takes a value, not " + value.dump());
    out.args.push_back("--" + key);
    if (std::find(kPathOptions.begin(), kPathOptions.end(), key) != kPathOptions.end()) {
      out.args.push_back(resolve(field));
    } else if (value.is_array()) {
      if (option->get_expected_max() <= 1)
        field.fail("--" + key + " takes one value, written as on the command line (`recoil " + out.mode +
                   " --help`), not a list");
      for (const JsonCursor& element : field.elements()) out.args.push_back(option_value(element));
    } else {
      out.args.push_back(option_value(field));
    }
  }
  check_with_command_parser(out.args, item);
  check_option_values(out.args, item);
  return out;
}

// Item folder names made unique in item order, ignoring case (so that they
// stay apart on any file system): after "Cube", "cube" is "cube-2".
void make_names_unique(std::vector<BatchItem>& items) {
  std::set<std::string> taken;
  for (BatchItem& item : items) {
    std::string name = item.name;
    for (int n = 2; taken.count(lower_case(name)); ++n) name = item.name + "-" + std::to_string(n);
    item.name = name;
    taken.insert(lower_case(name));
  }
}

}  // namespace

std::vector<BatchItem> load_batch_items(const fs::path& source, const nlohmann::json& defaults) {
  std::error_code ec;
  std::vector<BatchItem> items;
  if (fs::is_directory(source, ec)) {
    std::vector<fs::path> meshes;
    for (const fs::directory_entry& entry : fs::directory_iterator(source, ec)) {
      const std::string file = entry.path().filename().string();
      if (!file.empty() && file.front() != '.' && entry.is_regular_file(ec) && sim::is_mesh_file_name(entry.path()))
        meshes.push_back(entry.path());
    }
    if (ec) throw bad_input(source.string() + ": cannot list the folder: " + ec.message());
    std::sort(meshes.begin(), meshes.end());
    if (meshes.empty()) throw bad_input(source.string() + ": no mesh files in this folder (nothing for batch to do)");
    for (size_t i = 0; i < meshes.size(); ++i) {
      require_utf8(meshes[i].string(), "mesh file");
      const nlohmann::json entry = {{"mesh", meshes[i].filename().string()}};
      items.push_back(to_item(JsonCursor(entry, meshes[i].string()), defaults, source, static_cast<int>(i)));
    }
  } else {
    const std::vector<std::uint8_t> bytes = read_file_bytes(source);
    const nlohmann::json document = parse_json_text(std::string(bytes.begin(), bytes.end()), source.string());
    const JsonCursor list(document, source.string());
    if (!document.is_array()) list.fail("a batch manifest is a JSON list of items, got " + std::string(document.type_name()));
    if (document.empty()) list.fail("the manifest lists no items");
    const std::vector<JsonCursor> entries = list.elements();
    for (size_t i = 0; i < entries.size(); ++i)
      items.push_back(to_item(entries[i], defaults, source.parent_path(), static_cast<int>(i)));
  }
  make_names_unique(items);
  return items;
}

}  // namespace recoil::cli
