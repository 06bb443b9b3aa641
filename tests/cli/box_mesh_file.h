#pragma once
// Writes small box meshes as OFF files for the command-line tests: a tall thin
// box modelled Z-up or Y-up, and a box with its top face left out (an open mesh).
#include <Eigen/Core>
#include <filesystem>
#include <fstream>
#include <functional>

namespace recoil::test {

// The box [lo, hi] as 12 outward-wound triangles, each vertex passed through
// `map` first (identity when empty); `skip_top` leaves out the two triangles
// of the z = hi.z face. Returns `path`.
inline std::filesystem::path write_box_off(const std::filesystem::path& path, const Eigen::Vector3d& lo,
                                           const Eigen::Vector3d& hi, bool skip_top = false,
                                           const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& map = {}) {
  // Corner c: bit 0 -> x = hi, bit 1 -> y = hi, bit 2 -> z = hi.
  constexpr int kBoxFaces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  std::ofstream out(path);
  out.precision(17);
  out << "OFF\n8 " << (skip_top ? 10 : 12) << " 0\n";
  for (int c = 0; c < 8; ++c) {
    Eigen::Vector3d p((c & 1) ? hi.x() : lo.x(), (c & 2) ? hi.y() : lo.y(), (c & 4) ? hi.z() : lo.z());
    if (map) p = map(p);
    out << p.x() << " " << p.y() << " " << p.z() << "\n";
  }
  for (int f = 0; f < 12; ++f) {
    if (skip_top && (f == 2 || f == 3)) continue;
    out << "3 " << kBoxFaces[f][0] << " " << kBoxFaces[f][1] << " " << kBoxFaces[f][2] << "\n";
  }
  return path;
}

}  // namespace recoil::test
