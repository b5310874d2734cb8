#pragma once
// Structure-of-arrays contact rows for the wide solve: up to simd::width
// manifolds of one colour (constraint_colouring.h), one per SIMD lane, with
// as many point slots as the group's largest manifold has points (a manifold
// with fewer points leaves the rest empty: zero mass, zero impulse, so they
// change nothing). Lanes of a group
// share no movable body, so the group gathers its bodies' velocities once,
// solves every point of every lane at once, and scatters them back.
//
// Each lane does exactly what the scalar solver does for its manifold, in the
// same order: normal rows point by point (in reverse on alternate sweeps;
// empty slots come last, so reversing all the group's slots visits the real
// points in their reverse order), then friction. The speculative manifolds solved
// all points together (the 4x4 approach solve) stay scalar. An isotropic
// group's turns (cross times scale) are the scalar turns as numbers; only a
// zero may come out with the other sign, which changes no sum.
#include <array>
#include <cstdint>
#include <memory>
#include <new>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/contacts/contact_manifold.h"
#include "engine/solver/point_constraint.h"
#include "engine/solver/simd_lanes.h"
#include "engine/solver/body_ranks.h"
#include "engine/solver/solver_body.h"
#include "engine/solver/step_context.h"

namespace physdbg {

// One point slot of every lane: what every sweep reads.
// The arms from the bodies' centres of mass: each row's cross (arm x row
// direction) is taken where a sweep needs it (rowCrosses). Stored, the nine
// crosses a body made a slot 896 bytes instead of 512, and the sweeps, which
// stream a large island's slots from memory, read them all every pass.
struct WidePoint {
  simd::Lanes armA[3], armB[3];
  simd::Lanes normalMass, tangentMass[2], friction, gap;
  simd::Lanes normalImpulse, tangentImpulse[2], largestImpulse, stepNormalImpulse;
};

// What a unit impulse along each row does to each body's spin (inverse
// inertia x cross). Kept only for groups whose bodies' inverse inertia is not
// a multiple of the identity (WideManifolds::isotropic).
struct WideTurns {
  simd::Lanes turnA[3][3], turnB[3][3];  // [row][axis]
};

// a x b, as Eigen's cross product, so a lane's numbers are the scalar solver's.
[[gnu::always_inline]] inline void crossLanes(const simd::Lanes* a, const simd::Lanes* b, simd::Lanes* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// One row's crosses on both bodies: arm x the row's direction.
struct RowCrosses {
  simd::Lanes a[3], b[3];
};
[[gnu::always_inline]] inline RowCrosses rowCrosses(const WidePoint& point, const simd::Lanes (&direction)[3]) {
  RowCrosses crosses;
  crossLanes(point.armA, direction, crosses.a);
  crossLanes(point.armB, direction, crosses.b);
  return crosses;
}

// Makes elements default-initialised, where std::allocator value-initialises
// (zeroes) them: for a vector whose elements are written before they are read.
template <class T>
struct DefaultInitialisingAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = DefaultInitialisingAllocator<U>;
  };
  DefaultInitialisingAllocator() = default;
  template <class U>
  DefaultInitialisingAllocator(const DefaultInitialisingAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* place) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(place)) U;
  }
  template <class U, class... Arguments>
  void construct(U* place, Arguments&&... arguments) {
    ::new (static_cast<void*>(place)) U(std::forward<Arguments>(arguments)...);
  }
};
template <class T>
using DefaultInitialisedVector = std::vector<T, DefaultInitialisingAllocator<T>>;

// Each point's anchors in its bodies' frames, for the gaps, and which lanes
// have the point.
struct WideAnchors {
  simd::Lanes localA[3], localB[3];
  simd::Lanes present;  // mask: the lane's manifold has this point
};

// The point slots of a batch's groups, group after group, each group taking
// as many as its lanes' largest manifold has points (a group of sphere
// contacts one, a box pile's four): fixed at four a group, a sphere pile's
// groups held three empty slots each, 1.3 KB a contact. Nothing is zeroed:
// buildWideManifolds writes every slot a sweep reads, and the turns of
// isotropic groups are never written, so their pages are never touched.
struct WideSlots {
  DefaultInitialisedVector<WidePoint> points;
  DefaultInitialisedVector<WideAnchors> anchors;
  DefaultInitialisedVector<WideTurns> turns;  // written only for groups that are not isotropic
  void resize(std::size_t count) {
    points.resize(count);
    anchors.resize(count);
    turns.resize(count);
  }
};

