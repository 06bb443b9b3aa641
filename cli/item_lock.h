#pragma once
// An exclusive claim on one batch item: an flock on OUT/.recoil-locks/NAME,
// held by the batch and inherited by the item process it starts. An item
// orphaned by a killed batch keeps the claim until it has stopped writing, so
// a rerun never clears a folder still in use, and two batches (two shards
// given the same items) never run one item at once.
#include <filesystem>
#include <optional>
#include <string>

namespace recoil::cli {

class ItemLock {
 public:
  // The claim, or nothing when another process holds it. Throws output_error
  // when the lock file cannot be opened.
  static std::optional<ItemLock> try_take(const std::filesystem::path& output, const std::string& name);
  ItemLock(ItemLock&& other) noexcept;
  ItemLock& operator=(ItemLock&& other) noexcept;
  ItemLock(const ItemLock&) = delete;
  ItemLock& operator=(const ItemLock&) = delete;
  ~ItemLock();

  // In a forked child before exec: keep the descriptor open across exec, so
  // the item process holds the claim as long as it runs.
  void inherit() const;

 private:
  explicit ItemLock(int fd) : m_fd(fd) {}
  int m_fd = -1;
};

}  // namespace recoil::cli
