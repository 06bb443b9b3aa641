#pragma once
// Plain values and arrays appended to a byte string and read back in the same
// order, for answers a child process hands its parent (same build, same
// machine, so no byte-order or layout concerns). Reading past the end or an
// impossible count is a bug in the writer: RECOIL_CHECK aborts.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "core/check.h"

namespace recoil {

template <typename T>
void put_value(std::string& bytes, const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// A count (int64) then the items.
template <typename T>
void put_array(std::string& bytes, const T* items, size_t count) {
  put_value(bytes, static_cast<std::int64_t>(count));
  if (count > 0) bytes.append(reinterpret_cast<const char*>(items), sizeof(T) * count);
}

template <typename T>
void put_array(std::string& bytes, const std::vector<T>& items) {
  put_array(bytes, items.data(), items.size());
}

inline void put_string(std::string& bytes, const std::string& text) { put_array(bytes, text.data(), text.size()); }

class ByteReader {
 public:
  explicit ByteReader(const std::string& bytes, size_t offset = 0) : m_bytes(bytes), m_offset(offset) {}

  template <typename T>
  T value() {
    static_assert(std::is_trivially_copyable_v<T>);
    T out{};
    take(&out, sizeof out);
    return out;
  }
  // The count of an array, checked against the bytes left for items of `item_size`.
  size_t count(size_t item_size) {
    const auto n = value<std::int64_t>();
    RECOIL_CHECK(n >= 0 && static_cast<std::uint64_t>(n) <= left() / std::max<size_t>(item_size, 1),
                 "array of " << n << " items of " << item_size << " bytes with " << left() << " bytes left");
    return static_cast<size_t>(n);
  }
  template <typename T>
  void items(T* out, size_t count) { take(out, sizeof(T) * count); }
  template <typename T>
  std::vector<T> array() {
    std::vector<T> out(count(sizeof(T)));
    items(out.data(), out.size());
    return out;
  }
  std::string string() {
    std::string out(count(1), '\0');
    items(out.data(), out.size());
    return out;
  }
  size_t offset() const { return m_offset; }
  size_t left() const { return m_bytes.size() - m_offset; }

 private:
  void take(void* to, size_t size) {
    RECOIL_CHECK(size <= left(), "reading " << size << " bytes with " << left() << " left");
    if (size > 0) std::memcpy(to, m_bytes.data() + m_offset, size);
    m_offset += size;
  }
  const std::string& m_bytes;
  size_t m_offset;
};

}  // namespace recoil
