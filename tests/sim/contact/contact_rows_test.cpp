// Contact rows against finite differences of the gap and the tangential
// displacement (1e-5 relative), the right-hand sides, the
// tangent basis and the warm-start memory.
#include "sim/contact/contact_model.h"

#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "sim/collision/embree_scene.h"
#include "sim/contact/tangent_basis.h"
#include "sim/fem/deformable_body.h"
#include "sim/geometry/primitives.h"
#include "sim/rigid/rigid_body.h"

namespace recoil::sim {
namespace {

TEST(TangentBasis, IsOrthonormalRightHandedAndSmoothNearTheGroundNormal) {
  std::mt19937 rng(1);
  std::normal_distribution<double> g;
  double worst = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d n = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    const TangentBasis b = tangent_basis(n);
    Eigen::Matrix3d F;
    F << n, b.t1, b.t2;
    worst = std::max(worst, (F.transpose() * F - Eigen::Matrix3d::Identity()).norm());
    EXPECT_GT(F.determinant(), 0.0);
  }
  EXPECT_LT(worst, 1e-12);
  const TangentBasis up = tangent_basis(Eigen::Vector3d::UnitY());
  const TangentBasis tilted = tangent_basis(Eigen::Vector3d(1e-4, 1.0, -1e-4).normalized());
  EXPECT_LT((up.t1 - tilted.t1).norm() + (up.t2 - tilted.t2).norm(), 1e-3);
}

// A deformable box (two nodes pinned), a dynamic rigid box and a kinematic
// box, with hand-made candidates of every kind between them.
struct RowScene {
  EmbreeDevice device;
  DeformableBody soft;
  RigidBody rigid, kinematic;
  Eigen::VectorXd x, v;
  double h = 0.01;
  std::vector<ContactCandidate> candidates;

  RowScene() {
    DeformableBodyDesc d;
    d.mesh = make_box({0.2, 0.2, 0.2}, 2);
    d.resolution = 2;
    d.pinned = PinBox{{-1, 0.05, -1}, {1, 1, 1}};
    soft = build_deformable_body(d, device, "bodies/0", 0.002);
    RigidBodyDesc r;
    r.mesh = make_box({0.3, 0.1, 0.2}, 1);
    r.transform.position = {0.1, -0.2, 0.0};
    r.transform.rotation = {10, 20, 30};
    rigid = build_rigid_body(r, device, "rigid_bodies/0", 0.002);
    rigid.linear_node = soft.num_nodes;
    r.kind = BodyKind::kinematic;
    r.transform.position = {0.0, 0.3, 0.1};
    r.velocity = {0.3, -0.2, 0.1};
    r.angular_velocity = {1.0, 2.0, -0.5};
    kinematic = build_rigid_body(r, device, "rigid_bodies/1", 0.002);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int nodes = soft.num_nodes + 2;
    x = Eigen::VectorXd::Zero(3 * nodes);
    v = Eigen::VectorXd::Zero(3 * nodes);
    for (int n = 0; n < soft.num_nodes; ++n) {
      x.segment<3>(3 * n) = soft.rest.nodes.row(n).transpose() + 0.01 * Eigen::Vector3d(u(rng), u(rng), u(rng));
      if (!soft.pinned[static_cast<size_t>(n)]) v.segment<3>(3 * n) = Eigen::Vector3d(u(rng), u(rng), u(rng));
    }
    x.segment<3>(3 * rigid.linear_node) = rigid.pose.center;
    v.segment<3>(3 * rigid.linear_node) = Eigen::Vector3d(u(rng), u(rng), u(rng));
    v.segment<3>(3 * rigid.linear_node + 3) = 3.0 * Eigen::Vector3d(u(rng), u(rng), u(rng));

    auto cand = [&](ContactKind kind, int sa, int sb, int pa, int pb) {
      ContactCandidate c;
      c.kind = kind;
      c.surface_a = sa;
      c.surface_b = sb;
      c.primitive_a = pa;
      c.primitive_b = pb;
      c.normal = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
      return c;
    };
    // vertex (soft) - triangle (rigid)
    ContactCandidate vt = cand(ContactKind::vertex_triangle, 0, 1, 3, 2);
    vt.a = {1, {3, -1, -1}, {1.0, 0.0, 0.0}};
    const auto tri = rigid.triangles.row(2);
    vt.b = {3, {tri[0], tri[1], tri[2]}, {0.2, 0.3, 0.5}};
    candidates.push_back(vt);
    // vertex (rigid) - triangle (kinematic)
    ContactCandidate vk = cand(ContactKind::vertex_triangle, 1, 2, 5, 7);
    vk.a = {1, {5, -1, -1}, {1.0, 0.0, 0.0}};
    const auto tk = kinematic.triangles.row(7);
    vk.b = {3, {tk[0], tk[1], tk[2]}, {0.6, 0.3, 0.1}};
    candidates.push_back(vk);
    // edge (soft) - edge (rigid)
    ContactCandidate ee = cand(ContactKind::edge_edge, 0, 1, 4, 9);
    ee.a = {2, {soft.surface.triangles(4, 0), soft.surface.triangles(4, 1), -1}, {0.3, 0.7, 0.0}};
    ee.b = {2, {rigid.triangles(9, 1), rigid.triangles(9, 2), -1}, {0.55, 0.45, 0.0}};
    candidates.push_back(ee);
    // vertex (rigid) - plane, and soft self-contact vertex - triangle
    ContactCandidate vp = cand(ContactKind::vertex_plane, 1, 0, 2, 0);
    vp.a = {1, {2, -1, -1}, {1.0, 0.0, 0.0}};
    vp.plane_point = Eigen::Vector3d(0.0, -0.5, 0.0);
    candidates.push_back(vp);
    ContactCandidate self = cand(ContactKind::vertex_triangle, 0, 0, 0, 20);
    self.a = {1, {0, -1, -1}, {1.0, 0.0, 0.0}};
    const auto ts = soft.surface.triangles.row(20);
    self.b = {3, {ts[0], ts[1], ts[2]}, {0.1, 0.1, 0.8}};
    candidates.push_back(self);
  }

