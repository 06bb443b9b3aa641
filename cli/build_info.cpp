#include "cli/build_info.h"

#include "recoil_git.h"  // generated in the build folder at every build

namespace recoil::cli {

const char* build_commit() { return RECOIL_GIT; }

}  // namespace recoil::cli
