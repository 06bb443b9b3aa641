#include "sim/rigid/rigid_body.h"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/error.h"
#include "sim/collision/collision_proxy.h"
#include "sim/geometry/mesh_stats.h"
#include "sim/geometry/skew.h"
#include "sim/geometry/tetrahedralize.h"
#include "sim/rigid/mass_properties.h"

namespace recoil::sim {

Eigen::Matrix3d RigidBody::world_inertia() const {
  const Eigen::Matrix3d R = rotation();
  Eigen::Matrix3d I = R * inertia * R.transpose();
  return 0.5 * (I + I.transpose());
}

double RigidBody::kinetic_energy() const {
  if (kind != BodyKind::rigid) return 0.0;
  return 0.5 * mass * velocity.squaredNorm() + 0.5 * angular_velocity.dot(world_inertia() * angular_velocity);
}

RigidBody build_rigid_body(const RigidBodyDesc& desc, EmbreeDevice& device, const std::string& where, double margin,
                           int threads) {
  if (desc.kind == BodyKind::deformable)
    throw bad_input(where + ": a rigid body description is rigid, kinematic or fixed, not deformable");
  if (desc.mesh.empty()) throw bad_input(desc.origin.mesh_field(where) + ": a rigid body needs a surface");
  if (!desc.mesh.vertices.allFinite()) throw bad_input(desc.origin.mesh_field(where) + ": vertices must be finite");
  if (!desc.transform.position.allFinite() || !desc.transform.rotation.allFinite() || !desc.velocity.allFinite() ||
      !desc.angular_velocity.allFinite())
    throw bad_input(where + ": transform, velocity and angular_velocity must be finite");
  if (!desc.transform.scale.allFinite() || (desc.transform.scale.array() == 0.0).any())
    throw bad_input(where + "/transform/scale: must be finite and non-zero");
  const FrictionDesc& f = desc.friction;
  if (!(f.static_coefficient >= 0.0) || !(f.kinetic_coefficient >= 0.0) || !std::isfinite(f.static_coefficient) ||
      !std::isfinite(f.kinetic_coefficient))
    throw bad_input(where + "/friction: coefficients must be finite and >= 0");

  RigidBody body;
  body.name = desc.name;
  body.kind = desc.kind;
  body.friction = desc.friction;
  TriMesh mesh = desc.mesh;
  transform_in_place(mesh, desc.transform.rotation_matrix(), desc.transform.scale, desc.transform.position);
  body.triangles = mesh.triangles;
  body.look = mesh.look;

  Eigen::Vector3d reference = desc.transform.position;
  if (desc.kind == BodyKind::rigid) {
    if (!(desc.density > 0.0) || !std::isfinite(desc.density)) throw bad_input(where + "/density: must be > 0");
    // A surface that is not closed bounds no volume by itself: its solid is
    // where its winding number says inside (winding_solid.h), as a deformable
    // body's; one that encloses nothing weighs the lattice cells it crosses.
    const bool closed = compute_mesh_stats(mesh).watertight;
    MassProperties props;
    if (closed) {
      props = mass_properties(mesh, desc.density);
    } else {
      const WindingSolid solid = winding_solid(mesh, kWeighingResolution, threads);
      body.encloses_nothing = solid.centers.empty();
      props = body.encloses_nothing ? mass_properties(tetrahedralize(mesh, kDefaultResolution), desc.density)
                                    : mass_properties(solid, desc.density);
    }
    if (!(props.volume > 0.0))
      throw bad_input(desc.origin.mesh_field(where) + ": " +
                      (closed ? "the closed surface encloses " + std::to_string(props.volume) +
                                    " m^3: its faces are wound inward; flip them"
                              : std::string("the surface encloses no volume")));
    body.mass = props.mass;
    body.inertia = props.inertia;
    body.principal = principal_inertia(props.inertia);
    reference = props.center;
    // Initial velocity is given for the reference point of the description
    // (transform.position); the centre of mass moves with v + w x (c - p).
    body.velocity = desc.velocity + desc.angular_velocity.cross(props.center - desc.transform.position);
  } else if (desc.kind == BodyKind::kinematic) {
    body.velocity = desc.velocity;
  }
  if (desc.kind != BodyKind::fixed) body.angular_velocity = desc.angular_velocity;
  body.pose.center = reference;
  // The cell a deformable body of this shape would have at the default resolution.
  const double cell = bounding_box(mesh).extent().maxCoeff() / kDefaultResolution;
  const CollisionProxy proxy = make_collision_proxy(device, mesh, collision_budget(desc.collision, mesh, cell, margin));
  if (proxy.separate) {
    body.render_local = mesh.vertices.rowwise() - reference.transpose();
    body.render_triangles = mesh.triangles;
    body.triangles = proxy.surface.triangles;
    body.collision_deviation = proxy.deviation;
  }
  const Points& collision = proxy.separate ? proxy.surface.vertices : mesh.vertices;
  body.local = collision.rowwise() - reference.transpose();
  return body;
}

RigidPose advance_pose(const RigidPose& pose, const Eigen::Vector3d& velocity, const Eigen::Vector3d& angular_velocity,
                       double h) {
  RigidPose out;
  out.center = pose.center + h * velocity;
  out.orientation = (from_rotation_vector(h * angular_velocity) * pose.orientation).normalized();
  return out;
}

PrincipalInertia principal_inertia(const Eigen::Matrix3d& inertia) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia);
  PrincipalInertia out;
  out.axes = solver.eigenvectors();
  if (out.axes.determinant() < 0.0) out.axes.col(2) = -out.axes.col(2);
  out.moments = solver.eigenvalues();
  return out;
}

