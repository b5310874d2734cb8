#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/dynamics/rigid_body.h"

namespace physdbg {
namespace {

std::vector<Vec3> cubeCorners(const Vec3& half, const Vec3& offset = Vec3::Zero()) {
  std::vector<Vec3> points;
  for (int i = 0; i < 8; ++i) {
    points.push_back(offset + Vec3(i & 1 ? half.x() : -half.x(), i & 2 ? half.y() : -half.y(), i & 4 ? half.z() : -half.z()));
  }
  return points;
}

TEST(ConvexMeshCollider, CubeWithDuplicatesAndCoplanarPointsHasSixQuads) {
  std::vector<Vec3> points = cubeCorners(Vec3(1, 1, 1));
  points.push_back(points[3]);              // duplicate
  points.emplace_back(0, 0, 0);             // interior
  points.emplace_back(1, 0.3, -0.2);        // on a face
  points.emplace_back(1, 1, 0);             // on an edge
  points.insert(points.begin(), Vec3(-1, 0.5, 0.5));  // on a face before the corners
  ConvexMeshCollider mesh(points);
  EXPECT_EQ(mesh.hullFaces().size(), 6u);
  for (const HullFace& face : mesh.hullFaces()) {
    EXPECT_NEAR(face.normal.cwiseAbs().maxCoeff(), 1.0, 1e-12);
    EXPECT_NEAR(face.offset, 1.0, 1e-12);
    for (int v : face.vertices) EXPECT_NEAR(face.normal.dot(mesh.hullVertices()[v]), 1.0, 1e-12);
    // Counter-clockwise seen from outside: every corner turns the same way.
    const auto& verts = mesh.hullVertices();
    for (std::size_t i = 0; i < face.vertices.size(); ++i) {
      const Vec3& p0 = verts[face.vertices[i]];
      const Vec3& p1 = verts[face.vertices[(i + 1) % face.vertices.size()]];
      const Vec3& p2 = verts[face.vertices[(i + 2) % face.vertices.size()]];
      EXPECT_GE((p1 - p0).cross(p2 - p1).dot(face.normal), 0.0);
    }
  }
  EXPECT_NEAR(mesh.volume(), 8.0, 1e-12);
  EXPECT_LE(mesh.centroid().norm(), 1e-12);
}

TEST(ConvexMeshCollider, MassPropertiesMatchTheBoxAboutTheCentroid) {
  const Vec3 half(0.5, 1.0, 1.5), offset(3, -2, 7);
  ConvexMeshCollider mesh(cubeCorners(half, offset));
  BoxCollider box(half);
  EXPECT_NEAR(mesh.volume(), box.volume(), 1e-12);
  EXPECT_LE((mesh.centroid() - offset).norm(), 1e-12);
  EXPECT_LE((mesh.unitInertia() - box.unitInertia()).norm(), 1e-12);
  EXPECT_LE((mesh.localBounds().min - (offset - half)).norm(), 0.0);
}

TEST(ConvexMeshCollider, HillClimbingSupportMatchesBruteForce) {
  std::mt19937 rng(17);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  std::vector<Vec3> sphereCloud;
  for (int i = 0; i < 256; ++i) sphereCloud.push_back(Vec3(gaussian(rng), gaussian(rng), gaussian(rng)).normalized());
  ConvexMeshCollider mesh(sphereCloud);
  EXPECT_GT(mesh.hullVertices().size(), 200u);
  int hint = -1;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 direction(gaussian(rng), gaussian(rng), gaussian(rng));
    double best = -1e300;
    for (const Vec3& p : sphereCloud) best = std::max(best, p.dot(direction));
    EXPECT_NEAR(mesh.localSupport(direction).dot(direction), best, 1e-12);
    hint = mesh.supportIndex(direction, hint);
    EXPECT_NEAR(mesh.hullVertices()[hint].dot(direction), best, 1e-12);
  }
}

// The linear scan the hill climb must reproduce bit for bit: p . d in the
// same order of operations, the first (lowest) index of the largest value.
int scannedSupport(const std::vector<Vec3>& vertices, const Vec3& d) {
  int best = 0;
  double top = vertices[0].x() * d.x() + vertices[0].y() * d.y() + vertices[0].z() * d.z();
  for (int i = 1; i < static_cast<int>(vertices.size()); ++i) {
    const double value = vertices[i].x() * d.x() + vertices[i].y() * d.y() + vertices[i].z() * d.z();
    if (value > top) top = value, best = i;
  }
  return best;
}

std::vector<Vec3> sphereCloud(int count, unsigned seed, const Vec3& offset = Vec3::Zero()) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  std::vector<Vec3> cloud;
  for (int i = 0; i < count; ++i) cloud.push_back(offset + Vec3(gaussian(rng), gaussian(rng), gaussian(rng)).normalized());
  return cloud;
}

