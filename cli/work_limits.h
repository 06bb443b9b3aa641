#pragma once
// What a run will cost, checked before anything is written or allocated: the
// number of steps and frames, and an estimate of the memory its tetrahedra,
// matrices and framebuffers take, against a limit (--max-memory).
#include <string>

#include "cli/scene_desc.h"

namespace recoil::cli {

// Bytes of memory a run may use: `max_memory_gib` when > 0, else 80 % of
// the machine's physical memory.
double memory_limit_bytes(double max_memory_gib);

// The range of --max-memory, GiB.
inline constexpr double kLeastMaxMemoryGib = 0.01, kMostMaxMemoryGib = 1e6;

struct MemoryEstimate {
  double bytes = 0.0;          // the whole run, `in_use` included
  double in_use = 0.0;         // what the process holds already: libraries, imported meshes
  double largest_bytes = 0.0;  // its largest single part
  std::string largest_field;   // the JSON pointer that sets that part
  std::string largest_what;    // "84.9 million tetrahedra", "16384x16384 pixels at msaa 4"
};
MemoryEstimate estimate_memory(const SceneDesc& scene, bool render);

// Throws bad_input naming the scene file and field when the steps, frames or
// estimated memory of running `scene` up to `last_frame` exceed their limits.
void check_work_limits(const SceneDesc& scene, int last_frame, bool render, double memory_limit);

}  // namespace recoil::cli
