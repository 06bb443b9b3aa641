#pragma once
// UTF-8 well-formedness (RFC 3629): what a JSON writer accepts in a string.
#include <string>
#include <string_view>

namespace recoil {

// Bytes of the well-formed sequence that `text` starts with; 0 when it
// starts with a malformed one (a stray continuation byte, a truncated
// sequence, an overlong form, a surrogate, past U+10FFFF) or is empty.
inline std::size_t utf8_sequence_length(std::string_view text) {
  if (text.empty()) return 0;
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(0);
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // the range of the second byte
  if (lead < 0x80) return 1;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;   // overlong below U+0800
    if (lead == 0xED) high = 0x9F;  // surrogates U+D800-DFFF
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;   // overlong below U+10000
    if (lead == 0xF4) high = 0x8F;  // past U+10FFFF
  } else {
    return 0;
  }
  if (length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    const unsigned char c = byte(k);
    if (k == 1 ? (c < low || c > high) : (c < 0x80 || c > 0xBF)) return 0;
  }
  return length;
}

// Bytes before the first malformed sequence in `text`, or npos when it is
// well-formed throughout.
inline std::size_t first_invalid_utf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = utf8_sequence_length(text.substr(i));
    if (length == 0) return i;
    i += length;
  }
  return std::string_view::npos;
}

// `text` with every byte of a malformed sequence written as \xNN, for a message.
inline std::string escape_invalid_utf8(std::string_view text) {
  std::string out;
  while (!text.empty()) {
    const std::size_t bad = first_invalid_utf8(text);
    out += text.substr(0, bad);
    if (bad == std::string_view::npos) break;
    static const char* const kHex = "0123456789ABCDEF";
    const auto c = static_cast<unsigned char>(text[bad]);
    out += {'\\', 'x', kHex[c >> 4], kHex[c & 15]};
    text.remove_prefix(bad + 1);
  }
  return out;
}

}  // namespace recoil
