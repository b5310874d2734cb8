// 100 random scenes of spheres and boxes, stepped once with collision on the
// CPU and on the GPU from the same state: the candidate pairs must be equal
// and every manifold the solver received must agree to round-off (normal
// 1e-12, points and separations 1e-10 of the larger body's size; the issue
// asked for float's 1e-5).
// Scenes mix touching, deep and resting bodies, random rotations and boxes
// aligned on a floor; a quarter sit about 1e4 m from the origin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <random>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "gpu/gpu_collision.h"
#include "scenes/body_builders.h"
#include "engine/world.h"
#include "scenes/scene.h"

namespace physdbg::gpu {
namespace {

constexpr int sceneCount = 100;
// The shader computes in double as the CPU does (gpu_narrow_phase.h): what
// is left is operation order, about 1e-15 here; a driver fusing multiply-adds
// may add a few digits.
constexpr double normalTolerance = 1e-12, pointTolerance = 1e-10, separationTolerance = 1e-10;

class RandomScene {
 public:
  explicit RandomScene(unsigned seed) : random_(seed) {}

  SceneDescription make() {
    SceneDescription scene;
    scene.name = "random";
    const bool far = uniform(0, 1) < 0.25;
    const Vec3 origin = far ? Vec3{uniform(0.9e4, 1.1e4), uniform(-1.1e4, -0.9e4), uniform(0.9e4, 1.1e4)} : Vec3::Zero();
    scene.bodies.push_back(staticBox(origin + Vec3{0, -0.5, 0}, {6, 0.5, 6}));
    const int count = static_cast<int>(uniform(10, 40));
    for (int i = 0; i < count; ++i) scene.bodies.push_back(body(origin));
    scene.world.allowSleep = false;
    return scene;
  }

 private:
  double uniform(double low, double high) { return std::uniform_real_distribution<double>(low, high)(random_); }

  // Half on the floor (resting, aligned or turned about y), half in a heap
  // where they overlap each other at random depths and angles.
  BodyDefinition body(const Vec3& origin) {
    const bool isBox = uniform(0, 1) < 0.6;
    const double size = uniform(0.2, 0.8);
    std::shared_ptr<const Collider> collider;
    if (isBox) {
      const double sx = uniform(0.6, 1.4), sy = uniform(0.6, 1.4), sz = uniform(0.6, 1.4);
      collider = std::make_shared<BoxCollider>(Vec3{size * sx, size * sy, size * sz});
    } else {
      collider = std::make_shared<SphereCollider>(size);
    }
    const double x = uniform(-4, 4), z = uniform(-4, 4);
    const bool resting = uniform(0, 1) < 0.5;
    BodyDefinition definition = dynamicBody(collider, origin, 1.0);
    if (resting) {
      const double halfHeight = collider->localBounds().max.y();
      const double sink = uniform(-0.002, 0.01);  // a hair above to a centimetre in
      definition.position = origin + Vec3{x, halfHeight - sink, z};
      definition.orientation = Quat(Eigen::AngleAxisd(uniform(-M_PI, M_PI), Vec3::UnitY()));
    } else {
      const double a = uniform(-1, 1), b = uniform(-1, 1), c = uniform(-1, 1), d = uniform(-1, 1);
      definition.position = origin + Vec3{x * 0.25, uniform(0.2, 2.0), z * 0.25};
      definition.orientation = Quat(a, b, c, d).normalized();
    }
    return definition;
  }

  std::mt19937 random_;
};

double sizeOf(const World& world, BodyId id) {
  const Aabb bounds = world.body(id).collider().localBounds();
  return (bounds.max - bounds.min).norm() / 2;
}

const ManifoldPoint& counterpart(const ContactManifold& manifold, const ManifoldPoint& point) {
  const ManifoldPoint* best = &manifold.points[0];
  for (int k = 0; k < manifold.pointCount; ++k) {
    if (manifold.points[k].featureId == point.featureId) return manifold.points[k];
    if ((manifold.points[k].pointA - point.pointA).norm() < (best->pointA - point.pointA).norm()) best = &manifold.points[k];
  }
  return *best;
}

struct Figures {
  long long pairs = 0, manifolds = 0, points = 0, failures = 0;
  double normal = 0, point = 0, separation = 0;
};

void compareManifolds(const World& cpu, const World& gpu, Figures& figures) {
  const auto &mine = gpu.manifolds(), &theirs = cpu.manifolds();
  ASSERT_EQ(mine.size(), theirs.size());
  for (std::size_t m = 0; m < mine.size(); ++m) {
    ASSERT_EQ(mine[m].a, theirs[m].a);
    ASSERT_EQ(mine[m].b, theirs[m].b);
    const double size = std::max(sizeOf(cpu, theirs[m].a), sizeOf(cpu, theirs[m].b));
    const double normal = (mine[m].normal - theirs[m].normal).norm();
    double point = 0, separation = 0;
    if (mine[m].pointCount == theirs[m].pointCount) {
      for (int k = 0; k < mine[m].pointCount; ++k) {
        const ManifoldPoint& other = counterpart(theirs[m], mine[m].points[k]);
        point = std::max(point, (mine[m].points[k].pointA - other.pointA).norm() / size);
        point = std::max(point, (mine[m].points[k].pointB - other.pointB).norm() / size);
        separation = std::max(separation, std::abs(mine[m].points[k].separation - other.separation) / size);
      }
    }
    const bool agrees = mine[m].pointCount == theirs[m].pointCount && normal <= normalTolerance &&
                        point <= pointTolerance && separation <= separationTolerance;
    EXPECT_TRUE(agrees) << "manifold " << mine[m].a << "-" << mine[m].b << ": points " << mine[m].pointCount << " vs "
                        << theirs[m].pointCount << ", normal " << normal << ", point " << point << ", separation "
                        << separation;
    figures.failures += agrees ? 0 : 1;
    ++figures.manifolds;
    figures.points += theirs[m].pointCount;
    figures.normal = std::max(figures.normal, normal);
    figures.point = std::max(figures.point, point);
    figures.separation = std::max(figures.separation, separation);
  }
}

TEST(GpuRandomScenes, PairsAndManifoldsAgreeWithTheCpuPath) {
  Figures figures;
  for (int index = 0; index < sceneCount; ++index) {
    SCOPED_TRACE("scene " + std::to_string(index));
    SceneDescription scene = RandomScene(1000u + static_cast<unsigned>(index)).make();
    World cpu = buildWorld(scene);
    scene.world.collisionDevice = CollisionDevice::Gpu;
    World gpu = buildWorld(scene, std::make_shared<GpuCollision>(render::Backend::OsMesa));
    cpu.step();
    gpu.step();
    ASSERT_EQ(gpu.candidatePairs(), cpu.candidatePairs());
    figures.pairs += static_cast<long long>(cpu.candidatePairs().size());
    compareManifolds(cpu, gpu, figures);
  }
  std::printf("%d random scenes: %lld candidate pairs equal; %lld manifolds, %lld points; largest normal %.2e, "
              "point %.2e, separation %.2e (x size); %lld disagreeing\n",
              sceneCount, figures.pairs, figures.manifolds, figures.points, figures.normal, figures.point,
              figures.separation, figures.failures);
  RecordProperty("candidatePairs", std::to_string(figures.pairs));
  RecordProperty("manifolds", std::to_string(figures.manifolds));
  RecordProperty("largestNormal", std::to_string(figures.normal));
  EXPECT_GE(figures.manifolds, 1000);
  EXPECT_EQ(figures.failures, 0);
}

}  // namespace
}  // namespace physdbg::gpu
