// Property tests of buildConvexHull against brute force, on random clouds with
// fixed seeds, at sizes from 1e-150 to 1e150 and far from the origin, and the
// degenerate clouds that must be refused with std::invalid_argument.
#include "engine/colliders/convex_hull.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace physdbg {
namespace {

// The test's own arithmetic runs on the cloud moved to its bounding box's
// centre and divided by its half-extent, where nothing under- or overflows.
struct UnitFrame {
  Vec3 centre = Vec3::Zero();
  double scale = 1.0;
  Vec3 map(const Vec3& p) const { return (p - centre) / scale; }
};

UnitFrame unitFrameOf(const std::vector<Vec3>& points) {
  Vec3 low = points.front(), high = points.front();
  for (const Vec3& p : points) low = low.cwiseMin(p), high = high.cwiseMax(p);
  return {0.5 * low + 0.5 * high, (0.5 * high - 0.5 * low).maxCoeff()};
}

Vec3 unitNormal(const ConvexHull& hull, const UnitFrame& frame, const std::array<int, 3>& t) {
  const Vec3 a = frame.map(hull.vertices[t[0]]), b = frame.map(hull.vertices[t[1]]), c = frame.map(hull.vertices[t[2]]);
  return (b - a).cross(c - a).normalized();
}

double unitVolume(const ConvexHull& hull, const UnitFrame& frame) {
  double volume = 0.0;
  for (const auto& t : hull.triangles) {
    volume += frame.map(hull.vertices[t[0]]).dot(frame.map(hull.vertices[t[1]]).cross(frame.map(hull.vertices[t[2]])));
  }
  return volume / 6.0;
}

void expectVerticesAreInputPoints(const ConvexHull& hull, const std::vector<Vec3>& points) {
  std::vector<std::array<double, 3>> input;
  for (const Vec3& p : points) input.push_back({p.x(), p.y(), p.z()});
  std::ranges::sort(input);
  for (const Vec3& v : hull.vertices) EXPECT_TRUE(std::ranges::binary_search(input, std::array{v.x(), v.y(), v.z()}));
}

// Directed edges (from, to) with the vertex opposite each, sorted.
std::vector<std::array<int, 3>> directedEdges(const ConvexHull& hull) {
  std::vector<std::array<int, 3>> edges;
  for (const auto& t : hull.triangles) {
    for (int e = 0; e < 3; ++e) edges.push_back({t[e], t[(e + 1) % 3], t[(e + 2) % 3]});
  }
  std::ranges::sort(edges);
  return edges;
}

// The edge (from, to) in `edges`, or nullptr.
const std::array<int, 3>* findEdge(const std::vector<std::array<int, 3>>& edges, int from, int to) {
  const auto it = std::ranges::lower_bound(edges, std::array{from, to, std::numeric_limits<int>::min()});
  return it != edges.end() && (*it)[0] == from && (*it)[1] == to ? &*it : nullptr;
}

// Every directed edge once with its reverse (closed, oriented), every vertex
// used, and V - E + F = 2.
void expectClosedSphere(const ConvexHull& hull) {
  const std::vector<std::array<int, 3>> edges = directedEdges(hull);
  std::vector<char> used(hull.vertices.size(), 0);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    EXPECT_FALSE(i > 0 && edges[i][0] == edges[i - 1][0] && edges[i][1] == edges[i - 1][1]) << "edge twice";
    EXPECT_NE(findEdge(edges, edges[i][1], edges[i][0]), nullptr) << "edge without its reverse";
    used[edges[i][0]] = 1;
  }
  EXPECT_EQ(std::ranges::count(used, 1), static_cast<long>(hull.vertices.size()));
  const long vertices = static_cast<long>(hull.vertices.size()), undirected = static_cast<long>(edges.size()) / 2;
  EXPECT_EQ(vertices - undirected + static_cast<long>(hull.triangles.size()), 2);
}

// The plane of a thin triangle is only known to DBL_EPSILON times its length
// over its height (a tilt), which moves the plane that much at the far side
// of the cloud: the test allows for it.
double planeUncertainty(const ConvexHull& hull, const UnitFrame& frame, const std::array<int, 3>& t) {
  const Vec3 a = frame.map(hull.vertices[t[0]]), b = frame.map(hull.vertices[t[1]]), c = frame.map(hull.vertices[t[2]]);
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  const double height = (b - a).cross(c - a).norm() / longest;
  return 1e-14 * longest / height;
}

