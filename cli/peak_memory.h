#pragma once
// The run's peak resident memory, for run.json: what a farm job must ask for.
#include <optional>

namespace recoil::cli {

// MiB: the larger of this process's own high-water mark since it started
// (Linux VmHWM; unlike its ru_maxrss it does not count the memory of the
// process that forked it) and the largest of its finished child processes
// (the mesh reader, which assimp's scene is held in, and the video encoder);
// nullopt where /proc is not available.
std::optional<double> peak_memory_mib();

}  // namespace recoil::cli
