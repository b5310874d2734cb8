// The box-box separating-axis path against GJK + EPA on random pairs, and on
// cases whose answer is known exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "box_box_test_support.h"

namespace physdbg {
namespace {

using testing::BoxPair;
using testing::boxSurfaceDistance;
using testing::gjkEpaOnly;

// EPA and GJK are asserted exact to 1e-9 of the pair's size (GjkEpaProperty);
// the separating axes are exact to round-off, so that is the bound for both.
constexpr double kRelative = 1e-9;
// Normals of the two paths; GJK/EPA normals of near-ties are less well
// conditioned than their depths (as in ConvexMeshCubeMatchesTheBox).
constexpr double kNormal = 1e-7;

// Largest differences seen, printed for the record.
struct Agreement {
  double normal = 0, depth = 0, distance = 0, offSurface = 0;
  int penetrating = 0, touching = 0, separated = 0, gjkFallbacks = 0;
  void print(const char* label) const {
    std::printf("[%s] penetrating %d, touching %d, separated %d (GJK for %d); largest |normal difference| %.3g, "
                "|depth difference| %.3g m, |distance difference| %.3g m, witness off surface %.3g m\n",
                label, penetrating, touching, separated, gjkFallbacks, normal, depth, distance, offSurface);
  }
};

double signedDistance(const ContactResult& r) { return r.status == ContactStatus::Penetrating ? -r.depth : r.distance; }

// Compares the two paths on one pair; `expectedDistance` (when >= 0) is the
// distance known by construction.
void compare(const BoxPair& p, Agreement& agreement, double expectedDistance = -1.0) {
  const BoxCollider a(p.halfA), b(p.halfB);
  const ContactResult sat = collide(a, p.ta, b, p.tb);
  const ContactResult reference = collide(a, p.ta, b, p.tb, gjkEpaOnly());
  testing::expectFinite(sat);
  EXPECT_TRUE(sat.usedBoxBox);
  EXPECT_EQ(sat.epaIterations, 0);
  const double size = p.halfA.norm() + p.halfB.norm();
  const double tolerance = kRelative * size;
  // Witness points lie on both surfaces.
  const double offA = std::abs(boxSurfaceDistance(p.halfA, p.ta, sat.pointA));
  const double offB = std::abs(boxSurfaceDistance(p.halfB, p.tb, sat.pointB));
  EXPECT_LE(offA, tolerance);
  EXPECT_LE(offB, tolerance);
  agreement.offSurface = std::max({agreement.offSurface, offA, offB});
  if (sat.gjkIterations > 0) ++agreement.gjkFallbacks;
  // Within a few touching tolerances of contact either verdict is right.
  if (std::abs(signedDistance(reference)) < 3e-6) {
    EXPECT_LE(std::abs(signedDistance(sat) - signedDistance(reference)), 2e-6);
    if (sat.status == ContactStatus::Touching) ++agreement.touching;
    return;
  }
  ASSERT_EQ(sat.status, reference.status) << signedDistance(reference);
  const double normalDifference = (sat.normal - reference.normal).norm();
  EXPECT_LE(normalDifference, kNormal);
  agreement.normal = std::max(agreement.normal, normalDifference);
  if (sat.status == ContactStatus::Penetrating) {
    ++agreement.penetrating;
    EXPECT_NEAR(sat.depth, reference.depth, tolerance);
    agreement.depth = std::max(agreement.depth, std::abs(sat.depth - reference.depth));
    EXPECT_LE((sat.pointA - sat.pointB - sat.depth * sat.normal).norm(), tolerance);
  } else {
    ++agreement.separated;
    EXPECT_NEAR(sat.distance, reference.distance, tolerance);
    agreement.distance = std::max(agreement.distance, std::abs(sat.distance - reference.distance));
    EXPECT_NEAR((sat.pointB - sat.pointA).norm(), sat.distance, tolerance);
    if (expectedDistance >= 0.0) {
      EXPECT_NEAR(sat.distance, expectedDistance, tolerance);
    }
  }
}

// B moved along the pair's own contact normal by `shift`.
BoxPair movedAlong(BoxPair p, const Vec3& normal, double shift) {
  p.tb.position += shift * normal;
  return p;
}

// `count` random pairs of boxes with half extents in [halfMin, halfMax],
// centres within `spread` of the origin on each axis.
Agreement randomSweep(unsigned seed, int count, double halfMin, double halfMax, double spread, const char* label) {
  std::mt19937 rng(seed);
  Agreement agreement;
  for (int i = 0; i < count; ++i) {
    SCOPED_TRACE(i);
    compare(testing::randomBoxPair(rng, halfMin, halfMax, spread), agreement);
  }
  agreement.print(label);
  return agreement;
}

TEST(BoxBoxContact, DeepRotatedPairsAgreeWithGjkEpa) {
  EXPECT_GT(randomSweep(2024, 3000, 0.1, 1.5, 1.0, "deep").penetrating, 2000);
}

// Each penetrating pair moved out along its normal by exactly its depth
// (touching) and then by a gap the solver would still reach (separated: the
// distance is the gap, since the closest features stay those of the normal).
TEST(BoxBoxContact, TouchingAndSeparatedWithinReachAgreeWithGjkEpa) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> gap(1e-5, 0.05);
  Agreement touching, separated;
  for (int i = 0; i < 1500; ++i) {
    SCOPED_TRACE(i);
    const BoxPair p = testing::randomBoxPair(rng, 0.1, 1.5, 1.0);
    const ContactResult start = collide(BoxCollider(p.halfA), p.ta, BoxCollider(p.halfB), p.tb, gjkEpaOnly());
    if (start.status != ContactStatus::Penetrating) continue;
    compare(movedAlong(p, start.normal, start.depth), touching);
    const double g = gap(rng);
    compare(movedAlong(p, start.normal, start.depth + g), separated, g);
  }
  touching.print("touching");
  separated.print("separated within reach");
  EXPECT_GT(touching.touching, 1000);
  EXPECT_GT(separated.separated, 1000);
}

TEST(BoxBoxContact, FarFromTheOriginAgreesWithGjkEpa) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> gap(1e-5, 0.05);
  Agreement agreement;
  const std::vector<Transform> motions = testing::testMotions(19);
  for (int i = 0; i < 600; ++i) {
    SCOPED_TRACE(i);
    BoxPair p = testing::randomBoxPair(rng, 0.1, 1.5, 1.0);
    const Transform& motion = motions[1 + i % (motions.size() - 1)];
    p.ta = testing::compose(motion, p.ta);
    p.tb = testing::compose(motion, p.tb);
    compare(p, agreement);
    const ContactResult start = collide(BoxCollider(p.halfA), p.ta, BoxCollider(p.halfB), p.tb, gjkEpaOnly());
    if (start.status == ContactStatus::Penetrating) compare(movedAlong(p, start.normal, start.depth + gap(rng)), agreement);
  }
  agreement.print("far from origin");
  EXPECT_GT(agreement.separated, 200);
}

