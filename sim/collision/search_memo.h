#pragma once
// SearchMemo: the candidates of the last two collision searches, by their
// exact input. The search is a pure function of the surfaces and planes it
// is given, and bodies at rest give it the same input step after step (a
// stack standing still offers the step's own search one input and the
// search after its solve another), so such a search is answered again, bit
// for bit what running it would give, instead of being run.
#include <array>
#include <vector>

#include "sim/collision/collision_types.h"

namespace recoil::sim {

class SearchMemo {
 public:
  // The candidates remembered for exactly this input, or null.
  const std::vector<ContactCandidate>* find(const std::vector<CollisionSurface>& surfaces,
                                            const std::vector<CollisionPlane>& planes) const;
  // Remembers `candidates` for this input in place of the older of the two.
  void remember(const std::vector<CollisionSurface>& surfaces, const std::vector<CollisionPlane>& planes,
                const std::vector<ContactCandidate>& candidates);

 private:
  struct Entry {
    bool filled = false;
    // Copies; `rest` is compared by address, as the detector's rest
    // clearance is keyed: a rest shape must not change in place.
    std::vector<CollisionSurface> surfaces;
    std::vector<CollisionPlane> planes;
    std::vector<ContactCandidate> candidates;
  };
  std::array<Entry, 2> m_entries;
  std::size_t m_older = 0;
};

}  // namespace recoil::sim