// Every input point is inside or on every `stride`-th triangle's plane and
// every merged face's plane, within `tolerance` of the cloud's half-extent.
void expectContainsAll(const ConvexHull& hull, const std::vector<Vec3>& points, double tolerance, int stride = 1) {
  const UnitFrame frame = unitFrameOf(points);
  std::vector<Vec3> local;
  for (const Vec3& p : points) local.push_back(frame.map(p));
  for (std::size_t t = 0; t < hull.triangles.size(); t += stride) {
    const Vec3 normal = unitNormal(hull, frame, hull.triangles[t]);
    const Vec3 corner = frame.map(hull.vertices[hull.triangles[t][0]]);
    double worst = -1.0;
    for (const Vec3& p : local) worst = std::max(worst, normal.dot(p - corner));
    EXPECT_LE(worst, tolerance + planeUncertainty(hull, frame, hull.triangles[t])) << "triangle " << t;
  }
  for (std::size_t f = 0; f < hull.faces.size(); f += stride) {
    const HullFace& face = hull.faces[f];
    const Vec3 corner = frame.map(hull.vertices[face.vertices[0]]);
    for (int v : face.vertices) EXPECT_LE(std::abs(face.normal.dot(frame.map(hull.vertices[v]) - corner)), tolerance);
    double worst = -1.0;
    for (const Vec3& p : local) worst = std::max(worst, face.normal.dot(p - corner));
    EXPECT_LE(worst, tolerance) << "face " << f;
  }
}

// Each edge is convex: the far vertex of the neighbouring triangle is not above the plane.
void expectLocallyConvex(const ConvexHull& hull, double tolerance) {
  const UnitFrame frame = unitFrameOf(hull.vertices);
  const std::vector<std::array<int, 3>> edges = directedEdges(hull);
  for (const auto& t : hull.triangles) {
    const Vec3 normal = unitNormal(hull, frame, t), corner = frame.map(hull.vertices[t[0]]);
    for (int e = 0; e < 3; ++e) {
      const std::array<int, 3>* twin = findEdge(edges, t[(e + 1) % 3], t[e]);
      ASSERT_NE(twin, nullptr);
      EXPECT_LE(normal.dot(frame.map(hull.vertices[(*twin)[2]]) - corner),
                tolerance + planeUncertainty(hull, frame, t));
    }
  }
}

void expectSoundHull(const ConvexHull& hull, const std::vector<Vec3>& points, double tolerance, int stride = 1) {
  expectVerticesAreInputPoints(hull, points);
  expectClosedSphere(hull);
  expectLocallyConvex(hull, tolerance);
  expectContainsAll(hull, points, tolerance, stride);
  EXPECT_EQ(hull.neighbourStart.size(), hull.vertices.size() + 1);
  EXPECT_EQ(hull.neighbourPoints.size(), hull.neighbours.size());
}

enum class Cloud { Ball, Sphere, Cube, Gaussian };

std::vector<Vec3> randomCloud(Cloud kind, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> points;
  while (static_cast<int>(points.size()) < count) {
    const Vec3 direction = Vec3(gaussian(rng), gaussian(rng), gaussian(rng)).normalized();
    if (kind == Cloud::Ball) points.push_back(direction * std::cbrt(0.5 * unit(rng) + 0.5));
    if (kind == Cloud::Sphere) points.push_back(direction);
    if (kind == Cloud::Cube) points.emplace_back(unit(rng), unit(rng), unit(rng));
    if (kind == Cloud::Gaussian) points.emplace_back(gaussian(rng), gaussian(rng), gaussian(rng));
  }
  return points;
}

std::vector<Vec3> moved(std::vector<Vec3> points, const Vec3& offset, double scale) {
  for (Vec3& p : points) p = (p + offset) * scale;
  return points;
}

// Corners of [-1, 1]^3, random points inside and on its faces.
std::vector<Vec3> cubeWithInnerPoints(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < 100; ++i) points.emplace_back(0.9 * unit(rng), 0.9 * unit(rng), 0.9 * unit(rng));
  for (int i = 0; i < 30; ++i) {
    Vec3 p(unit(rng), unit(rng), unit(rng));
    p[i % 3] = i % 2 == 0 ? 1.0 : -1.0;
    points.push_back(p);
  }
  for (int i = 0; i < 8; ++i) points.emplace_back(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0);
  std::shuffle(points.begin(), points.end(), rng);
  return points;
}

