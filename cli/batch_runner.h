#pragma once
// Runs a batch's items, each as its own recoil process (a crash or a runaway
// item takes only itself down), at most `jobs` at a time. An item writes into
// OUT/NAME.partial/; its item.json is written there last and the folder is
// then renamed to OUT/NAME/, so OUT/NAME/ with a "succeeded" item.json is a
// complete item and anything else is redone by the next run.
#include <filesystem>
#include <vector>

#include "cli/batch_manifest.h"
#include "cli/batch_record.h"
#include "cli/batch_shard.h"
#include "cli/commands.h"

namespace recoil::cli {

struct BatchRunOptions {
  std::filesystem::path output;
  int jobs = 1;  // items run at once; the cores are shared out among them
  Shard shard;
};

// Runs the items `options.shard` keeps that are not complete yet; returns the
// record of every kept item (skipped ones read from disk), in item order.
// Throws Interrupted after stopping the items in flight on SIGINT/SIGTERM.
std::vector<ItemRecord> run_batch_items(const std::vector<BatchItem>& items, const BatchRunOptions& options,
                                        const GlobalOptions& global);

// The batch's exit code: 0 when every record succeeded, else the most severe
// item's (the largest). An item stopped by a signal from outside (SIGKILL,
// which the kernel's out-of-memory killer sends, or SIGTERM, SIGINT, SIGHUP,
// SIGXCPU: a scheduler's limits) counts as retryable, 4; one that crashed
// (SIGSEGV, SIGABRT, ...) as internal, 5.
int batch_exit_code(const std::vector<ItemRecord>& records);

}  // namespace recoil::cli
