// The narrow phase in compute shaders against the CPU path (collide() and
// buildManifold()) on llvmpipe: randomised scenes of every supported pair,
// near the origin and 1e4 m from it, all in one dispatch. Prints the pairs
// compared and the largest differences, the figures the integrator needs.
#include "gpu/gpu_narrow_phase.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <string>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/narrowphase/narrow_phase.h"
#include "engine/world.h"
#include "scenes/scene.h"

namespace physdbg::gpu {
namespace {

// Double answers against double ones, relative to the larger body's size.
// Measured: normals, depths and separations agree to a few 1e-15, points
// to 1.5e-12 at 1e4 m from the origin (the last bit of the absolute
// coordinates); the margins leave room for another driver's fused
// multiply-adds, not for another decision.
constexpr double kNormalTolerance = 1e-12;
constexpr double kDepthTolerance = 1e-12;
constexpr double kPointTolerance = 1e-10;
constexpr double kSeparationTolerance = 1e-10;

struct Pair {
  std::string category;
  std::shared_ptr<const Collider> a, b;
  Transform ta, tb;
  double reach = 0.05;
};

double boundingRadius(const Collider& collider) {
  switch (collider.kind()) {
    case ColliderKind::Sphere: return static_cast<const SphereCollider&>(collider).radius();
    case ColliderKind::Box: return static_cast<const BoxCollider&>(collider).halfExtents().norm();
    case ColliderKind::Capsule: {
      const auto& capsule = static_cast<const CapsuleCollider&>(collider);
      return capsule.radius() + capsule.halfHeight();
    }
    default: return 1.0;
  }
}

// Braces wherever one expression draws several numbers: they are evaluated
// left to right, so every compiler builds the same scenes from a seed.
class SceneMaker {
 public:
  explicit SceneMaker(unsigned seed) : random_(seed) {}

  double uniform(double low, double high) { return std::uniform_real_distribution<double>(low, high)(random_); }
  bool coin() { return uniform(0, 1) < 0.5; }
  Vec3 uniformVec(double extent) { return {uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent)}; }
  Vec3 unit() {
    std::normal_distribution<double> normal;
    return Vec3{normal(random_), normal(random_), normal(random_)}.normalized();
  }
  Quat rotation() {
    std::normal_distribution<double> normal;
    return Quat{normal(random_), normal(random_), normal(random_), normal(random_)}.normalized();
  }
  Quat yaw() { return Quat(Eigen::AngleAxisd(uniform(-M_PI, M_PI), Vec3::UnitY())); }
  Vec3 halfExtents(double low, double high) { return {uniform(low, high), uniform(low, high), uniform(low, high)}; }
  // Deep, shallow, touching, separated within reach, separated beyond it.
  double gap(int kind, double size, double reach) {
    switch (kind % 5) {
      case 0: return -uniform(0.05, 0.4) * size;
      case 1: return -uniform(1e-4, 2e-3);
      case 2: return 0.0;
      case 3: return uniform(0.1, 0.9) * reach;
      default: return uniform(1.5, 3.0) * reach;
    }
  }

