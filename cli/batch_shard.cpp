#include "cli/batch_shard.h"

#include <charconv>
#include <cstdlib>

#include "core/error.h"

namespace recoil::cli {
namespace {

bool parse_int(const std::string& text, int& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

// An environment variable as a whole non-negative integer; `set` says whether it exists.
int env_int(const char* name, bool& set) {
  const char* text = std::getenv(name);
  set = text != nullptr && *text != '\0';
  if (!set) return 0;
  int value = 0;
  if (!parse_int(text, value) || value < 0)
    throw bad_input(std::string("environment variable ") + name + "=\"" + text + "\" is not a whole number >= 0");
  return value;
}

Shard checked(Shard shard, const std::string& source) {
  if (shard.count < 1 || shard.index < 0 || shard.index >= shard.count)
    throw bad_input(source + ": shard " + shard.text() + " does not exist (I/N needs 0 <= I < N)");
  return shard;
}

}  // namespace

Shard choose_shard(const std::string& shard_option, int shard_count) {
  if (!shard_option.empty()) {
    const size_t slash = shard_option.find('/');
    Shard shard;
    if (slash == std::string::npos || !parse_int(shard_option.substr(0, slash), shard.index) ||
        !parse_int(shard_option.substr(slash + 1), shard.count))
      throw bad_input("--shard \"" + shard_option + "\": expected I/N, e.g. 0/4 (0-based I)");
    if (shard_count > 0 && shard_count != shard.count)
      throw bad_input("--shard " + shard_option + " and --shard-count " + std::to_string(shard_count) + " disagree");
    return checked(shard, "--shard");
  }
  bool has_id = false, has_count = false, has_min = false, has_completion = false;
  const int slurm_id = env_int("SLURM_ARRAY_TASK_ID", has_id);
  const int slurm_count = env_int("SLURM_ARRAY_TASK_COUNT", has_count);
  const int slurm_min = env_int("SLURM_ARRAY_TASK_MIN", has_min);
  if (has_id) {
    // Slurm sets both for an array task; an index alone would run every item in every task.
    if (!has_count && shard_count <= 0)
      throw bad_input("SLURM_ARRAY_TASK_ID is set but SLURM_ARRAY_TASK_COUNT is not: give --shard-count, or --shard I/N");
    // Array indices need not start at 0 (--array=1-8): count from the first.
    return checked({slurm_id - (has_min ? slurm_min : 0), shard_count > 0 ? shard_count : slurm_count},
                   "SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT");
  }
  const int completion = env_int("JOB_COMPLETION_INDEX", has_completion);
  if (has_completion) {
    if (shard_count <= 0)
      throw bad_input("JOB_COMPLETION_INDEX is set but --shard-count is not: give the Indexed Job's completions");
    return checked({completion, shard_count}, "JOB_COMPLETION_INDEX with --shard-count");
  }
  if (shard_count > 0)
    throw bad_input("--shard-count " + std::to_string(shard_count) +
                    " needs JOB_COMPLETION_INDEX or SLURM_ARRAY_TASK_ID to say which shard this is");
  return {};
}

}  // namespace recoil::cli
