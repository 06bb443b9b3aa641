#pragma once
// Output folders: the default place for a run's products and their creation.
#include <filesystem>
#include <string>

namespace recoil::cli {

// output/<name>/ when the user gave no -o.
std::filesystem::path default_output_dir(const std::string& name);

// Creates `dir` (and parents); throws recoil::Error naming it when that is
// impossible: bad_input when `dir` is a file, output_failed otherwise (a
// file in the way above it, no permission, disk full).
void ensure_output_dir(const std::filesystem::path& dir);

}  // namespace recoil::cli

namespace recoil::cli {

// Deletes the temporaries a killed run left in `dir` (frame_N.png.tmp-PID-*,
// scene.json.tmp-*, run.json.tmp-*: core/atomic_write.h) whose process PID is
// no longer running; returns how many.
// Throws output_failed with the reason when one cannot be removed.
int remove_stale_temporaries(const std::filesystem::path& dir);

}  // namespace recoil::cli

namespace recoil::cli {

// Deletes the frames an earlier run of another length left in `dir`: files
// named frame_N.png that no frame of a `frame_count`-frame run is named
// (N past it, or written with another number of digits: frame_names.h), so
// the folder holds one run's frames. Returns how many, with the first and
// last name in sequence order. Throws output_failed when one cannot be removed.
struct RemovedFrames {
  int count = 0;
  std::string first, last;
};
RemovedFrames remove_frames_past(const std::filesystem::path& dir, int frame_count);

}  // namespace recoil::cli
