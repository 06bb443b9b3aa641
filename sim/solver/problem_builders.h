#pragma once
// Contact problems built from a handful of parameters, shared by the solver
// tests and benchmarks (Box2D style scene builders): random dense SPD
// systems for brute-force comparisons, a single particle on a tilted plane,
// and a spring lattice resting on the ground for convergence and timing.
#include <Eigen/Core>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include "sim/solver/contact_problem.h"

namespace recoil::sim {

// Owns the matrix that problem.A points to (movable: the pointer stays valid).
struct OwnedProblem {
  std::unique_ptr<BlockSparseMatrix> A;
  ContactProblem problem;
};

// A = M + h^2 K of point masses joined by isotropic springs: `masses` (kg,
// one per node) on the diagonal blocks, and h^2 k (N s^2/m) stamped for
// each spring (a, b) into blocks (a,a), (b,b), (a,b), (b,a).
std::unique_ptr<BlockSparseMatrix> mass_spring_matrix(const std::vector<double>& masses,
                                                      const std::vector<std::pair<int, int>>& springs,
                                                      double h2_stiffness);

// A random SPD A of `nodes` 3x3 block rows (every block present, diagonal
// dominance controlled by `shift`), a random b, and no contacts.
OwnedProblem random_system(int nodes, double shift, std::mt19937& rng);

// A contact row block for one node: normal `n`, tangents completing an
// orthonormal basis (rows of the returned 3x3), scaled by `weight`.
Eigen::Matrix3d contact_frame(const Eigen::Vector3d& normal, double weight = 1.0);

// Appends a contact on `nodes` with per-node weights and the given normal.
void add_contact(ContactProblem& problem, const std::vector<int>& nodes, const std::vector<double>& weights,
                 const Eigen::Vector3d& normal, double rhs_normal, double mu_static, double mu_kinetic);

// A particle of mass `mass` (kg, A = m I) on a plane tilted by `theta`
// (rad) about the x axis: normal (0, -sin, cos), t1 = (0, cos, sin) up the
// slope, t2 = x across it. Gravity g (m/s^2, along -z) over a step h (s)
// gives b = h m g. The particle touches the plane (rhs_normal = 0) and
// moves with tangential velocity v_t (m/s, in (t1, t2)) at the start of the
// step, so rhs_tangent = -v_t: the rows then read the end-of-step velocity.
OwnedProblem particle_on_incline(double mass, double theta, double g, double h, const Eigen::Vector2d& v_t,
                                 double mu_static, double mu_kinetic);

// A nx by ny by nz lattice of nodes (spacing 1, masses drawn from
// [mass, mass * mass_ratio] log-uniformly), neighbours joined by isotropic
// springs of stiffness h^2 k (A = M + h^2 K), gravity over a step h; the
// bottom layer touches a ground plane (one contact per node, friction mu)
// while drifting sideways at `drift` m/s.
OwnedProblem lattice_on_ground(int nx, int ny, int nz, double mass, double mass_ratio, double stiffness, double h,
                               double mu, double drift, std::mt19937& rng);

// A rigid box (full size `size`, mass `mass`, uniform density) standing on
// the ground z = 0 on its four bottom corners, turned by `yaw` (rad) about
// z so that its world inertia tensor is not diagonal. DoF: node 0 the
// linear velocity (A block m I), node 1 the angular velocity (A block the
// world inertia tensor). Contact k at corner r_k (from the centre of mass)
// reads the corner velocity v + w x r_k = v - [r_k]_x w, so its blocks are
// F and -F [r_k]_x with F the ground frame. 12 rows on 6 DoF: B is
// singular, but consistent. The box moves with velocity `velocity` (m/s,
// horizontal) at the start of the step; gravity g over a step h.
OwnedProblem rigid_box_on_ground(const Eigen::Vector3d& size, double mass, double yaw, double g, double h,
                                 const Eigen::Vector3d& velocity, double mu_static, double mu_kinetic);

}  // namespace recoil::sim