// No member is initialised by default: buildWideManifolds writes every
// field a sweep reads, and a batch's groups (WideGroups) are made without
// zeroing first.
//
// The sweeps stream a large island's groups from memory, so what they read
// comes first: the header here, then the group's point slots (WideSlots).
// The anchors are read once per substep to measure gaps; the turns only by
// groups whose bodies' inertia is not isotropic (spheres and cubes do
// without).
struct WideManifolds {
  static constexpr std::uint32_t empty = ~0u;
  // bodyA, bodyB: the bodies' ranks (body_ranks.h), where the kernels find
  // them in the solver's dense table. `empty` in unused lanes.
  std::array<std::uint32_t, simd::width> manifold, bodyA, bodyB;
  std::array<bool, simd::width> writableA, writableB;             // a movable body in the lane
  // Every lane's inverse inertia, on both sides, is spinScale times the
  // identity with no rotation locked: a turn is the cross times that scale
  // (zero for an immovable body), and `turns` is left unwritten.
  bool isotropic;
  // The most points any lane has: slots past it are empty in every lane, so
  // a group of sphere contacts (one point each) solves one slot, not four.
  int pointSlots;
  simd::Lanes direction[3][3];  // [row][axis]: the normal, then the two tangents
  simd::Lanes inverseMassA, inverseMassB;  // as scaled for the contact
  simd::Lanes spinScaleA, spinScaleB;      // as scaled for the contact; 0 unless isotropic
  // [0, pointSlots) of each, in the batch's WideSlots (attachSlots).
  WidePoint* points;
  WideAnchors* anchors;
  WideTurns* turns;  // unless isotropic
};

// Points `group` at the slots of `slots` from `first`, which the caller has
// sized to hold as many as the group will use (its pointSlots, at most
// ContactManifold::maxPoints). The pointers hold until `slots` is resized.
void attachSlots(WideManifolds& group, WideSlots& slots, std::size_t first);

using WideGroups = std::vector<WideManifolds, DefaultInitialisingAllocator<WideManifolds>>;

// Up to simd::width manifolds (indices into `manifolds`, sharing no movable
// body) into `group`: their constraints, built straight into the lanes from
// frames[lane] (wide_constraint_build.cpp) by the operations
// buildPointConstraints does, in its order, so each lane holds the numbers it
// would; their directions (the frames' normal and tangents); their current
// impulses. Returns a bit per lane
// whose manifold has a point that may bounce (restitution not 0).
unsigned buildWideManifolds(const std::uint32_t* members, int count, const std::vector<ContactManifold>& manifolds,
                            const ManifoldFrame* frames, const std::vector<SolverBody>& bodies,
                            const BodyRanks& ranks, const ConstraintSettings& settings, WideManifolds& group);

// Every point's gap at the bodies' current poses (pointGaps, lane by lane)
// into points[p].gap; 0 where a lane has no such point.
void measureWideGaps(WideManifolds& group, const std::vector<SolverBody>& bodies);

// Applies the impulses the groups start the substep with. `groups` are
// groups of one colour: they share no movable body.
void warmStartWide(std::span<WideManifolds> groups, std::vector<SolverBody>& bodies);

struct WideSweep {
  const SubstepContext* substeps = nullptr;
  double maxPushSpeed = 0.0;
  bool useBias = true;  // the soft push-out of overlap (off in the relax sweep)
  bool reversed = false;
  // The relax sweep after the step's last move: a manifold none of whose
  // points is within kReachedGap is left alone (the scalar solve's rule).
  bool stepEnds = false;
};
// One sweep over groups of one colour: in each group every point's normal
// row, then its friction. Each group's numbers are those it would have
// solved alone (up to four are interleaved to overlap their dependency
// chains).
void solveWide(std::span<WideManifolds> groups, std::vector<SolverBody>& bodies, const WideSweep& sweep);

// Impulses back to the manifolds, and each point's largest one to the
// constraints of the manifolds that keep theirs (`kept`, per manifold;
// manifold m's points from constraints[constraintStart[m]]).
void storeWideImpulses(const WideManifolds& group, std::vector<ContactManifold>& manifolds,
                       PointConstraint* constraints, const std::vector<std::size_t>& constraintStart,
                       const std::vector<char>& kept);

}  // namespace physdbg
