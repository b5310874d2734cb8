// buildWideManifolds (wide_contact_rows.h): a group's constraints built
// simd::width manifolds at a time, straight into the lanes the solve reads.
// Built one point at a time in scalar code, they were a tenth of a box pile's
// step. Each lane repeats buildPointConstraints (point_constraint.cpp)
// operation for operation: the same products, sums in the same order, the
// same comparisons, and no fused multiply-add (the engine is built without
// -mfma, and Eigen's 3-vector products sum left to right), so a lane holds
// the scalar numbers bit for bit. Slots a manifold does not use hold zeros.
#include <algorithm>
#include <cstddef>

#include "engine/solver/wide_contact_rows.h"

namespace physdbg {
namespace {

using simd::Lanes;
constexpr int lanes = simd::width;

void setLanes(Lanes (&target)[3], int lane, const Vec3& value) {
  for (int axis = 0; axis < 3; ++axis) simd::setLane(target[axis], lane, value[axis]);
}

void setLanes(Lanes (&target)[3][3], int lane, const Mat3& value) {
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 3; ++column) simd::setLane(target[row][column], lane, value(row, column));
}

void cross(const Lanes* a, const Lanes* b, Lanes* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

Lanes dot(const Lanes* a, const Lanes* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// (inertia * cross) masked, as Eigen's 3x3 product: each row summed left to right.
void turn(const Lanes (&inertia)[3][3], const Lanes* crossed, const Lanes* mask, Lanes* out) {
  for (int i = 0; i < 3; ++i)
    out[i] = (inertia[i][0] * crossed[0] + inertia[i][1] * crossed[1] + inertia[i][2] * crossed[2]) * mask[i];
}

// rowMass of point_constraint.cpp: 1 / k where k > 0, else 0.
Lanes rowMass(Lanes inverseMassSum, const Lanes* crossA, const Lanes* turnA, const Lanes* crossB, const Lanes* turnB) {
  const Lanes k = inverseMassSum + dot(crossA, turnA) + dot(crossB, turnB);
  const Lanes positive = simd::greater(k, Lanes::zero());
  const Lanes one = Lanes::all(1.0);
  return simd::select(positive, one / simd::select(positive, k, one), Lanes::zero());
}

// What every point of a lane's manifold shares (zero in empty lanes).
struct FrameLanes {
  Lanes positionA[3], positionB[3], directions[3][3];
  Lanes inertiaA[3][3], inertiaB[3][3], angularMaskA[3], angularMaskB[3];
  Lanes linearVelocityA[3], angularVelocityA[3], linearVelocityB[3], angularVelocityB[3];
  Lanes inverseMassSum, staticFriction, dynamicFriction, restitution;
};

FrameLanes frameLanes(const ManifoldFrame* frames, int count) {
  FrameLanes result;
  const ManifoldFrame empty{Vec3::Zero(), Vec3::Zero(), {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()},
                            Mat3::Zero(), Mat3::Zero(), Vec3::Zero(),
                            Vec3::Zero(), Vec3::Zero(), Vec3::Zero(),
                            Vec3::Zero(), Vec3::Zero(), 0.0,
                            0.0,          0.0,          CombinedMaterial{}};
  for (int lane = 0; lane < lanes; ++lane) {
    const ManifoldFrame& frame = lane < count ? frames[lane] : empty;
    setLanes(result.positionA, lane, frame.positionA);
    setLanes(result.positionB, lane, frame.positionB);
    for (int row = 0; row < 3; ++row) setLanes(result.directions[row], lane, frame.directions[row]);
    setLanes(result.inertiaA, lane, frame.inverseInertiaA);
    setLanes(result.inertiaB, lane, frame.inverseInertiaB);
    setLanes(result.angularMaskA, lane, frame.angularMaskA);
    setLanes(result.angularMaskB, lane, frame.angularMaskB);
    setLanes(result.linearVelocityA, lane, frame.linearVelocityA);
    setLanes(result.angularVelocityA, lane, frame.angularVelocityA);
    setLanes(result.linearVelocityB, lane, frame.linearVelocityB);
    setLanes(result.angularVelocityB, lane, frame.angularVelocityB);
    simd::setLane(result.inverseMassSum, lane, frame.inverseMassSum);
    simd::setLane(result.staticFriction, lane, frame.material.staticFriction);
    simd::setLane(result.dynamicFriction, lane, frame.material.dynamicFriction);
    simd::setLane(result.restitution, lane, frame.material.restitution);
  }
  return result;
}

// One point slot of every lane, as the manifolds hold it (zero where a lane
// has no such point; `present` says where it has).
struct SlotInput {
  Lanes pointA[3], pointB[3], localA[3], localB[3], separation, present;
  Lanes normalImpulse, tangentImpulse[2], stepNormalImpulse;
};

SlotInput slotInput(const std::uint32_t* members, int count, const std::vector<ContactManifold>& manifolds, int p) {
  SlotInput in;
  const ManifoldPoint nothing{};
  for (int lane = 0; lane < lanes; ++lane) {
    const bool present = lane < count && p < manifolds[members[lane]].pointCount;
    const ManifoldPoint& point = present ? manifolds[members[lane]].points[p] : nothing;
    setLanes(in.pointA, lane, point.pointA);
    setLanes(in.pointB, lane, point.pointB);
    setLanes(in.localA, lane, point.localA);
    setLanes(in.localB, lane, point.localB);
    simd::setLane(in.separation, lane, point.separation);
    simd::setMaskLane(in.present, lane, present);
    simd::setLane(in.normalImpulse, lane, point.normalImpulse);
    simd::setLane(in.tangentImpulse[0], lane, point.tangentImpulse[0]);
    simd::setLane(in.tangentImpulse[1], lane, point.tangentImpulse[1]);
    simd::setLane(in.stepNormalImpulse, lane, point.stepNormalImpulse);
  }
  return in;
}

// buildPointConstraints for one slot of every lane. Returns the slot's restitution.
Lanes buildSlot(const FrameLanes& frame, const SlotInput& in, const ConstraintSettings& settings, WidePoint& out) {
  const Lanes zero = Lanes::zero();
  const auto keep = [&in, zero](Lanes value) { return simd::select(in.present, value, zero); };
  const Lanes apart = simd::greater(in.separation, Lanes::all(settings.linearSlop));
  Lanes armA[3], armB[3];
  for (int axis = 0; axis < 3; ++axis) {
    const Lanes middle = Lanes::all(0.5) * (in.pointA[axis] + in.pointB[axis]);
    armA[axis] = simd::select(apart, in.pointA[axis], middle) - frame.positionA[axis];
    armB[axis] = simd::select(apart, in.pointB[axis], middle) - frame.positionB[axis];
  }
  Lanes crossA[3][3], crossB[3][3], turnA[3][3], turnB[3][3];
  for (int row = 0; row < 3; ++row) {
    cross(armA, frame.directions[row], crossA[row]);
    cross(armB, frame.directions[row], crossB[row]);
    turn(frame.inertiaA, crossA[row], frame.angularMaskA, turnA[row]);
    turn(frame.inertiaB, crossB[row], frame.angularMaskB, turnB[row]);
  }
  out.normalMass = keep(rowMass(frame.inverseMassSum, crossA[0], turnA[0], crossB[0], turnB[0]));
  for (int t = 0; t < 2; ++t)
    out.tangentMass[t] = keep(rowMass(frame.inverseMassSum, crossA[t + 1], turnA[t + 1], crossB[t + 1], turnB[t + 1]));
  Lanes spinA[3], spinB[3], relative[3];
  cross(frame.angularVelocityA, armA, spinA);
  cross(frame.angularVelocityB, armB, spinB);
  for (int axis = 0; axis < 3; ++axis)
    relative[axis] = (frame.linearVelocityB[axis] + spinB[axis]) - (frame.linearVelocityA[axis] + spinA[axis]);
  const Lanes* normal = frame.directions[0];
  const Lanes approach = dot(relative, normal);
  Lanes sliding[3];
  for (int axis = 0; axis < 3; ++axis) sliding[axis] = relative[axis] - approach * normal[axis];
  const Lanes slidingSpeed = simd::sqrt(dot(sliding, sliding));
  out.friction = keep(simd::select(simd::greater(Lanes::all(settings.stickingSpeed), slidingSpeed),
                                   frame.staticFriction, frame.dynamicFriction));
  for (int row = 0; row < 3; ++row)
    for (int axis = 0; axis < 3; ++axis) {
      out.crossA[row][axis] = keep(crossA[row][axis]);
      out.crossB[row][axis] = keep(crossB[row][axis]);
      out.turnA[row][axis] = keep(turnA[row][axis]);
      out.turnB[row][axis] = keep(turnB[row][axis]);
    }
  out.gap = zero;
  out.largestImpulse = zero;
  out.normalImpulse = in.normalImpulse;
  out.tangentImpulse[0] = in.tangentImpulse[0];
  out.tangentImpulse[1] = in.tangentImpulse[1];
  out.stepNormalImpulse = in.stepNormalImpulse;
  return keep(
      simd::select(simd::greater(Lanes::all(-settings.restitutionThreshold), approach), frame.restitution, zero));
}

}  // namespace

unsigned buildWideManifolds(const std::uint32_t* members, int count, const std::vector<ContactManifold>& manifolds,
                            const ManifoldFrame* frames, const std::vector<ManifoldTangents>& tangents,
                            const std::vector<SolverBody>& bodies, const ConstraintSettings& settings,
                            WideManifolds& group) {
  count = std::min(count, lanes);
  group.pointSlots = 0;
  group.linearLocks = false;
  const Vec3 zero = Vec3::Zero();
  for (int lane = 0; lane < lanes; ++lane) {
    const bool used = lane < count;
    const std::uint32_t m = used ? members[lane] : WideManifolds::empty;
    const ContactManifold* manifold = used ? &manifolds[m] : nullptr;
    group.manifold[lane] = m;
    group.bodyA[lane] = used ? manifold->a : WideManifolds::empty;
    group.bodyB[lane] = used ? manifold->b : WideManifolds::empty;
    group.writableA[lane] = used && bodies[manifold->a].movable;
    group.writableB[lane] = used && bodies[manifold->b].movable;
    setLanes(group.direction[0], lane, used ? manifold->normal : zero);
    setLanes(group.direction[1], lane, used ? tangents[m][0] : zero);
    setLanes(group.direction[2], lane, used ? tangents[m][1] : zero);
    simd::setLane(group.inverseMassA, lane, used ? frames[lane].inverseMassA : 0.0);
    simd::setLane(group.inverseMassB, lane, used ? frames[lane].inverseMassB : 0.0);
    setLanes(group.linearMaskA, lane, used ? bodies[manifold->a].linearMask : zero);
    setLanes(group.linearMaskB, lane, used ? bodies[manifold->b].linearMask : zero);
    if (!used) continue;
    group.pointSlots = std::max(group.pointSlots, manifold->pointCount);
    group.linearLocks = group.linearLocks || bodies[manifold->a].linearMask != Vec3::Ones() ||
                        bodies[manifold->b].linearMask != Vec3::Ones();
  }
  const FrameLanes frame = frameLanes(frames, count);
  unsigned bouncing = 0;
  for (int p = 0; p < group.pointSlots; ++p) {
    const SlotInput in = slotInput(members, count, manifolds, p);
    for (int axis = 0; axis < 3; ++axis) {
      group.localA[p][axis] = in.localA[axis];
      group.localB[p][axis] = in.localB[axis];
    }
    group.present[p] = in.present;
    const Lanes restitution = buildSlot(frame, in, settings, group.points[p]);
    for (int lane = 0; lane < count; ++lane)
      if (simd::getLane(restitution, lane) != 0.0) bouncing |= 1u << lane;
  }
  return bouncing;
}

// pointGaps (point_constraint.cpp) lane by lane, operation for operation.
void measureWideGaps(WideManifolds& group, const std::vector<SolverBody>& bodies) {
  // Whole packets from each lane's body, transposed (simd::gatherRuns). A
  // position is read with the doubles after it (BodyMotion's orientation),
  // so the run is at least a packet long; only the first three are used.
  constexpr int positionRun = std::max(3, lanes);
  static_assert(offsetof(BodyMotion, position) + positionRun * sizeof(double) <= sizeof(BodyMotion));
  alignas(64) static constexpr double nothing[16] = {};  // an empty lane's
  const double *runsA[lanes], *runsB[lanes], *turnsA[lanes], *turnsB[lanes];
  for (int lane = 0; lane < lanes; ++lane) {
    const bool used = group.manifold[lane] != WideManifolds::empty;
    runsA[lane] = used ? bodies[group.bodyA[lane]].motion.position.data() : nothing;
    runsB[lane] = used ? bodies[group.bodyB[lane]].motion.position.data() : nothing;
    turnsA[lane] = used ? bodies[group.bodyA[lane]].rotation.data() : nothing;
    turnsB[lane] = used ? bodies[group.bodyB[lane]].rotation.data() : nothing;
  }
  Lanes positionA[positionRun], positionB[positionRun], columnsA[9], columnsB[9];
  simd::gatherRuns<positionRun>(runsA, positionA);
  simd::gatherRuns<positionRun>(runsB, positionB);
  simd::gatherRuns<9>(turnsA, columnsA);  // column-major: R(row, column) at 3 column + row
  simd::gatherRuns<9>(turnsB, columnsB);
  const Lanes* normal = group.direction[0];
  Lanes offset[3], normalInA[3], normalInB[3];
  for (int i = 0; i < 3; ++i) {
    offset[i] = positionB[i] - positionA[i];
    normalInA[i] = columnsA[3 * i] * normal[0] + columnsA[3 * i + 1] * normal[1] + columnsA[3 * i + 2] * normal[2];
    normalInB[i] = columnsB[3 * i] * normal[0] + columnsB[3 * i + 1] * normal[1] + columnsB[3 * i + 2] * normal[2];
  }
  const Lanes centres = dot(offset, normal);
  for (int p = 0; p < group.pointSlots; ++p) {
    const Lanes gap = centres + (dot(normalInB, group.localB[p]) - dot(normalInA, group.localA[p]));
    group.points[p].gap = simd::select(group.present[p], gap, Lanes::zero());
  }
}

}  // namespace physdbg
