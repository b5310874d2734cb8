// "mesh": Jolt's PerformanceTest ConvexVsMeshScene as physdbg defines it, a
// pile of mixed convex bodies falling onto level geometry, against Bullet
// (btBvhTriangleMeshShape, btHeightfieldTerrainShape) in the same run:
// - mesh/triangles: a 100 x 100 cell sine-wave mesh of 20,000 triangles
//   (1 m cells, y = 2 sin(0.2 i) cos(0.2 j)) under 1,764 bodies: a 21 x 21
//   grid 4 m apart of a sphere, a box, a capsule and a convex hull each,
//   stacked 2.5 m apart from 5 m up, a rim of boxes along the mesh's edges
//   keeping them on it; 500 steps, sleeping off;
// - mesh/heightfield: the same surface as a 1,000 x 1,000 sample
//   heightfield (0.1 m cells) under the same pile.
// Each record also gives the time to build the mesh (its hierarchy and
// active edges) against Bullet's quantised hierarchy, and the same-work
// verdict: contacts, mean heights, and nobody below the surface.
#include <chrono>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>

#include "bench/bench.h"
#include "bench/bullet_world.h"
#include "bench/side_by_side.h"
#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/heightfield_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/colliders/triangle_mesh_collider.h"

namespace physdbg::bench {
namespace {

constexpr double amplitude = 2.0, waveNumber = 0.2;  // per metre of the 1 m cells

double surface(double x, double z) { return amplitude * std::sin(waveNumber * x) * std::cos(waveNumber * z); }

std::shared_ptr<HeightfieldCollider> sineField(int samples, double extent);

// The mesh: the triangles of the same surface sampled at every metre (a
// field's grid, so mesh and field split their cells alike).
std::shared_ptr<TriangleMeshCollider> sineMesh(int cells) {
  std::vector<Vec3> vertices;
  std::vector<MeshTriangle> triangles;
  sineField(cells + 1, cells)->sampledGrid(cells, vertices, triangles);
  return std::make_shared<TriangleMeshCollider>(std::move(vertices), triangles);
}

std::shared_ptr<HeightfieldCollider> sineField(int samples, double extent) {
  const double spacing = extent / (samples - 1), half = 0.5 * extent;
  std::vector<float> heights;
  heights.reserve(static_cast<std::size_t>(samples) * samples);
  for (int j = 0; j < samples; ++j)
    for (int i = 0; i < samples; ++i)
      heights.push_back(static_cast<float>(surface(i * spacing - half, j * spacing - half)));
  return std::make_shared<HeightfieldCollider>(std::move(heights), samples, samples, spacing, spacing, 1.0);
}

// `extent`: the surface's side, m.
SceneDescription pileOver(std::shared_ptr<const Collider> ground, double extent, int grid, int steps) {
  SceneDescription scene;
  scene.steps = steps;
  scene.world.allowSleep = false;
  BodyDefinition floor;
  floor.collider = std::move(ground);
  floor.isStatic = true;
  floor.material = {0.2, 0.5, 0.5};
  scene.bodies.push_back(floor);
  // A rim along the surface's edges, so that bodies rolling down its slopes
  // stay on it in both engines: bodies that left it would be outside.
  const double edge = 0.5 * extent;
  for (const double side : {-1.0, 1.0})
    for (const bool alongX : {false, true}) {
      BodyDefinition rim;
      rim.collider = std::make_shared<BoxCollider>(alongX ? Vec3(edge + 1.0, 3.0, 0.5) : Vec3(0.5, 3.0, edge + 1.0));
      rim.position = alongX ? Vec3(0, 0, side * (edge + 0.5)) : Vec3(side * (edge + 0.5), 0, 0);
      rim.isStatic = true;
      rim.material = floor.material;
      scene.bodies.push_back(rim);
    }
  const std::vector<std::shared_ptr<const Collider>> shapes = {
      std::make_shared<SphereCollider>(0.5), std::make_shared<BoxCollider>(Vec3(0.5, 0.5, 0.5)),
      std::make_shared<CapsuleCollider>(0.3, 0.5),
      std::make_shared<ConvexMeshCollider>(std::vector<Vec3>{{0.5, 0, 0}, {-0.4, 0.1, 0.3}, {0, 0.5, -0.2},
                                                             {0.1, -0.45, 0.3}, {0, 0, -0.5}, {-0.3, -0.3, -0.3},
                                                             {0.3, 0.3, 0.3}})};
  const double spacing = 4.0, half = 0.5 * (grid - 1) * spacing;
  for (int z = 0; z < grid; ++z)
    for (int x = 0; x < grid; ++x)
      for (std::size_t k = 0; k < shapes.size(); ++k) {
        BodyDefinition body;
        body.collider = shapes[k];
        body.position = Vec3(x * spacing - half, 5.0 + 2.5 * static_cast<double>(k), z * spacing - half);
        body.orientation = Quat(Eigen::AngleAxisd(0.3 * (x + z + static_cast<int>(k)), Vec3(1, 1, 0).normalized()));
        body.material = {0.2, 0.5, 0.5};
        scene.bodies.push_back(body);
      }
  return scene;
}

void runPile(const std::string& name, const SceneDescription& scene, double oursBuildMs, double peerBuildMs,
             const BenchOptions& options, const BenchSink& sink) {
  const int steps = scene.steps;
  const EngineRun peer = runBullet(scene, steps, false);
  std::optional<double> singleThreadMs;
  for (const int threads : benchThreadCounts(options)) {
    const EngineRun ours = runOurs(scene, steps, options, threads);
    nlohmann::json record = benchRecord(name, static_cast<long long>(scene.bodies.size() - 5), ours.msPerStep,
                                        peer.ran ? "bullet 3.24 btDbvt+SI(10), btBvhTriangleMeshShape / "
                                                   "btHeightfieldTerrainShape"
                                                 : "",
                                        peer.msPerStep);
    addThreadFields(record, threads, ours.msPerStep, singleThreadMs);
    addStageFields(record, ours, steps);
    if (threads == 1) singleThreadMs = ours.msPerStep;
    record["steps"] = steps;
    record["ours_build_ms"] = oursBuildMs;
    if (peer.ran && peerBuildMs > 0) {
      record["peer_build_ms"] = peerBuildMs;
      record["build_ratio"] = oursBuildMs / peerBuildMs;
    }
    WorkCheck check;
    check.firstDynamic = 5;  // after the surface and its rim
    check.bodySize = 1.0;
    check.outside = [](const Vec3& p) { return p.y() < surface(p.x(), p.z()) - 1.0; };  // below the surface
    addWorkFields(record, ours, peer, check);
    record["ours_final_kinetic_energy"] = ours.kineticEnergy;
    if (peer.ran) record["peer_final_kinetic_energy"] = peer.kineticEnergy;
    sink(record);
  }
}

void runMeshBenchmark(const BenchOptions& options, const BenchSink& sink) {
  const int cells = options.quick ? 20 : 100, grid = options.quick ? 4 : 21, steps = options.quick ? 10 : 500;
  const auto start = std::chrono::steady_clock::now();
  const std::shared_ptr<TriangleMeshCollider> mesh = sineMesh(cells);
  const double buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  runPile("mesh/triangles", pileOver(mesh, cells, grid, steps), buildMs, BulletWorld::meshBuildMilliseconds(*mesh), options,
          sink);
  const int samples = options.quick ? 101 : 1000;
  const auto fieldStart = std::chrono::steady_clock::now();
  const std::shared_ptr<HeightfieldCollider> field = sineField(samples, cells);
  const double fieldMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - fieldStart).count();
  runPile("mesh/heightfield", pileOver(field, cells, grid, steps), fieldMs, 0.0, options, sink);
}

}  // namespace

Benchmark meshBenchmark() {
  return {"mesh",
          "Jolt's ConvexVsMesh scene as physdbg defines it: 1,764 mixed bodies onto a 20,000-triangle sine mesh, and "
          "onto the same surface as a 1,000 x 1,000 heightfield, 500 steps, against Bullet",
          runMeshBenchmark};
}

}  // namespace physdbg::bench