// Two regular polygons stacked: caps with `sides` corners seen head-on tie
// every corner, and the side quads tie pairs and fours.
std::vector<Vec3> prism(int sides) {
  std::vector<Vec3> points;
  for (int i = 0; i < sides; ++i) {
    const double angle = 2.0 * M_PI * i / sides;
    for (double z : {-0.5, 0.5}) points.emplace_back(std::cos(angle), std::sin(angle), z);
  }
  return points;
}

// Directions where several vertices tie: hull triangle normals, face
// normals, axes, and the same nudged by a few ulps; then random ones.
std::vector<Vec3> probeDirections(const ConvexMeshCollider& mesh, std::mt19937& rng) {
  std::normal_distribution<double> gaussian(0.0, 1.0);
  const auto& v = mesh.hullVertices();
  std::vector<Vec3> directions;
  for (const auto& t : mesh.hullTriangles()) directions.push_back((v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]));
  for (const HullFace& face : mesh.hullFaces()) directions.push_back(face.normal);
  for (int axis = 0; axis < 3; ++axis) directions.push_back(Vec3::Unit(axis)), directions.push_back(-Vec3::Unit(axis));
  const std::size_t exact = directions.size();
  for (std::size_t i = 0; i < exact; ++i) {
    directions.push_back(directions[i] + 1e-15 * Vec3(gaussian(rng), gaussian(rng), gaussian(rng)));
  }
  for (int i = 0; i < 2000; ++i) directions.emplace_back(gaussian(rng), gaussian(rng), gaussian(rng));
  directions.push_back(Vec3::Zero());
  // The start map's cell borders, where rounding decides the cell, and
  // beyond its trusted range of scales.
  const int cells = mesh.startMap().cellsPerEdge();
  for (int face = 0; cells > 0 && face < 6; ++face) {
    const int axis = face / 2;
    for (int i = 0; i <= cells; ++i) {
      for (int j = 0; j <= cells; ++j) {
        Vec3 d;
        d[axis] = face % 2 == 0 ? 1.0 : -1.0;
        d[axis == 0 ? 1 : 0] = -1.0 + 2.0 * i / cells;
        d[axis == 2 ? 1 : 2] = -1.0 + 2.0 * j / cells;
        directions.push_back(d);
        directions.push_back(d + 1e-16 * Vec3(gaussian(rng), gaussian(rng), gaussian(rng)));
      }
    }
  }
  for (const double scale : {1e-300, 1e-200, 1e200, 1e300}) directions.push_back(scale * Vec3(0.3, -0.5, 0.8));
  return directions;
}

TEST(ConvexMeshCollider, SupportIndexIsTheLinearScansWhateverTheHint) {
  std::vector<Vec3> duplicated = sphereCloud(300, 9);
  for (int i = 0; i < 100; ++i) duplicated.push_back(duplicated[i]);  // duplicates
  std::vector<Vec3> lattice;  // coplanar and collinear points everywhere; only the corners stay
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      for (int k = 0; k < 6; ++k) lattice.emplace_back(i, j, k);
    }
  }
  const std::vector<std::pair<const char*, std::vector<Vec3>>> clouds{
      {"tetrahedron", {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}},
      {"lattice", lattice},
      {"sphere 256", sphereCloud(256, 17)},
      {"sphere 1000 far from the origin", sphereCloud(1000, 23, Vec3(1e5, -3e4, 2e5))},
      {"sphere with duplicates", duplicated},
      {"prism of 24 sides", prism(24)},
      {"prism of 100 sides (a plateau past the walk's capacity)", prism(100)},
  };
  std::mt19937 rng(31);
  for (const auto& [name, cloud] : clouds) {
    const ConvexMeshCollider mesh(cloud);
    const auto& v = mesh.hullVertices();
    const int count = static_cast<int>(v.size());
    int checked = 0;
    for (const Vec3& d : probeDirections(mesh, rng)) {
      const int expected = scannedSupport(v, d);
      for (const int hint : {-1, static_cast<int>(rng() % count), expected, count + 5}) {
        ASSERT_EQ(mesh.supportIndex(d, hint), expected) << name << ", direction " << d.transpose() << ", hint " << hint;
        ++checked;
      }
      ASSERT_EQ(mesh.localSupport(d), v[expected]) << name;
    }
    EXPECT_GT(checked, 8000) << name;
  }
}

