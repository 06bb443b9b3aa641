#include "cli/rest_watch.h"

#include <algorithm>
#include <cmath>

namespace recoil::cli {

double rms_speed(const sim::BodyStats& body) {
  return body.mass > 0.0 ? std::sqrt(2.0 * body.kinetic_energy / body.mass) : 0.0;
}

RestWatch::RestWatch(double dt) : m_needed(std::max(1L, std::lround(kRestHold / dt))) {}

bool RestWatch::update(const std::vector<sim::BodyStats>& bodies) {
  if (bodies.empty()) return true;
  const bool resting =
      std::all_of(bodies.begin(), bodies.end(), [](const sim::BodyStats& b) { return rms_speed(b) < kRestSpeed; });
  m_held = resting ? m_held + 1 : 0;
  return m_held >= m_needed;
}

}  // namespace recoil::cli
