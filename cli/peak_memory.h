#pragma once
// The process's resident memory: its peak, for run.json (what a farm job
// must ask for), and its present size, where a run's memory estimate starts.
#include <optional>

namespace recoil::cli {

// MiB: the larger of this process's own high-water mark since it started
// (Linux VmHWM; unlike its ru_maxrss it does not count the memory of the
// process that forked it) and the largest of its finished child processes
// (the mesh reader, which assimp's scene is held in, and the video encoder);
// nullopt where /proc is not available.
std::optional<double> peak_memory_mib();

// MiB this process holds now (Linux VmRSS); nullopt where /proc is not available.
std::optional<double> resident_memory_mib();

}  // namespace recoil::cli
