#include "engine/solver/wide_contact_rows.h"

#include <algorithm>
#include <cassert>
#include <cstring>

namespace physdbg {
namespace {

using simd::Lanes;
constexpr int lanes = simd::width;

using simd::getLane;

// The velocities of one side's bodies, lane by lane (zero in empty lanes):
// v[0..2] linear, v[3..5] angular. A body's six velocities are one run of
// doubles (BodyMotion keeps angularVelocity right after linearVelocity), read
// as whole packets from every lane's body and transposed, so the lanes fill
// without a round trip through memory. Packets start at 0, W, 2W, ... and the
// last one ends at the sixth double (with 4 lanes: at 0 and 2, overlapping).
struct LaneVelocities {
  Lanes v[6];
  const Lanes* linear() const { return v; }
  const Lanes* angular() const { return v + 3; }
};

alignas(64) constexpr double noVelocity[6] = {};  // an empty lane's

const double* velocities(const BodyMotion& motion) {
  assert(motion.angularVelocity.data() == motion.linearVelocity.data() + 3);
  return motion.linearVelocity.data();
}

[[gnu::always_inline]] inline LaneVelocities gather(const std::array<std::uint32_t, lanes>& ids,
                                                    const std::vector<SolverBody>& bodies) {
  const double* rows[lanes];
  for (int lane = 0; lane < lanes; ++lane)
    rows[lane] = ids[lane] == WideManifolds::empty ? noVelocity : velocities(bodies[ids[lane]].motion);
  LaneVelocities result;
  simd::gatherRuns<6>(rows, result.v);
  return result;
}

// Only movable bodies are written: an immovable one (the floor) may sit in
// several lanes, groups and islands at once, and its velocity never changes.
[[gnu::always_inline]] inline void scatter(const LaneVelocities& velocities,
                                           const std::array<std::uint32_t, lanes>& ids,
                                           const std::array<bool, lanes>& writable, std::vector<SolverBody>& bodies) {
  for (int b = 0; b < simd::runBlocks(6); ++b) {
    const int start = simd::runBlockStart(6, b);
    Lanes block[lanes];
    for (int i = 0; i < lanes; ++i) block[i] = velocities.v[start + i];
    simd::transpose(block);
    for (int lane = 0; lane < lanes; ++lane)
      if (writable[lane]) block[lane].store(bodies[ids[lane]].motion.linearVelocity.data() + start);
  }
}

[[gnu::always_inline]] inline Lanes dot(const Lanes* x, const Lanes* y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

// The relative velocity along a row, as the scalar solver's rowVelocity.
[[gnu::always_inline]] inline Lanes rowVelocity(const LaneVelocities& a, const LaneVelocities& b,
                                                const WideManifolds& group, const RowCrosses& crosses, int row) {
  Lanes difference[3];
  for (int axis = 0; axis < 3; ++axis) difference[axis] = b.linear()[axis] - a.linear()[axis];
  return dot(difference, group.direction[row]) + dot(b.angular(), crosses.b) - dot(a.angular(), crosses.a);
}

// How a group is solved: `isotropic`, its turns are its crosses times a
// scale per lane (WideManifolds::isotropic), which spares the sweeps a third
// of their reads. No lane has a locked translation: such manifolds are
// solved one by one, with masked rows (SequentialImpulseSolver::hasLinearLocks).
template <bool isotropicIn>
struct Kind {
  static constexpr bool isotropic = isotropicIn;
};

template <class K>
[[gnu::always_inline]] inline void applyRow(LaneVelocities& a, LaneVelocities& b, const WideManifolds& group, int slot,
                                            int row, const RowCrosses& crosses, Lanes impulse) {
  const Lanes linearA = group.inverseMassA * impulse, linearB = group.inverseMassB * impulse;
  for (int axis = 0; axis < 3; ++axis) {
    const Lanes direction = group.direction[row][axis];
    const Lanes turnA = K::isotropic ? crosses.a[axis] * group.spinScaleA : group.turns[slot].turnA[row][axis];
    const Lanes turnB = K::isotropic ? crosses.b[axis] * group.spinScaleB : group.turns[slot].turnB[row][axis];
    a.v[axis] -= linearA * direction;
    a.v[3 + axis] -= impulse * turnA;
    b.v[axis] += linearB * direction;
    b.v[3 + axis] += impulse * turnB;
  }
}

template <class K>
[[gnu::always_inline]] inline void applyNormal(LaneVelocities& a, LaneVelocities& b, WideManifolds& group, int slot,
                                               const RowCrosses& crosses, Lanes impulse) {
  applyRow<K>(a, b, group, slot, 0, crosses, impulse);
  group.points[slot].stepNormalImpulse += impulse;
}

// Lanes whose manifold has no point within kReachedGap.
Lanes unreachedLanes(const WideManifolds& group) {
  const Lanes yes = simd::greater(Lanes::all(1.0), Lanes::zero());
  Lanes unreached = yes;
  for (int p = 0; p < group.pointSlots; ++p) {
    const Lanes open = simd::greater(group.points[p].gap, Lanes::all(kReachedGap));
    unreached = simd::both(unreached, simd::select(group.anchors[p].present, open, yes));
  }
  return unreached;
}

// `leave`: lanes to leave alone (unreachedLanes at the step's end), or none.
template <class K>
[[gnu::always_inline]] inline void solveNormal(LaneVelocities& a, LaneVelocities& b, WideManifolds& group, int slot,
                                               const WideSweep& sweep, const Lanes* leave) {
  WidePoint& point = group.points[slot];
  const Softness& softness = sweep.substeps->softness;
  const Lanes zero = Lanes::zero(), one = Lanes::all(1.0);
  const Lanes apart = simd::greater(point.gap, zero);
  const Lanes closing = point.gap / Lanes::all(sweep.substeps->h);
  Lanes bias = simd::select(apart, closing, zero), massScale = one, impulseScale = zero;
  if (sweep.useBias) {
    const Lanes push = simd::max(Lanes::all(softness.biasRate) * point.gap, Lanes::all(-sweep.maxPushSpeed));
    bias = simd::select(apart, closing, push);
    massScale = simd::select(apart, one, Lanes::all(softness.massScale));
    impulseScale = simd::select(apart, zero, Lanes::all(softness.impulseScale));
  }
  const RowCrosses crosses = rowCrosses(point, group.direction[0]);
  const Lanes normalVelocity = rowVelocity(a, b, group, crosses, 0);
  Lanes impulse = -point.normalMass * massScale * (normalVelocity + bias) - impulseScale * point.normalImpulse;
  if (leave) impulse = simd::select(*leave, zero, impulse);
  const Lanes total = simd::max(point.normalImpulse + impulse, zero);
  applyNormal<K>(a, b, group, slot, crosses, total - point.normalImpulse);
  point.normalImpulse = total;
  point.largestImpulse = simd::max(point.largestImpulse, total);
}

template <class K>
[[gnu::always_inline]] inline void solveFriction(LaneVelocities& a, LaneVelocities& b, WideManifolds& group, int slot) {
  WidePoint& point = group.points[slot];
  Lanes velocity[2], tangent[2];
  RowCrosses crosses[2];
  for (int t = 0; t < 2; ++t) {
    crosses[t] = rowCrosses(point, group.direction[t + 1]);
    velocity[t] = rowVelocity(a, b, group, crosses[t], t + 1);
    tangent[t] = point.tangentImpulse[t] - point.tangentMass[t] * velocity[t];
  }
  const Lanes limit = point.friction * point.normalImpulse;
  const Lanes squared = tangent[0] * tangent[0] + tangent[1] * tangent[1];
  const Lanes clamp = simd::both(simd::greater(squared, limit * limit), simd::greater(squared, Lanes::zero()));
  // Resting contacts stick: most sweeps clamp no lane, and the square root
  // and division were a fifth of the whole wide solve. A lane sliding past
  // what its full friction could stop gets the force opposing its sliding
  // velocity (the scalar solveFriction's rule).
  if (simd::any(clamp)) {
    const Lanes one = Lanes::all(1.0);
    const Lanes speed = velocity[0] * velocity[0] + velocity[1] * velocity[1];
    const Lanes least = simd::min(point.tangentMass[0], point.tangentMass[1]);
    const Lanes sliding = simd::greater(speed * least * least, limit * limit);
    const Lanes along = -limit / simd::sqrt(simd::select(sliding, speed, one));
    const Lanes scale = limit / simd::sqrt(simd::select(clamp, squared, one));
    for (int t = 0; t < 2; ++t)
      tangent[t] = simd::select(clamp, simd::select(sliding, velocity[t] * along, tangent[t] * scale), tangent[t]);
  }
  applyRow<K>(a, b, group, slot, 1, crosses[0], tangent[0] - point.tangentImpulse[0]);
  applyRow<K>(a, b, group, slot, 2, crosses[1], tangent[1] - point.tangentImpulse[1]);
  point.tangentImpulse[0] = tangent[0];
  point.tangentImpulse[1] = tangent[1];
}

}  // namespace

namespace {

// Gauss-Seidel hands each row's impulse to the next through the bodies'
// velocities, so one group's rows form a single chain of dependent
// arithmetic. Groups of one colour share no movable body: `count` of them are
// solved point by point side by side, each exactly as it would be alone, so
// their chains overlap. All of them must use the same point slots.
template <class K, int count>
void warmStartGroups(WideManifolds* const* groups, std::vector<SolverBody>& bodies) {
  LaneVelocities a[count], b[count];
  for (int g = 0; g < count; ++g) {
    a[g] = gather(groups[g]->bodyA, bodies);
    b[g] = gather(groups[g]->bodyB, bodies);
  }
  for (int p = 0; p < groups[0]->pointSlots; ++p)
    for (int g = 0; g < count; ++g) {
      const WidePoint& point = groups[g]->points[p];
      const WideManifolds& group = *groups[g];
      applyNormal<K>(a[g], b[g], *groups[g], p, rowCrosses(point, group.direction[0]), point.normalImpulse);
      applyRow<K>(a[g], b[g], group, p, 1, rowCrosses(point, group.direction[1]), point.tangentImpulse[0]);
      applyRow<K>(a[g], b[g], group, p, 2, rowCrosses(point, group.direction[2]), point.tangentImpulse[1]);
    }
  for (int g = 0; g < count; ++g) {
    scatter(a[g], groups[g]->bodyA, groups[g]->writableA, bodies);
    scatter(b[g], groups[g]->bodyB, groups[g]->writableB, bodies);
  }
}

template <class K, int count>
void solveGroups(WideManifolds* const* groups, std::vector<SolverBody>& bodies, const WideSweep& sweep) {
  LaneVelocities a[count], b[count];
  for (int g = 0; g < count; ++g) {
    a[g] = gather(groups[g]->bodyA, bodies);
    b[g] = gather(groups[g]->bodyB, bodies);
  }
  const int used = groups[0]->pointSlots;
  Lanes unreached[count];
  if (sweep.stepEnds)
    for (int g = 0; g < count; ++g) unreached[g] = unreachedLanes(*groups[g]);
  for (int visit = 0; visit < used; ++visit) {
    const int p = sweep.reversed ? used - 1 - visit : visit;
    for (int g = 0; g < count; ++g) solveNormal<K>(a[g], b[g], *groups[g], p, sweep, sweep.stepEnds ? &unreached[g] : nullptr);
  }
  for (int visit = 0; visit < used; ++visit) {
    const int p = sweep.reversed ? used - 1 - visit : visit;
    for (int g = 0; g < count; ++g) solveFriction<K>(a[g], b[g], *groups[g], p);
  }
  for (int g = 0; g < count; ++g) {
    scatter(a[g], groups[g]->bodyA, groups[g]->writableA, bodies);
    scatter(b[g], groups[g]->bodyB, groups[g]->writableB, bodies);
  }
}

// Groups run together share their kind's `isotropic` (sideBySide).
template <template <class, int> class Solve, int count, class... Arguments>
void runTogether(std::span<WideManifolds> groups, Arguments&... arguments) {
  WideManifolds* together[count];
  for (int g = 0; g < count; ++g) together[g] = &groups[g];
  if (groups[0].isotropic)
    Solve<Kind<true>, count>::run(together, arguments...);
  else
    Solve<Kind<false>, count>::run(together, arguments...);
}

bool runsWith(const WideManifolds& group, const WideManifolds& first) {
  return group.pointSlots == first.pointSlots && group.isotropic == first.isotropic;
}

// Runs Solve over the groups, up to four side by side where their point
// slots and isotropy match (measured on a 1000-box drop: one at a time 0.86
// ms of islands per step, two 0.82, four 0.80).
template <template <class, int> class Solve, class... Arguments>
void sideBySide(std::span<WideManifolds> groups, Arguments&... arguments) {
  for (std::size_t i = 0; i < groups.size();) {
    std::size_t same = 1;
    while (same < 4 && i + same < groups.size() && runsWith(groups[i + same], groups[i])) ++same;
    const std::span<WideManifolds> rest = groups.subspan(i);
    if (same == 4) {
      runTogether<Solve, 4>(rest, arguments...);
      i += 4;
    } else if (same >= 2) {
      runTogether<Solve, 2>(rest, arguments...);
      i += 2;
    } else {
      runTogether<Solve, 1>(rest, arguments...);
      i += 1;
    }
  }
}

template <class K, int count>
struct WarmStart {
  static void run(WideManifolds* const* groups, std::vector<SolverBody>& bodies) {
    warmStartGroups<K, count>(groups, bodies);
  }
};

template <class K, int count>
struct Sweep {
  static void run(WideManifolds* const* groups, std::vector<SolverBody>& bodies, const WideSweep& sweep) {
    solveGroups<K, count>(groups, bodies, sweep);
  }
};

}  // namespace

void warmStartWide(std::span<WideManifolds> groups, std::vector<SolverBody>& bodies) {
  sideBySide<WarmStart>(groups, bodies);
}

void solveWide(std::span<WideManifolds> groups, std::vector<SolverBody>& bodies, const WideSweep& sweep) {
  sideBySide<Sweep>(groups, bodies, sweep);
}

void attachSlots(WideManifolds& group, WideSlots& slots, std::size_t first) {
  group.points = slots.points.data() + first;
  group.anchors = slots.anchors.data() + first;
  group.turns = slots.turns.data() + first;
}

void storeWideImpulses(const WideManifolds& group, std::vector<ContactManifold>& manifolds,
                       PointConstraint* constraints, const std::vector<std::size_t>& constraintStart,
                       const std::vector<char>& kept) {
  for (int lane = 0; lane < lanes; ++lane) {
    const std::uint32_t m = group.manifold[lane];
    if (m == WideManifolds::empty) continue;
    ContactManifold& manifold = manifolds[m];
    for (int p = 0; p < manifold.pointCount; ++p) {
      const WidePoint& wide = group.points[p];
      ManifoldPoint& point = manifold.points[p];
      point.normalImpulse = getLane(wide.normalImpulse, lane);
      point.tangentImpulse[0] = getLane(wide.tangentImpulse[0], lane);
      point.tangentImpulse[1] = getLane(wide.tangentImpulse[1], lane);
      point.stepNormalImpulse = getLane(wide.stepNormalImpulse, lane);
      if (kept[m]) constraints[constraintStart[m] + p].largestImpulse = getLane(wide.largestImpulse, lane);
    }
  }
}

}  // namespace physdbg
