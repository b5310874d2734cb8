// The box-box manifold builder against the general one, the manifold the
// box-box narrow phase leads to against the one GJK + EPA lead to, exact
// cases, and feature ids that persist while a box slides.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "../narrowphase/box_box_test_support.h"
#include "engine/contacts/box_box_manifold.h"
#include "engine/contacts/manifold_builder.h"

namespace physdbg {
namespace {

using testing::BoxPair;
using testing::boxSurfaceDistance;
using testing::gjkEpaOnly;

// Metres. Clipped points may lie up to the clip tolerance (1e-6 m) outside
// two of the reference face's side planes at once (sqrt(2) * 1e-6 from a
// corner); a little more covers round-off.
constexpr double kOnSurface = 1.5e-6;
// How far a speculative point may be and still be kept (a solver's reach).
constexpr double kReach = 0.05;

std::vector<std::uint32_t> sortedIds(const ContactManifold& m) {
  std::vector<std::uint32_t> ids;
  for (int i = 0; i < m.pointCount; ++i) ids.push_back(m.points[i].featureId);
  std::sort(ids.begin(), ids.end());
  return ids;
}

bool hasDuplicateIds(const ContactManifold& m) {
  const std::vector<std::uint32_t> ids = sortedIds(m);
  return std::adjacent_find(ids.begin(), ids.end()) != ids.end();
}

bool isCornerId(std::uint32_t id) { return (id & 0xFFFu) < 0x800u; }

// How far `point` is from the nearest of the general builder's candidates
// (every clipped point it kept before choosing four).
double distanceToCandidates(const ManifoldPoint& point, const std::vector<ManifoldPoint>& candidates) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const ManifoldPoint& c : candidates)
    nearest = std::min(nearest, std::max((c.pointA - point.pointA).norm(), (c.pointB - point.pointB).norm()));
  return nearest;
}

double deepest(const ContactManifold& m) {
  double d = std::numeric_limits<double>::infinity();
  for (int i = 0; i < m.pointCount; ++i) d = std::min(d, m.points[i].separation);
  return d;
}

void expectPointsOnSurfaces(const BoxPair& p, const ContactManifold& m, double& largestOff) {
  for (int i = 0; i < m.pointCount; ++i) {
    const ManifoldPoint& point = m.points[i];
    const double offA = std::abs(boxSurfaceDistance(p.halfA, p.ta, point.pointA));
    const double offB = std::abs(boxSurfaceDistance(p.halfB, p.tb, point.pointB));
    EXPECT_LE(offA, kOnSurface) << i;
    EXPECT_LE(offB, kOnSurface) << i;
    largestOff = std::max({largestOff, offA, offB});
    EXPECT_LE((p.ta.apply(point.localA) - point.pointA).norm(), 1e-9);
    EXPECT_LE((p.tb.apply(point.localB) - point.pointB).norm(), 1e-9);
    EXPECT_NEAR(point.separation, (point.pointB - point.pointA).dot(m.normal), 1e-9);
    EXPECT_LE(point.separation, kReach + 1e-12);
  }
}

struct BuilderComparison {
  int compared = 0, reduced = 0, generalDuplicates = 0;
  double pointDifference = 0, separationDifference = 0;
};

// `ours` against the general builder's manifold `general` and its
// candidates: same count and normal; with four or fewer candidates the same
// points in the same order (and the same ids at corners); with more, each of
// ours is one of the candidates and the deepest separation is the same.
void compareBuilders(const ContactManifold& general, const std::vector<ManifoldPoint>& candidates,
                     const ContactManifold& ours, double tolerance, BuilderComparison& comparison) {
  ++comparison.compared;
  ASSERT_EQ(general.pointCount, ours.pointCount);
  EXPECT_LE((general.normal - ours.normal).norm(), 1e-7);
  EXPECT_FALSE(hasDuplicateIds(ours));
  if (hasDuplicateIds(general)) ++comparison.generalDuplicates;
  const double separation = std::abs(deepest(general) - deepest(ours));
  EXPECT_LE(separation, tolerance);
  comparison.separationDifference = std::max(comparison.separationDifference, separation);
  if (ours.pointCount <= 1) return;
  const bool reduced = candidates.size() > static_cast<std::size_t>(ContactManifold::maxPoints);
  if (reduced) ++comparison.reduced;
  for (int k = 0; k < ours.pointCount; ++k) {
    const ManifoldPoint &mine = ours.points[k], &theirs = general.points[k];
    const double difference = reduced ? distanceToCandidates(mine, candidates)
                                      : std::max((mine.pointA - theirs.pointA).norm(), (mine.pointB - theirs.pointB).norm());
    EXPECT_LE(difference, tolerance) << k;
    comparison.pointDifference = std::max(comparison.pointDifference, difference);
    if (!reduced && isCornerId(theirs.featureId)) {
      EXPECT_EQ(theirs.featureId, mine.featureId) << k;
    }
  }
}