  ContactModel model() {
    std::vector<ContactSurface> s(3);
    s[0].kind = BodyKind::deformable;
    s[0].triangles = soft.surface.triangles;
    s[0].embedding = &soft.embedding;
    s[0].tets = &soft.rest.tets;
    s[0].pinned = &soft.pinned;
    s[0].mu_static = 0.8;
    s[1].kind = BodyKind::rigid;
    s[1].triangles = rigid.triangles;
    s[1].local = &rigid.local;
    s[1].pose = rigid.pose;
    s[1].linear_node = rigid.linear_node;
    s[1].mu_static = 0.2;
    s[2].kind = BodyKind::kinematic;
    s[2].triangles = kinematic.triangles;
    s[2].local = &kinematic.local;
    s[2].pose = kinematic.pose;
    s[2].velocity = kinematic.velocity;
    s[2].angular_velocity = kinematic.angular_velocity;
    ContactPlane plane;
    plane.plane.normal = Eigen::Vector3d(0.1, 1.0, 0.0).normalized();
    return ContactModel(std::move(s), {plane}, DofState{&x, &v, h}, 0.002, nullptr, ContactPolicy{});
  }
};

TEST(ContactRows, MatchFiniteDifferencesOfGapAndTangentialDisplacement) {
  RowScene scene;
  ContactModel model = scene.model();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd dv(scene.x.size());
  for (Eigen::Index i = 0; i < dv.size(); ++i) dv[i] = 0.5 * u(rng);
  for (int n = 0; n < scene.soft.num_nodes; ++n)
    if (scene.soft.pinned[static_cast<size_t>(n)]) dv.segment<3>(3 * n).setZero();
  ContactProblem problem;
  model.build(scene.candidates, dv, ContactMemory{}, problem);
  ASSERT_EQ(problem.rows.size(), scene.candidates.size());
  double worst = 0.0, worst_rhs = 0.0;
  const double eps = 1e-6;
  for (int k = 0; k < model.num_contacts(); ++k) {
    const ContactRows& rows = problem.rows[static_cast<size_t>(k)];
    ASSERT_TRUE(std::is_sorted(rows.nodes.begin(), rows.nodes.end()));
    for (int node : rows.nodes) {
      if (node < scene.soft.num_nodes) {
        EXPECT_FALSE(scene.soft.pinned[static_cast<size_t>(node)]);
      }
    }
    const TangentBasis t = tangent_basis(model.normal(k));
    Eigen::Vector3d jdv = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < rows.nodes.size(); ++i) jdv += rows.blocks[i] * dv.segment<3>(3 * rows.nodes[i]);
    // Right-hand sides make the rows exact at x*.
    const Eigen::Vector3d d = model.displacement(k, dv);
    const double g = model.gap(k, dv);
    worst_rhs = std::max({worst_rhs, std::abs(rows.rhs_normal - (jdv[0] - g / scene.h)),
                          std::abs(rows.rhs_tangent[0] - (jdv[1] - t.t1.dot(d) / scene.h)),
                          std::abs(rows.rhs_tangent[1] - (jdv[2] - t.t2.dot(d) / scene.h))});
    for (int trial = 0; trial < 4; ++trial) {
      Eigen::VectorXd e(dv.size());
      for (Eigen::Index i = 0; i < e.size(); ++i) e[i] = u(rng);
      for (int n = 0; n < scene.soft.num_nodes; ++n)
        if (scene.soft.pinned[static_cast<size_t>(n)]) e.segment<3>(3 * n).setZero();
      Eigen::Vector3d analytic = Eigen::Vector3d::Zero();
      for (size_t i = 0; i < rows.nodes.size(); ++i) analytic += scene.h * rows.blocks[i] * e.segment<3>(3 * rows.nodes[i]);
      const Eigen::Vector3d dp = model.displacement(k, dv + eps * e), dm = model.displacement(k, dv - eps * e);
      const Eigen::Vector3d fd((model.gap(k, dv + eps * e) - model.gap(k, dv - eps * e)) / (2 * eps),
                               t.t1.dot(dp - dm) / (2 * eps), t.t2.dot(dp - dm) / (2 * eps));
      worst = std::max(worst, (fd - analytic).norm() / std::max(analytic.norm(), 1e-12));
    }
    // Geometric means: soft 0.8, rigid 0.2, kinematic and plane 0.5 (defaults).
    const double expected_mu[] = {std::sqrt(0.8 * 0.2), std::sqrt(0.2 * 0.5), std::sqrt(0.8 * 0.2), std::sqrt(0.2 * 0.5), 0.8};
    EXPECT_NEAR(rows.mu_static, expected_mu[k], 1e-15);
  }
  std::cout << "contact rows vs finite differences: worst relative error " << worst << ", rhs error " << worst_rhs
            << " m/s\n";
  EXPECT_LT(worst, 1e-5);
  EXPECT_LT(worst_rhs, 1e-9);
}

