#pragma once
// What batch knows about one item on disk: DIR/NAME/item.json, the
// completion marker written last, and DIR/batch.json, the summary of all.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli/batch_manifest.h"

namespace recoil::cli {

// One input file as an item found it: a changed size or modification time
// says the file changed (as make and rsync judge it); size -1: it was missing.
struct InputStamp {
  std::string path;
  long long size = -1;      // bytes
  long long mtime_ns = 0;   // nanoseconds since the Unix epoch
  bool operator==(const InputStamp&) const = default;
};

// The stamps of the files `item` reads: its scene or mesh files, and the
// mesh and tet files its scene names (bodies/*/mesh, bodies/*/tets/file).
// Not the files a mesh file itself refers to (an OBJ's materials and
// textures, a glTF's buffers).
std::vector<InputStamp> input_stamps(const BatchItem& item);

struct ItemRecord {
  int index = 0;
  std::string name;
  std::string status;  // "succeeded", "failed" or (never on disk) "pending"
  int exit_code = 0;
  double seconds = 0.0;
  std::string message;  // the item's error line when it failed
  std::string shard;    // "I/N" of the process that ran it
  std::vector<std::string> command;  // the item's command line it ran (BatchItem::args)
  std::vector<InputStamp> inputs;    // its input files as it started
  bool reused = false;  // finished by an earlier batch, not run by this one (never on disk)
  bool succeeded() const { return status == "succeeded"; }
};

// The record describes `item` as the manifest and its files give it now: a
// record of another command line (the manifest or a --set changed since), or
// of input files that changed since, is stale, and its item is run again.
inline bool records_item(const ItemRecord& record, const BatchItem& item) {
  return record.command == item.args && record.inputs == input_stamps(item);
}

// DIR/NAME/item.json when it is there and readable, else nothing.
std::optional<ItemRecord> read_item_record(const std::filesystem::path& item_dir);

// Writes `record` as `item_dir`/item.json, atomically.
void write_item_record(const std::filesystem::path& item_dir, const ItemRecord& record);

// Writes `output`/batch.json with one entry per item of the batch: its record
// from disk, or "pending"; returns the records.
std::vector<ItemRecord> write_batch_summary(const std::filesystem::path& output, const std::filesystem::path& source,
                                            const std::vector<BatchItem>& items);

}  // namespace recoil::cli