std::string messageOf(const std::vector<Vec3>& points) {
  try {
    buildConvexHull(points);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(no exception)";
}

void expectRefused(const std::vector<Vec3>& points, const std::string& reason) {
  EXPECT_NE(messageOf(points).find(reason), std::string::npos) << messageOf(points);
}

TEST(ConvexHull, RandomCloudsMatchBruteForceAtEveryScaleAndOffset) {
  for (Cloud kind : {Cloud::Ball, Cloud::Sphere, Cloud::Cube, Cloud::Gaussian}) {
    for (unsigned seed : {1u, 2u, 3u}) {
      for (const auto& [offset, scale] :
           {std::pair{0.0, 1.0}, {1e6, 1e-100}, {1e6, 1e100}, {0.0, 1e-150}, {-3e5, 1e150}}) {
        SCOPED_TRACE(::testing::Message() << "kind " << static_cast<int>(kind) << " seed " << seed << " offset "
                                          << offset << " scale " << scale);
        const std::vector<Vec3> points =
            moved(randomCloud(kind, 300, seed), Vec3(offset, -offset, 0.5 * offset), scale);
        expectSoundHull(buildConvexHull(points), points, 1e-8);
      }
    }
  }
}

TEST(ConvexHull, CubeVolumeIsExactAtEveryScaleAndOffset) {
  for (const auto& [offset, scale] : {std::pair{0.0, 1.0}, {1e6, 1e-100}, {1e6, 1e100}, {-1e6, 1.0}, {0.0, 1e-150}}) {
    SCOPED_TRACE(::testing::Message() << "offset " << offset << " scale " << scale);
    const std::vector<Vec3> points = moved(cubeWithInnerPoints(7), Vec3(offset, offset, -offset), scale);
    const ConvexHull hull = buildConvexHull(points);
    expectSoundHull(hull, points, 1e-8);
    EXPECT_EQ(hull.vertices.size(), 8u);
    EXPECT_EQ(hull.faces.size(), 6u);
    EXPECT_NEAR(unitVolume(hull, unitFrameOf(points)), 8.0, 1e-8);
  }
}

TEST(ConvexHull, SpherePointsAreAllVerticesAndNearlyTheSphereVolume) {
  const std::vector<Vec3> points = randomCloud(Cloud::Sphere, 4000, 11);
  const ConvexHull hull = buildConvexHull(points);
  expectSoundHull(hull, points, 1e-9, 7);
  const double sphere = 4.0 / 3.0 * std::acos(-1.0);
  const double volume = unitVolume(hull, unitFrameOf(points)) * std::pow(unitFrameOf(points).scale, 3);
  EXPECT_LT(volume, sphere);
  EXPECT_GT(volume, 0.995 * sphere);
  EXPECT_EQ(hull.vertices.size(), points.size());  // every point of a sphere is extreme
}

TEST(ConvexHull, CloudFarFromTheOriginThatUsedToCrash) {
  // 200 points in a 1 m cube a million metres out: the old build read the
  // boundary of an empty face group (SIGSEGV).
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  for (double distance : {1e6, 1e7, 1e12}) {
    SCOPED_TRACE(::testing::Message() << "distance " << distance);
    std::vector<Vec3> points;
    for (int i = 0; i < 200; ++i)
      points.push_back(Vec3(1.0, -0.5, 0.25) * distance + Vec3(unit(rng), unit(rng), unit(rng)));
    const ConvexHull hull = buildConvexHull(points);
    // Coordinates at 1e12 are spaced 1.2e-4 apart: the tolerance grows with them.
    expectSoundHull(hull, points, distance < 1e10 ? 1e-8 : 1e-2);
  }
}

TEST(ConvexHull, TinyAndHugeTetrahedraAreNotFlat) {
  for (double scale : {1e-150, 1e150, 1e-300, 1e300}) {
    SCOPED_TRACE(::testing::Message() << "scale " << scale);
    const std::vector<Vec3> points{Vec3::Zero(), Vec3(scale, 0, 0), Vec3(0, scale, 0), Vec3(0, 0, scale)};
    const ConvexHull hull = buildConvexHull(points);
    EXPECT_EQ(hull.vertices.size(), 4u);
    EXPECT_EQ(hull.faces.size(), 4u);
    expectSoundHull(hull, points, 1e-12);
    EXPECT_NEAR(unitVolume(hull, unitFrameOf(points)), 8.0 / 6.0, 1e-12);
  }
}

TEST(ConvexHull, CloudTooSmallForItsDistanceIsRefused) {
  std::vector<Vec3> points = moved(randomCloud(Cloud::Cube, 50, 4), Vec3(2e14, 0, 0), 1.0);
  expectRefused(points, "too small for its distance from the origin");
  points = moved(randomCloud(Cloud::Cube, 50, 4), Vec3(0, 0, -1e13), 1e-3);
  expectRefused(points, "too small for its distance from the origin");
}

TEST(ConvexHull, IntegerGridsGiveTheirBoundingBox) {
  for (double offset : {0.0, -5.0, 1e9}) {
    std::vector<Vec3> grid;
    for (int i = 0; i <= 10; ++i) {
      for (int j = 0; j <= 6; ++j) {
        for (int k = 0; k <= 4; ++k) grid.push_back(Vec3(i, j, k) + Vec3::Constant(offset));
      }
    }
    std::shuffle(grid.begin(), grid.end(), std::mt19937(9));
    const ConvexHull hull = buildConvexHull(grid);
    expectSoundHull(hull, grid, 1e-12);
    EXPECT_EQ(hull.vertices.size(), 8u);
    EXPECT_EQ(hull.faces.size(), 6u);
    const UnitFrame frame = unitFrameOf(grid);
    EXPECT_NEAR(unitVolume(hull, frame) * std::pow(frame.scale, 3), 10.0 * 6.0 * 4.0, 1e-9);
  }
}

TEST(ConvexHull, LatitudeLongitudeSphereMergesItsPlanarQuads) {
  // Rings of equal latitude are exactly coplanar, and neighbouring pairs of
  // two rings make planar trapezoids.
  std::vector<Vec3> points{Vec3(0, 0, 1), Vec3(0, 0, -1)};
  const double pi = std::acos(-1.0);
  for (int ring = 1; ring < 12; ++ring) {
    for (int k = 0; k < 24; ++k) {
      const double polar = pi * ring / 12.0, azimuth = 2.0 * pi * k / 24.0;
      points.push_back(Vec3(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar)));
    }
  }
  const ConvexHull hull = buildConvexHull(points);
  expectSoundHull(hull, points, 1e-9);
  EXPECT_EQ(hull.vertices.size(), points.size());
  EXPECT_EQ(hull.faces.size(), 24u * 10u + 2u * 24u);  // quads between rings, triangles at the poles
}

