// `physdbg bench narrow`: pairs per second and depth error of collide()
// against libccd's GJK/EPA and MPR on identical pairs, for sphere-sphere,
// box-box, box-sphere and convex hulls of 32 and 256 points, at shallow and
// deep penetration. Errors are relative to the pair's size (sum of bounding
// radii) and measured against narrow_reference.h.
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <random>

#include <nlohmann/json.hpp>

#include "bench/bench.h"
#include "bench/narrow_ccd_peer.h"
#include "bench/narrow_reference.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/narrowphase/narrow_phase.h"

namespace physdbg::bench {
namespace {

struct Pose {
  const Collider* colliderA;
  const Collider* colliderB;
  Transform a, b;
  double reference = NAN;  // NaN: no reference computed for this pose
  double size = 1.0;       // errors are relative to this
};

struct PairCase {
  std::string name;
  std::shared_ptr<const Collider> a, b;
  std::function<double(const Pose&)> reference;
  int referencePoses;  // references are costly for big hulls: only the first ones
};

double boundingRadius(const Collider& c) { return c.localBounds().halfExtents().norm(); }

Quat randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> gaussian(0.0, 1.0);
  return Quat(gaussian(rng), gaussian(rng), gaussian(rng), gaussian(rng)).normalized();
}

// B is pushed along a random direction until the supports overlap by a
// multiple of `fraction` of the pair size along it and the pair penetrates.
std::vector<Pose> makePoses(const PairCase& c, double fraction, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  const double size = boundingRadius(*c.a) + boundingRadius(*c.b);
  std::vector<Pose> poses;
  for (int i = 0; i < count; ++i) {
    const Vec3 u = Vec3(gaussian(rng), gaussian(rng), gaussian(rng)).normalized();
    Pose pose{c.a.get(), c.b.get(), {Vec3::Zero(), randomRotation(rng)}, {Vec3::Zero(), randomRotation(rng)}, NAN, size};
    const double reachA = c.a->support(pose.a, u).dot(u);
    const double reachB = c.b->support(pose.b, -u).dot(-u);
    // Overlapping supports along u need not mean contact (another axis may
    // separate): step closer until the pair really penetrates.
    for (int step = 1; step < 100; ++step) {
      pose.b.position = u * (reachA + reachB - step * fraction * size);
      if (collide(*c.a, pose.a, *c.b, pose.b).status == ContactStatus::Penetrating) break;
    }
    if (i < c.referencePoses) pose.reference = c.reference(pose);
    poses.push_back(pose);
  }
  return poses;
}

std::vector<Vec3> worldVertices(const Collider& c, const Transform& t) {
  std::vector<Vec3> out;
  if (c.kind() == ColliderKind::Box) {
    const Vec3 h = static_cast<const BoxCollider&>(c).halfExtents();
    for (int i = 0; i < 8; ++i) out.push_back(t.apply(Vec3(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z())));
  } else {
    for (const Vec3& v : static_cast<const ConvexMeshCollider&>(c).hullVertices()) out.push_back(t.apply(v));
  }
  return out;
}

std::shared_ptr<const Collider> ellipsoidHull(int points, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  std::vector<Vec3> cloud;
  for (int i = 0; i < points; ++i) {
    cloud.push_back(Vec3(gaussian(rng), gaussian(rng), gaussian(rng)).normalized().cwiseProduct(Vec3(0.6, 0.5, 0.4)));
  }
  return std::make_shared<ConvexMeshCollider>(cloud);
}

std::vector<PairCase> pairCases(bool quick) {
  auto sphereA = std::make_shared<SphereCollider>(0.5), sphereB = std::make_shared<SphereCollider>(0.4);
  auto boxA = std::make_shared<BoxCollider>(Vec3(0.5, 0.4, 0.3)), boxB = std::make_shared<BoxCollider>(Vec3(0.6, 0.2, 0.35));
  const auto polytope = [](const PairCase* c) {
    return [c](const Pose& p) { return polytopeDepth(worldVertices(*c->a, p.a), worldVertices(*c->b, p.b)); };
  };
  std::vector<PairCase> cases;
  cases.push_back({"sphere-sphere", sphereA, sphereB,
                   [](const Pose& p) { return sphereSphereDepth(0.5, p.a.position, 0.4, p.b.position); }, 1 << 30});
  cases.push_back({"box-sphere", boxA, sphereB,
                   [boxA](const Pose& p) { return boxSphereDepth(*boxA, p.a, 0.4, p.b.position); }, 1 << 30});
  cases.push_back({"box-box", boxA, boxB, nullptr, 1 << 30});
  cases.push_back({"mesh32-mesh32", ellipsoidHull(32, 1), ellipsoidHull(32, 2), nullptr, quick ? 20 : 400});
  cases.push_back({"mesh256-mesh256", ellipsoidHull(256, 3), ellipsoidHull(256, 4), nullptr, quick ? 2 : 16});
  for (PairCase& c : cases) {
    if (!c.reference) c.reference = polytope(&c);
  }
  return cases;
}

struct Measured {
  double ms = 0.0;
  double maxError = 0.0;  // relative to the pair size
  int nan = 0;
  std::vector<double> depths;  // per pose, kept for small pose sets
};

template <typename Query>
Measured measure(const std::vector<Pose>& poses, int repeats, const Query& query) {
  Measured m;
  volatile double sink = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r) {
    for (const Pose& pose : poses) sink = sink + query(pose).first;
  }
  m.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  for (const Pose& pose : poses) {
    const auto [depth, finite] = query(pose);
    if (poses.size() <= 16) m.depths.push_back(depth);
    if (!finite) ++m.nan;  // a NaN normal with a finite depth still counts its depth error
    if (std::isfinite(depth) && !std::isnan(pose.reference)) {
      m.maxError = std::max(m.maxError, std::abs(depth - pose.reference) / pose.size);
    }
  }
  return m;
}

