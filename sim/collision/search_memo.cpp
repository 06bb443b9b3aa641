#include "sim/collision/search_memo.h"

#include <algorithm>

namespace recoil::sim {
namespace {

bool same(const CollisionSurface& a, const CollisionSurface& b) {
  return a.body == b.body && a.kind == b.kind && a.self_contact == b.self_contact && a.rest == b.rest &&
         a.x0.rows() == b.x0.rows() && a.x1.rows() == b.x1.rows() && a.triangles.rows() == b.triangles.rows() &&
         a.x0 == b.x0 && a.x1 == b.x1 && a.triangles == b.triangles;
}

bool same(const CollisionPlane& a, const CollisionPlane& b) {
  return a.body == b.body && a.point == b.point && a.normal == b.normal;
}

template <typename T>
bool same(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](const T& x, const T& y) { return same(x, y); });
}

}  // namespace

const std::vector<ContactCandidate>* SearchMemo::find(const std::vector<CollisionSurface>& surfaces,
                                                      const std::vector<CollisionPlane>& planes) const {
  for (const Entry& entry : m_entries)
    if (entry.filled && same(entry.planes, planes) && same(entry.surfaces, surfaces)) return &entry.candidates;
  return nullptr;
}

void SearchMemo::remember(const std::vector<CollisionSurface>& surfaces, const std::vector<CollisionPlane>& planes,
                          const std::vector<ContactCandidate>& candidates) {
  Entry& entry = m_entries[m_older];
  entry.filled = true;
  entry.surfaces = surfaces;
  entry.planes = planes;
  entry.candidates = candidates;
  m_older = 1 - m_older;
}

}  // namespace recoil::sim
