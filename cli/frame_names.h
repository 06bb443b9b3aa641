#pragma once
// Frame file names: frame_0001.png ... with more digits when a sequence
// needs them. Frame numbers start at 1.
#include <string>

namespace recoil::cli {

inline std::string frame_file_name(int frame, int frame_count) {
  int digits = 4;
  for (int limit = 10000; frame_count >= limit && digits < 9; limit *= 10) ++digits;
  std::string number = std::to_string(frame);
  if (static_cast<int>(number.size()) < digits) number.insert(0, digits - number.size(), '0');
  return "frame_" + number + ".png";
}

}  // namespace recoil::cli
