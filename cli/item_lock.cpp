#include "cli/item_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "cli/output_dir.h"
#include "core/error.h"

namespace recoil::cli {
namespace fs = std::filesystem;

std::optional<ItemLock> ItemLock::try_take(const fs::path& output, const std::string& name) {
  const fs::path dir = output / ".recoil-locks";
  ensure_output_dir(dir);
  const fs::path file = dir / name;
  // Close-on-exec: only the item this claim is for inherits it (inherit()).
  const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (fd < 0) throw output_error("cannot open lock file " + file.string() + ": " + std::strerror(errno));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd);
    if (err == EWOULDBLOCK) return std::nullopt;
    throw output_error("cannot lock " + file.string() + ": " + std::strerror(err));
  }
  return ItemLock(fd);
}

ItemLock::ItemLock(ItemLock&& other) noexcept : m_fd(other.m_fd) { other.m_fd = -1; }

ItemLock& ItemLock::operator=(ItemLock&& other) noexcept {
  if (this != &other) {
    if (m_fd >= 0) ::close(m_fd);
    m_fd = other.m_fd;
    other.m_fd = -1;
  }
  return *this;
}

ItemLock::~ItemLock() {
  if (m_fd >= 0) ::close(m_fd);
}

void ItemLock::inherit() const { ::fcntl(m_fd, F_SETFD, 0); }

}  // namespace recoil::cli
