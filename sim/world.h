#pragma once
// sim::World: built once from a plain WorldDesc, then stepped. A step is a
// short list of timed stages: assemble -> collide -> solve
// -> integrate -> check health. Numerical trouble is reported in the
// StepReport, never thrown.
//
// DoF layout: one global vector of 3 entries per node for positions and
// velocities. Deformable bodies own node ranges first, in description order;
// then each dynamic rigid body owns two nodes: its linear and its angular
// velocity. A rigid body's pose lives in its RigidBody only (the position
// entries of its nodes are unused); positions() and set_state() give it as
// the centre of mass (m) and the rotation vector angle * axis (rad).
// Kinematic and fixed bodies and planes have no DoFs.
//
// Collide: every mesh body is a collision surface (deformable: the embedded
// surface; rigid, kinematic, fixed: the transformed mesh), moving from its
// positions at the start of the step to those predicted by the contact-free
// solve; planes are analytic. Solve: without candidates the contact-free
// solve stands; otherwise solve_contacts runs on the rows of sim/contact,
// warm-started from the last step's multipliers.
#include <Eigen/Core>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/body/body_kind.h"
#include "sim/contact/contact_model.h"
#include "sim/fem/block_sparse.h"
#include "sim/fem/deformable_body.h"
#include "sim/fem/pcg.h"
#include "sim/rigid/rigid_body.h"
#include "sim/world_desc.h"

namespace recoil::sim {

class EmbreeDevice;
class CollisionDetector;


// runaway: the contact search found more candidates than any physical
// contact state has (kMaxCandidatesPerVertex), so the step was not solved.
enum class StepStatus { ok, nan, inverted, energy_blowup, runaway };

// Candidates per collision-surface vertex beyond which a step's contact set
// is taken as runaway: a resting or sliding surface gives a few per vertex
// (its nearby triangles and edges), a body folding through itself hundreds.
inline constexpr long long kMaxCandidatesPerVertex = 32;
const char* to_string(StepStatus status);

// Wall-clock milliseconds per stage of the last step.
struct Profile {
  double assemble = 0.0;
  double collide = 0.0;    // candidate search, including mid-solve new-collision checks
  double solve = 0.0;      // linear solve or contact solve
  double integrate = 0.0;
  double health = 0.0;
  double total = 0.0;
};

struct StepReport {
  StepStatus status = StepStatus::ok;
  std::string body;            // the body the status is about (empty when ok)
  long step = 0;               // steps taken so far, this one included
  double time = 0.0;           // simulated seconds after this step
  int solver_iterations = 0;
  double solver_residual = 0.0;
  double solver_kkt = 0.0;     // contact stage: KKT residual of the returned solution, m/s (sim/solver/kkt_residual.h)
  bool solver_converged = true;
  int inverted_tets = 0;       // over all bodies
  // Contact stage (zero without candidates); stats.jsonl sums these per frame.
  int contacts = 0;            // constraint candidates given to the solver
  int active = 0, sticking = 0, sliding = 0;
  int solver_restarts = 0;
  // cr / cr_plain: Krylov solves started per cause and the iterations they took (ContactSolverStats).
  std::array<int, kKrylovStarts> krylov_starts{}, krylov_start_iterations{};
  double max_penetration = 0.0;  // m, largest over contacts after the step (>= 0)
  Profile profile;
};

// Warning counters over the whole run (MuJoCo style).
struct WorldCounters {
  long steps = 0;
  long solver_not_converged = 0;
  long inverted_steps = 0;
  long nan_steps = 0;
  long energy_blowup_steps = 0;
};

struct BodySurface {
  std::string name;
  BodyKind kind = BodyKind::deformable;
  Points positions;     // #V by 3, world space, current
  Triangles triangles;  // #F by 3
  std::shared_ptr<const SurfaceLook> look;  // how `triangles` are drawn, per triangle; null: in the body's colour
};

struct BodyStats {
  std::string name;
  double mass = 0.0;                                          // kg
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();   // m (lumped nodes)
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();         // kg m/s
  double kinetic_energy = 0.0;                                // J
  double elastic_energy = 0.0;                                // J
  double min_volume_ratio = 1.0;                              // current / rest, min over tets
  int num_nodes = 0;
  int num_tets = 0;
};

// A body that starts inside another body (or behind a plane) by `depth` m,
// more than the contact margin.
struct InitialOverlap {
  std::string body;    // the body with a vertex inside
  std::string inside;  // the body or plane it is inside
  double depth = 0.0;  // m
};

class World {
 public:
  // Throws bad_input for invalid descriptions, naming each by its origin
  // ("FILE: /bodies/3/...") or, built in code, by its list ("bodies/i/...").
  explicit World(const WorldDesc& desc);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  StepReport step();

  // Every mesh body (deformable, then rigid/kinematic/fixed), in description order; planes are not included.
  std::vector<BodySurface> surfaces() const;
  // Bounds of each body in surfaces()' order, from its collision surface:
  // cheaper than the drawn one and holding it (offset outward when simplified).
  std::vector<Aabb> body_bounds() const;
  // Dynamic bodies (deformable, then rigid), in description order.
  std::vector<BodyStats> stats() const;
  const WorldCounters& counters() const { return m_counters; }
  // The deepest such overlap in the current state, if any (sim/collision/initial_overlap.h).
  std::optional<InitialOverlap> initial_overlap() const;

