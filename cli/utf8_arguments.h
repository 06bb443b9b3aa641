#pragma once
#include <string>

#include "cli/commands.h"

namespace recoil::cli {

// run, drop, turntable and batch record their command line and file paths
// in run.json, scene.json, item.json and batch.json, and JSON strings hold
// UTF-8 only, so a name that is not UTF-8 text (a Latin-1 file name, say)
// is refused before anything is written.

// Throws bad input saying that `text`, a `what` ("argument", "file name"),
// is not UTF-8 text, when it is not.
void require_utf8(const std::string& text, const std::string& what);

// require_utf8 on every word of the command line and on the working
// directory (relative paths are recorded made absolute).
void require_utf8_arguments(const GlobalOptions& global);

}  // namespace recoil::cli