constexpr double kCcdTolerance = 1e-4;  // libccd's default EPA and MPR tolerance, metres

// One record per libccd method: ours and the peer on the same poses.
void emitRecords(const std::string& name, const std::vector<Pose>& poses, int repeats, int referencePoses,
                 const BenchSink& sink) {
  const Measured ours = measure(poses, repeats, [](const Pose& p) {
    const ContactResult r = collide(*p.colliderA, p.a, *p.colliderB, p.b);
    return std::pair{r.depth, std::isfinite(r.depth) && isFinite(r.normal)};
  });
  // Work-precision: ours with its relative tolerance at libccd's 1e-4 m over
  // the pair's size, which is where our EPA then stops (GJK's stop is
  // relative to the squared distance, so it only loosens with it).
  const Measured loose = measure(poses, repeats, [](const Pose& p) {
    NarrowPhaseOptions options;
    options.relativeTolerance = kCcdTolerance / p.size;
    const ContactResult r = collide(*p.colliderA, p.a, *p.colliderB, p.b, options);
    return std::pair{r.depth, std::isfinite(r.depth) && isFinite(r.normal)};
  });
  for (CcdMethod method : {CcdMethod::GjkEpa, CcdMethod::Mpr}) {
    const bool peer = ccdAvailable();
    const Measured theirs = peer ? measure(poses, repeats, [&](const Pose& p) {
      const PeerContact r = ccdPenetration(method, *p.colliderA, p.a, *p.colliderB, p.b);
      return std::pair{r.depth, std::isfinite(r.depth) && isFinite(r.normal)};
    }) : Measured{};
    const long long n = static_cast<long long>(poses.size()) * repeats;
    nlohmann::json record = benchRecord(name, n, ours.ms, peer ? ccdMethodName(method) : "", theirs.ms);
    record["ours_pairs_per_s"] = n / (ours.ms * 1e-3);
    record["peer_pairs_per_s"] = peer ? nlohmann::json(n / (theirs.ms * 1e-3)) : nlohmann::json();
    record["ours_err"] = ours.maxError;
    record["peer_err"] = peer ? nlohmann::json(theirs.maxError) : nlohmann::json();
    record["ours_nan"] = ours.nan;
    record["peer_nan"] = theirs.nan;
    record["reference_poses"] = referencePoses;
    record["ours_at_peer_tolerance_ms"] = loose.ms;
    record["ours_at_peer_tolerance_err"] = loose.maxError;
    record["ours_at_peer_tolerance_nan"] = loose.nan;
    record["ratio_at_peer_tolerance"] = peer ? nlohmann::json(loose.ms / theirs.ms) : nlohmann::json();
    if (!ours.depths.empty()) {  // NaN becomes null in JSON
      record["ours_depths"] = ours.depths;
      record["peer_depths"] = theirs.depths;
    }
    sink(record);
  }
}

// The inputs public implementations get wrong (NOTES.md): face-on cubes 1.9
// apart, identical boxes, touching cubes, a sphere on a 0.01 plate, spheres
// 1e5 from the origin. Each has an analytic depth.
void runPathological(int repeats, const BenchSink& sink) {
  const BoxCollider cube(Vec3(1, 1, 1)), flatBox(Vec3(1, 0.5, 0.25)), plate(Vec3(1, 1, 0.005));
  const SphereCollider sphere(0.5), unit(1.0);
  const auto at = [](double x, double y, double z) { return Transform{Vec3(x, y, z), Quat::Identity()}; };
  const std::vector<Pose> poses{
      {&cube, &cube, at(0, 0, 0), at(0, 0, 1.9), 0.1, 2 * std::sqrt(3.0)},
      {&cube, &cube, at(0, 0, 0), at(1.9, 0.5, 0.0), 0.1, 2 * std::sqrt(3.0)},
      {&flatBox, &flatBox, at(0, 0, 0), at(0, 0, 0), 0.5, 2 * 1.1456439237389600},
      {&cube, &cube, at(0, 0, 0), at(0, 0, 2.0), 0.0, 2 * std::sqrt(3.0)},
      {&plate, &sphere, at(0, 0, 0), at(0.2, -0.3, 0.497), 0.008, 1.5},
      {&unit, &unit, at(1e5, 0, 0), at(1e5 + 1.5, 0, 0), 0.5, 2.0},
  };
  emitRecords("narrow/pathological", poses, repeats, static_cast<int>(poses.size()), sink);
}

void runNarrow(const BenchOptions& options, const BenchSink& sink) {
  const int poseCount = options.quick ? 50 : 2000;
  const int repeats = options.quick ? 1 : 10;
  const struct { const char* name; double fraction; } depths[] = {{"shallow", 0.02}, {"deep", 0.3}};
  for (const PairCase& c : pairCases(options.quick)) {
    for (const auto& [depthName, fraction] : depths) {
      emitRecords("narrow/" + c.name + "/" + depthName, makePoses(c, fraction, poseCount, 42), repeats,
                  std::min(c.referencePoses, poseCount), sink);
    }
  }
  runPathological(options.quick ? 1 : 1000, sink);
}

}  // namespace

Benchmark narrowBenchmark() {
  return {"narrow", "narrow phase: pairs/s and depth error vs libccd GJK/EPA and MPR", runNarrow};
}

}  // namespace physdbg::bench
