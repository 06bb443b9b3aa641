#pragma once
// `--frames SPEC`: "1-100", "1-100:5", "1,3,7-9".
// Frame numbers start at 1.
#include <string>
#include <vector>

namespace recoil::cli {

// The selected frames, ascending and unique. Throws bad_input naming
// `option` for malformed text, a zero frame or a reversed range.
std::vector<int> parse_frame_spec(const std::string& spec, const std::string& option = "--frames");

// 1, 2, ..., count.
std::vector<int> all_frames(int count);

}  // namespace recoil::cli
