// buildWideManifolds (wide_contact_rows.h) builds a group's constraints in
// SIMD lanes; each lane must hold, bit for bit, what buildPointConstraints
// (point_constraint.h) gives for its manifold, and slots a manifold lacks
// must hold zeros. Random frames: turned inertia, locked axes, moving
// bodies, touching and speculative points, bouncing and resting. Groups of
// one colour solved side by side must give what each gives alone.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <span>
#include <vector>

#include "engine/solver/point_constraint.h"
#include "engine/solver/wide_contact_rows.h"

namespace physdbg {
namespace {

// The tests' bodies are indexed by id: every body ranks as itself.
BodyRanks identityRanks(const std::vector<SolverBody>& bodies) {
  std::vector<std::uint32_t> ids(bodies.size());
  for (std::uint32_t id = 0; id < ids.size(); ++id) ids[id] = id;
  BodyRanks ranks;
  ranks.assign(ids, bodies.size());
  return ranks;
}


using simd::Lanes;

struct Case {
  std::vector<ContactManifold> manifolds;
  std::vector<ManifoldTangents> tangents;
  std::vector<SolverBody> bodies;
  std::vector<ManifoldFrame> frames;
};

Vec3 randomVector(std::mt19937& random, double scale) {
  std::uniform_real_distribution<double> value(-scale, scale);
  return Vec3(value(random), value(random), value(random));
}

Mat3 randomInverseInertia(std::mt19937& random) {
  const Mat3 rotation = Quat(Eigen::AngleAxisd(2.0, randomVector(random, 1.0).normalized())).toRotationMatrix();
  std::uniform_real_distribution<double> moment(0.2, 5.0);
  return rotation * Vec3(moment(random), moment(random), moment(random)).asDiagonal() * rotation.transpose();
}

// Spheres and cubes: the same moment about every axis.
Mat3 isotropicInverseInertia(std::mt19937& random) {
  std::uniform_real_distribution<double> moment(0.2, 5.0);
  return Mat3::Identity() * moment(random);
}

// isotropic: every body's inverse inertia is a multiple of the identity
// (zero for the still ones) and no rotation is locked.
ManifoldFrame randomFrame(std::mt19937& random, const ContactManifold& manifold, const ManifoldTangents& tangents,
                          bool isotropic) {
  std::bernoulli_distribution locked(0.2), still(0.3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ManifoldFrame frame;
  frame.positionA = randomVector(random, 3.0);
  frame.positionB = randomVector(random, 3.0);
  frame.directions[0] = manifold.normal;
  frame.directions[1] = tangents[0];
  frame.directions[2] = tangents[1];
  frame.inverseInertiaA = isotropic ? isotropicInverseInertia(random) : randomInverseInertia(random);
  frame.inverseInertiaB =
      still(random) ? Mat3::Zero() : (isotropic ? isotropicInverseInertia(random) : randomInverseInertia(random));
  for (int axis = 0; axis < 3; ++axis) {
    frame.angularMaskA[axis] = !isotropic && locked(random) ? 0.0 : 1.0;
    frame.angularMaskB[axis] = !isotropic && locked(random) ? 0.0 : 1.0;
  }
  frame.linearVelocityA = randomVector(random, 2.0);
  frame.angularVelocityA = randomVector(random, 2.0);
  frame.linearVelocityB = still(random) ? Vec3::Zero() : randomVector(random, 2.0);
  frame.angularVelocityB = randomVector(random, 1.0);
  frame.inverseMassA = unit(random);
  frame.inverseMassB = still(random) ? 0.0 : unit(random);
  frame.inverseMassSum = frame.inverseMassA + frame.inverseMassB;
  frame.material = {unit(random), unit(random), 0.5 * unit(random)};
  return frame;
}

Case randomCase(std::mt19937& random, int count, bool isotropic = false) {
  Case result;
  std::uniform_int_distribution<int> points(1, ContactManifold::maxPoints);
  std::uniform_real_distribution<double> separation(-0.02, 0.03);
  for (int lane = 0; lane < count; ++lane) {
    ContactManifold manifold;
    manifold.a = 2 * lane;
    manifold.b = 2 * lane + 1;
    manifold.normal = randomVector(random, 1.0).normalized();
    manifold.pointCount = points(random);
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = manifold.points[p];
      point.pointA = randomVector(random, 3.0);
      point.separation = separation(random);
      point.pointB = point.pointA + point.separation * manifold.normal;
      point.normalImpulse = 0.1 * p;
      point.tangentImpulse[0] = -0.05 * p;
      point.tangentImpulse[1] = 0.02 * lane;
    }
    ManifoldTangents tangents;
    tangents[0] = manifold.normal.unitOrthogonal();
    tangents[1] = manifold.normal.cross(tangents[0]);
    result.frames.push_back(randomFrame(random, manifold, tangents, isotropic));
    result.manifolds.push_back(manifold);
    result.tangents.push_back(tangents);
  }
  result.bodies.resize(2 * count);
  for (SolverBody& body : result.bodies) body.movable = true;
  return result;
}

// Bit for bit, so that -0 and 0 differ too.
void expectSame(double expected, const Lanes& lanes, int lane, const char* field, int p) {
  const double actual = simd::getLane(lanes, lane);
  EXPECT_EQ(0, std::memcmp(&expected, &actual, sizeof expected))
      << field << ", lane " << lane << ", point " << p << ": " << expected << " vs " << actual;
}

// A group with room for every point slot (WideSlots).
struct SlottedGroup {
  WideSlots slots;
  WideManifolds group;
  SlottedGroup() {
    slots.resize(ContactManifold::maxPoints);
    attachSlots(group, slots, 0);
  }
  SlottedGroup(const SlottedGroup&) = delete;
  SlottedGroup& operator=(const SlottedGroup&) = delete;
};

TEST(WideConstraintBuild, LanesHoldTheScalarConstraintsBitForBit) {
  std::mt19937 random(17);
  const ConstraintSettings settings{0.005, 0.02, 0.2};
  for (int trial = 0; trial < 200; ++trial) {
    const int count = 1 + trial % simd::width;
    const bool isotropic = trial % 3 == 2;
    const Case input = randomCase(random, count, isotropic);
    std::vector<std::uint32_t> members(count);
    for (int lane = 0; lane < count; ++lane) members[lane] = static_cast<std::uint32_t>(lane);
    SlottedGroup slotted;
    WideManifolds& group = slotted.group;
    const unsigned bouncing =
        buildWideManifolds(members.data(), count, input.manifolds, input.frames.data(), input.bodies, identityRanks(input.bodies), settings, group);
    int mostPoints = 0;
    for (int lane = 0; lane < count; ++lane) {
      const ContactManifold& manifold = input.manifolds[lane];
      mostPoints = std::max(mostPoints, manifold.pointCount);
      PointConstraint expected[ContactManifold::maxPoints];
      buildPointConstraints(input.frames[lane], manifold, settings, expected);
      bool bounces = false;
      for (int p = 0; p < manifold.pointCount; ++p) {
        const PointConstraint& c = expected[p];
        const WidePoint& wide = group.points[p];
        bounces = bounces || c.restitution != 0.0;
        expectSame(c.normalMass, wide.normalMass, lane, "normalMass", p);
        expectSame(c.tangentMass[0], wide.tangentMass[0], lane, "tangentMass[0]", p);
        expectSame(c.tangentMass[1], wide.tangentMass[1], lane, "tangentMass[1]", p);
        expectSame(c.friction, wide.friction, lane, "friction", p);
        expectSame(manifold.points[p].normalImpulse, wide.normalImpulse, lane, "normalImpulse", p);
        expectSame(manifold.points[p].tangentImpulse[1], wide.tangentImpulse[1], lane, "tangentImpulse[1]", p);
        for (int axis = 0; axis < 3; ++axis) {
          expectSame(c.armA[axis], wide.armA[axis], lane, "armA", p);
          expectSame(c.armB[axis], wide.armB[axis], lane, "armB", p);
        }
        for (int row = 0; row < 3; ++row)
          for (int axis = 0; axis < 3; ++axis) {
            // The sweeps' crosses, taken from the arms.
            const RowCrosses crosses = rowCrosses(wide, group.direction[row]);
            expectSame(c.crossA[row][axis], crosses.a[axis], lane, "crossA", p);
            expectSame(c.crossB[row][axis], crosses.b[axis], lane, "crossB", p);
            if (!group.isotropic) {
              expectSame(c.turnA[row][axis], group.turns[p].turnA[row][axis], lane, "turnA", p);
              expectSame(c.turnB[row][axis], group.turns[p].turnB[row][axis], lane, "turnB", p);
              continue;
            }
            // The solve's turn: the cross times the lane's scale, the same
            // number (a zero's sign aside, which no sum keeps).
            const double turnA = simd::getLane(crosses.a[axis] * group.spinScaleA, lane);
            const double turnB = simd::getLane(crosses.b[axis] * group.spinScaleB, lane);
            EXPECT_EQ(c.turnA[row][axis], turnA) << "isotropic turnA, lane " << lane << ", point " << p;
            EXPECT_EQ(c.turnB[row][axis], turnB) << "isotropic turnB, lane " << lane << ", point " << p;
          }
      }
      EXPECT_EQ(bounces, (bouncing >> lane & 1u) != 0) << "trial " << trial << ", lane " << lane;
      expectSame(input.frames[lane].inverseMassA, group.inverseMassA, lane, "inverseMassA", 0);
      // A slot the manifold lacks changes nothing: no mass, no impulse.
      for (int p = manifold.pointCount; p < mostPoints; ++p) {
        expectSame(0.0, group.points[p].normalMass, lane, "empty normalMass", p);
        if (!group.isotropic) expectSame(0.0, group.turns[p].turnA[1][2], lane, "empty turnA", p);
        expectSame(0.0, group.points[p].armA[2], lane, "empty armA", p);
        expectSame(0.0, group.points[p].normalImpulse, lane, "empty normalImpulse", p);
      }
    }
    EXPECT_EQ(group.pointSlots, mostPoints);
    EXPECT_EQ(group.isotropic, isotropic) << "trial " << trial;
    for (int lane = count; lane < simd::width; ++lane) {
      EXPECT_EQ(group.manifold[lane], WideManifolds::empty);
      EXPECT_FALSE(group.writableA[lane]);
      for (int p = 0; p < group.pointSlots; ++p) expectSame(0.0, group.points[p].tangentMass[0], lane, "empty lane", p);
    }
    if (HasFailure()) FAIL() << "trial " << trial;
  }
}

// A group takes the scaled-cross turns only when every lane, on both sides,
// has an inverse inertia that is exactly a scale times the identity and no
// locked rotation.
TEST(WideConstraintBuild, IsotropicOnlyWhenEveryLaneTurnsByAScale) {
  std::mt19937 random(41);
  const ConstraintSettings settings{0.005, 0.02, 0.2};
  const auto build = [&](const Case& input) {
    std::vector<std::uint32_t> members(simd::width);
    for (int lane = 0; lane < simd::width; ++lane) members[lane] = static_cast<std::uint32_t>(lane);
    SlottedGroup slotted;
    buildWideManifolds(members.data(), simd::width, input.manifolds, input.frames.data(), input.bodies, identityRanks(input.bodies), settings,
                       slotted.group);
    return slotted.group.isotropic;
  };
  for (int trial = 0; trial < 20; ++trial) {
    Case input = randomCase(random, simd::width, true);
    EXPECT_TRUE(build(input));
    const int lane = trial % simd::width;
    Case locked = input;
    locked.frames[lane].angularMaskB[trial % 3] = 0.0;
    EXPECT_FALSE(build(locked));
    Case turned = input;
    turned.frames[lane].inverseInertiaA = randomInverseInertia(random);
    EXPECT_FALSE(build(turned));
    Case stretched = input;
    stretched.frames[lane].inverseInertiaA(2, 2) *= 1.5;
    EXPECT_FALSE(build(stretched));
    // -0 off the diagonal is the same matrix, but its product's zeros could
    // take its sign: only +0 counts.
    Case negativeZero = input;
    negativeZero.frames[lane].inverseInertiaA(0, 1) = -0.0;
    EXPECT_FALSE(build(negativeZero));
  }
}

// The same isotropic groups solved with the scaled crosses and with stored
// turns (a -0 off the diagonal makes the build store them) give the same
// velocities and impulses, as numbers.
TEST(WideContactRows, IsotropicGroupsSolveAsStoredTurnsWould) {
  std::mt19937 random(43);
  const ConstraintSettings settings{0.005, 0.02, 0.2};
  const StepContext step;
  const SubstepContext substeps = substepContext(step, 4, 60.0, 5.0);
  for (int trial = 0; trial < 20; ++trial) {
    Case input = randomCase(random, simd::width, true);
    for (SolverBody& body : input.bodies) {
      body.motion.linearVelocity = randomVector(random, 2.0);
      body.motion.angularVelocity = randomVector(random, 2.0);
    }
    Case stored = input;
    for (ManifoldFrame& frame : stored.frames) frame.inverseInertiaA(1, 0) = -0.0;
    std::vector<std::uint32_t> members(simd::width);
    for (int lane = 0; lane < simd::width; ++lane) members[lane] = static_cast<std::uint32_t>(lane);
    WideGroups scaled(1), turned(1);
    WideSlots scaledSlots, turnedSlots;
    scaledSlots.resize(ContactManifold::maxPoints);
    turnedSlots.resize(ContactManifold::maxPoints);
    attachSlots(scaled[0], scaledSlots, 0);
    attachSlots(turned[0], turnedSlots, 0);
    buildWideManifolds(members.data(), simd::width, input.manifolds, input.frames.data(), input.bodies, identityRanks(input.bodies), settings,
                       scaled[0]);
    buildWideManifolds(members.data(), simd::width, stored.manifolds, stored.frames.data(), stored.bodies, identityRanks(stored.bodies), settings,
                       turned[0]);
    ASSERT_TRUE(scaled[0].isotropic);
    ASSERT_FALSE(turned[0].isotropic);
    for (WideGroups* groups : {&scaled, &turned})
      for (int p = 0; p < (*groups)[0].pointSlots; ++p) (*groups)[0].points[p].gap = Lanes::all(0.01 * (p - 1));
    const auto sweep = [&](WideGroups& groups, std::vector<SolverBody>& bodies) {
      const std::span<WideManifolds> these(groups.data(), groups.size());
      warmStartWide(these, bodies);
      solveWide(these, bodies, WideSweep{&substeps, 3.0, true, false});
      solveWide(these, bodies, WideSweep{&substeps, 3.0, false, true});
    };
    sweep(scaled, input.bodies);
    sweep(turned, stored.bodies);
    for (std::size_t id = 0; id < input.bodies.size(); ++id)
      for (int axis = 0; axis < 3; ++axis) {
        EXPECT_EQ(input.bodies[id].motion.linearVelocity[axis], stored.bodies[id].motion.linearVelocity[axis]);
        EXPECT_EQ(input.bodies[id].motion.angularVelocity[axis], stored.bodies[id].motion.angularVelocity[axis]);
      }
    for (int p = 0; p < scaled[0].pointSlots; ++p)
      for (int lane = 0; lane < simd::width; ++lane) {
        EXPECT_EQ(simd::getLane(scaled[0].points[p].normalImpulse, lane),
                  simd::getLane(turned[0].points[p].normalImpulse, lane));
        EXPECT_EQ(simd::getLane(scaled[0].points[p].tangentImpulse[1], lane),
                  simd::getLane(turned[0].points[p].tangentImpulse[1], lane));
      }
    if (HasFailure()) FAIL() << "trial " << trial;
  }
}

// measureWideGaps gives each lane what pointGaps gives its manifold, bit
// for bit, and 0 where a lane has no such point.
TEST(WideConstraintBuild, LaneGapsMatchTheScalarGapsBitForBit) {
  std::mt19937 random(23);
  const ConstraintSettings settings{0.005, 0.02, 0.2};
  for (int trial = 0; trial < 200; ++trial) {
    const int count = 1 + trial % simd::width;
    Case input = randomCase(random, count);
    for (ContactManifold& manifold : input.manifolds)
      for (int p = 0; p < manifold.pointCount; ++p) {
        manifold.points[p].localA = randomVector(random, 0.7);
        manifold.points[p].localB = randomVector(random, 0.7);
      }
    for (SolverBody& body : input.bodies) {
      body.motion.position = randomVector(random, 5.0);
      body.rotation = Quat(Eigen::AngleAxisd(3.0, randomVector(random, 1.0).normalized())).toRotationMatrix();
    }
    std::vector<std::uint32_t> members(count);
    for (int lane = 0; lane < count; ++lane) members[lane] = static_cast<std::uint32_t>(lane);
    SlottedGroup slotted;
    WideManifolds& group = slotted.group;
    buildWideManifolds(members.data(), count, input.manifolds, input.frames.data(), input.bodies, identityRanks(input.bodies), settings, group);
    measureWideGaps(group, input.bodies);
    for (int lane = 0; lane < count; ++lane) {
      const ContactManifold& manifold = input.manifolds[lane];
      const SolverBody &a = input.bodies[manifold.a], &b = input.bodies[manifold.b];
      double gaps[ContactManifold::maxPoints];
      pointGaps(manifold, a.motion.position, a.rotation, b.motion.position, b.rotation, gaps);
      for (int p = 0; p < group.pointSlots; ++p)
        expectSame(p < manifold.pointCount ? gaps[p] : 0.0, group.points[p].gap, lane, "gap", p);
    }
    if (HasFailure()) FAIL() << "trial " << trial;
  }
}

// solveWide and warmStartWide interleave up to four groups of one colour
// (they share no movable body); each must end exactly as it would alone.
// Seven groups make a bundle of four, then of two, then one alone; groups
// with one point slot among groups with four break bundles; one group has a
// locked axis, so its bundle takes the masks; two are isotropic, which runs
// them apart from the rest; some bodies do not move.
TEST(WideContactRows, GroupsSolvedSideBySideEndAsTheyWouldAlone) {
  std::mt19937 random(29);
  const ConstraintSettings settings{0.005, 0.02, 0.2};
  const StepContext step;
  const SubstepContext substeps = substepContext(step, 4, 60.0, 5.0);
  constexpr int groupCount = 7;
  for (int trial = 0; trial < 20; ++trial) {
    Case input = randomCase(random, groupCount * simd::width);
    const int onePoint = trial % groupCount, locked = (trial + 3) % groupCount;
    // Two isotropic groups: they run apart from the others, side by side
    // when they are neighbours.
    for (const int isotropic : {(trial + 5) % groupCount, (trial + 6) % groupCount})
      for (int lane = 0; lane < simd::width; ++lane) {
        ManifoldFrame& frame = input.frames[isotropic * simd::width + lane];
        frame.inverseInertiaA = isotropicInverseInertia(random);
        frame.inverseInertiaB = isotropicInverseInertia(random);
        frame.angularMaskA = frame.angularMaskB = Vec3::Ones();
      }
    for (std::size_t m = 0; m < input.manifolds.size(); ++m)
      if (static_cast<int>(m) / simd::width == onePoint) input.manifolds[m].pointCount = 1;
    for (std::size_t id = 0; id < input.bodies.size(); ++id) {
      SolverBody& body = input.bodies[id];
      body.motion.linearVelocity = randomVector(random, 2.0);
      body.motion.angularVelocity = randomVector(random, 2.0);
      body.movable = id % 5 != 3;
      const int group = static_cast<int>(id / 2) / simd::width;
      if (group == locked && id % 2 == 0) body.linearMask = Vec3(1.0, 0.0, 1.0);
    }
    constexpr int slotsEach = ContactManifold::maxPoints;
    WideGroups groups(groupCount);
    WideSlots slots;
    slots.resize(groupCount * slotsEach);
    for (int g = 0; g < groupCount; ++g) {
      attachSlots(groups[g], slots, g * slotsEach);
      const int count = g == groupCount - 1 ? std::max(1, simd::width - 1) : simd::width;
      std::vector<std::uint32_t> members(count);
      for (int lane = 0; lane < count; ++lane) members[lane] = static_cast<std::uint32_t>(g * simd::width + lane);
      buildWideManifolds(members.data(), count, input.manifolds, input.frames.data() + g * simd::width,
                         input.bodies, identityRanks(input.bodies), settings, groups[g]);
      for (int p = 0; p < groups[g].pointSlots; ++p) groups[g].points[p].gap = Lanes::all(0.01 * (p - 1));
    }
    WideGroups alone = groups;
    WideSlots slotsAlone = slots;
    for (int g = 0; g < groupCount; ++g) attachSlots(alone[g], slotsAlone, g * slotsEach);
    std::vector<SolverBody> bodiesAlone = input.bodies;
    const auto sweep = [&](std::span<WideManifolds> these, std::vector<SolverBody>& bodies, bool reversed) {
      warmStartWide(these, bodies);
      solveWide(these, bodies, WideSweep{&substeps, 3.0, true, reversed});
      solveWide(these, bodies, WideSweep{&substeps, 3.0, false, !reversed});
    };
    for (int pass = 0; pass < 2; ++pass) {
      sweep(std::span<WideManifolds>(groups.data(), groups.size()), input.bodies, pass == 1);
      for (WideManifolds& group : alone) sweep(std::span<WideManifolds>(&group, 1), bodiesAlone, pass == 1);
    }
    for (std::size_t id = 0; id < input.bodies.size(); ++id) {
      const BodyMotion &together = input.bodies[id].motion, &single = bodiesAlone[id].motion;
      for (int axis = 0; axis < 3; ++axis) {
        EXPECT_EQ(0, std::memcmp(&together.linearVelocity[axis], &single.linearVelocity[axis], sizeof(double)))
            << "body " << id << ", axis " << axis;
        EXPECT_EQ(0, std::memcmp(&together.angularVelocity[axis], &single.angularVelocity[axis], sizeof(double)))
            << "body " << id << ", axis " << axis;
      }
    }
    for (int g = 0; g < groupCount; ++g)
      for (int p = 0; p < groups[g].pointSlots; ++p)
        for (int lane = 0; lane < simd::width; ++lane) {
          const WidePoint &together = groups[g].points[p], &single = alone[g].points[p];
          expectSame(simd::getLane(single.normalImpulse, lane), together.normalImpulse, lane, "normalImpulse", p);
          expectSame(simd::getLane(single.tangentImpulse[0], lane), together.tangentImpulse[0], lane, "tangent", p);
          expectSame(simd::getLane(single.tangentImpulse[1], lane), together.tangentImpulse[1], lane, "tangent", p);
        }
    if (HasFailure()) FAIL() << "trial " << trial;
  }
}

}  // namespace
}  // namespace physdbg
