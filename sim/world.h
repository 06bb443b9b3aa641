#pragma once
// sim::World: built once from a plain WorldDesc, then stepped. A step is a
// short list of timed stages (ARCHITECTURE.md): assemble -> solve ->
// integrate -> check health. Numerical trouble is reported in the StepReport,
// never thrown. DoF layout: one global vector of 3 entries per node for
// positions and velocities; each body owns a node range. Later issues add
// rigid bodies, collision and the contact solver as further stages.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "sim/fem/block_sparse.h"
#include "sim/fem/deformable_body.h"
#include "sim/fem/pcg.h"
#include "sim/world_desc.h"

namespace recoil::sim {

class EmbreeDevice;


enum class StepStatus { ok, nan, inverted, energy_blowup };
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
  bool solver_converged = true;
  int inverted_tets = 0;       // over all bodies
  // Contact stage (zero without candidates); SPEC.md section 4 sums these per frame.
  int contacts = 0;            // constraint candidates given to the solver
  int active = 0, sticking = 0, sliding = 0;
  int solver_restarts = 0;
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

enum class BodyKind { deformable, rigid, kinematic, fixed };

struct BodySurface {
  std::string name;
  BodyKind kind = BodyKind::deformable;
  Points positions;     // #V by 3, world space, current
  Triangles triangles;  // #F by 3
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

class World {
 public:
  // Throws bad_input (naming "bodies/i/...") for invalid descriptions.
  explicit World(const WorldDesc& desc);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  StepReport step();

  // Every mesh body (deformable, then rigid/kinematic/fixed), in description order; planes are not included.
  std::vector<BodySurface> surfaces() const;
  // Dynamic bodies (deformable, then rigid), in description order.
  std::vector<BodyStats> stats() const;
  const WorldCounters& counters() const { return m_counters; }

  double time() const { return m_time; }
  double dt() const { return m_dt; }
  int num_bodies() const { return static_cast<int>(m_bodies.size()); }
  const DeformableBody& body(int i) const { return m_bodies[static_cast<size_t>(i)]; }
  // Global DoF vectors: 3 per node, bodies in order.
  const Eigen::VectorXd& positions() const { return m_x; }
  const Eigen::VectorXd& velocities() const { return m_v; }
  // Replaces positions and velocities (3 per node, same layout), e.g. to
  // restart from a saved state or to start deformed. Pinned nodes keep
  // whatever they are given. RECOIL_CHECKs the sizes. The energy reference of
  // the blow-up check restarts from the new state unless told otherwise.
  void set_state(const Eigen::VectorXd& positions, const Eigen::VectorXd& velocities,
                 bool reset_energy_reference = true);
  // The system matrix of the last step (for tests and the contact solver).
  const BlockSparseMatrix& system_matrix() const { return m_A; }

 private:
  void assemble();
  PcgResult solve();
  void integrate();
  void check_health(StepReport& report);
  // Kinetic + elastic + gravitational energy of a body, J, with the given elastic part.
  double total_energy(int body, double elastic) const;
  void reset_energy_reference();

  std::unique_ptr<EmbreeDevice> m_device;
  double m_dt;
  Eigen::Vector3d m_gravity;
  PcgSettings m_solver;
  std::vector<DeformableBody> m_bodies;
  Eigen::VectorXd m_x, m_v, m_b, m_dv;
  BlockSparseMatrix m_A;
  std::vector<char> m_fixed;                 // per global node
  std::vector<double> m_energy0, m_energy_scale;  // per body, for the blow-up check
  std::vector<double> m_elastic;    // per body: elastic energy at the start of the last step (from assembly)
  double m_time = 0.0;
  WorldCounters m_counters;
};

}  // namespace recoil::sim
