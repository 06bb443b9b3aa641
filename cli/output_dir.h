#pragma once
// Output folders: the default place for a run's products and their creation.
#include <filesystem>
#include <string>
#include <vector>

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

// Deletes the frames an earlier run left in `dir` that this one has no part
// in, so the folder holds one scene's frames: files named frame_N.png that no
// frame of a `frame_count`-frame run is named (N past it, or written with
// another number of digits: frame_names.h), and, when `only` is given (an
// earlier run of another scene drew them), every frame whose number it does
// not hold. Returns how many, with the first and last name in sequence
// order. Throws output_failed when one cannot be removed.
struct RemovedFrames {
  int count = 0;
  std::string first, last;
};
RemovedFrames remove_foreign_frames(const std::filesystem::path& dir, int frame_count,
                                    const std::vector<int>* only = nullptr);

}  // namespace recoil::cli
