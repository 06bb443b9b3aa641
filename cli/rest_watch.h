#pragma once
// When settling may stop: every dynamic body at rest, meaning its kinetic
// energy is that of its whole mass moving slower than kRestSpeed, and has
// stayed so for kRestHold (a body released at rest on an edge starts at zero
// speed and needs time to tip).
#include <vector>

#include "sim/world.h"

namespace recoil::cli {

inline constexpr double kRestSpeed = 1e-3;  // m/s, root-mean-square over the body's mass
inline constexpr double kRestHold = 0.5;    // s

// sqrt(2 E_kin / m), m/s: the speed of the body's mass on average, rotation included.
double rms_speed(const sim::BodyStats& body);

class RestWatch {
 public:
  explicit RestWatch(double dt);
  // Call after each step with the world's stats; true once every body has
  // been at rest for kRestHold (at once for a world without dynamic bodies).
  bool update(const std::vector<sim::BodyStats>& bodies);

 private:
  long m_needed;    // steps of kRestHold
  long m_held = 0;  // consecutive steps at rest so far
};

}  // namespace recoil::cli
