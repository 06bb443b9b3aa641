#pragma once
// The items of `recoil batch`: read from a manifest (a JSON list) or from a
// folder of meshes, each turned into the command line of one recoil run and
// checked by the real command parsers before anything runs.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace recoil::cli {

struct BatchItem {
  int index = 0;                  // position in the manifest (or the folder's sorted listing)
  std::string name;               // the item's output folder name, unique within the batch
  std::string mode;               // "run", "turntable" or "drop"
  std::vector<std::string> args;  // the command line after `recoil`, without -o
  std::vector<std::string> inputs;  // the scene or mesh files it reads, as in `args`
};

// Reads `source` (a manifest file, or a folder: every mesh file in it, as a
// turntable); `defaults` (an object) holds keys every item gets unless it
// sets them itself. Throws bad_input naming the manifest and the JSON pointer
// of the field at fault (/INDEX/KEY).
std::vector<BatchItem> load_batch_items(const std::filesystem::path& source, const nlohmann::json& defaults);

}  // namespace recoil::cli
