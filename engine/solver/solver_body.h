#pragma once
// The sequential-impulse solver's working copy of a body: its motion,
// integrated through every substep and written back to the RigidBody once
// per island, the rotation matrix used to measure gaps, the inverse mass and
// the lock masks, so the inner loops touch one struct per body.
#include "engine/dynamics/motion.h"
#include "engine/math.h"

namespace physdbg {

// How a body's turning during the step moves the anchors its gaps are
// measured at. A sphere's surface is the same after any turn, and a
// capsule's after a turn about its own axis: an anchor carried round by such
// a turn (a ball rolling) would rise off the floor, the gap open, and the
// relax sweep let the body sink at gap / h, a velocity it never moves with
// (a ball rolling at 1.43 m/s reported -0.054 m/s while its height stayed
// put). Such turns leave their anchors where they were.
enum class GapTurn : unsigned char { Whole, None, Swing };

struct SolverBody {
  BodyMotion motion;
  // The rotation gaps are measured with: the orientation's, less the turns
  // that leave the shape in place (GapTurn).
  Mat3 rotation = Mat3::Identity();
  Mat3 inverseInertia = Mat3::Zero();
  // At least the largest eigenvalue of inverseInertia (its largest absolute
  // row sum): bounds what a unit angular impulse can do to the spin.
  double inverseInertiaBound = 0;
  Vec3 linearMask = Vec3::Ones(), angularMask = Vec3::Ones();  // 0 on locked axes
  double inverseMass = 0;
  double size = 0;  // middle extent of the collider's box, m
  // False for static, kinematic, sleeping and frozen bodies: impulses leave
  // them alone, so manifolds of other islands or colours may share them
  // while those run on other threads (nothing writes them).
  bool movable = false;
  GapTurn gapTurn = GapTurn::Whole;
  Quat startOrientation = Quat::Identity();  // Swing: the step's, to split its turn from
  Vec3 symmetryAxis = Vec3::UnitY();          // Swing: body frame
};

// What the solver's set-up reads of each body in a manifold, side by side: a
// SolverBody spans six cache lines and a RigidBody nine, and the set-up (mass
// scaling, the kinematic and calm checks, body sizes, each island's loaded
// frequency bound) reads one per manifold end. One line a body.
struct BodyTraits {
  Vec3 position = Vec3::Zero();    // at the start of the step
  double inverseMass = 0;          // as SolverBody: 0 when immovable this step
  double inverseInertiaBound = 0;  // as SolverBody
  double size = 0;                 // as SolverBody
  bool kinematic = false;
  bool movable = false;  // as SolverBody
};

}  // namespace physdbg