TEST(ConvexHull, DuplicatesAreDropped) {
  std::vector<Vec3> points;
  for (int copy = 0; copy < 50; ++copy) {
    for (const Vec3& corner : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}) points.push_back(corner);
  }
  const ConvexHull hull = buildConvexHull(points);
  EXPECT_EQ(hull.vertices.size(), 4u);
  expectSoundHull(hull, points, 1e-12);
}

TEST(ConvexHull, FlatAndNearlyFlatClouds) {
  std::vector<Vec3> plane;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Quat tilt(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  for (int i = 0; i < 200; ++i) plane.push_back(tilt * Vec3(unit(rng), unit(rng), 0.0));
  plane.push_back(tilt * Vec3(-1, -1, 0));
  plane.push_back(tilt * Vec3(1, -1, 0));
  plane.push_back(tilt * Vec3(1, 1, 0));
  plane.push_back(tilt * Vec3(-1, 1, 0));
  expectRefused(plane, "flat");
  // One point barely off: within the tolerance (1e-10 of the size) it is flat,
  // beyond it a thin pyramid on the square with volume 4 h / 3.
  for (double height : {1e-12, 1e-9, 1e-6, 1e-2}) {
    SCOPED_TRACE(::testing::Message() << "height " << height);
    std::vector<Vec3> points = plane;
    points.push_back(tilt * Vec3(0.3, -0.2, height));
    if (height < 1e-10) {
      expectRefused(points, "flat");
      continue;
    }
    const ConvexHull hull = buildConvexHull(points);
    expectSoundHull(hull, points, 1e-9);
    EXPECT_EQ(hull.vertices.size(), 5u);
    // The brute-force volume sums terms of the cloud's size: it rounds to 1e-16 of that.
    EXPECT_NEAR(unitVolume(hull, unitFrameOf(points)) * std::pow(unitFrameOf(points).scale, 3), 4.0 * height / 3.0,
                1e-14);
  }
  // A slab of random points 1e-12 thick is flat too.
  std::vector<Vec3> slab = plane;
  for (Vec3& p : slab) p += tilt * Vec3(0, 0, 1e-12 * unit(rng));
  expectRefused(slab, "flat");
}

// Points on a few planes, shaken by less and more than the tolerance: the
// classic way to fold a hull built with tolerances over itself.
std::vector<Vec3> nearlyCoplanarCloud(int kind, double shake, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  const Quat turn(Eigen::AngleAxisd(3.0 * unit(rng), Vec3(gaussian(rng), gaussian(rng), gaussian(rng)).normalized()));
  std::vector<Vec3> points;
  for (int i = 0; i < 150; ++i) {
    Vec3 p(unit(rng), unit(rng), unit(rng));
    if (kind == 0) p[i % 3] = (i / 3) % 2 == 0 ? 1.0 : -1.0;  // on a cube's faces
    if (kind == 1) p = (3.0 * p).array().round();             // a small integer grid
    if (kind == 2) {                                          // rings of equal latitude
      const double z = std::round(4.0 * unit(rng)) / 4.0, azimuth = 3.2 * unit(rng);
      p = Vec3(std::sqrt(1.0 - z * z) * std::cos(azimuth), std::sqrt(1.0 - z * z) * std::sin(azimuth), z);
    }
    if (kind == 3) p.z() = i % 7 == 0 ? 1.0 : 0.0;  // two parallel planes
    points.push_back(turn * (p + shake * Vec3(unit(rng), unit(rng), unit(rng))));
  }
  return points;
}

TEST(ConvexHull, NearlyCoplanarCloudsNeverFoldOver) {
  for (int kind = 0; kind < 4; ++kind) {
    for (double shake : {0.0, 1e-13, 1e-11, 1e-10, 5e-10, 1e-9, 1e-7}) {
      for (double offset : {0.0, 1e6}) {
        for (unsigned seed = 0; seed < 8; ++seed) {
          SCOPED_TRACE(::testing::Message()
                       << "kind " << kind << " shake " << shake << " offset " << offset << " seed " << seed);
          const std::vector<Vec3> points = moved(nearlyCoplanarCloud(kind, shake, seed), Vec3::Constant(offset), 1.0);
          expectSoundHull(buildConvexHull(points), points, 1e-8);
        }
      }
    }
  }
}

TEST(ConvexHull, BadCloudsAreRefusedWithTheReason) {
  expectRefused({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, "at least 4 distinct points");
  expectRefused({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 1, 0), Vec3(1, 0, 0)}, "at least 4 distinct");
  expectRefused({Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2), Vec3(3, 3, 3), Vec3(1.5, 1.5, 1.5)}, "collinear");
  std::vector<Vec3> needle;
  for (int i = 0; i < 20; ++i) needle.emplace_back(i, 1e-12 * (i % 3), 1e-12 * (i % 5));
  expectRefused(needle, "collinear");
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  expectRefused({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, nan)}, "non-finite");
  expectRefused({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, inf)}, "non-finite");
}

