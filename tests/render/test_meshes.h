#pragma once
// Small procedural meshes for render tests and benches (header-only so the
// bench executable can use them too). render/ must not depend on sim/, and
// sim/geometry/primitives does not exist yet, so these are our own.
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <utility>

#include "render/render_scene.h"

namespace recoil::render::test {

// An axis-aligned box with the given full edge lengths centred on `center`,
// 4 vertices per face so each face shades flat. 24 vertices, 12 triangles.
inline RenderMesh make_box(std::array<float, 3> center, std::array<float, 3> size, Rgb color) {
  RenderMesh mesh;
  mesh.color = color;
  // Each face: outward axis, then two in-plane axes with u x v = outward.
  const int faces[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {1.0f, -1.0f}) {
      const int u = faces[axis][1], v = faces[axis][2];
      const auto base = static_cast<std::uint32_t>(mesh.positions.size() / 3);
      const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (const auto& c : corners) {
        std::array<float, 3> p{};
        p[static_cast<size_t>(axis)] = sign;
        // Mirror u on the negative face so the winding stays counter-clockwise outside.
        p[static_cast<size_t>(u)] = c[0] * sign;
        p[static_cast<size_t>(v)] = c[1];
        for (size_t k = 0; k < 3; ++k) mesh.positions.push_back(center[k] + 0.5f * size[k] * p[k]);
      }
      for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
    }
  }
  return mesh;
}

// A unit-normal icosphere: the icosahedron with each triangle split into 4,
// `levels` times (20 * 4^levels triangles), vertices shared between faces.
inline RenderMesh make_icosphere(std::array<float, 3> center, float radius, int levels, Rgb color) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<std::array<double, 3>> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                          {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                          {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::uint32_t, 3>> f = {
      {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  auto normalize = [](std::array<double, 3> p) {
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    return std::array<double, 3>{p[0] / n, p[1] / n, p[2] / n};
  };
  for (auto& p : v) p = normalize(p);
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = midpoints.find(key);
      if (it != midpoints.end()) return it->second;
      v.push_back(normalize({v[a][0] + v[b][0], v[a][1] + v[b][1], v[a][2] + v[b][2]}));
      const auto index = static_cast<std::uint32_t>(v.size() - 1);
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<std::array<std::uint32_t, 3>> finer;
    finer.reserve(f.size() * 4);
    for (const auto& tri : f) {
      const std::uint32_t ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]), ca = midpoint(tri[2], tri[0]);
      finer.push_back({tri[0], ab, ca});
      finer.push_back({tri[1], bc, ab});
      finer.push_back({tri[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    f = std::move(finer);
  }
  RenderMesh mesh;
  mesh.color = color;
  mesh.positions.reserve(v.size() * 3);
  for (const auto& p : v) {
    for (size_t k = 0; k < 3; ++k) mesh.positions.push_back(center[k] + radius * static_cast<float>(p[k]));
  }
  mesh.indices.reserve(f.size() * 3);
  for (const auto& tri : f) mesh.indices.insert(mesh.indices.end(), tri.begin(), tri.end());
  return mesh;
}

// A torus in the x-z plane (major radius R, tube radius r), `rings` x `sides`
// quads as 2 * rings * sides triangles.
inline RenderMesh make_torus(std::array<float, 3> center, float major, float minor, int rings, int sides, Rgb color) {
  RenderMesh mesh;
  mesh.color = color;
  mesh.positions.reserve(static_cast<size_t>(rings) * sides * 3);
  for (int i = 0; i < rings; ++i) {
    const double u = 2.0 * std::numbers::pi * i / rings;
    for (int j = 0; j < sides; ++j) {
      const double w = 2.0 * std::numbers::pi * j / sides;
      const double ring = major + minor * std::cos(w);
      mesh.positions.push_back(center[0] + static_cast<float>(ring * std::cos(u)));
      mesh.positions.push_back(center[1] + static_cast<float>(minor * std::sin(w)));
      mesh.positions.push_back(center[2] + static_cast<float>(ring * std::sin(u)));
    }
  }
  mesh.indices.reserve(static_cast<size_t>(rings) * sides * 6);
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      const auto a = static_cast<std::uint32_t>(i * sides + j);
      const auto b = static_cast<std::uint32_t>(((i + 1) % rings) * sides + j);
      const auto c = static_cast<std::uint32_t>(((i + 1) % rings) * sides + (j + 1) % sides);
      const auto d = static_cast<std::uint32_t>(i * sides + (j + 1) % sides);
      mesh.indices.insert(mesh.indices.end(), {a, d, c, a, c, b});
    }
  }
  return mesh;
}

// Box, sphere and a transparent torus on the grid floor: every feature at once.
inline RenderScene studio_scene() {
  RenderScene scene;
  scene.meshes.push_back(make_box({0.0f, 0.5f, 0.0f}, {1.0f, 1.0f, 1.0f}, {0.85f, 0.63f, 0.40f}));
  scene.meshes.push_back(make_icosphere({1.1f, 0.4f, 0.4f}, 0.4f, 2, {0.30f, 0.50f, 0.85f}));
  RenderMesh torus = make_torus({-1.0f, 0.15f, 0.6f}, 0.4f, 0.15f, 32, 12, {0.8f, 0.2f, 0.2f});
  torus.opacity = 0.5f;
  scene.meshes.push_back(torus);
  return scene;
}

}  // namespace recoil::render::test
