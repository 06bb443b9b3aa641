#pragma once
// What batch knows about one item on disk: DIR/NAME/item.json, the
// completion marker written last, and DIR/batch.json, the summary of all.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli/batch_manifest.h"

namespace recoil::cli {

struct ItemRecord {
  int index = 0;
  std::string name;
  std::string status;  // "succeeded", "failed" or (never on disk) "pending"
  int exit_code = 0;
  double seconds = 0.0;
  std::string message;  // the item's error line when it failed
  std::string shard;    // "I/N" of the process that ran it
  std::vector<std::string> command;  // the item's command line it ran (BatchItem::args)
  bool reused = false;  // finished by an earlier batch, not run by this one (never on disk)
  bool succeeded() const { return status == "succeeded"; }
};

// The record describes `item` as the manifest gives it now: a record of
// another command line (the manifest or a --set changed since) is stale,
// and its item is run again.
inline bool records_item(const ItemRecord& record, const BatchItem& item) { return record.command == item.args; }

// DIR/NAME/item.json when it is there and readable, else nothing.
std::optional<ItemRecord> read_item_record(const std::filesystem::path& item_dir);

// Writes `record` as `item_dir`/item.json, atomically.
void write_item_record(const std::filesystem::path& item_dir, const ItemRecord& record);

// Writes `output`/batch.json with one entry per item of the batch: its record
// from disk, or "pending"; returns the records.
std::vector<ItemRecord> write_batch_summary(const std::filesystem::path& output, const std::filesystem::path& source,
                                            const std::vector<BatchItem>& items);

}  // namespace recoil::cli
