#pragma once
// Runs a third-party file reader in a forked child process, so that its crash,
// abort, heap corruption or endless loop on a broken file ends the child only
// and reaches the caller as a bad-input error naming the file.
#include <functional>
#include <string>

namespace recoil::sim {

// Runs `read` in a child process limited to `cpu_seconds` of CPU time and
// returns the bytes it returned there. A recoil::Error thrown in the child is
// thrown again here with its kind and message, any other exception as
// bad_input; a child that dies, runs out of time or exits without an answer
// is bad_input naming `file` and `reader`.
std::string read_in_child(const std::function<std::string()>& read, const std::string& file, const std::string& reader,
                          int cpu_seconds);

// Sets a function that runs first in every reader child. The fuzz targets use
// it to take back the crash reporting the child inherits from libFuzzer, which
// would record a crash the parent answers as bad input as a finding.
void set_reader_child_setup(void (*setup)());

}  // namespace recoil::sim
