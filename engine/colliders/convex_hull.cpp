#include "engine/colliders/convex_hull.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace physdbg {
namespace {

struct WorkFace {
  std::array<int, 3> v;
  Vec3 normal;
  double offset;
  bool alive = true;
};

WorkFace makeFace(const std::vector<Vec3>& p, int a, int b, int c) {
  const Vec3 n = (p[b] - p[a]).cross(p[c] - p[a]);
  const double length = n.norm();
  const Vec3 unit = length > 0.0 ? Vec3(n / length) : Vec3::Zero();
  return {{a, b, c}, unit, unit.dot(p[a]), true};
}

void validate(const std::vector<Vec3>& points) {
  for (const Vec3& p : points) {
    if (!p.allFinite()) throw std::invalid_argument("ConvexHull: point cloud has non-finite coordinates");
  }
  std::vector<std::array<double, 3>> sorted;
  for (const Vec3& p : points) sorted.push_back({p.x(), p.y(), p.z()});
  std::sort(sorted.begin(), sorted.end());
  const auto distinct = std::unique(sorted.begin(), sorted.end()) - sorted.begin();
  if (distinct < 4) throw std::invalid_argument("ConvexHull: point cloud needs at least 4 distinct points");
}

int farthest(const std::vector<Vec3>& p, const auto& distanceOf) {
  int best = 0;
  double bestDistance = -1.0;
  for (int i = 0; i < static_cast<int>(p.size()); ++i) {
    const double d = distanceOf(p[i]);
    if (d > bestDistance) bestDistance = d, best = i;
  }
  return best;
}

// Four well-spread points, or throws when the cloud is flat.
std::array<int, 4> initialTetrahedron(const std::vector<Vec3>& p, double eps) {
  const int i0 = farthest(p, [](const Vec3& x) { return -x.x(); });
  const int i1 = farthest(p, [&](const Vec3& x) { return (x - p[i0]).norm(); });
  const Vec3 axis = (p[i1] - p[i0]).normalized();
  const int i2 = farthest(p, [&](const Vec3& x) { return (x - p[i0]).cross(axis).norm(); });
  if ((p[i2] - p[i0]).cross(axis).norm() <= eps) throw std::invalid_argument("ConvexHull: point cloud is collinear");
  const Vec3 normal = (p[i1] - p[i0]).cross(p[i2] - p[i0]).normalized();
  const int i3 = farthest(p, [&](const Vec3& x) { return std::abs(normal.dot(x - p[i0])); });
  if (std::abs(normal.dot(p[i3] - p[i0])) <= eps) throw std::invalid_argument("ConvexHull: point cloud is flat");
  return {i0, i1, i2, i3};
}

std::vector<WorkFace> triangulateHull(const std::vector<Vec3>& p, double eps) {
  const auto [a, b, c, d] = initialTetrahedron(p, eps);
  const Vec3 inside = 0.25 * (p[a] + p[b] + p[c] + p[d]);
  std::vector<WorkFace> faces;
  for (const auto& [x, y, z] : {std::array{a, b, c}, std::array{a, d, b}, std::array{b, d, c}, std::array{c, d, a}}) {
    WorkFace face = makeFace(p, x, y, z);
    if (face.normal.dot(inside) > face.offset) face = makeFace(p, x, z, y);
    faces.push_back(face);
  }
  std::vector<std::pair<int, int>> visibleEdges;
  for (int i = 0; i < static_cast<int>(p.size()); ++i) {
    visibleEdges.clear();
    for (WorkFace& face : faces) {
      if (!face.alive || face.normal.dot(p[i]) - face.offset <= eps) continue;
      face.alive = false;
      for (int e = 0; e < 3; ++e) visibleEdges.emplace_back(face.v[e], face.v[(e + 1) % 3]);
    }
    for (const auto& [from, to] : visibleEdges) {
      const bool shared = std::find(visibleEdges.begin(), visibleEdges.end(), std::pair{to, from}) != visibleEdges.end();
      if (!shared) faces.push_back(makeFace(p, from, to, i));
    }
    if (!visibleEdges.empty()) std::erase_if(faces, [](const WorkFace& f) { return !f.alive; });
  }
  return faces;
}

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Groups of edge-adjacent triangles whose planes agree within tolerance.
std::vector<int> coplanarGroups(const ConvexHull& hull, const std::vector<Vec3>& normals, double eps) {
  const int count = static_cast<int>(hull.triangles.size());
  std::vector<int> parent(count);
  std::iota(parent.begin(), parent.end(), 0);
  std::map<std::pair<int, int>, int> edgeOwner;
  for (int t = 0; t < count; ++t) {
    for (int e = 0; e < 3; ++e) edgeOwner[{hull.triangles[t][e], hull.triangles[t][(e + 1) % 3]}] = t;
  }
  for (int t = 0; t < count; ++t) {
    for (int e = 0; e < 3; ++e) {
      const auto it = edgeOwner.find({hull.triangles[t][(e + 1) % 3], hull.triangles[t][e]});
      if (it == edgeOwner.end()) continue;
      const int other = it->second;
      const Vec3& far = hull.vertices[hull.triangles[other][0]];
      const double offsetGap = std::abs(normals[t].dot(far - hull.vertices[hull.triangles[t][0]]));
      if (normals[t].dot(normals[other]) > 1.0 - 1e-10 && offsetGap <= eps) {
        parent[findRoot(parent, t)] = findRoot(parent, other);
      }
    }
  }
  for (int t = 0; t < count; ++t) parent[t] = findRoot(parent, t);
  return parent;
}

// Boundary loop of a group of triangles, or empty if it is not one loop.
std::vector<int> boundaryLoop(const ConvexHull& hull, const std::vector<int>& group) {
  std::vector<std::pair<int, int>> edges;
  for (int t : group) {
    for (int e = 0; e < 3; ++e) edges.emplace_back(hull.triangles[t][e], hull.triangles[t][(e + 1) % 3]);
  }
  std::vector<std::pair<int, int>> boundary;
  for (const auto& [from, to] : edges) {
    if (std::find(edges.begin(), edges.end(), std::pair{to, from}) == edges.end()) boundary.emplace_back(from, to);
  }
  std::vector<int> loop{boundary.front().first};
  while (loop.size() <= boundary.size()) {
    const auto next = std::find_if(boundary.begin(), boundary.end(), [&](const auto& e) { return e.first == loop.back(); });
    if (next == boundary.end()) return {};
    if (next->second == loop.front()) return loop.size() == boundary.size() ? loop : std::vector<int>{};
    loop.push_back(next->second);
  }
  return {};
}

void mergeFaces(ConvexHull& hull, double eps) {
  std::vector<Vec3> normals;
  for (const auto& t : hull.triangles) {
    normals.push_back((hull.vertices[t[1]] - hull.vertices[t[0]]).cross(hull.vertices[t[2]] - hull.vertices[t[0]]));
  }
  std::vector<Vec3> unitNormals;
  for (const Vec3& n : normals) unitNormals.push_back(n.normalized());
  const std::vector<int> root = coplanarGroups(hull, unitNormals, eps);
  for (int t = 0; t < static_cast<int>(root.size()); ++t) {
    if (std::find(root.begin(), root.begin() + t, root[t]) != root.begin() + t) continue;  // group already done
    std::vector<int> group;
    Vec3 areaNormal = Vec3::Zero();
    for (int u = t; u < static_cast<int>(root.size()); ++u) {
      if (root[u] == root[t]) group.push_back(u), areaNormal += normals[u];
    }
    std::vector<int> loop = boundaryLoop(hull, group);
    if (loop.empty()) {  // not a simple polygon: keep its triangles as faces
      for (int u : group) {
        const auto& tri = hull.triangles[u];
        hull.faces.push_back({{tri[0], tri[1], tri[2]}, unitNormals[u], unitNormals[u].dot(hull.vertices[tri[0]])});
      }
      continue;
    }
    const Vec3 normal = areaNormal.normalized();
    double offset = 0.0;
    for (int v : loop) offset += normal.dot(hull.vertices[v]) / static_cast<double>(loop.size());
    hull.faces.push_back({std::move(loop), normal, offset});
  }
}

void buildAdjacency(ConvexHull& hull) {
  std::vector<std::vector<int>> lists(hull.vertices.size());
  for (const auto& t : hull.triangles) {
    for (int e = 0; e < 3; ++e) lists[t[e]].push_back(t[(e + 1) % 3]);
  }
  hull.neighbourStart.push_back(0);
  for (auto& list : lists) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    hull.neighbours.insert(hull.neighbours.end(), list.begin(), list.end());
    hull.neighbourStart.push_back(static_cast<int>(hull.neighbours.size()));
  }
  for (int n : hull.neighbours) hull.neighbourPoints.push_back(hull.vertices[n]);
}

}  // namespace

ConvexHull buildConvexHull(const std::vector<Vec3>& points) {
  validate(points);
  Vec3 low = points.front(), high = points.front();
  for (const Vec3& p : points) low = low.cwiseMin(p), high = high.cwiseMax(p);
  const double eps = 1e-10 * (high - low).norm();
  const std::vector<WorkFace> faces = triangulateHull(points, eps);

  std::vector<int> used;
  for (const WorkFace& f : faces) used.insert(used.end(), f.v.begin(), f.v.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::map<int, int> remap;
  ConvexHull hull;
  for (int original : used) {
    remap[original] = static_cast<int>(hull.vertices.size());
    hull.vertices.push_back(points[original]);
  }
  for (const WorkFace& f : faces) hull.triangles.push_back({remap[f.v[0]], remap[f.v[1]], remap[f.v[2]]});
  mergeFaces(hull, eps);
  buildAdjacency(hull);
  return hull;
}

}  // namespace physdbg