TEST(ConvexHull, HundredThousandPointsInABallAndOnASphere) {
  // Correctness only; the build times are in the commit that made it quickhull.
  for (Cloud kind : {Cloud::Ball, Cloud::Sphere}) {
    SCOPED_TRACE(::testing::Message() << "kind " << static_cast<int>(kind));
    const std::vector<Vec3> points = randomCloud(kind, 100000, 21);
    const ConvexHull hull = buildConvexHull(points);
    expectVerticesAreInputPoints(hull, points);
    expectClosedSphere(hull);
    expectLocallyConvex(hull, 1e-9);
    expectContainsAll(hull, points, 1e-9, kind == Cloud::Sphere ? 997 : 13);
    if (kind == Cloud::Sphere) {
      EXPECT_EQ(hull.vertices.size(), points.size());
    }
    // Along any direction the hull reaches as far as the cloud.
    std::mt19937 rng(22);
    std::normal_distribution<double> gaussian(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
      const Vec3 direction(gaussian(rng), gaussian(rng), gaussian(rng));
      double cloud = -1e300, vertices = -1e300;
      for (const Vec3& p : points) cloud = std::max(cloud, p.dot(direction));
      for (const Vec3& v : hull.vertices) vertices = std::max(vertices, v.dot(direction));
      EXPECT_NEAR(vertices, cloud, 1e-9 * direction.norm());
    }
  }
}

}  // namespace
}  // namespace physdbg