 private:
  std::mt19937 random_;
};

std::shared_ptr<const Collider> sphere(double radius) { return std::make_shared<SphereCollider>(radius); }
std::shared_ptr<const Collider> box(const Vec3& half) { return std::make_shared<BoxCollider>(half); }
std::shared_ptr<const Collider> capsule(double radius, double halfHeight) {
  return std::make_shared<CapsuleCollider>(radius, halfHeight);
}

// A then B, or B then A: the GPU must answer both orders as collide() does.
Pair ordered(SceneMaker& maker, Pair pair) {
  if (maker.coin()) {
    std::swap(pair.a, pair.b);
    std::swap(pair.ta, pair.tb);
  }
  return pair;
}

void addSphereSpheres(SceneMaker& maker, int count, std::vector<Pair>& pairs) {
  for (int i = 0; i < count; ++i) {
    const double ra = maker.uniform(0.05, 2.0), rb = maker.uniform(0.05, 2.0), reach = maker.uniform(0.02, 0.1);
    const double distance = ra + rb + maker.gap(i, std::min(ra, rb), reach);
    pairs.push_back({"sphere-sphere", sphere(ra), sphere(rb), {Vec3::Zero(), Quat::Identity()},
                     {distance * maker.unit(), Quat::Identity()}, reach});
  }
}

void addSphereBoxes(SceneMaker& maker, int count, std::vector<Pair>& pairs) {
  for (int i = 0; i < count; ++i) {
    const Vec3 half = maker.halfExtents(0.1, 2.0);
    const double radius = maker.uniform(0.05, 1.5);
    const Quat rotation = maker.rotation();
    const Vec3 local = (half + Vec3::Constant(radius + 0.1)).cwiseProduct(maker.uniformVec(1.0));
    pairs.push_back(ordered(maker, {"sphere-box", box(half), sphere(radius), {Vec3::Zero(), rotation},
                                    {rotation * local, Quat::Identity()}, maker.uniform(0.02, 0.1)}));
  }
}

void addSphereCapsules(SceneMaker& maker, int count, std::vector<Pair>& pairs) {
  for (int i = 0; i < count; ++i) {
    const double radius = maker.uniform(0.05, 1.0), halfHeight = maker.uniform(0.0, 1.5), other = maker.uniform(0.05, 1.5);
    const Quat rotation = maker.rotation();
    const Vec3 local = Vec3(radius + other, halfHeight + radius + other, radius + other).cwiseProduct(maker.uniformVec(1.1));
    pairs.push_back(ordered(maker, {"sphere-capsule", capsule(radius, halfHeight), sphere(other),
                                    {Vec3::Zero(), rotation}, {rotation * local, Quat::Identity()},
                                    maker.uniform(0.02, 0.1)}));
  }
}

void addRandomBoxes(SceneMaker& maker, int count, std::vector<Pair>& pairs) {
  for (int i = 0; i < count; ++i) {
    const Vec3 halfA = maker.halfExtents(0.1, 1.5), halfB = maker.halfExtents(0.1, 1.5);
    const Vec3 offset = (halfA + halfB).cwiseProduct(maker.uniformVec(1.0));
    pairs.push_back({"box-box rotated", box(halfA), box(halfB), {Vec3::Zero(), maker.rotation()},
                     {offset, maker.rotation()}, maker.uniform(0.02, 0.1)});
  }
}

// B resting on A's top face, both turned about the vertical only.
void addBoxStacks(SceneMaker& maker, int count, std::vector<Pair>& pairs) {
  for (int i = 0; i < count; ++i) {
    const Vec3 halfA = maker.halfExtents(0.2, 1.0), halfB = maker.halfExtents(0.2, 1.0);
    const double reach = maker.uniform(0.02, 0.1);
    const Quat rotationA = maker.coin() ? Quat::Identity() : maker.yaw();
    const Quat rotationB = i % 3 == 0 ? rotationA : maker.yaw();
    const double height = halfA.y() + halfB.y() + maker.gap(i, std::min(halfA.y(), halfB.y()) * 0.1, reach);
    const Vec3 offset = rotationA * Vec3{maker.uniform(-0.3, 0.3) * halfA.x(), height, maker.uniform(-0.3, 0.3) * halfA.z()};
    pairs.push_back(ordered(maker, {"box stack", box(halfA), box(halfB), {Vec3::Zero(), rotationA},
                                    {offset, rotationB}, reach}));
  }
}

void addFloorStacks(SceneMaker& maker, int count, std::vector<Pair>& pairs) {
  const Vec3 floorHalf(50.0, 0.5, 50.0);
  for (int i = 0; i < count; ++i) {
    const Vec3 half = maker.halfExtents(0.1, 1.0);
    const double reach = maker.uniform(0.02, 0.1);
    const double height = floorHalf.y() + half.y() + maker.gap(i, half.y() * 0.1, reach);
    const Vec3 position{maker.uniform(-40, 40), height, maker.uniform(-40, 40)};
    pairs.push_back(ordered(maker, {"box on floor", box(floorHalf), box(half), {Vec3::Zero(), Quat::Identity()},
                                    {position, maker.yaw()}, reach}));
  }
}

// A's top is an edge along x, B's bottom an edge crossing it.
void addEdgeEdges(SceneMaker& maker, int count, std::vector<Pair>& pairs) {
  const double quarter = M_PI / 4;
  for (int i = 0; i < count; ++i) {
    const Vec3 halfA = maker.halfExtents(0.3, 1.2), halfB = maker.halfExtents(0.3, 1.2);
    const double reach = maker.uniform(0.02, 0.1);
    const Quat rotationA(Eigen::AngleAxisd(quarter, Vec3::UnitX()));
    const Quat rotationB = Quat(Eigen::AngleAxisd(maker.uniform(-0.6, 0.6), Vec3::UnitY())) *
                           Quat(Eigen::AngleAxisd(quarter, Vec3::UnitZ()));
    const double top = (halfA.y() + halfA.z()) / std::sqrt(2.0), bottom = (halfB.x() + halfB.y()) / std::sqrt(2.0);
    const double gap = i % 5 == 2 ? -0.01 : maker.gap(i, 0.05, reach);
    const Vec3 offset{maker.uniform(-0.5, 0.5) * halfA.x(), top + bottom + gap, maker.uniform(-0.5, 0.5) * halfB.z()};
    pairs.push_back(ordered(maker, {"box edge-edge", box(halfA), box(halfB), {Vec3::Zero(), rotationA},
                                    {offset, rotationB}, reach}));
  }
}

void addDifferentSizes(SceneMaker& maker, int count, std::vector<Pair>& pairs) {
  for (int i = 0; i < count; ++i) {
    const Vec3 bigHalf = maker.halfExtents(10.0, 20.0);
    const double reach = maker.uniform(0.02, 0.1);
    const Quat rotation = maker.rotation();
    const Vec3 onTop{maker.uniform(-0.9, 0.9) * bigHalf.x(), bigHalf.y(), maker.uniform(-0.9, 0.9) * bigHalf.z()};
    if (i % 2 == 0) {
      const double radius = maker.uniform(0.01, 0.05);
      const Vec3 local = onTop + Vec3(0, radius + maker.gap(i / 2, radius, reach), 0);
      pairs.push_back(ordered(maker, {"tiny sphere on big box", box(bigHalf), sphere(radius),
                                      {Vec3::Zero(), rotation}, {rotation * local, Quat::Identity()}, reach}));
    } else {
      const Vec3 half = maker.halfExtents(0.05, 0.1);
      const Vec3 local = onTop + Vec3(0, half.y() + maker.gap(i / 2, half.y() * 0.1, reach), 0);
      pairs.push_back(ordered(maker, {"tiny box on big box", box(bigHalf), box(half), {Vec3::Zero(), rotation},
                                      {rotation * local, rotation * maker.yaw()}, reach}));
    }
  }
}

std::vector<Pair> randomScenes(unsigned seed, const Vec3& origin, double scatter) {
  SceneMaker maker(seed);
  std::vector<Pair> pairs;
  addSphereSpheres(maker, 200, pairs);
  addSphereBoxes(maker, 300, pairs);
  addSphereCapsules(maker, 200, pairs);
  addRandomBoxes(maker, 400, pairs);
  addBoxStacks(maker, 300, pairs);
  addFloorStacks(maker, 300, pairs);
  addEdgeEdges(maker, 200, pairs);
  addDifferentSizes(maker, 200, pairs);
  for (Pair& pair : pairs) {
    const Vec3 shift = origin + maker.uniformVec(scatter);
    pair.ta.position += shift;
    pair.tb.position += shift;
  }
  return pairs;
}

RigidBody bodyOf(const std::shared_ptr<const Collider>& collider, const Transform& transform) {
  BodyDefinition definition;
  definition.collider = collider;
  definition.position = transform.position;
  definition.orientation = transform.rotation;
  return RigidBody(definition);
}

struct Batch {
  std::vector<RigidBody> bodies;
  std::vector<NarrowPhaseRequest> requests;
};

Batch batchOf(const std::vector<Pair>& pairs) {
  Batch batch;
  for (const Pair& pair : pairs) {
    const auto first = static_cast<std::uint32_t>(batch.bodies.size());
    batch.bodies.push_back(bodyOf(pair.a, pair.ta));
    batch.bodies.push_back(bodyOf(pair.b, pair.tb));
    batch.requests.push_back({first, first + 1, pair.reach});
  }
  return batch;
}

double signedDistance(const ContactResult& result) {
  if (result.status == ContactStatus::Separated) return result.distance;
  return result.status == ContactStatus::Penetrating ? -result.depth : 0.0;
}

struct Differences {
  int pairs = 0, points = 0, featureIdDifferences = 0, failures = 0;
  double normal = 0, depth = 0, point = 0, separation = 0;  // largest, relative to size (normal absolute)
};

// The CPU point the GPU one stands for: same feature id when the CPU's ids
// are unique, otherwise the nearest.
const ManifoldPoint& counterpart(const ContactManifold& cpu, const ManifoldPoint& point) {
  int sameId = 0, idIndex = 0, nearest = 0;
  for (int k = 0; k < cpu.pointCount; ++k) {
    if (cpu.points[k].featureId == point.featureId) ++sameId, idIndex = k;
    if ((cpu.points[k].pointB - point.pointB).norm() < (cpu.points[nearest].pointB - point.pointB).norm()) nearest = k;
  }
  return cpu.points[sameId == 1 ? idIndex : nearest];
}

class Comparison {
 public:
  void compare(const Pair& pair, const GpuContact& gpu) {
    const ContactResult cpu = physdbg::collide(*pair.a, pair.ta, *pair.b, pair.tb);
    ContactManifold manifold;
    buildManifold(*pair.a, pair.ta, *pair.b, pair.tb, cpu, pair.reach, scratch_, manifold);
    const double size = std::max(boundingRadius(*pair.a), boundingRadius(*pair.b));
    Differences& total = overall_;
    Differences& category = categories_[pair.category];
    for (Differences* differences : {&total, &category}) ++differences->pairs;
    std::string why;
    if (gpu.result.status != cpu.status) why += " status";
    const double normal = (gpu.result.normal - cpu.normal).norm();
    const double depth = std::abs(signedDistance(gpu.result) - signedDistance(cpu)) / size;
    if (normal > kNormalTolerance) why += " normal";
    if (depth > kDepthTolerance) why += " depth";
    if (gpu.manifold.pointCount != manifold.pointCount) why += " point count";
    double point = 0, separation = 0;
    int idDifferences = 0;
    for (int k = 0; k < gpu.manifold.pointCount && gpu.manifold.pointCount == manifold.pointCount; ++k) {
      const ManifoldPoint& mine = gpu.manifold.points[k];
      const ManifoldPoint& theirs = counterpart(manifold, mine);
      point = std::max({point, (mine.pointA - theirs.pointA).norm() / size, (mine.pointB - theirs.pointB).norm() / size,
                        (mine.localA - theirs.localA).norm() / size, (mine.localB - theirs.localB).norm() / size});
      separation = std::max(separation, std::abs(mine.separation - theirs.separation) / size);
      if (mine.featureId != theirs.featureId) ++idDifferences;
    }
    if (point > kPointTolerance) why += " points";
    if (separation > kSeparationTolerance) why += " separation";
    if (idDifferences > 0) why += " feature ids";
    for (Differences* differences : {&total, &category}) {
      differences->normal = std::max(differences->normal, normal);
      differences->depth = std::max(differences->depth, depth);
      differences->point = std::max(differences->point, point);
      differences->separation = std::max(differences->separation, separation);
      differences->points += manifold.pointCount;
      differences->featureIdDifferences += idDifferences;
      if (!why.empty()) ++differences->failures;
    }
    if (!why.empty() && reported_++ < 10)
      ADD_FAILURE() << pair.category << " differs in" << why << ": CPU " << contactStatusName(cpu.status) << " "
                    << signedDistance(cpu) << " n " << cpu.normal.transpose() << " points " << manifold.pointCount
                    << "; GPU " << contactStatusName(gpu.result.status) << " " << signedDistance(gpu.result) << " n "
                    << gpu.result.normal.transpose() << " points " << gpu.manifold.pointCount;
  }

