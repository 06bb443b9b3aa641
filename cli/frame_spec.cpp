#include "cli/frame_spec.h"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "cli/scene_limits.h"
#include "core/error.h"

namespace recoil::cli {
namespace {

// A positive frame number (or step); whole text must be digits. `below_one`
// says what a 0 breaks.
int parse_frame(const std::string& text, const std::string& spec, const std::string& option,
                const char* below_one = "frame numbers start at 1") {
  if (text.empty() || text.size() > 9 || !std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    throw bad_input(option + ": expected frame numbers like 1-100, 1-100:5 or 1,3,7-9, got '" + spec + "'");
  const int n = std::stoi(text);
  if (n < 1) throw bad_input(option + ": " + below_one + ", got '" + spec + "'");
  if (n > kMaxFrames) throw bad_input(option + ": frame numbers go up to " + std::to_string(kMaxFrames) + ", got '" + spec + "'");
  return n;
}

}  // namespace

std::vector<int> parse_frame_spec(const std::string& spec, const std::string& option) {
  std::vector<int> frames;
  std::stringstream parts(spec);
  std::string part;
  bool any = false;
  while (std::getline(parts, part, ',')) {
    any = true;
    int step = 1;
    const size_t colon = part.find(':');
    if (colon != std::string::npos) {
      step = parse_frame(part.substr(colon + 1), spec, option, "the step (:N) is at least 1");
      part = part.substr(0, colon);
    }
    const size_t dash = part.find('-');
    const int first = parse_frame(part.substr(0, dash), spec, option);
    const int last = dash == std::string::npos ? first : parse_frame(part.substr(dash + 1), spec, option);
    if (last < first) throw bad_input(option + ": range " + part + " runs backwards in '" + spec + "'");
    if (colon != std::string::npos && dash == std::string::npos)
      throw bad_input(option + ": a step (:N) needs a range, as in 1-100:5, got '" + spec + "'");
    for (long f = first; f <= last; f += step) {
      frames.push_back(static_cast<int>(f));
      if (frames.size() > static_cast<size_t>(kMaxFrames)) throw bad_input(option + ": too many frames in '" + spec + "'");
    }
  }
  if (!any || spec.back() == ',') throw bad_input(option + ": expected frame numbers like 1-100, 1-100:5 or 1,3,7-9, got '" + spec + "'");
  std::sort(frames.begin(), frames.end());
  frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
  return frames;
}

std::vector<int> all_frames(int count) {
  std::vector<int> frames(static_cast<size_t>(std::max(count, 0)));
  for (int i = 0; i < count; ++i) frames[static_cast<size_t>(i)] = i + 1;
  return frames;
}

}  // namespace recoil::cli
