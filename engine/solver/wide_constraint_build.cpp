// buildWideManifolds (wide_contact_rows.h): a group's constraints built
// simd::width manifolds at a time, straight into the lanes the solve reads.
// Built one point at a time in scalar code, they were a tenth of a box pile's
// step. Each lane repeats buildPointConstraints (point_constraint.cpp)
// operation for operation: the same products, sums in the same order, the
// same comparisons, and no fused multiply-add (the engine is built without
// -mfma, and Eigen's 3-vector products sum left to right), so a lane holds
// the scalar numbers bit for bit. Slots a manifold does not use hold zeros.
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "engine/solver/wide_contact_rows.h"

namespace physdbg {
namespace {

using simd::Lanes;
constexpr int lanes = simd::width;

void cross(const Lanes* a, const Lanes* b, Lanes* out) { crossLanes(a, b, out); }

Lanes dot(const Lanes* a, const Lanes* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// (inertia * cross) masked, as Eigen's 3x3 product: each row summed left to right.
void turn(const Lanes (&inertia)[3][3], const Lanes* crossed, const Lanes* mask, Lanes* out) {
  for (int i = 0; i < 3; ++i)
    out[i] = (inertia[i][0] * crossed[0] + inertia[i][1] * crossed[1] + inertia[i][2] * crossed[2]) * mask[i];
}

// Whether the masked `inertia x cross` is `scale x cross` for every cross:
// inertia is scale times the identity, its off-diagonal entries +0 (so they
// add nothing, not even a zero's sign, to a non-zero product), and no axis is
// masked. Then the solve needs no stored turn.
bool spinScale(const Mat3& inertia, const Vec3& mask, double& scale) {
  scale = inertia(0, 0);
  if (mask != Vec3::Ones() || inertia(1, 1) != scale || inertia(2, 2) != scale) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j && std::bit_cast<std::uint64_t>(inertia(i, j)) != 0) return false;
  return true;
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
  Lanes inverseMassA, inverseMassB, inverseMassSum, staticFriction, dynamicFriction, restitution;
};

// A whole frame or point is a run of doubles, so the lanes fill from whole
// packets of each lane's struct, transposed (simd::gatherRuns), instead of
// one double at a time: a packet read right after four one-double writes to
// it waits for them, and those waits were about half of this file's time.
constexpr int frameRun = sizeof(ManifoldFrame) / sizeof(double);
static_assert(sizeof(ManifoldFrame) == 57 * sizeof(double) &&
                  offsetof(ManifoldFrame, positionB) == 3 * sizeof(double) &&
                  offsetof(ManifoldFrame, directions) == 6 * sizeof(double) &&
                  offsetof(ManifoldFrame, inverseInertiaA) == 15 * sizeof(double) &&
                  offsetof(ManifoldFrame, inverseInertiaB) == 24 * sizeof(double) &&
                  offsetof(ManifoldFrame, angularMaskA) == 33 * sizeof(double) &&
                  offsetof(ManifoldFrame, linearVelocityA) == 39 * sizeof(double) &&
                  offsetof(ManifoldFrame, inverseMassA) == 51 * sizeof(double) &&
                  offsetof(ManifoldFrame, material) == 54 * sizeof(double) &&
                  offsetof(CombinedMaterial, staticFriction) == sizeof(double) &&
                  offsetof(CombinedMaterial, dynamicFriction) == 2 * sizeof(double),
              "frameLanes reads ManifoldFrame as one run of doubles in this order");
constexpr int pointRun = sizeof(ManifoldPoint) / sizeof(double);
static_assert(sizeof(ManifoldPoint) == 18 * sizeof(double) && offsetof(ManifoldPoint, pointB) == 3 * sizeof(double) &&
                  offsetof(ManifoldPoint, localA) == 6 * sizeof(double) &&
                  offsetof(ManifoldPoint, localB) == 9 * sizeof(double) &&
                  offsetof(ManifoldPoint, separation) == 12 * sizeof(double) &&
                  offsetof(ManifoldPoint, normalImpulse) == 14 * sizeof(double) &&
                  offsetof(ManifoldPoint, tangentImpulse) == 15 * sizeof(double) &&
                  offsetof(ManifoldPoint, stepNormalImpulse) == 17 * sizeof(double),
              "slotInput reads ManifoldPoint as one run of doubles in this order");
alignas(64) constexpr double emptyLane[std::max(frameRun, pointRun)] = {};

void copyRun(const Lanes* run, int first, Lanes (&target)[3]) {
  for (int axis = 0; axis < 3; ++axis) target[axis] = run[first + axis];
}

// Eigen's Mat3 is column-major: (row, column) at 3 column + row.
void copyMatrix(const Lanes* run, int first, Lanes (&target)[3][3]) {
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 3; ++column) target[row][column] = run[first + 3 * column + row];
}

FrameLanes frameLanes(const ManifoldFrame* frames, int count) {
  const double* runs[lanes];
  for (int lane = 0; lane < lanes; ++lane)
    runs[lane] = lane < count ? reinterpret_cast<const double*>(&frames[lane]) : emptyLane;
  Lanes run[frameRun];
  simd::gatherRuns<frameRun>(runs, run);
  FrameLanes result;
  copyRun(run, 0, result.positionA);
  copyRun(run, 3, result.positionB);
  for (int row = 0; row < 3; ++row) copyRun(run, 6 + 3 * row, result.directions[row]);
  copyMatrix(run, 15, result.inertiaA);
  copyMatrix(run, 24, result.inertiaB);
  copyRun(run, 33, result.angularMaskA);
  copyRun(run, 36, result.angularMaskB);
  copyRun(run, 39, result.linearVelocityA);
  copyRun(run, 42, result.angularVelocityA);
  copyRun(run, 45, result.linearVelocityB);
  copyRun(run, 48, result.angularVelocityB);
  result.inverseMassA = run[51];
  result.inverseMassB = run[52];
  result.inverseMassSum = run[53];
  result.restitution = run[54];
  result.staticFriction = run[55];
  result.dynamicFriction = run[56];
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
  const double* runs[lanes];
  for (int lane = 0; lane < lanes; ++lane) {
    const bool present = lane < count && p < manifolds[members[lane]].pointCount;
    runs[lane] = present ? reinterpret_cast<const double*>(&manifolds[members[lane]].points[p]) : emptyLane;
    simd::setMaskLane(in.present, lane, present);
  }
  Lanes run[pointRun];  // run[13] holds the feature id's bits: unused
  simd::gatherRuns<pointRun>(runs, run);
  copyRun(run, 0, in.pointA);
  copyRun(run, 3, in.pointB);
  copyRun(run, 6, in.localA);
  copyRun(run, 9, in.localB);
  in.separation = run[12];
  in.normalImpulse = run[14];
  in.tangentImpulse[0] = run[15];
  in.tangentImpulse[1] = run[16];
  in.stepNormalImpulse = run[17];
  return in;
}

// buildPointConstraints for one slot of every lane. Returns the slot's restitution.
Lanes buildSlot(const FrameLanes& frame, const SlotInput& in, const ConstraintSettings& settings, WidePoint& out,
                WideTurns* turns) {
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
  for (int axis = 0; axis < 3; ++axis) {
    out.armA[axis] = keep(armA[axis]);
    out.armB[axis] = keep(armB[axis]);
  }
  if (turns != nullptr)
    for (int row = 0; row < 3; ++row)
      for (int axis = 0; axis < 3; ++axis) {
        turns->turnA[row][axis] = keep(turnA[row][axis]);
        turns->turnB[row][axis] = keep(turnB[row][axis]);
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
                            const ManifoldFrame* frames, const std::vector<SolverBody>& bodies,
                            const BodyRanks& ranks, const ConstraintSettings& settings, WideManifolds& group) {
  count = std::min(count, lanes);
  group.pointSlots = 0;
  for (int lane = 0; lane < lanes; ++lane) {
    const bool used = lane < count;
    const std::uint32_t m = used ? members[lane] : WideManifolds::empty;
    const ContactManifold* manifold = used ? &manifolds[m] : nullptr;
    group.manifold[lane] = m;
    group.bodyA[lane] = used ? ranks(manifold->a) : WideManifolds::empty;
    group.bodyB[lane] = used ? ranks(manifold->b) : WideManifolds::empty;
    group.writableA[lane] = used && bodies[group.bodyA[lane]].movable;
    group.writableB[lane] = used && bodies[group.bodyB[lane]].movable;
    if (!used) continue;
    group.pointSlots = std::max(group.pointSlots, manifold->pointCount);
  }
  const FrameLanes frame = frameLanes(frames, count);
  // The frame's directions are the manifold's normal and tangents.
  for (int row = 0; row < 3; ++row)
    for (int axis = 0; axis < 3; ++axis) group.direction[row][axis] = frame.directions[row][axis];
  group.inverseMassA = frame.inverseMassA;
  group.inverseMassB = frame.inverseMassB;
  group.isotropic = true;
  group.spinScaleA = group.spinScaleB = Lanes::zero();
  for (int lane = 0; lane < count; ++lane) {
    double scaleA = 0.0, scaleB = 0.0;
    const bool both = spinScale(frames[lane].inverseInertiaA, frames[lane].angularMaskA, scaleA) &&
                      spinScale(frames[lane].inverseInertiaB, frames[lane].angularMaskB, scaleB);
    group.isotropic = group.isotropic && both;
    simd::setLane(group.spinScaleA, lane, scaleA);
    simd::setLane(group.spinScaleB, lane, scaleB);
  }
  unsigned bouncing = 0;
  for (int p = 0; p < group.pointSlots; ++p) {
    const SlotInput in = slotInput(members, count, manifolds, p);
    for (int axis = 0; axis < 3; ++axis) {
      group.anchors[p].localA[axis] = in.localA[axis];
      group.anchors[p].localB[axis] = in.localB[axis];
    }
    group.anchors[p].present = in.present;
    const Lanes restitution =
        buildSlot(frame, in, settings, group.points[p], group.isotropic ? nullptr : &group.turns[p]);
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
    const WideAnchors& anchors = group.anchors[p];
    const Lanes gap = centres + (dot(normalInB, anchors.localB) - dot(normalInA, anchors.localA));
    group.points[p].gap = simd::select(anchors.present, gap, Lanes::zero());
  }
}

}  // namespace physdbg
