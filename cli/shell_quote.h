#pragma once
// Text as /bin/sh reads it back: a command line recorded in run.json, the
// ffmpeg command recoil starts.
#include <string>

namespace recoil::cli {

// `text` in single quotes, each ' written as '\''.
inline std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// `text` as it is when the shell would not split or expand it, else quoted.
inline std::string shell_word(const std::string& text) {
  const bool plain = !text.empty() && text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                             "0123456789_./=:,+-@%") == std::string::npos;
  return plain ? text : shell_quote(text);
}

}  // namespace recoil::cli
