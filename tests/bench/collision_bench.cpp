// Candidate search cost per step against surface size (two subdivided spheres
// pressed together), and the Embree detector against the brute-force oracle.
#include <deque>
#include <iostream>

#include "sim/collision/brute_force.h"
#include "sim/collision/collision_detector.h"
#include "tests/bench/bench.h"
#include "tests/sim/collision/collision_test_meshes.h"

namespace recoil::bench {
namespace {

using sim::CollisionSurface;

// Two unit spheres overlapping by 1 mm, closing at 0.5 mm per step, the left
// one deformable (self-contact on if asked, measured from its starting shape
// as its rest shape), the right one rigid.
std::vector<CollisionSurface> touching_spheres(int subdivisions_left, int subdivisions_right, bool self = true) {
  static std::deque<sim::Points> rest_shapes;  // stable addresses for CollisionSurface::rest
  sim::TriMesh left = sim::testing::icosphere(subdivisions_left);
  sim::TriMesh right = sim::testing::icosphere(subdivisions_right);
  right.vertices.col(0).array() += 2.0 - 0.001;
  std::vector<CollisionSurface> s;
  s.push_back(sim::testing::moving_surface(left, 0, sim::BodyKind::deformable, {0.00025, 0, 0}));
  s.back().self_contact = self;
  if (self) s.back().rest = &rest_shapes.emplace_back(s.back().x0);
  s.push_back(sim::testing::moving_surface(right, 1, sim::BodyKind::rigid, {-0.00025, 0, 0}));
  return s;
}

void advance(std::vector<CollisionSurface>& surfaces) {
  for (CollisionSurface& s : surfaces) {
    const sim::Points step = s.x1 - s.x0;
    s.x0 = s.x1;
    s.x1 += step;
  }
}

// The next three steps of `surfaces`: timed in turn, none is one of the
// detector's last two inputs, so its memo (search_memo.h) never answers and
// every call searches, as in a simulation whose bodies move.
std::vector<std::vector<CollisionSurface>> next_steps(std::vector<CollisionSurface> surfaces) {
  std::vector<std::vector<CollisionSurface>> steps;
  for (int i = 0; i < 3; ++i) {
    advance(surfaces);
    steps.push_back(surfaces);
  }
  return steps;
}

void bench_scaling() {
  BenchTable table("collision candidates per step, two touching spheres (margin 2 mm)",
                   {"triangles", "self", "threads", "first call ms", "step ms", "candidates", "vt pairs offered",
                    "ee pairs offered"});
  // Subdivisions left/right, threads, self-contact on the left sphere.
  const std::vector<std::array<int, 4>> cases = {{2, 2, 1, 1}, {3, 3, 1, 1}, {4, 4, 1, 1}, {5, 5, 1, 1},
                                                 {6, 6, 1, 1}, {6, 6, 2, 1}, {6, 6, 1, 0}, {7, 7, 1, 1},
                                                 {7, 7, 2, 1}, {7, 7, 1, 0}, {8, 4, 1, 0}};
  for (const auto& [sl, sr, threads, self] : cases) {
    std::vector<CollisionSurface> surfaces = touching_spheres(sl, sr, self != 0);
    const long long triangles = surfaces[0].triangles.rows() + surfaces[1].triangles.rows();
    sim::CollisionDetector detector({0.002, threads});
    size_t count = 0;
    const double first = best_ms(1, [&] { count = detector.detect(surfaces, {}).size(); });
    const std::vector<std::vector<CollisionSurface>> steps = next_steps(surfaces);
    size_t next = 0;
    const double step = best_ms(3, [&] { count = detector.detect(steps[next++ % steps.size()], {}).size(); });
    const sim::CollisionStats stats = detector.last_stats();
    table.add_row({std::to_string(triangles), self ? "yes" : "no", std::to_string(threads), fixed(first, 2), fixed(step, 2),
                   std::to_string(count), std::to_string(stats.vertex_triangle_pairs),
                   std::to_string(stats.edge_edge_pairs)});
  }
  table.print();
}

void bench_against_brute_force() {
  BenchTable table("Embree detector vs brute-force oracle (same candidates)",
                   {"triangles", "embree step ms", "brute force ms", "speed-up", "candidates", "same"});
  for (int s : {0, 1, 2, 3}) {
    std::vector<CollisionSurface> surfaces = touching_spheres(s, s);
    // Coarse spheres: a margin comparable to their facets, so there is work.
    const sim::CollisionSettings settings{0.02, 1};
    sim::CollisionDetector detector(settings);
    detector.detect(surfaces, {});
    const std::vector<std::vector<CollisionSurface>> steps = next_steps(surfaces);
    size_t next = 0;
    std::vector<sim::ContactCandidate> fast, slow;
    const double embree_ms = best_ms(3, [&] { fast = detector.detect(steps[next++ % steps.size()], {}); });
    const double brute_ms = best_ms(1, [&] { slow = sim::brute_force_candidates(steps.back(), {}, settings); });
    bool same = fast.size() == slow.size();
    for (size_t i = 0; same && i < fast.size(); ++i)
      same = !sim::candidate_less(fast[i], slow[i]) && !sim::candidate_less(slow[i], fast[i]) &&
             fast[i].gap == slow[i].gap;
    table.add_row({std::to_string(surfaces[0].triangles.rows() + surfaces[1].triangles.rows()), fixed(embree_ms, 3),
                   fixed(brute_ms, 3), fixed(brute_ms / std::max(embree_ms, 1e-9), 1), std::to_string(fast.size()),
                   same ? "yes" : "NO"});
  }
  table.print();
}

void bench_collision() {
  bench_against_brute_force();
  bench_scaling();
}

const Register registered_collision("collision", bench_collision);

}  // namespace
}  // namespace recoil::bench