// A cell with a list answers without climbing, so the scan's vertex must be
// on it for every direction in the cell, up to its borders; and on a round
// hull most directions should find a list (else the map only slows small
// hulls down).
TEST(ConvexMeshCollider, CellListsHoldTheScansAnswerToTheirBorders) {
  for (const int count : {32, 256, 3000}) {
    const std::vector<Vec3> cloud = sphereCloud(count, 41);
    const ConvexMeshCollider mesh(cloud);
    const SupportCubeMap& map = mesh.startMap();
    const auto& v = mesh.hullVertices();
    std::mt19937 rng(43);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int answered = 0, probes = 0, listed = 0;
    for (int cell = 0; cell < map.cellCount(); ++cell) {
      const Vec3 centre = map.cellCentre(cell);
      // Corners and random points of the cell, pushed just past its sides.
      const double half = 1.0 / map.cellsPerEdge();
      for (int k = 0; k < 12; ++k) {
        const double s = k < 4 ? (k & 1 ? 1.0 : -1.0) : 2.0 * unit(rng) - 1.0;
        const double t = k < 4 ? (k & 2 ? 1.0 : -1.0) : 2.0 * unit(rng) - 1.0;
        Vec3 d = centre;
        int axis = 0;
        centre.cwiseAbs().maxCoeff(&axis);
        d[axis == 0 ? 1 : 0] += s * half * (1.0 + 1e-14);
        d[axis == 2 ? 1 : 2] += t * half * (1.0 + 1e-14);
        const SupportCubeMap::Entry entry = map.lookup(d);
        ++probes;
        if (entry.count == 0) continue;
        ++answered;
        listed += entry.count;
        ASSERT_TRUE(std::is_sorted(entry.vertices, entry.vertices + entry.count));
        ASSERT_NE(std::find(entry.vertices, entry.vertices + entry.count, scannedSupport(v, d)),
                  entry.vertices + entry.count)
            << count << " points, cell " << cell << ", direction " << d.transpose();
      }
    }
    int random = 0;
    std::normal_distribution<double> gaussian(0.0, 1.0);
    for (int i = 0; i < 10000; ++i) random += map.lookup(Vec3(gaussian(rng), gaussian(rng), gaussian(rng))).count > 0;
    EXPECT_GT(answered, 1000) << count << " points: too few answered probes to check";
    // Large hulls have more vertices than the capped map has cells: there
    // the map gives starts, not answers.
    if (count <= 256) {
      EXPECT_GT(random, 9000) << count << " points";
      EXPECT_GT(answered, probes * 9 / 10) << count << " points";
      EXPECT_LT(listed, 3 * answered) << count << " points: lists too long to beat a climb";
    }
  }
}

TEST(ConvexMeshCollider, TrianglesCoverTheSurfaceOutward) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> cloud;
  for (int i = 0; i < 60; ++i) cloud.emplace_back(unit(rng), unit(rng), unit(rng));
  ConvexMeshCollider mesh(cloud);
  const auto& v = mesh.hullVertices();
  // Euler: V - E + F = 2 for a closed triangulated sphere, E = 3F/2.
  EXPECT_EQ(static_cast<int>(v.size()) - static_cast<int>(mesh.hullTriangles().size()) / 2, 2);
  for (const auto& t : mesh.hullTriangles()) {
    const Vec3 normal = (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]);
    for (const Vec3& p : cloud) EXPECT_LE(normal.normalized().dot(p - v[t[0]]), 1e-9);
  }
}

