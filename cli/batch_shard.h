#pragma once
// Which items of a batch this process runs: every item whose index mod
// `count` is `index`. From --shard I/N, else from a farm's array job
// variables (Slurm's SLURM_ARRAY_TASK_ID/COUNT, Kubernetes' JOB_COMPLETION_INDEX
// with --shard-count), else all items.
#include <string>

namespace recoil::cli {

struct Shard {
  int index = 0;  // 0-based
  int count = 1;
  bool keeps(int item_index) const { return item_index % count == index; }
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// `shard_option`: --shard ("" when absent); `shard_count`: --shard-count (0 when absent).
// Throws bad_input naming the option or variable at fault.
Shard choose_shard(const std::string& shard_option, int shard_count);

}  // namespace recoil::cli
