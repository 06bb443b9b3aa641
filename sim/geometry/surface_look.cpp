#include "sim/geometry/surface_look.h"

#include <algorithm>

#include "core/byte_stream.h"
#include "core/check.h"
#include "core/utf8.h"

namespace recoil::sim {

bool SurfaceLook::draws_anything() const {
  return !corner_color.empty() ||
         std::any_of(materials.begin(), materials.end(), [](const LookMaterial& m) { return m.has_color || m.texture || m.has_surface; });
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

void encode_look(const SurfaceLook& look, std::string& bytes) {
  put_value(bytes, static_cast<std::int64_t>(look.materials.size()));
  for (const LookMaterial& m : look.materials) {
    put_string(bytes, m.name);
    put_value(bytes, std::array<std::uint8_t, 4>{m.has_color, m.has_uvs, m.vertex_colored, m.has_surface});
    put_value(bytes, m.color);
    put_value(bytes, std::array<float, 2>{m.metallic, m.roughness});
  }
  put_array(bytes, look.triangle_material);
  put_array(bytes, look.corner_uv);
  put_array(bytes, look.corner_color);
  put_value(bytes, static_cast<std::int64_t>(look.warnings.size()));
  for (const std::string& w : look.warnings) put_string(bytes, w);
}

SurfaceLook decode_look(const std::string& bytes, size_t& offset) {
  ByteReader in(bytes, offset);
  SurfaceLook look;
  look.materials.resize(in.count(1));
  for (LookMaterial& m : look.materials) {
    m.name = in.string();
    const auto flags = in.value<std::array<std::uint8_t, 4>>();
    m.has_color = flags[0] != 0;
    m.has_uvs = flags[1] != 0;
    m.vertex_colored = flags[2] != 0;
    m.has_surface = flags[3] != 0;
    m.color = in.value<std::array<float, 3>>();
    const auto surface = in.value<std::array<float, 2>>();
    m.metallic = surface[0];
    m.roughness = surface[1];
  }
  look.triangle_material = in.array<std::int32_t>();
  look.corner_uv = in.array<float>();
  look.corner_color = in.array<float>();
  look.warnings.resize(in.count(1));
  for (std::string& w : look.warnings) w = in.string();
  offset = in.offset();
  const size_t triangles = look.triangle_material.size();
  RECOIL_CHECK((look.corner_uv.empty() || look.corner_uv.size() == 6 * triangles) &&
                   (look.corner_color.empty() || look.corner_color.size() == 9 * triangles),
               "look arrays do not match " << triangles << " triangles");
  for (std::int32_t m : look.triangle_material)
    RECOIL_CHECK(m >= 0 && static_cast<size_t>(m) < look.materials.size(), "material index " << m);
  return look;
}

std::string printable(const std::string& text, size_t limit) {
  std::string out;
  for (size_t i = 0; i < text.size();) {
    if (out.size() >= limit) return out + "...";
    const auto byte = static_cast<unsigned char>(text[i]);
    // A well-formed UTF-8 sequence is kept; a control character or a malformed byte is not.
    const size_t length = utf8_sequence_length(std::string_view(text).substr(i));
    if (length == 0 || byte < 0x20 || byte == 0x7f) {
      out.push_back('?');
      ++i;
      continue;
    }
    out.append(text, i, length);
    i += length;
  }
  return out;
}

}  // namespace recoil::sim