TEST(ConvexMeshCollider, LatticeFarFromTheOriginGivesACleanBox) {
  // Every point coplanar or collinear with many others, offset by 1e5.
  std::vector<Vec3> lattice;
  const Vec3 offset(1e5, -1e5, 3e4);
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      for (int k = 0; k < 5; ++k) lattice.push_back(offset + Vec3(i, 0.5 * j, 0.25 * k));
    }
  }
  ConvexMeshCollider mesh(lattice);
  EXPECT_EQ(mesh.hullFaces().size(), 6u);
  EXPECT_NEAR(mesh.volume(), 4.0 * 2.0 * 1.0, 1e-9);
  EXPECT_LE((mesh.centroid() - (offset + Vec3(2.0, 1.0, 0.5))).norm(), 1e-9);
  BoxCollider box(Vec3(2.0, 1.0, 0.5));
  EXPECT_LE((mesh.unitInertia() - box.unitInertia()).norm(), 1e-9);
}

TEST(ConvexMeshCollider, BadCloudsThrow) {
  EXPECT_THROW(ConvexMeshCollider({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}), std::invalid_argument);
  EXPECT_THROW(ConvexMeshCollider({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 1, 0), Vec3(1, 0, 0)}),
               std::invalid_argument);
  EXPECT_THROW(ConvexMeshCollider({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)}), std::invalid_argument);
  EXPECT_THROW(ConvexMeshCollider({Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2), Vec3(3, 3, 3)}), std::invalid_argument);
  EXPECT_THROW(ConvexMeshCollider({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, NAN)}), std::invalid_argument);
  EXPECT_NO_THROW(ConvexMeshCollider({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}));
}

TEST(ConvexMeshCollider, MassPropertiesOfTinyAndHugeHullsAreExact) {
  // volume() is m^3: 1e-360 and 1e360 are out of double range, the rest is not.
  for (double scale : {1e-120, 1e120}) {
    const Vec3 half = Vec3(0.5, 1.0, 1.5) * scale, offset = Vec3(3, -2, 7) * scale;
    ConvexMeshCollider mesh(cubeCorners(half, offset));
    BoxCollider box(half);
    EXPECT_LE((mesh.centroid() - offset).norm(), 1e-12 * offset.norm());
    EXPECT_LE((mesh.unitInertia() - box.unitInertia()).norm(), 1e-12 * box.unitInertia().norm());
  }
}

std::string bodyError(const BodyDefinition& definition) {
  try {
    RigidBody body(definition);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(no exception)";
}

TEST(ConvexMeshCollider, BodiesOfTinyMassAreValidAndDegenerateOnesSayWhy) {
  BodyDefinition definition;
  definition.mass = 1e-150;
  for (std::shared_ptr<const Collider> collider :
       {std::shared_ptr<const Collider>(std::make_shared<BoxCollider>(Vec3(0.5, 1.0, 1.5))),
        std::shared_ptr<const Collider>(std::make_shared<ConvexMeshCollider>(cubeCorners(Vec3(0.5, 1.0, 1.5))))}) {
    definition.collider = collider;
    const RigidBody body(definition);
    const Mat3 expected = collider->unitInertia().inverse() / definition.mass;
    EXPECT_LE((body.worldInverseInertia() - expected).norm(), 1e-12 * expected.norm());
  }
  definition.collider = std::make_shared<BoxCollider>(Vec3(1.0, 0.0, 0.0));  // a rod: no moment about its axis
  EXPECT_NE(bodyError(definition).find("singular inertia tensor"), std::string::npos) << bodyError(definition);
  definition.collider = std::make_shared<ConvexMeshCollider>(cubeCorners(Vec3::Constant(1e-100)));
  definition.mass = 1e-300;  // inertia 1e-500
  EXPECT_NE(bodyError(definition).find("underflows"), std::string::npos) << bodyError(definition);
  definition.collider = std::make_shared<BoxCollider>(Vec3(0.5, 0.5, 0.5));
  definition.mass = 1e-320;  // 1 / mass overflows
  EXPECT_NE(bodyError(definition).find("too small"), std::string::npos) << bodyError(definition);
}

}  // namespace
}  // namespace physdbg
