#pragma once
// What the running binary was built from, for --version and run.json.

namespace recoil::cli {

// `git describe --always --dirty` of the source tree at the last build
// (not at configure time), or "unknown" outside a git checkout.
const char* build_commit();

}  // namespace recoil::cli