  const Differences& overall() const { return overall_; }

  void print(const char* title) const {
    std::printf("%s\n", title);
    for (const auto& [name, d] : categories_) printLine(name, d);
    printLine("all", overall_);
  }

 private:
  static void printLine(const std::string& name, const Differences& d) {
    std::printf(
        "  %-24s pairs %5d points %5d | largest: normal %.2e depth %.2e point %.2e separation %.2e (x size) | "
        "feature ids differing %d, failures %d\n",
        name.c_str(), d.pairs, d.points, d.normal, d.depth, d.point, d.separation, d.featureIdDifferences,
        d.failures);
  }

  ManifoldScratch scratch_;
  Differences overall_;
  std::map<std::string, Differences> categories_;
  int reported_ = 0;
};

// One context and program for the suite: llvmpipe compiles the shader at its
// first dispatch (seconds without Mesa's disk cache).
class GpuNarrowPhaseTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    shared_ = new Shared;
  }
  static void TearDownTestSuite() {
    delete shared_;
    shared_ = nullptr;
  }
  struct Shared {
    ComputeContext context{render::Backend::OsMesa};
    GpuNarrowPhase narrowPhase{context};
  };
  static Shared* shared_;
  ComputeContext& context = shared_->context;
  GpuNarrowPhase& narrowPhase = shared_->narrowPhase;
};
GpuNarrowPhaseTest::Shared* GpuNarrowPhaseTest::shared_ = nullptr;