Eigen::Quaterniond advance_free_rotation(const Eigen::Quaterniond& orientation, const PrincipalInertia& inertia,
                                         const Eigen::Vector3d& L, double h) {
  const Eigen::Matrix3d& Q = inertia.axes;
  const Eigen::Vector3d& moments = inertia.moments;
  Eigen::Matrix3d P = orientation.toRotationMatrix() * Q;  // principal frame -> world
  Eigen::Vector3d m = P.transpose() * L;                   // L in the principal frame
  // Turning about principal axis i keeps m_i and so its share m_i^2 / (2 I_i)
  // of the energy: that part of the motion is a rotation at m_i / I_i rad/s.
  const auto turn = [&](int i, double t) {
    const Eigen::Matrix3d G = Eigen::AngleAxisd(t * m[i] / moments[i], Eigen::Vector3d::Unit(i)).toRotationMatrix();
    P = P * G;
    m = G.transpose() * m;
  };
  turn(0, 0.5 * h);
  turn(1, 0.5 * h);
  turn(2, h);
  turn(1, 0.5 * h);
  turn(0, 0.5 * h);
  return Eigen::Quaterniond(P * Q.transpose()).normalized();
}

void world_points(const Points& local, const RigidPose& pose, Points& out) {
  const Eigen::Matrix3d R = pose.orientation.toRotationMatrix();
  out.resize(local.rows(), 3);
  for (Eigen::Index i = 0; i < local.rows(); ++i)
    out.row(i) = (pose.center + R * local.row(i).transpose()).transpose();
}

Eigen::Vector3d rotation_vector(const Eigen::Quaterniond& q) {
  const Eigen::AngleAxisd aa(q.normalized());
  double angle = aa.angle();
  Eigen::Vector3d axis = aa.axis();
  if (angle > M_PI) {
    angle = 2.0 * M_PI - angle;
    axis = -axis;
  }
  return angle * axis;
}

Eigen::Quaterniond from_rotation_vector(const Eigen::Vector3d& phi) {
  const double angle = phi.norm();
  if (angle < 1e-300) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, phi / angle));
}

Eigen::Matrix3d so3_left_jacobian(const Eigen::Vector3d& phi) {
  const double t = phi.norm();
  const Eigen::Matrix3d K = skew(phi);
  if (t < 1e-6) return Eigen::Matrix3d::Identity() + 0.5 * K + (1.0 / 6.0) * K * K;
  return Eigen::Matrix3d::Identity() + (1.0 - std::cos(t)) / (t * t) * K + (t - std::sin(t)) / (t * t * t) * K * K;
}

}  // namespace recoil::sim
