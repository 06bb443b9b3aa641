#include "sim/geometry/surface_look.h"

#include <algorithm>
#include <cstring>

#include "core/check.h"

namespace recoil::sim {

bool SurfaceLook::draws_anything() const {
  return !corner_color.empty() ||
         std::any_of(materials.begin(), materials.end(), [](const LookMaterial& m) { return m.has_color || m.texture; });
}

SurfaceLook select_triangles(const SurfaceLook& look, const std::vector<int>& kept) {
  SurfaceLook out;
  out.materials = look.materials;
  out.warnings = look.warnings;
  out.triangle_material.reserve(kept.size());
  for (int f : kept) out.triangle_material.push_back(look.triangle_material[static_cast<size_t>(f)]);
  auto gather = [&](const std::vector<float>& from, size_t per_triangle, std::vector<float>& to) {
    if (from.empty()) return;
    to.reserve(kept.size() * per_triangle);
    for (int f : kept) {
      const auto first = from.begin() + static_cast<std::ptrdiff_t>(per_triangle * static_cast<size_t>(f));
      to.insert(to.end(), first, first + static_cast<std::ptrdiff_t>(per_triangle));
    }
  };
  gather(look.corner_uv, 6, out.corner_uv);
  gather(look.corner_color, 9, out.corner_color);
  return out;
}

SurfaceLook with_swapped_corners(const SurfaceLook& look) {
  SurfaceLook out = look;
  auto swap_corners = [](std::vector<float>& values, size_t per_corner) {
    for (size_t f = 0; f + 3 * per_corner <= values.size(); f += 3 * per_corner)
      std::swap_ranges(values.begin() + static_cast<std::ptrdiff_t>(f + per_corner),
                       values.begin() + static_cast<std::ptrdiff_t>(f + 2 * per_corner),
                       values.begin() + static_cast<std::ptrdiff_t>(f + 2 * per_corner));
  };
  swap_corners(out.corner_uv, 2);
  swap_corners(out.corner_color, 3);
  return out;
}

}  // namespace recoil::sim

namespace recoil::sim {
namespace {

template <typename T>
void put(std::string& bytes, const T& value) {
  bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <typename T>
void put_array(std::string& bytes, const std::vector<T>& values) {
  put(bytes, static_cast<std::int64_t>(values.size()));
  if (!values.empty()) bytes.append(reinterpret_cast<const char*>(values.data()), sizeof(T) * values.size());
}

class Reader {
 public:
  Reader(const std::string& bytes, size_t& offset) : m_bytes(bytes), m_offset(offset) {}
  template <typename T>
  T get() {
    T value{};
    take(&value, sizeof value);
    return value;
  }
  template <typename T>
  std::vector<T> get_array() {
    const auto count = get<std::int64_t>();
    RECOIL_CHECK(count >= 0 && static_cast<size_t>(count) <= (m_bytes.size() - m_offset) / sizeof(T),
                 "look array of " << count << " items past the end");
    std::vector<T> values(static_cast<size_t>(count));
    take(values.data(), sizeof(T) * values.size());
    return values;
  }

 private:
  void take(void* to, size_t size) {
    RECOIL_CHECK(size <= m_bytes.size() - m_offset, "look bytes end early");
    if (size > 0) std::memcpy(to, m_bytes.data() + m_offset, size);
    m_offset += size;
  }
  const std::string& m_bytes;
  size_t& m_offset;
};

void put_string(std::string& bytes, const std::string& text) { put_array(bytes, std::vector<char>(text.begin(), text.end())); }

std::string get_string(Reader& in) {
  const std::vector<char> chars = in.get_array<char>();
  return {chars.begin(), chars.end()};
}

}  // namespace

void encode_look(const SurfaceLook& look, std::string& bytes) {
  put(bytes, static_cast<std::int64_t>(look.materials.size()));
  for (const LookMaterial& m : look.materials) {
    put_string(bytes, m.name);
    put(bytes, static_cast<std::uint8_t>(m.has_color));
    put(bytes, m.color);
    put(bytes, static_cast<std::uint8_t>(m.texture != nullptr));
    if (!m.texture) continue;
    put(bytes, m.texture->width);
    put(bytes, m.texture->height);
    put_array(bytes, m.texture->rgba);
  }
  put_array(bytes, look.triangle_material);
  put_array(bytes, look.corner_uv);
  put_array(bytes, look.corner_color);
  put(bytes, static_cast<std::int64_t>(look.warnings.size()));
  for (const std::string& w : look.warnings) put_string(bytes, w);
}

SurfaceLook decode_look(const std::string& bytes, size_t& offset) {
  Reader in(bytes, offset);
  SurfaceLook look;
  const auto materials = in.get<std::int64_t>();
  RECOIL_CHECK(materials >= 0 && static_cast<size_t>(materials) <= bytes.size(), "materials " << materials);
  for (std::int64_t i = 0; i < materials; ++i) {
    LookMaterial m;
    m.name = get_string(in);
    m.has_color = in.get<std::uint8_t>() != 0;
    m.color = in.get<std::array<float, 3>>();
    if (in.get<std::uint8_t>() != 0) {
      auto image = std::make_shared<LookImage>();
      image->width = in.get<int>();
      image->height = in.get<int>();
      image->rgba = in.get_array<std::uint8_t>();
      RECOIL_CHECK(image->width > 0 && image->height > 0 &&
                       image->rgba.size() == static_cast<size_t>(image->width) * static_cast<size_t>(image->height) * 4,
                   "texture " << image->width << " x " << image->height << " in " << image->rgba.size() << " bytes");
      m.texture = std::move(image);
    }
    look.materials.push_back(std::move(m));
  }
  look.triangle_material = in.get_array<std::int32_t>();
  look.corner_uv = in.get_array<float>();
  look.corner_color = in.get_array<float>();
  const auto warnings = in.get<std::int64_t>();
  RECOIL_CHECK(warnings >= 0 && static_cast<size_t>(warnings) <= bytes.size(), "warnings " << warnings);
  for (std::int64_t i = 0; i < warnings; ++i) look.warnings.push_back(get_string(in));
  const size_t triangles = look.triangle_material.size();
  RECOIL_CHECK((look.corner_uv.empty() || look.corner_uv.size() == 6 * triangles) &&
                   (look.corner_color.empty() || look.corner_color.size() == 9 * triangles),
               "look arrays do not match " << triangles << " triangles");
  for (std::int32_t m : look.triangle_material)
    RECOIL_CHECK(m >= 0 && static_cast<size_t>(m) < look.materials.size(), "material index " << m);
  return look;
}

}  // namespace recoil::sim