  double time() const { return m_time; }
  double dt() const { return m_dt; }
  // Deformable bodies, in description order.
  int num_deformable_bodies() const { return static_cast<int>(m_bodies.size()); }
  const DeformableBody& deformable_body(int i) const { return m_bodies[static_cast<size_t>(i)]; }
  // Rigid, kinematic and fixed bodies, in description order.
  int num_rigid_bodies() const { return static_cast<int>(m_rigid.size()); }
  const RigidBody& rigid_body(int i) const { return m_rigid[static_cast<size_t>(i)]; }
  // Global DoF vectors: 3 per node, layout above (positions() fills in the rigid poses).
  Eigen::VectorXd positions() const;
  const Eigen::VectorXd& velocities() const { return m_v; }
  // Replaces positions and velocities (3 per node, same layout; rigid bodies
  // take centre, rotation vector, velocity and angular velocity), e.g. to
  // restart from a saved state or to start deformed. Pinned nodes keep
  // whatever they are given. RECOIL_CHECKs the sizes. The energy reference of
  // the blow-up check restarts from the new state unless told otherwise.
  void set_state(const Eigen::VectorXd& positions, const Eigen::VectorXd& velocities,
                 bool reset_energy_reference = true);
  // While held, kinematic bodies stand where they are (a scene settles
  // before its first frame with them still); released, their scripted
  // velocities drive them on from there.
  void hold_kinematic(bool held);
  // The system matrix of the last step (for tests and the contact solver).
  const BlockSparseMatrix& system_matrix() const { return m_A; }

 private:
  void assemble();
  // P_A^-1 of this step's m_A with every deformable body's rigid modes at m_x.
  MomentumPreconditioner momentum_preconditioner() const;
  // The contact stage: candidates for the contact-free prediction in m_dv,
  // then the contact solve (m_dv in: contact-free, out: with contacts).
  void collide_and_solve(StepReport& report);
  // Where the contact solve's dv starts (ContactProblem::start_dv): the
  // contact-free solution m_dv on the bodies that no row of `problem`
  // touches, zero on the others.
  Eigen::VectorXd contact_solve_start(const ContactProblem& problem) const;
  std::vector<ContactSurface> contact_surfaces() const;
  std::vector<ContactPlane> contact_planes() const;
  // Marks `report` runaway (naming the surface with the most candidates)
  // when `candidates` exceed kMaxCandidatesPerVertex per surface vertex.
  bool ran_away(const std::vector<ContactCandidate>& candidates, const std::vector<CollisionSurface>& surfaces,
                StepReport& report) const;
  // The body of contact surface s (deformable bodies, then rigid ones).
  const std::string& surface_body_name(int s) const;
  void integrate();
  void check_health(StepReport& report);
  // A body with degrees of freedom: the deformable bodies, then the dynamic
  // rigid ones (the order of stats()); exactly one of the pointers is set.
  struct DynamicBody {
    const DeformableBody* deformable = nullptr;
    const RigidBody* rigid = nullptr;
    int first_node = 0;  // into the global node list (3 DoFs per node)
    int num_nodes = 0;   // a rigid body's two: its centre and its rotation vector
    const std::string& name() const;
  };
  int num_dynamic_bodies() const { return static_cast<int>(m_bodies.size() + m_dynamic.size()); }
  DynamicBody dynamic_body(int i) const;
  // Kinetic + elastic + gravitational energy of dynamic body i, J, with the given elastic part.
  double total_energy(int i, double elastic) const;
  void reset_energy_reference();

  std::unique_ptr<EmbreeDevice> m_device;
  std::unique_ptr<CollisionDetector> m_detector;
  double m_dt;
  Eigen::Vector3d m_gravity;
  PcgSettings m_solver;
  ContactSettings m_contact;
  std::vector<DeformableBody> m_bodies;
  std::vector<double> m_mu_static, m_mu_kinetic;  // per deformable body
  std::vector<char> m_self_contact;               // per deformable body
  std::vector<RigidBody> m_rigid;                 // rigid, kinematic and fixed
  std::vector<int> m_dynamic;                     // indices into m_rigid of the dynamic bodies
  std::vector<PlaneDesc> m_planes;                // normals normalised
  ContactMemory m_memory;                         // warm start for the next step
  Eigen::VectorXd m_x, m_v, m_b, m_dv;
  BlockSparseMatrix m_A;
  std::optional<MomentumPreconditioner> m_preconditioner;  // of m_A, set with it each step
  std::vector<char> m_fixed;                 // per global node
  std::vector<double> m_energy0, m_energy_scale;  // per dynamic body, for the blow-up check
  // While kinematic bodies are held (hold_kinematic): per kinematic body in
  // m_rigid order, its scripted velocity and angular velocity.
  bool m_kinematic_held = false;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> m_held_scripts;
  std::vector<double> m_elastic;    // per deformable body: elastic energy at the start of the last step (from assembly)
  double m_time = 0.0;
  WorldCounters m_counters;
};

}  // namespace recoil::sim