void recordFigures(const Differences& d, const std::string& prefix) {
  ::testing::Test::RecordProperty(prefix + "pairs", d.pairs);
  ::testing::Test::RecordProperty(prefix + "largestNormal", std::to_string(d.normal));
  ::testing::Test::RecordProperty(prefix + "largestDepthOverSize", std::to_string(d.depth));
  ::testing::Test::RecordProperty(prefix + "largestPointOverSize", std::to_string(d.point));
}

TEST_F(GpuNarrowPhaseTest, AgreesWithTheCpuPathNearTheOriginAndFarFromIt) {
  std::vector<Pair> pairs = randomScenes(12345u, Vec3::Zero(), 5.0);
  const std::vector<Pair> far = randomScenes(67890u, Vec3(1e4, -1e4, 1e4), 50.0);
  pairs.insert(pairs.end(), far.begin(), far.end());
  const Batch batch = batchOf(pairs);
  std::vector<GpuContact> out;
  narrowPhase.collide(batch.bodies, batch.requests, out);
  ASSERT_EQ(out.size(), pairs.size());
  Comparison near, distant;
  for (std::size_t i = 0; i < pairs.size(); ++i) (i < pairs.size() - far.size() ? near : distant).compare(pairs[i], out[i]);
  near.print("GPU narrow phase against the CPU path, near the origin:");
  distant.print("GPU narrow phase against the CPU path, centres about 1e4 m from the origin:");
  const GpuNarrowPhaseTimings& timings = narrowPhase.lastTimings();
  std::printf("%zu pairs: upload %.2f ms, dispatch %.2f ms, readback %.2f ms, CPU fallbacks %d\n", pairs.size(),
              1e3 * timings.uploadSeconds, 1e3 * timings.dispatchSeconds, 1e3 * timings.readbackSeconds,
              timings.cpuFallbacks);
  recordFigures(near.overall(), "near_");
  recordFigures(distant.overall(), "far_");
  EXPECT_EQ(near.overall().failures, 0);
  EXPECT_EQ(distant.overall().failures, 0);
  EXPECT_GE(near.overall().pairs + distant.overall().pairs, 4000);
}