// Separated pairs anywhere around each other: vertex against vertex and edge
// against parallel edge have closest directions no axis names, so GJK runs.
TEST(BoxBoxContact, SeparatedPairsGetTheExactDistance) {
  const Agreement agreement = randomSweep(31, 2000, 0.1, 1.0, 2.5, "separated anywhere");
  EXPECT_GT(agreement.separated, 500);
  EXPECT_GT(agreement.gjkFallbacks, 0);
  EXPECT_LT(agreement.gjkFallbacks, agreement.separated);
}

Transform at(const Vec3& position, const Quat& rotation = Quat::Identity()) { return {position, rotation}; }

TEST(BoxBoxContact, BoxRestingFaceDownIsExact) {
  const BoxCollider floor(Vec3(2, 0.5, 2)), box(Vec3(0.5, 0.3, 0.4));
  const Quat yaw(Eigen::AngleAxisd(0.3, Vec3::UnitY()));
  const ContactResult r = collide(floor, at(Vec3::Zero()), box, at(Vec3(0.2, 0.5 + 0.3 - 0.01, -0.1), yaw));
  EXPECT_EQ(r.status, ContactStatus::Penetrating);
  EXPECT_NEAR(r.depth, 0.01, 1e-15);
  EXPECT_EQ(r.normal, Vec3::UnitY());
  EXPECT_NEAR(r.pointA.y(), 0.5, 1e-15);
  EXPECT_NEAR(r.pointB.y(), 0.49, 1e-15);
  EXPECT_TRUE(r.usedBoxBox);
  EXPECT_FALSE(r.usedGeneralPath);
}

