#pragma once
// The check every file a scene or a batch manifest names must pass before it
// is read: readers block on a FIFO and never finish /dev/zero.
#include <filesystem>

#include "cli/json_cursor.h"

namespace recoil::cli {

// Fails at `field` unless `path`, the file it names, is a regular file,
// saying what it is instead (missing, a folder, a device or FIFO).
void require_regular_file(const JsonCursor& field, const std::filesystem::path& path);

}  // namespace recoil::cli