// The pairs the built-in scenes' tree hands the narrow phase, at rest and in
// motion: the GPU answers each as the CPU path does.
TEST_F(GpuNarrowPhaseTest, AgreesWithTheCpuPathOnTheBuiltInScenesPairs) {
  std::vector<Pair> pairs;
  for (const BuiltinScene& builtin : builtinScenes()) {
    World world = buildWorld(builtin.make());
    for (int step = 1; step <= 90; ++step) {
      world.step();
      if (step != 1 && step != 30 && step != 90) continue;
      for (const BodyPair& candidate : world.candidatePairs()) {
        const RigidBody &a = world.body(candidate.a), &b = world.body(candidate.b);
        if (!GpuNarrowPhase::supports(a.collider().kind(), b.collider().kind())) continue;
        pairs.push_back({builtin.name, a.colliderPointer(), b.colliderPointer(), a.transform(), b.transform()});
      }
    }
  }
  const Batch batch = batchOf(pairs);
  std::vector<GpuContact> out;
  narrowPhase.collide(batch.bodies, batch.requests, out);
  Comparison comparison;
  for (std::size_t i = 0; i < pairs.size(); ++i) comparison.compare(pairs[i], out[i]);
  comparison.print("GPU narrow phase against the CPU path, built-in scenes' candidate pairs at steps 1, 30, 90:");
  std::printf("%zu pairs, CPU fallbacks %d\n", pairs.size(), narrowPhase.lastTimings().cpuFallbacks);
  recordFigures(comparison.overall(), "builtin_");
  EXPECT_EQ(comparison.overall().failures, 0);
  EXPECT_GE(comparison.overall().pairs, 500);
}

