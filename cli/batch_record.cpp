#include "cli/batch_record.h"

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/file_io.h"

namespace recoil::cli {
namespace fs = std::filesystem;

namespace {

InputStamp stamp(const fs::path& file) {
  InputStamp out;
  out.path = file.string();
  std::error_code ec;
  const auto size = fs::file_size(file, ec);
  if (ec) return out;
  const auto time = fs::last_write_time(file, ec);
  if (ec) return out;
  out.size = static_cast<long long>(size);
  const auto unix_time = std::chrono::file_clock::to_sys(time);  // libstdc++'s file clock has an epoch of its own
  out.mtime_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(unix_time.time_since_epoch()).count();
  return out;
}

// The mesh and tet files a scene file names (bodies/*/mesh, bodies/*/tets/file),
// resolved against its folder as the scene reader does; none when it cannot
// be read (the item then fails on it).
std::vector<fs::path> scene_files(const fs::path& scene) {
  std::ifstream in(scene);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  std::vector<fs::path> out;
  if (!j.is_object() || !j.contains("bodies") || !j["bodies"].is_array()) return out;
  auto add = [&](const nlohmann::json& name) {
    if (name.is_string()) out.push_back((scene.parent_path() / name.get<std::string>()).lexically_normal());
  };
  for (const nlohmann::json& body : j["bodies"]) {
    if (!body.is_object()) continue;
    if (body.contains("mesh")) add(body["mesh"]);
    if (body.contains("tets") && body["tets"].is_object() && body["tets"].contains("file")) add(body["tets"]["file"]);
  }
  return out;
}

}  // namespace

std::vector<InputStamp> input_stamps(const BatchItem& item) {
  std::vector<InputStamp> out;
  for (const std::string& file : item.inputs) {
    out.push_back(stamp(file));
    if (item.mode == "run")
      for (const fs::path& named : scene_files(file)) out.push_back(stamp(named));
  }
  return out;
}

std::optional<ItemRecord> read_item_record(const fs::path& item_dir) {
  std::ifstream in(item_dir / "item.json");
  if (!in) return std::nullopt;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object()) return std::nullopt;
  ItemRecord r;
  r.index = j.value("index", -1);
  r.name = j.value("name", "");
  r.status = j.value("status", "");
  r.exit_code = j.value("exit_code", 0);
  r.seconds = j.value("seconds", 0.0);
  r.message = j.value("message", "");
  r.shard = j.value("shard", "");
  if (const auto command = j.find("command"); command != j.end() && command->is_array())
    for (const nlohmann::json& arg : *command)
      if (arg.is_string()) r.command.push_back(arg.get<std::string>());
  if (const auto inputs = j.find("inputs"); inputs != j.end() && inputs->is_array())
    for (const nlohmann::json& input : *inputs)
      if (input.is_object())
        r.inputs.push_back({input.value("path", ""), input.value("size", -1LL), input.value("mtime_ns", 0LL)});
  if (r.status != "succeeded" && r.status != "failed") return std::nullopt;
  return r;
}

namespace {

nlohmann::json to_json(const ItemRecord& r) {
  nlohmann::json inputs = nlohmann::json::array();
  for (const InputStamp& input : r.inputs)
    inputs.push_back({{"path", input.path}, {"size", input.size}, {"mtime_ns", input.mtime_ns}});
  return {{"index", r.index},     {"name", r.name},       {"status", r.status}, {"exit_code", r.exit_code},
          {"seconds", r.seconds}, {"message", r.message}, {"shard", r.shard},   {"command", r.command},
          {"inputs", inputs}};
}

}  // namespace

void write_item_record(const fs::path& item_dir, const ItemRecord& record) {
  write_text_atomically(item_dir / "item.json", to_json(record).dump(2) + "\n");
}

std::vector<ItemRecord> write_batch_summary(const fs::path& output, const fs::path& source,
                                            const std::vector<BatchItem>& items) {
  std::vector<ItemRecord> records;
  nlohmann::json list = nlohmann::json::array();
  int succeeded = 0, failed = 0;
  for (const BatchItem& item : items) {
    ItemRecord r = read_item_record(output / item.name).value_or(ItemRecord{});
    if (!records_item(r, item)) r = ItemRecord{};
    if (r.status.empty()) r.status = "pending";
    r.index = item.index;
    r.name = item.name;
    succeeded += r.status == "succeeded";
    failed += r.status == "failed";
    nlohmann::json entry = to_json(r);
    entry["output"] = (output / item.name).string();
    entry["command"] = item.args;  // also for an item still pending
    list.push_back(entry);
    records.push_back(r);
  }
  const nlohmann::json summary = {{"source", source.string()},
                                  {"items", list},
                                  {"succeeded", succeeded},
                                  {"failed", failed},
                                  {"pending", static_cast<int>(items.size()) - succeeded - failed}};
  write_text_atomically(output / "batch.json", summary.dump(2) + "\n");
  return records;
}

}  // namespace recoil::cli
