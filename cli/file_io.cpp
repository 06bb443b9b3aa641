#include "cli/file_io.h"

#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <system_error>

#include "core/error.h"

namespace recoil::cli {
namespace fs = std::filesystem;

AtomicFile::AtomicFile(fs::path target) : m_target(std::move(target)) {
  static std::atomic<int> counter{0};
  m_temporary = m_target;
  m_temporary += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  m_stream.open(m_temporary, std::ios::binary | std::ios::trunc);
  if (!m_stream) throw output_error("cannot write " + m_target.string() + " (opening " + m_temporary.string() + ")");
}

AtomicFile::~AtomicFile() {
  if (m_committed) return;
  m_stream.close();
  std::error_code ignored;
  fs::remove(m_temporary, ignored);
}

void AtomicFile::commit() {
  m_stream.flush();
  const bool written = static_cast<bool>(m_stream);
  m_stream.close();
  if (!written || m_stream.fail()) throw output_error("cannot write " + m_target.string() + " (disk full?)");
  std::error_code ec;
  fs::rename(m_temporary, m_target, ec);
  if (ec) throw output_error("cannot write " + m_target.string() + ": " + ec.message());
  m_committed = true;
}

void write_text_atomically(const fs::path& target, const std::string& text) {
  AtomicFile file(target);
  file.stream() << text;
  file.commit();
}

std::vector<std::uint8_t> read_file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw bad_input("cannot read " + path.string());
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw bad_input("cannot read " + path.string());
  return bytes;
}

void copy_file_atomically(const fs::path& source, const fs::path& target) {
  const std::vector<std::uint8_t> bytes = read_file_bytes(source);
  AtomicFile file(target);
  file.stream().write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  file.commit();
}

}  // namespace recoil::cli