// A 1 m cube 1 cm into a floor, 1e4 m out: four corners, each 1 cm deep.
TEST_F(GpuNarrowPhaseTest, ABoxSunkIntoTheFloorFarFromTheOriginHasFourCornersOneCentimetreDeep) {
  const Vec3 origin(1e4, 2e3, -1e4);
  const Batch batch = batchOf({{"known", box(Vec3(50, 0.5, 50)), box(Vec3(0.5, 0.5, 0.5)),
                                {origin, Quat::Identity()}, {origin + Vec3(3.0, 0.99, -2.0), Quat::Identity()}, 0.05}});
  std::vector<GpuContact> out;
  narrowPhase.collide(batch.bodies, batch.requests, out);
  ASSERT_EQ(out.size(), 1u);
  const GpuContact& contact = out[0];
  EXPECT_EQ(contact.result.status, ContactStatus::Penetrating);
  EXPECT_NEAR(contact.result.depth, 0.01, 1e-9);
  EXPECT_LT((contact.result.normal - Vec3::UnitY()).norm(), 1e-9);
  EXPECT_TRUE(contact.result.usedBoxBox);
  ASSERT_EQ(contact.manifold.pointCount, 4);
  for (int k = 0; k < 4; ++k) {
    const ManifoldPoint& point = contact.manifold.points[k];
    EXPECT_NEAR(point.separation, -0.01, 1e-9);
    EXPECT_NEAR(point.pointA.y(), origin.y() + 0.5, 1e-9);
    EXPECT_NEAR(point.pointB.y(), origin.y() + 0.49, 1e-9);
    EXPECT_NEAR(std::abs(point.localB.x()), 0.5, 1e-9);
    EXPECT_NEAR(std::abs(point.localB.z()), 0.5, 1e-9);
    EXPECT_EQ(point.featureId & 0xFFFu, static_cast<std::uint32_t>(k + 1));  // incident corners 1-4
  }
}

TEST_F(GpuNarrowPhaseTest, TwoSpheresOverlappingByATenthGiveThatDepthAlongTheirCentres) {
  const Batch batch = batchOf({{"known", sphere(1.0), sphere(0.5), {Vec3(1e4, 0, 0), Quat::Identity()},
                                {Vec3(1e4, 0, 0) + Vec3(0.0, 0.8, 0.6) * 1.4, Quat::Identity()}, 0.05}});
  std::vector<GpuContact> out;
  narrowPhase.collide(batch.bodies, batch.requests, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].result.status, ContactStatus::Penetrating);
  EXPECT_NEAR(out[0].result.depth, 0.1, 1e-9);
  EXPECT_LT((out[0].result.normal - Vec3(0.0, 0.8, 0.6)).norm(), 1e-9);
  ASSERT_EQ(out[0].manifold.pointCount, 1);
  EXPECT_NEAR(out[0].manifold.points[0].separation, -0.1, 1e-9);
}