void print(const char* label, const BuilderComparison& c) {
  std::printf("[%s] %d manifolds (%d chosen from more than four points), general builder's with a repeated id %d, "
              "largest point difference %.3g m, deepest separation difference %.3g m\n",
              label, c.compared, c.reduced, c.generalDuplicates, c.pointDifference, c.separationDifference);
}

// Random pairs, penetrating and moved apart within reach: the same
// narrow-phase result through both builders.
TEST(BoxBoxManifold, AgreesWithTheGeneralBuilderForTheSameResult) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> gap(0.0, kReach);
  BuilderComparison comparison;
  for (int i = 0; i < 2000; ++i) {
    SCOPED_TRACE(i);
    BoxPair p = testing::randomBoxPair(rng, 0.1, 1.5, 1.0);
    const BoxCollider a(p.halfA), b(p.halfB);
    ContactResult r = collide(a, p.ta, b, p.tb);
    if (r.status != ContactStatus::Penetrating) continue;
    if (i % 2 == 1) {  // half of them speculative
      p.tb.position += (r.depth + gap(rng)) * r.normal;
      r = collide(a, p.ta, b, p.tb);
    }
    ManifoldScratch scratch;
    ContactManifold general, ours;
    buildGeneralManifold(a, p.ta, b, p.tb, r, kReach, scratch, general);
    buildBoxBoxManifold(a, p.ta, b, p.tb, r, kReach, ours);
    compareBuilders(general, scratch.kept, ours, 1e-12, comparison);
  }
  print("builders", comparison);
  EXPECT_GT(comparison.reduced, 100);
}

// What the solver gets: SAT result + box builder against GJK/EPA result +
// general builder (the old route), on deep, touching, speculative and far
// pairs.
TEST(BoxBoxManifold, SatManifoldsMatchTheGjkEpaRoute) {
  std::mt19937 rng(90);
  std::uniform_real_distribution<double> gap(0.0, kReach);
  const std::vector<Transform> motions = testing::testMotions(23);
  BuilderComparison comparison;
  double largestOff = 0;
  for (int i = 0; i < 2000; ++i) {
    SCOPED_TRACE(i);
    BoxPair p = testing::randomBoxPair(rng, 0.1, 1.5, 1.0);
    const Transform& motion = motions[i % motions.size()];
    p.ta = testing::compose(motion, p.ta);
    p.tb = testing::compose(motion, p.tb);
    const BoxCollider a(p.halfA), b(p.halfB);
    ContactResult epa = collide(a, p.ta, b, p.tb, gjkEpaOnly());
    if (epa.status != ContactStatus::Penetrating) continue;
    if (i % 3 == 1) p.tb.position += (epa.depth + gap(rng)) * epa.normal;
    if (i % 3 == 2) p.tb.position += epa.depth * epa.normal;
    epa = collide(a, p.ta, b, p.tb, gjkEpaOnly());
    const ContactResult sat = collide(a, p.ta, b, p.tb);
    ContactManifold old, ours;
    ManifoldScratch scratch, unused;
    buildManifold(a, p.ta, b, p.tb, epa, kReach, scratch, old);
    buildManifold(a, p.ta, b, p.tb, sat, kReach, unused, ours);
    expectPointsOnSurfaces(p, ours, largestOff);
    compareBuilders(old, scratch.kept, ours, 1e-9 * (1.0 + motion.position.norm()), comparison);
  }
  print("SAT route against GJK/EPA route", comparison);
  std::printf("[SAT route] manifold points off the boxes' surfaces by at most %.3g m\n", largestOff);
  EXPECT_GT(comparison.reduced, 100);
}

