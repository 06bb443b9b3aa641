#include "render/png_probe.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>

namespace recoil::render {
namespace {

std::uint32_t read_be32(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
}

}  // namespace

bool is_whole_png(const std::filesystem::path& path, int width, int height) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return false;
  std::ifstream in(path, std::ios::binary);
  constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::array<unsigned char, 8 + 8 + 13> head{};
  if (!in.read(reinterpret_cast<char*>(head.data()), head.size())) return false;
  const bool ihdr = std::memcmp(head.data(), kSignature, 8) == 0 && read_be32(&head[8]) == 13 &&
                    std::memcmp(&head[12], "IHDR", 4) == 0;
  if (!ihdr || read_be32(&head[16]) != static_cast<std::uint32_t>(width) ||
      read_be32(&head[20]) != static_cast<std::uint32_t>(height))
    return false;
  // Walking the chunk lengths (8 bytes read per chunk, the data skipped)
  // catches a file cut anywhere, even one cut right after an IDAT.
  std::uintmax_t offset = 8;
  while (offset + 12 <= size) {
    unsigned char chunk[8];
    in.seekg(static_cast<std::streamoff>(offset));
    if (!in.read(reinterpret_cast<char*>(chunk), sizeof(chunk))) return false;
    const std::uintmax_t next = offset + 12 + read_be32(chunk);
    if (std::memcmp(chunk + 4, "IEND", 4) == 0) return next == size;
    offset = next;
  }
  return false;
}

}  // namespace recoil::render
