#pragma once
// A rigid body as the design's CustomRigidbody: forces and impulses are
// accumulated by addForce/addTorque with a ForceMode; beginStep turns them
// into the step's accelerations, and the solver integrates a copy of the
// body's motion with them (motion.h) and writes it back.
#include <array>
#include <memory>
#include <optional>
#include <string>

#include "engine/colliders/collider.h"
#include "engine/dynamics/collision_filter.h"
#include "engine/dynamics/material.h"
#include "engine/dynamics/motion.h"
#include "engine/math.h"

namespace physdbg {

// What a pushed quantity means:
//   Force          N (or N m), scaled by dt and by the inverse mass (inertia)
//   Acceleration   m/s^2,      scaled by dt, mass ignored
//   Impulse        N s,        scaled by the inverse mass, applied once
//   VelocityChange m/s,        applied once, mass ignored
enum class ForceMode { Force, Acceleration, Impulse, VelocityChange };

struct BodyDefinition {
  std::shared_ptr<const Collider> collider;
  Vec3 position = Vec3::Zero();
  Quat orientation = Quat::Identity();
  Vec3 linearVelocity = Vec3::Zero();
  Vec3 angularVelocity = Vec3::Zero();  // world frame, rad/s
  double mass = 1.0;
  bool isStatic = false;
  // Moved by its velocities alone: no gravity, forces or contacts change them,
  // and it has infinite mass in contacts (it pushes, it is never pushed).
  bool isKinematic = false;
  bool useGravity = true;
  double linearDrag = 0.0;   // 1/s: v / (1 + drag h) per integration of length h (motion.h)
  double angularDrag = 0.0;  // 1/s: same rule for the angular velocity
  Material material;
  std::array<bool, 3> lockTranslation{false, false, false};  // world axes
  std::array<bool, 3> lockRotation{false, false, false};     // world axes
  // Inertia tensor in kg m^2 about the centre of mass, body axes, for this
  // body's mass (not per kg): replaces the collider's unit inertia times the
  // mass. Must pass inertiaTensorProblem. Dynamic bodies only. Last, so the
  // positional initialisers before it keep their meaning.
  std::optional<Mat3> localInertia;
  CollisionFilter filter;
  // A sensor (trigger volume) reports when it overlaps other bodies
  // (contact events, the contacts layer) but never pushes or is pushed.
  bool isSensor = false;
};

// A body turns about its centre of mass, which is its position. A convex
// mesh given in a frame whose origin is not its centroid is re-expressed
// about the centroid, and the position moved there (by the orientation), so
// the same points in the same place give the right dynamics. Other bodies
// come back unchanged. World::addBody and the scene loader both apply it.
BodyDefinition aboutCentreOfMass(BodyDefinition definition);

// Why `inertia` cannot be a body's explicit inertia tensor, or "" when it can:
// it must be finite, symmetric within a relative 1e-9 (of its largest entry),
// positive definite (its smallest principal moment above 16 DBL_EPSILON of its
// largest, the rule the collider's inertia is held to), and its principal
// moments must each be at most the sum of the other two (within a relative
// 1e-9), as every real mass distribution's are.
std::string inertiaTensorProblem(const Mat3& inertia);

class RigidBody {
 public:
  // Throws std::invalid_argument for a missing collider, a non-positive mass
  // on a dynamic body, a body both static and kinematic, non-finite state, or
  // an explicit localInertia that inertiaTensorProblem refuses (or that a
  // static or kinematic body is given).
  explicit RigidBody(const BodyDefinition& definition);

  const Collider& collider() const { return *collider_; }
  const std::shared_ptr<const Collider>& colliderPointer() const { return collider_; }

  const Vec3& position() const { return position_; }
  const Quat& orientation() const { return orientation_; }
  const Vec3& linearVelocity() const { return linearVelocity_; }
  const Vec3& angularVelocity() const { return angularVelocity_; }
  Transform transform() const { return {position_, orientation_}; }