TEST(ContactRows, RelinearizeKeepsWeightsAndReexpressesFriction) {
  RowScene scene;
  ContactModel model = scene.model();
  ContactProblem problem;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(scene.x.size());
  model.build(scene.candidates, zero, ContactMemory{}, problem);
  // A sticking impulse in world space must survive the basis change.
  problem.states[1].mode = ContactMode::sticking;
  problem.states[1].gamma = Eigen::Vector2d(0.3, -0.4);
  const Eigen::Vector3d normal_before = model.normal(1);
  const TangentBasis before = tangent_basis(normal_before);
  const Eigen::Vector3d world_gamma = 0.3 * before.t1 - 0.4 * before.t2;
  Eigen::VectorXd dv = zero;
  dv.segment<3>(3 * scene.rigid.linear_node + 3) = Eigen::Vector3d(5.0, -3.0, 2.0);  // spin the rigid body
  const double change = model.relinearize(dv, problem);
  const TangentBasis after = tangent_basis(model.normal(1));
  const Eigen::Vector3d world_after = problem.states[1].gamma[0] * after.t1 + problem.states[1].gamma[1] * after.t2;
  std::cout << "relinearize: largest rhs change " << change << " m/s, normal turned by "
            << std::acos(std::min(1.0, normal_before.dot(model.normal(1)))) << " rad\n";
  EXPECT_GT(change, 0.0);
  // Tangential part of the impulse is kept (what is lost is its component along the new normal).
  const Eigen::Vector3d n = model.normal(1);
  EXPECT_LT((world_after - (world_gamma - n * n.dot(world_gamma))).norm(), 1e-12);
  // The rows are exact at the new linearisation point.
  Eigen::Vector3d jdv = Eigen::Vector3d::Zero();
  const ContactRows& rows = problem.rows[1];
  for (size_t i = 0; i < rows.nodes.size(); ++i) jdv += rows.blocks[i] * dv.segment<3>(3 * rows.nodes[i]);
  EXPECT_NEAR(rows.rhs_normal, jdv[0] - model.gap(1, dv) / scene.h, 1e-9);
}

TEST(ContactMemory, RecallsStateInANewBasis) {
  ContactMemory memory;
  ContactMemory::Entry e;
  e.state.mode = ContactMode::sliding;
  e.state.lambda = 2.0;
  e.state.slip = Eigen::Vector2d(1.0, 0.0);
  e.t1 = Eigen::Vector3d::UnitX();
  e.t2 = Eigen::Vector3d::UnitZ();
  memory.store({2, 0, 0, 5, 0}, e);
  const ContactState s = memory.recall({2, 0, 0, 5, 0}, Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitX());
  EXPECT_EQ(s.mode, ContactMode::sliding);
  EXPECT_EQ(s.lambda, 2.0);
  EXPECT_LT((s.slip - Eigen::Vector2d(0.0, -1.0)).norm(), 1e-15);
  EXPECT_EQ(memory.recall({2, 0, 0, 6, 0}, e.t1, e.t2).mode, ContactMode::inactive);
}

}  // namespace
}  // namespace recoil::sim
