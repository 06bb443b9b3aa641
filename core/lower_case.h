#pragma once
// ASCII lower case, for names compared without regard to case (file
// extensions, texture names, format keywords); bytes past ASCII are kept.
#include <cctype>
#include <string>

namespace recoil {

inline std::string lower_case(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace recoil