TEST_F(GpuNarrowPhaseTest, UploadsOnlyThePosesThatChanged) {
  Batch batch = batchOf(randomScenes(7u, Vec3(3.0, 0.0, 0.0), 5.0));  // poses no other test used
  std::vector<GpuContact> out;
  narrowPhase.collide(batch.bodies, batch.requests, out);
  EXPECT_EQ(narrowPhase.lastTimings().posesUploaded, static_cast<int>(batch.bodies.size()));
  narrowPhase.collide(batch.bodies, batch.requests, out);
  EXPECT_EQ(narrowPhase.lastTimings().posesUploaded, 0);
  batch.bodies[5].setPosition(batch.bodies[5].position() + Vec3(0.1, 0, 0));
  batch.bodies[6].setPosition(batch.bodies[6].position() + Vec3(0.1, 0, 0));
  narrowPhase.collide(batch.bodies, batch.requests, out);
  EXPECT_EQ(narrowPhase.lastTimings().posesUploaded, 2);
  // The moved pair's answer follows the move: the same as the CPU's.
  const ContactResult cpu = physdbg::collide(batch.bodies[4].collider(), batch.bodies[4].transform(),
                                             batch.bodies[5].collider(), batch.bodies[5].transform());
  const std::size_t request = 2;  // bodies 4 and 5
  EXPECT_NEAR(signedDistance(out[request].result), signedDistance(cpu), 1e-12);
}

TEST_F(GpuNarrowPhaseTest, OneDispatchOfAThousandPairs) {
  std::vector<Pair> pairs = randomScenes(99u, Vec3::Zero(), 5.0);
  pairs.resize(1000);
  const Batch batch = batchOf(pairs);
  std::vector<GpuContact> out;
  narrowPhase.collide(batch.bodies, batch.requests, out);  // first call: buffers grow, shader warms up
  narrowPhase.collide(batch.bodies, batch.requests, out);
  const GpuNarrowPhaseTimings& timings = narrowPhase.lastTimings();
  std::printf("1000 pairs on %s: upload %.3f ms, dispatch %.3f ms, readback %.3f ms, CPU fallbacks %d\n",
              context.identity().renderer.c_str(), 1e3 * timings.uploadSeconds, 1e3 * timings.dispatchSeconds,
              1e3 * timings.readbackSeconds, timings.cpuFallbacks);
  RecordProperty("dispatchMilliseconds1000", std::to_string(1e3 * timings.dispatchSeconds));
  EXPECT_GT(timings.dispatchSeconds, 0.0);
}

TEST_F(GpuNarrowPhaseTest, RefusesPairsItCannotCollideAndBodiesOutOfRange) {
  const Batch capsules = batchOf({{"capsules", capsule(0.5, 1.0), capsule(0.5, 1.0), {Vec3::Zero(), Quat::Identity()},
                                   {Vec3(0.0, 0.5, 0.0), Quat::Identity()}, 0.05}});
  std::vector<GpuContact> out;
  EXPECT_THROW(narrowPhase.collide(capsules.bodies, capsules.requests, out), std::invalid_argument);
  Batch spheres = batchOf({{"spheres", sphere(1.0), sphere(1.0), {Vec3::Zero(), Quat::Identity()},
                            {Vec3(1.5, 0.0, 0.0), Quat::Identity()}, 0.05}});
  spheres.requests[0].b = 2;
  EXPECT_THROW(narrowPhase.collide(spheres.bodies, spheres.requests, out), std::invalid_argument);
}

TEST(GpuNarrowPhaseSupport, SpheresWithEverythingButMeshesAndBoxesWithBoxes) {
  using K = ColliderKind;
  EXPECT_TRUE(GpuNarrowPhase::supports(K::Sphere, K::Sphere));
  EXPECT_TRUE(GpuNarrowPhase::supports(K::Box, K::Sphere));
  EXPECT_TRUE(GpuNarrowPhase::supports(K::Sphere, K::Capsule));
  EXPECT_TRUE(GpuNarrowPhase::supports(K::Box, K::Box));
  EXPECT_FALSE(GpuNarrowPhase::supports(K::Capsule, K::Capsule));
  EXPECT_FALSE(GpuNarrowPhase::supports(K::Capsule, K::Box));
  EXPECT_FALSE(GpuNarrowPhase::supports(K::ConvexMesh, K::Sphere));
}

}  // namespace
}  // namespace physdbg::gpu