  void setPosition(const Vec3& position) { position_ = position; }
  // Moves the body by `delta` except along locked translation axes.
  void translate(const Vec3& delta);
  // Turns the body by a rotation vector (axis times angle, world frame),
  // except about locked rotation axes.
  void rotate(const Vec3& rotation);
  void setOrientation(const Quat& orientation) { orientation_ = orientation.normalized(); }
  void setLinearVelocity(const Vec3& velocity) { linearVelocity_ = velocity; }
  void setAngularVelocity(const Vec3& velocity) { angularVelocity_ = velocity; }

  bool isStatic() const { return isStatic_; }
  bool isKinematic() const { return isKinematic_; }
  // Moved by forces and contacts: neither static nor kinematic.
  bool isDynamic() const { return !isStatic_ && !isKinematic_; }
  bool usesGravity() const { return useGravity_; }
  double mass() const { return mass_; }
  double inverseMass() const { return inverseMass_; }
  const Mat3& localInertia() const { return localInertia_; }
  Mat3 worldInverseInertia() const;
  const Material& material() const { return material_; }
  const CollisionFilter& filter() const { return filter_; }
  bool isSensor() const { return isSensor_; }
  double linearDrag() const { return linearDrag_; }
  double angularDrag() const { return angularDrag_; }
  const std::array<bool, 3>& lockTranslation() const { return lockTranslation_; }
  const std::array<bool, 3>& lockRotation() const { return lockRotation_; }
  // Bodies without locks skip all lock work.
  bool hasLocks() const { return hasLocks_; }

  void addForce(const Vec3& force, ForceMode mode = ForceMode::Force);
  void addTorque(const Vec3& torque, ForceMode mode = ForceMode::Force);
  // A force through a world point also makes a torque about the centre of mass.
  void addForceAtPoint(const Vec3& force, const Vec3& point, ForceMode mode = ForceMode::Force);

  // Applies an impulse at a world point right away (collision response).
  void applyImpulseAtPoint(const Vec3& impulse, const Vec3& point);

  // Consumes the accumulators: impulses change the velocities now, forces and
  // gravity become the accelerations the step integrates with.
  void beginStep(const Vec3& gravity);
  const Vec3& stepAcceleration() const { return stepAcceleration_; }
  // A copy of the pose and velocities to integrate, what integration reads,
  // and the way back (taken as it is: integratePosition keeps it unit length).
  BodyMotion motion() const { return {position_, orientation_, linearVelocity_, angularVelocity_}; }
  MotionProperties motionProperties() const;
  void setMotion(const BodyMotion& motion);

  // Zeroes velocities along locked axes. Locks act on velocities, so a locked
  // coordinate keeps its exact initial value.
  void applyLocks();

  bool hasPendingForces() const;
  double kineticEnergy() const;
  Vec3 angularMomentum() const;  // world frame, about the centre of mass
  bool hasFiniteState() const;

 private:
  Mat3 explicitOrColliderInertia(const BodyDefinition& definition) const;

  std::shared_ptr<const Collider> collider_;
  Vec3 position_, linearVelocity_, angularVelocity_;
  Quat orientation_;
  bool isStatic_;
  bool isKinematic_;
  bool useGravity_;
  double mass_, inverseMass_;
  Mat3 localInertia_, localInverseInertia_;
  bool isotropic_ = false;  // inertia c * identity: no gyroscopic term, world inertia = local
  double linearDrag_, angularDrag_;
  Material material_;
  std::array<bool, 3> lockTranslation_, lockRotation_;
  bool hasLocks_ = false;
  bool isSensor_ = false;
  CollisionFilter filter_;

  Vec3 forceAccumulator_ = Vec3::Zero();         // N
  Vec3 accelerationAccumulator_ = Vec3::Zero();  // m/s^2
  Vec3 velocityChange_ = Vec3::Zero();           // m/s, impulses already divided by mass
  Vec3 torqueAccumulator_ = Vec3::Zero();        // N m
  Vec3 angularAccelerationAccumulator_ = Vec3::Zero();
  Vec3 angularMomentumChange_ = Vec3::Zero();    // N m s
  Vec3 angularVelocityChange_ = Vec3::Zero();

  Vec3 stepAcceleration_ = Vec3::Zero();         // m/s^2, from beginStep
  Vec3 stepAngularAcceleration_ = Vec3::Zero();  // rad/s^2, world, from beginStep
};

}  // namespace physdbg
