#pragma once
// Writes a dense sphere as a binary STL for the command-line tests that need
// a mesh large enough to cost memory and reading time (a scan, as users bring).
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace recoil::test {

// A UV sphere of radius `radius` (m) with `rows` rows of 2 `rows` quads:
// 4 rows^2 triangles, wound outwards. Returns `path`.
inline std::filesystem::path write_sphere_stl(const std::filesystem::path& path, int rows, double radius = 0.15) {
  auto point = [&](int i, int j) {
    const double theta = M_PI * i / rows, phi = M_PI * j / rows;
    return Eigen::Vector3f(static_cast<float>(radius * std::sin(theta) * std::cos(phi)),
                           static_cast<float>(radius * std::cos(theta)),
                           static_cast<float>(radius * std::sin(theta) * std::sin(phi)));
  };
  std::ofstream out(path, std::ios::binary);
  const std::string header(80, '\0');
  out.write(header.data(), 80);
  const std::uint32_t count = 4u * static_cast<std::uint32_t>(rows * rows);
  out.write(reinterpret_cast<const char*>(&count), 4);
  auto triangle = [&](const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c) {
    const float normal[3] = {0.0f, 0.0f, 0.0f};  // readers recompute it
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(normal), 12);
    for (const Eigen::Vector3f& p : {a, b, c}) out.write(reinterpret_cast<const char*>(p.data()), 12);
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  };
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < 2 * rows; ++j) {
      const Eigen::Vector3f a = point(i, j), b = point(i, j + 1), c = point(i + 1, j + 1), d = point(i + 1, j);
      triangle(a, c, b);
      triangle(a, d, c);
    }
  return path;
}

}  // namespace recoil::test