// The narrow phase's result and the manifold built from it, as the solver gets them.
ContactManifold manifoldOf(const BoxPair& p) {
  const BoxCollider a(p.halfA), b(p.halfB);
  const ContactResult r = collide(a, p.ta, b, p.tb);
  EXPECT_TRUE(r.usedBoxBox);
  ContactManifold m;
  ManifoldScratch scratch;
  buildManifold(a, p.ta, b, p.tb, r, kReach, scratch, m);
  return m;
}

TEST(BoxBoxManifold, BoxRestingFaceDownHasFourCornerPoints) {
  const BoxPair p{Vec3(2, 0.5, 2), Vec3(0.5, 0.3, 0.4), {},
                  {Vec3(0.2, 0.5 + 0.3 - 0.01, -0.1), Quat(Eigen::AngleAxisd(0.3, Vec3::UnitY()))}};
  const ContactManifold m = manifoldOf(p);
  ASSERT_EQ(m.pointCount, 4);
  EXPECT_EQ(m.normal, Vec3::UnitY());
  for (int i = 0; i < 4; ++i) {
    const ManifoldPoint& point = m.points[i];
    EXPECT_NEAR(point.separation, -0.01, 1e-15);
    // B's bottom corners, exactly.
    const Vec3 corner = p.tb.applyInverse(point.pointB);
    EXPECT_NEAR(std::abs(corner.x()), 0.5, 1e-15);
    EXPECT_NEAR(corner.y(), -0.3, 1e-15);
    EXPECT_NEAR(std::abs(corner.z()), 0.4, 1e-15);
    EXPECT_NEAR(point.pointA.y(), 0.5, 1e-15);
    EXPECT_LE((point.pointA - point.pointB - Vec3(0, 0.01, 0)).norm(), 1e-15);
  }
}

TEST(BoxBoxManifold, EdgeOnEdgeCrossingHasOnePoint) {
  const double depth = 0.05, reach = std::sqrt(2.0);
  const BoxPair p{Vec3(1, 1, 1), Vec3(1, 1, 1), {Vec3::Zero(), Quat(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()))},
                  {Vec3(0, 2 * reach - depth, 0), Quat(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitX()))}};
  const ContactManifold m = manifoldOf(p);
  ASSERT_EQ(m.pointCount, 1);
  EXPECT_NEAR(m.points[0].separation, -depth, 1e-12);
  EXPECT_LE((m.points[0].pointA - Vec3(0, reach, 0)).norm(), 1e-12);
}

TEST(BoxBoxManifold, IdenticalBoxesAtTheSamePoseHaveFourPoints) {
  const Transform pose{Vec3(3, -2, 1), Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()))};
  const BoxPair same{Vec3(1, 0.5, 0.25), Vec3(1, 0.5, 0.25), pose, pose};
  const ContactManifold m = manifoldOf(same);
  ASSERT_EQ(m.pointCount, 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(m.points[i].separation, -0.5, 1e-12);
  double off = 0;
  expectPointsOnSurfaces(same, m, off);
}

// A box sliding slowly (and turning a little) keeps the same feature ids
// every step, so the solver warm-starts every point; on a wide floor (corners
// inside the face) and half over an equal box's edge (clipped points).
TEST(BoxBoxManifold, FeatureIdsPersistWhileABoxSlides) {
  struct Slide {
    const char* name;
    Vec3 halfA;
    Vec3 start;
    int expectedPoints;
  };
  const Slide slides[] = {{"wide floor", Vec3(5, 0.5, 5), Vec3(-1, 0, 0.3), 4},
                          {"over an edge", Vec3(0.5, 0.5, 0.5), Vec3(0.35, 0, 0.1), 4}};
  for (const Slide& slide : slides) {
    SCOPED_TRACE(slide.name);
    BoxPair p{slide.halfA, Vec3(0.5, 0.5, 0.5), {}, {}};
    std::vector<std::uint32_t> previous;
    for (int step = 0; step < 100; ++step) {
      p.tb.position = slide.start + Vec3(0.002 * step, slide.halfA.y() + 0.5 - 0.003, 0.0005 * step);
      p.tb.rotation = Quat(Eigen::AngleAxisd(0.05 + 0.0005 * step, Vec3::UnitY()));
      const ContactManifold m = manifoldOf(p);
      ASSERT_EQ(m.pointCount, slide.expectedPoints) << step;
      const std::vector<std::uint32_t> ids = sortedIds(m);
      if (step > 0) {
        EXPECT_EQ(ids, previous) << step;
      }
      previous = ids;
    }
  }
}

}  // namespace
}  // namespace physdbg
