// The floor's middle cell: every floor point a sphere can shadow lies in the
// shadow's reach, every point near the sphere in the near reach, and the cell
// stays inside the floor.
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

bool holds(const FloorRect& rect, double x, double z, double margin) {
  return x >= rect.x0 + margin && x <= rect.x1 - margin && z >= rect.z0 + margin && z <= rect.z1 - margin;
}

TEST(GroundCell, TheShadowReachHoldsTheShadowOfEveryPointOfTheSphere) {
  const Eigen::Vector3d center(0.4, 0.7, -0.2);
  const double radius = 0.6, height = 0.1, reach = 0.01;
  for (double elevation : {10.0, 30.0, 45.0, 70.0, 89.0}) {
    for (double azimuth = 0.0; azimuth < 360.0; azimuth += 37.0) {
      const double el = elevation * std::numbers::pi / 180.0, az = azimuth * std::numbers::pi / 180.0;
      const Eigen::Vector3d to_light(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
      const std::optional<FloorRect> rect = shadow_reach(height, center, radius, to_light, reach);
      ASSERT_TRUE(rect.has_value());
      for (double theta = 0.0; theta <= std::numbers::pi; theta += std::numbers::pi / 12) {
        for (double phi = 0.0; phi < 2.0 * std::numbers::pi; phi += std::numbers::pi / 12) {
          const Eigen::Vector3d on_sphere =
              center + radius * Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                std::sin(theta) * std::sin(phi));
          const Eigen::Vector3d hit = shadow_on_floor(on_sphere, to_light, height);
          EXPECT_TRUE(holds(*rect, hit.x(), hit.z(), reach)) << elevation << " " << azimuth;
        }
      }
    }
  }
}

TEST(GroundCell, AGrazingLightReachesTheWholeFloor) {
  EXPECT_FALSE(shadow_reach(0.0, Eigen::Vector3d(0.0, 1.0, 0.0), 1.0, Eigen::Vector3d(1.0, 0.0, 0.0), 0.0));
  EXPECT_FALSE(shadow_reach(0.0, Eigen::Vector3d(0.0, 1.0, 0.0), 1.0, Eigen::Vector3d(0.0, -1.0, 0.0), 0.0));
}

TEST(GroundCell, TheNearReachHoldsTheBoxSeenFromAboveAndTheCellStaysOnTheFloor) {
  const Eigen::Vector3d center(1.0, 0.5, -2.0);
  const Eigen::Vector3d half(0.5, 0.5, 0.3);
  const FloorRect near = near_reach(center - half, center + half, 0.1);
  EXPECT_TRUE(holds(near, 1.0 + 0.5, -2.0, 0.1 - 1e-12));
  EXPECT_TRUE(holds(near, 1.0, -2.0 - 0.3, 0.1 - 1e-12));
  EXPECT_FALSE(holds(near, 1.0 + 0.61, -2.0, 0.0));
  EXPECT_FALSE(holds(near, 1.0, -2.0 + 0.41, 0.0));

  GroundLayout layout = ground_layout(center.x(), center.z(), 0.5, 0.0);
  const FloorRect whole = layout.cell;
  EXPECT_EQ(whole, (FloorRect{1.0 - 3.0, 1.0 + 3.0, -2.0 - 3.0, -2.0 + 3.0}));
  set_cell(layout, near.united(FloorRect{-10.0, 0.0, -2.0, -1.0}));
  EXPECT_EQ(layout.cell, (FloorRect{whole.x0, near.x1, near.z0, -1.0}));
}

}  // namespace
}  // namespace recoil::render
