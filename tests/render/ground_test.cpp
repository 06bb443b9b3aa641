// The floor's shadow cell: every floor point a sphere can shadow lies in it.
#include "render/ground.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace recoil::render {
namespace {

// Where the ray from `point` away from the light (along -to_light) meets y = height.
Eigen::Vector3d shadow_on_floor(const Eigen::Vector3d& point, const Eigen::Vector3d& to_light, double height) {
  return point - to_light * ((point.y() - height) / to_light.y());
}

TEST(GroundShadowCell, HoldsTheShadowOfEveryPointOfTheSphere) {
  const Eigen::Vector3d center(0.4, 0.7, -0.2);
  const double radius = 0.6, height = 0.1, reach = 0.01;
  for (double elevation : {10.0, 30.0, 45.0, 70.0, 89.0}) {
    for (double azimuth = 0.0; azimuth < 360.0; azimuth += 37.0) {
      const double el = elevation * std::numbers::pi / 180.0, az = azimuth * std::numbers::pi / 180.0;
      const Eigen::Vector3d to_light(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
      GroundLayout layout = ground_layout(center.x(), center.z(), radius, height);
      shadow_cell(layout, center, radius, to_light, reach);
      const double whole = (layout.cell_x1 - layout.cell_x0) * (layout.cell_z1 - layout.cell_z0);
      if (elevation >= 30.0) {
        EXPECT_LT(whole, 0.5 * std::pow(2.0 * layout.fade_end, 2)) << elevation << " " << azimuth;
      }
      // Points on the sphere's surface, and within `reach` of their shadow.
      for (double theta = 0.0; theta <= std::numbers::pi; theta += std::numbers::pi / 12) {
        for (double phi = 0.0; phi < 2.0 * std::numbers::pi; phi += std::numbers::pi / 12) {
          const Eigen::Vector3d on_sphere =
              center + radius * Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                std::sin(theta) * std::sin(phi));
          const Eigen::Vector3d hit = shadow_on_floor(on_sphere, to_light, height);
          const bool in_square = std::abs(hit.x() - center.x()) <= layout.fade_end &&
                                 std::abs(hit.z() - center.z()) <= layout.fade_end;
          if (!in_square) continue;  // beyond the floor: nothing to shade
          // The lookups' reach matters only where the cell ends inside the floor.
          const double x0 = center.x() - layout.fade_end, x1 = center.x() + layout.fade_end;
          const double z0 = center.z() - layout.fade_end, z1 = center.z() + layout.fade_end;
          EXPECT_GE(hit.x(), layout.cell_x0 == x0 ? x0 : layout.cell_x0 + reach) << elevation << " " << azimuth;
          EXPECT_LE(hit.x(), layout.cell_x1 == x1 ? x1 : layout.cell_x1 - reach) << elevation << " " << azimuth;
          EXPECT_GE(hit.z(), layout.cell_z0 == z0 ? z0 : layout.cell_z0 + reach) << elevation << " " << azimuth;
          EXPECT_LE(hit.z(), layout.cell_z1 == z1 ? z1 : layout.cell_z1 - reach) << elevation << " " << azimuth;
        }
      }
    }
  }
}

TEST(GroundShadowCell, AGrazingLightKeepsTheWholeFloor) {
  GroundLayout layout = ground_layout(0.0, 0.0, 1.0, 0.0);
  const GroundLayout whole = layout;
  shadow_cell(layout, Eigen::Vector3d(0.0, 1.0, 0.0), 1.0, Eigen::Vector3d(1.0, 0.0, 0.0), 0.0);
  EXPECT_EQ(layout.cell_x0, whole.cell_x0);
  EXPECT_EQ(layout.cell_x1, whole.cell_x1);
  EXPECT_EQ(layout.cell_z0, whole.cell_z0);
  EXPECT_EQ(layout.cell_z1, whole.cell_z1);
}

}  // namespace
}  // namespace recoil::render