// A's top edge (along z) under B's bottom edge (along x), crossing at the
// origin's vertical: one contact, normal +y, depth exact.
TEST(BoxBoxContact, EdgeOnEdgeCrossingIsExact) {
  const BoxCollider cube(Vec3(1, 1, 1));
  const double depth = 0.05, reach = std::sqrt(2.0);
  const Transform ta = at(Vec3::Zero(), Quat(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ())));
  const Transform tb = at(Vec3(0, 2 * reach - depth, 0), Quat(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitX())));
  for (const Transform& motion : testing::testMotions(3)) {
    const ContactResult r = collide(cube, testing::compose(motion, ta), cube, testing::compose(motion, tb));
    EXPECT_EQ(r.status, ContactStatus::Penetrating);
    EXPECT_NEAR(r.depth, depth, 1e-12 * (1 + motion.position.norm()));
    EXPECT_LE((r.normal - motion.rotation * Vec3::UnitY()).norm(), 1e-12);
    EXPECT_LE((r.pointA - motion.apply(Vec3(0, reach, 0))).norm(), 1e-11 * (1 + motion.position.norm()));
    EXPECT_LE((r.pointB - motion.apply(Vec3(0, reach - depth, 0))).norm(), 1e-11 * (1 + motion.position.norm()));
    EXPECT_FALSE(r.usedGeneralPath);
  }
}

TEST(BoxBoxContact, IdenticalBoxesAtTheSamePose) {
  const BoxCollider box(Vec3(1, 0.5, 0.25));
  for (const Transform& motion : testing::testMotions(11)) {
    const ContactResult r = collide(box, motion, box, motion);
    testing::expectFinite(r);
    EXPECT_TRUE(r.usedBoxBox);
    EXPECT_EQ(r.status, ContactStatus::Penetrating);
    EXPECT_NEAR(r.depth, 0.5, 1e-12);
    EXPECT_NEAR(std::abs(r.normal.dot(motion.rotation * Vec3::UnitZ())), 1.0, 1e-12);
  }
}

// Boxes turned about a shared axis have parallel edges (cross products of
// zero length, left out); the face axes still give the exact answer.
TEST(BoxBoxContact, ParallelEdgesAgreeWithGjkEpa) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), offset(-1.6, 1.6);
  Agreement agreement;
  for (int i = 0; i < 500; ++i) {
    SCOPED_TRACE(i);
    BoxPair p{Vec3(0.6, 0.4, 0.9), Vec3(0.5, 0.7, 0.3), {}, {}};
    p.ta = at(Vec3::Zero(), Quat(Eigen::AngleAxisd(angle(rng), Vec3::UnitZ())));
    p.tb = at(Vec3(offset(rng), offset(rng), 0.5 * offset(rng)), Quat(Eigen::AngleAxisd(angle(rng), Vec3::UnitZ())));
    compare(p, agreement);
  }
  agreement.print("parallel edges");
  EXPECT_GT(agreement.penetrating, 100);
}

TEST(BoxBoxContact, ThinBoxesAndHugeSizeRatiosAgreeWithGjkEpa) {
  std::mt19937 rng(40);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Agreement thin, ratio;
  for (int i = 0; i < 800; ++i) {
    SCOPED_TRACE(i);
    BoxPair plate{Vec3(1.0, 1e-3, 0.8), Vec3(0.3, 0.2, 1e-3), {Vec3::Zero(), testing::randomRotation(rng)},
                  {0.8 * Vec3(unit(rng), unit(rng), unit(rng)), testing::randomRotation(rng)}};
    compare(plate, thin);
    // A 2 km slab and a 1 cm cube just above or in it.
    BoxPair huge{Vec3(1000, 1, 1000), Vec3(0.01, 0.01, 0.01), {Vec3::Zero(), Quat::Identity()},
                 {Vec3(500 * unit(rng), 1.0 + 0.025 * unit(rng), 500 * unit(rng)), testing::randomRotation(rng)}};
    compare(huge, ratio);
  }
  thin.print("thin boxes");
  ratio.print("size ratio 1e5");
  EXPECT_GT(thin.penetrating, 100);
  EXPECT_GT(ratio.penetrating, 100);
  EXPECT_GT(ratio.separated, 100);
}

TEST(BoxBoxContact, CountersTallyTheBoxBoxPath) {
  const BoxCollider cube(Vec3(1, 1, 1));
  NarrowPhaseCounters counters;
  counters.add(collide(cube, Transform{}, cube, at(Vec3(1, 0, 0))));   // overlapping: SAT alone
  counters.add(collide(cube, Transform{}, cube, at(Vec3(5, 0, 0))));   // face apart: SAT alone
  counters.add(collide(cube, Transform{}, cube, at(Vec3(3, 3, 3))));   // corner to corner: SAT, then GJK
  counters.add(collide(cube, Transform{}, cube, at(Vec3(1, 0, 0)), gjkEpaOnly()));
  EXPECT_EQ(counters.pairs, 4);
  EXPECT_EQ(counters.boxBox, 3);
  EXPECT_EQ(counters.fastPath, 0);
  EXPECT_EQ(counters.gjk, 2);
  EXPECT_EQ(counters.epa, 1);
}

}  // namespace
}  // namespace physdbg
