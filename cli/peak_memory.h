#pragma once
// The process's peak resident memory, for run.json: what a farm job must ask for.
#include <optional>

namespace recoil::cli {

// MiB: the high-water mark of this process's own memory since it started
// (Linux VmHWM). Unlike getrusage's ru_maxrss it does not count the memory
// of the process that forked it; nullopt where /proc is not available.
std::optional<double> peak_memory_mib();

}  // namespace recoil::cli
