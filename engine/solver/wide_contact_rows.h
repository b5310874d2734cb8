#pragma once
// Structure-of-arrays contact rows for the wide solve: up to simd::width
// manifolds of one colour (constraint_colouring.h), one per SIMD lane, each
// with its four point slots (a manifold with fewer points leaves the rest
// empty: zero mass, zero impulse, so they change nothing). Lanes of a group
// share no movable body, so the group gathers its bodies' velocities once,
// solves every point of every lane at once, and scatters them back.
//
// Each lane does exactly what the scalar solver does for its manifold, in the
// same order: normal rows point by point (in reverse on alternate sweeps;
// empty slots come last, so reversing all four slots visits the real points
// in their reverse order), then friction. The speculative manifolds solved
// all points together (the 4x4 approach solve) stay scalar.
#include <array>
#include <cstdint>
#include <vector>

#include "engine/contacts/contact_manifold.h"
#include "engine/solver/point_constraint.h"
#include "engine/solver/simd_lanes.h"
#include "engine/solver/solver_body.h"
#include "engine/solver/step_context.h"

namespace physdbg {

// One point slot of every lane.
struct WidePoint {
  simd::Lanes crossA[3][3], crossB[3][3];  // [row][axis]
  simd::Lanes turnA[3][3], turnB[3][3];
  simd::Lanes normalMass, tangentMass[2], friction, gap;
  simd::Lanes normalImpulse, tangentImpulse[2], largestImpulse, stepNormalImpulse;
};

struct WideManifolds {
  static constexpr std::uint32_t empty = ~0u;
  std::array<std::uint32_t, simd::width> manifold, bodyA, bodyB;  // `empty` in unused lanes
  std::array<bool, simd::width> writableA{}, writableB{};         // a movable body in the lane
  simd::Lanes direction[3][3];  // [row][axis]: the normal, then the two tangents
  simd::Lanes inverseMassA, inverseMassB;  // as scaled for the contact
  simd::Lanes linearMaskA[3], linearMaskB[3];
  std::array<WidePoint, ContactManifold::maxPoints> points;
  // The most points any lane has: slots past it are empty in every lane, so
  // a group of sphere contacts (one point each) solves one slot, not four.
  int pointSlots = 0;
};

// Up to simd::width manifolds (indices into `manifolds`, sharing no movable
// body) into `group`, from their constraints (lane i's points at
// constraints[i][0, pointCount)), their tangents and their current impulses.
void packWideManifolds(const std::uint32_t* members, int count, const std::vector<ContactManifold>& manifolds,
                       const PointConstraint* const* constraints, const std::vector<ManifoldTangents>& tangents,
                       const std::vector<SolverBody>& bodies, WideManifolds& group);

// Applies the impulses the group starts the substep with.
void warmStartWide(WideManifolds& group, std::vector<SolverBody>& bodies);

struct WideSweep {
  const SubstepContext* substeps = nullptr;
  double maxPushSpeed = 0.0;
  bool useBias = true;  // the soft push-out of overlap (off in the relax sweep)
  bool reversed = false;
};
// One sweep: every point's normal row, then its friction.
void solveWide(WideManifolds& group, std::vector<SolverBody>& bodies, const WideSweep& sweep);

// Impulses back to the manifolds, and each point's largest one to the
// constraints of the manifolds that keep theirs (`kept`, per manifold).
void storeWideImpulses(const WideManifolds& group, std::vector<ContactManifold>& manifolds,
                       std::vector<PointConstraint>& constraints, const std::vector<char>& kept);

}  // namespace physdbg
