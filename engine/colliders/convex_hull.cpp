#include "engine/colliders/convex_hull.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>

namespace physdbg {
namespace {

// A point within this share of the cloud's diagonal of a plane is on it.
constexpr double kOnPlaneShare = 1e-10;
// Input coordinates carry rounding of about one step of their own magnitude.
// A cloud no thicker than this many steps (DBL_EPSILON times the largest
// coordinate) is flat, and triangles this close to coplanar make one face, so
// a box far from the origin keeps flat faces. Which points are worth adding
// to the hull is decided with the tolerance above, relative to the cloud.
constexpr double kRoundingSteps = 8.0;
// A cloud narrower than this many such steps is noise, not a shape.
constexpr int kFewestSteps = 1024;
// The hull is built on local coordinates (at most 1) rounded to multiples of
// 2^-kGridBits, about their own rounding, so that orientation signs can be
// exact in integers: differences take 54 bits, a normal 108 (in 128), a
// volume 163 (in a 128-bit high part and a 64-bit low part). Exact signs keep
// the hull convex however nearly coplanar the points are.
constexpr int kGridBits = 52;
// A floating-point distance to a plane (normals are exact to rounding) farther
// from zero than this has the exact sign; nearer, the sign is computed exactly.
constexpr double kExactSignBelow = 1e-12;

__extension__ typedef __int128 Wide;
__extension__ typedef unsigned __int128 UnsignedWide;
using GridPoint = std::array<std::int64_t, 3>;

[[noreturn]] void reject(const std::string& why) { throw std::invalid_argument("ConvexHull: " + why); }

std::string figure(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

void requireFourDistinctFinitePoints(const std::vector<Vec3>& points) {
  std::vector<Vec3> distinct;
  for (const Vec3& p : points) {
    if (!p.allFinite()) reject("point cloud has non-finite coordinates");
    if (distinct.size() < 4 && std::find(distinct.begin(), distinct.end(), p) == distinct.end()) distinct.push_back(p);
  }
  if (distinct.size() < 4) {
    reject("point cloud needs at least 4 distinct points, it has " + std::to_string(distinct.size()));
  }
}

// The cloud moved to its bounding box's centre and scaled by a power of two
// (exactly) to a half-extent in [0.5, 1). Plane tests there round relative to
// the cloud's size, not to its distance from the origin, and no product
// under- or overflows however small or large the cloud is.
struct LocalCloud {
  std::vector<Vec3> points;     // as given, in local units
  std::vector<Vec3> snapped;    // rounded to the grid
  std::vector<GridPoint> grid;  // the same, in grid steps
  double tolerance = 0.0;       // on-plane distance, local units
  double noiseTolerance = 0.0;  // the same or the coordinates' rounding if more
};

LocalCloud toLocalFrame(const std::vector<Vec3>& points) {
  Vec3 low = points.front(), high = points.front();
  for (const Vec3& p : points) low = low.cwiseMin(p), high = high.cwiseMax(p);
  const Vec3 halfSize = 0.5 * high - 0.5 * low;  // halves first: no overflow near DBL_MAX
  const double largest = std::max(low.cwiseAbs().maxCoeff(), high.cwiseAbs().maxCoeff());
  const double span = 2.0 * halfSize.maxCoeff();
  if (span < kFewestSteps * DBL_EPSILON * largest) {
    reject("point cloud is too small for its distance from the origin: it spans " + figure(span) + " at " +
           figure(largest) + " from the origin, where doubles are about " + figure(DBL_EPSILON * largest) +
           " apart; it must span at least " + std::to_string(kFewestSteps) + " such steps");
  }
  int exponent = 0;
  std::frexp(halfSize.maxCoeff(), &exponent);
  const auto toLocal = [exponent](double x) { return std::ldexp(x, -exponent); };
  const Vec3 centre = 0.5 * low + 0.5 * high;
  LocalCloud cloud;
  cloud.points.reserve(points.size());
  cloud.snapped.reserve(points.size());
  cloud.grid.reserve(points.size());
  for (const Vec3& p : points) {
    cloud.points.push_back((p - centre).unaryExpr(toLocal));
    const Vec3 steps = cloud.points.back().unaryExpr([](double x) { return std::nearbyint(std::ldexp(x, kGridBits)); });
    cloud.grid.push_back({std::int64_t(steps.x()), std::int64_t(steps.y()), std::int64_t(steps.z())});
    cloud.snapped.push_back(steps.unaryExpr([](double x) { return std::ldexp(x, -kGridBits); }));
  }
  const double diagonal = 2.0 * halfSize.unaryExpr(toLocal).norm();
  cloud.tolerance = kOnPlaneShare * diagonal;
  cloud.noiseTolerance = std::max(cloud.tolerance, kRoundingSteps * DBL_EPSILON * toLocal(largest));
  return cloud;
}

// (b - a) x (c - a), exactly.
std::array<Wide, 3> exactCross(const GridPoint& a, const GridPoint& b, const GridPoint& c) {
  const Wide u0 = b[0] - a[0], u1 = b[1] - a[1], u2 = b[2] - a[2];
  const Wide v0 = c[0] - a[0], v1 = c[1] - a[1], v2 = c[2] - a[2];
  return {u1 * v2 - u2 * v1, u2 * v0 - u0 * v2, u0 * v1 - u1 * v0};
}

// Sign of normal . offset, exactly: each product (up to 162 bits) is split
// at 2^64 into a high and a low part, summed separately.
int signOfDot(const std::array<Wide, 3>& normal, const std::array<std::int64_t, 3>& offset) {
  const UnsignedWide lowMask = ~std::uint64_t{0};
  Wide high = 0, low = 0;  // the sum is high * 2^64 + low
  for (int k = 0; k < 3; ++k) {
    const int sign = ((normal[k] < 0) != (offset[k] < 0)) ? -1 : 1;
    const UnsignedWide n = normal[k] < 0 ? -UnsignedWide(normal[k]) : UnsignedWide(normal[k]);
    const UnsignedWide m = offset[k] < 0 ? -UnsignedWide(offset[k]) : UnsignedWide(offset[k]);
    const UnsignedWide lowProduct = (n & lowMask) * m;
    high += sign * Wide((n >> 64) * m + (lowProduct >> 64));
    low += sign * Wide(lowProduct & lowMask);
  }
  high += low >> 64;  // low becomes its part in [0, 2^64)
  low &= Wide(lowMask);
  return high != 0 ? (high > 0 ? 1 : -1) : (low > 0 ? 1 : 0);
}

// Sign of the volume of abcp: positive when p is above the counter-clockwise triangle abc.
int exactOrientation(const GridPoint& a, const GridPoint& b, const GridPoint& c, const GridPoint& p) {
  return signOfDot(exactCross(a, b, c), {p[0] - a[0], p[1] - a[1], p[2] - a[2]});
}

// Normal of triangle abc (counter-clockwise) in grid steps squared, rounded
// once, however thin the triangle; zero when it has no area.
Vec3 gridNormal(const GridPoint& a, const GridPoint& b, const GridPoint& c) {
  const std::array<Wide, 3> normal = exactCross(a, b, c);
  return {static_cast<double>(normal[0]), static_cast<double>(normal[1]), static_cast<double>(normal[2])};
}

// A triangle of the hull under construction; edge e runs from vertex[e] to
// vertex[(e + 1) % 3] and neighbour[e] is the triangle across it.
struct Triangle {
  std::array<int, 3> vertex{};
  std::array<int, 3> neighbour{};
  Vec3 normal = Vec3::Zero();  // unit, outward
  double offset = 0.0;
  int firstOutside = -1;  // list (through nextOutside) of points above the plane by more than the tolerance
  int searched = 0;       // stamp of the last visibility search that tested this triangle
  bool visible = false;   // its result
  bool alive = true;
};

struct HorizonEdge {
  int from = 0, to = 0;
  int hidden = 0;  // the triangle beyond the edge, which stays
};

// The hull as triangles with their neighbours, in input point indices.
struct Triangulation {
  std::vector<int> points;  // input indices of the hull vertices, ascending
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::array<int, 3>> neighbours;
};

// Quickhull with conflict lists: every point outside the hull belongs to one
// triangle it is above. The farthest point of a triangle joins the hull: the
// triangles it sees go, a cone from it to their horizon replaces them, and
// only their points are handed to the new triangles. Each point is looked at
// again only when its triangle goes, so the build is O(n log n) expected.
class QuickHull {
 public:
  explicit QuickHull(const LocalCloud& cloud)
      : points_(cloud.snapped),
        grid_(cloud.grid),
        tolerance_(cloud.tolerance),
        noiseTolerance_(cloud.noiseTolerance),
        nextOutside_(points_.size(), -1),
        vertexStamp_(points_.size(), 0),
        edgeFrom_(points_.size(), 0) {
    faces_.reserve(2 * points_.size() + 8);  // a hull of n vertices has 2n - 4 triangles
  }

  // The hull of the points whose indices are `candidates` (at least one).
  Triangulation build(std::vector<int> candidates) {
    candidates_ = std::move(candidates);
    startFromTetrahedron();
    while (!pending_.empty()) {
      const int face = pending_.back();
      pending_.pop_back();
      if (faces_[face].alive && faces_[face].firstOutside >= 0) addFarthestPoint(face);
    }
    return triangulation();
  }

 private:
  double distance(int face, int point) const { return faces_[face].normal.dot(points_[point]) - faces_[face].offset; }

  bool isAbove(int face, int point) const {
    const double d = distance(face, point);
    if (std::abs(d) > kExactSignBelow) return d > 0.0;
    const std::array<int, 3>& v = faces_[face].vertex;
    return exactOrientation(grid_[v[0]], grid_[v[1]], grid_[v[2]], grid_[point]) > 0;
  }
  bool isVisible(int face) const { return faces_[face].searched == stamp_ && faces_[face].visible; }

  int farthest(const auto& measure) const {
    int best = candidates_.front();
    double bestValue = measure(points_[best]);
    for (int i : candidates_) {
      const double value = measure(points_[i]);
      if (value > bestValue) best = i, bestValue = value;
    }
    return best;
  }

  // The point greatest along `axis`, ties going to the greatest along the
  // next axes (a corner of a grid, not a point inside one of its faces).
  int extreme(int axis, double sign) const {
    const auto key = [&](int i) {
      const Vec3& p = points_[i];
      return std::array{sign * p[axis], sign * p[(axis + 1) % 3], sign * p[(axis + 2) % 3]};
    };
    int best = candidates_.front();
    for (int i : candidates_) {
      if (key(i) > key(best)) best = i;
    }
    return best;
  }

  // The two farthest apart of the six axis extremes, the point farthest from
  // their line and the one farthest from the plane of the three.
  std::array<int, 4> spreadPoints() const {
    std::array<int, 6> extremes{};
    for (int axis = 0; axis < 3; ++axis) {
      extremes[2 * axis] = extreme(axis, -1.0);
      extremes[2 * axis + 1] = extreme(axis, 1.0);
    }
    int first = extremes[0], second = extremes[1];
    for (int i : extremes) {
      for (int j : extremes) {
        if ((points_[i] - points_[j]).norm() > (points_[first] - points_[second]).norm()) first = i, second = j;
      }
    }
    const Vec3 origin = points_[first], axis = (points_[second] - origin).normalized();
    const auto fromLine = [&](const Vec3& p) { return (p - origin).cross(axis).norm(); };
    const int third = farthest(fromLine);
    if (!(fromLine(points_[third]) > noiseTolerance_)) rejectThin("collinear", fromLine(points_[third]), "line");
    const Vec3 normal = axis.cross(points_[third] - origin).normalized();
    const auto fromPlane = [&](const Vec3& p) { return std::abs(normal.dot(p - origin)); };
    const int fourth = farthest(fromPlane);
    if (!(fromPlane(points_[fourth]) > noiseTolerance_)) rejectThin("flat", fromPlane(points_[fourth]), "plane");
    return {first, second, third, fourth};
  }

  [[noreturn]] void rejectThin(const std::string& shape, double width, const std::string& what) const {
    const double size = (points_[farthest([](const Vec3& p) { return p.norm(); })]).norm();
    reject("point cloud is " + shape + ": every point lies within " + figure(width / size) + " of its size from a " +
           what + " (tolerance " + figure(noiseTolerance_ / size) + " of its size)");
  }

  void startFromTetrahedron() {
    auto [a, b, c, d] = spreadPoints();
    if (exactOrientation(grid_[a], grid_[b], grid_[c], grid_[d]) > 0) std::swap(b, c);
    for (const auto& [x, y, z] : {std::array{a, b, c}, std::array{b, a, d}, std::array{c, b, d}, std::array{a, c, d}}) {
      if (addTriangle(x, y, z) < 0) rejectThin("flat", 0.0, "plane");
    }
    for (int face = 0; face < 4; ++face) {
      for (int e = 0; e < 3; ++e) faces_[face].neighbour[e] = faceAcross(face, e, {0, 1, 2, 3});
    }
    for (int point : candidates_) {
      if (point != a && point != b && point != c && point != d) assignToFarthestAbove(point, {0, 1, 2, 3});
    }
    for (int face = 0; face < 4; ++face) pending_.push_back(face);
  }

  // Of `candidates`, the triangle sharing edge e of `face` (reversed).
  int faceAcross(int face, int e, const std::vector<int>& candidates) const {
    const int from = faces_[face].vertex[e], to = faces_[face].vertex[(e + 1) % 3];
    for (int other : candidates) {
      if (edgeIndex(other, to, from) >= 0) return other;
    }
    return -1;
  }

  int edgeIndex(int face, int from, int to) const {
    for (int e = 0; e < 3; ++e) {
      if (faces_[face].vertex[e] == from && faces_[face].vertex[(e + 1) % 3] == to) return e;
    }
    return -1;
  }

  // Index of the new triangle, or -1 when it has no area to give a normal.
  int addTriangle(int a, int b, int c) {
    const Vec3 normal = gridNormal(grid_[a], grid_[b], grid_[c]);
    const double length = normal.norm();
    if (!(length > 0.0)) return -1;
    int face = static_cast<int>(faces_.size());
    if (free_.empty()) {
      faces_.emplace_back();
    } else {
      face = free_.back();
      free_.pop_back();
    }
    Triangle& t = faces_[face];
    t.vertex = {a, b, c};
    t.normal = normal / length;
    t.offset = t.normal.dot((points_[a] + points_[b] + points_[c]) / 3.0);
    t.firstOutside = -1;
    t.searched = 0;
    t.alive = true;
    return face;
  }

  void release(int face) {
    faces_[face].alive = false;
    faces_[face].firstOutside = -1;
    free_.push_back(face);
  }

  void assignToFarthestAbove(int point, const std::vector<int>& candidates) {
    int best = -1;
    double bestDistance = tolerance_;
    for (int face : candidates) {
      const double d = distance(face, point);
      if (d > bestDistance) best = face, bestDistance = d;
    }
    if (best < 0) return;
    nextOutside_[point] = faces_[best].firstOutside;
    faces_[best].firstOutside = point;
  }

  // The point farthest above the triangle; of points as far within the
  // tolerance (a grid's face parallel to it) the one farthest from its
  // centre, which is a corner of them, not a point between.
  int eyeOf(int face) const {
    double farthest = 0.0;
    for (int point = faces_[face].firstOutside; point >= 0; point = nextOutside_[point]) {
      farthest = std::max(farthest, distance(face, point));
    }
    const std::array<int, 3>& v = faces_[face].vertex;
    const Vec3 centre = (points_[v[0]] + points_[v[1]] + points_[v[2]]) / 3.0;
    int eye = faces_[face].firstOutside;
    double spread = -1.0;
    for (int point = eye; point >= 0; point = nextOutside_[point]) {
      const double fromCentre = (points_[point] - centre).squaredNorm();
      if (distance(face, point) >= farthest - tolerance_ && fromCentre > spread) eye = point, spread = fromCentre;
    }
    return eye;
  }

  void addFarthestPoint(int face) {
    const int eye = eyeOf(face);
    ++stamp_;
    findVisible(face, eye);
    bool ready = traceHorizon();
    if (!ready) absorbEnclosedHiddenRegions(), ready = traceHorizon();
    if (ready && coneHasArea(eye)) {
      replaceVisibleByCone(eye);
      return;
    }
    // Not reached with exact signs; were it, the point is left out rather
    // than the surface broken.
    int* link = &faces_[face].firstOutside;
    while (*link != eye) link = &nextOutside_[*link];
    *link = nextOutside_[eye];
    pending_.push_back(face);
  }

  // The triangles the eye is above, connected to the first one.
  void findVisible(int face, int eye) {
    visible_.assign(1, face);
    faces_[face].searched = stamp_;
    faces_[face].visible = true;
    for (std::size_t i = 0; i < visible_.size(); ++i) {
      for (int next : faces_[visible_[i]].neighbour) {
        if (faces_[next].searched == stamp_) continue;
        faces_[next].searched = stamp_;
        faces_[next].visible = isAbove(next, eye);
        if (faces_[next].visible) visible_.push_back(next);
      }
    }
  }

  // The boundary of the visible region in order, into horizon_; false unless
  // it is one simple loop (the region is a disc).
  bool traceHorizon() {
    ++horizonStamp_;
    unordered_.clear();
    for (int face : visible_) {
      for (int e = 0; e < 3; ++e) {
        const Triangle& t = faces_[face];
        if (isVisible(t.neighbour[e])) continue;
        const int from = t.vertex[e];
        if (vertexStamp_[from] == horizonStamp_) return false;  // the loop touches itself
        vertexStamp_[from] = horizonStamp_;
        edgeFrom_[from] = static_cast<int>(unordered_.size());
        unordered_.push_back({from, t.vertex[(e + 1) % 3], t.neighbour[e]});
      }
    }
    horizon_.clear();
    int edge = 0;
    for (std::size_t step = 0; step < unordered_.size(); ++step) {
      if (step > 0 && edge == 0) return false;  // closed early: more than one loop
      horizon_.push_back(unordered_[edge]);
      const int to = unordered_[edge].to;
      if (vertexStamp_[to] != horizonStamp_) return false;
      edge = edgeFrom_[to];
    }
    return !horizon_.empty() && edge == 0;
  }

  // Exact signs make the visible region a disc; should it ever not be, every
  // hidden region but the largest (the far side) joins the visible one.
  void absorbEnclosedHiddenRegions() {
    std::vector<int> region(faces_.size(), -1), sizes, queue;
    for (int seed = 0; seed < static_cast<int>(faces_.size()); ++seed) {
      if (!faces_[seed].alive || isVisible(seed) || region[seed] >= 0) continue;
      queue.assign(1, seed);
      region[seed] = static_cast<int>(sizes.size());
      for (std::size_t i = 0; i < queue.size(); ++i) {
        for (int next : faces_[queue[i]].neighbour) {
          if (isVisible(next) || region[next] >= 0) continue;
          region[next] = region[seed];
          queue.push_back(next);
        }
      }
      sizes.push_back(static_cast<int>(queue.size()));
    }
    const int largest = static_cast<int>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
    for (int face = 0; face < static_cast<int>(faces_.size()); ++face) {
      if (region[face] < 0 || region[face] == largest) continue;
      faces_[face].searched = stamp_;
      faces_[face].visible = true;
      visible_.push_back(face);
    }
  }

  bool coneHasArea(int eye) const {
    for (const HorizonEdge& edge : horizon_) {
      if (!(gridNormal(grid_[edge.from], grid_[edge.to], grid_[eye]).norm() > 0.0)) return false;
    }
    return true;
  }

  void replaceVisibleByCone(int eye) {
    orphans_.clear();
    for (int face : visible_) {
      for (int point = faces_[face].firstOutside; point >= 0; point = nextOutside_[point]) {
        if (point != eye) orphans_.push_back(point);
      }
      release(face);
    }
    cone_.clear();
    for (const HorizonEdge& edge : horizon_) {
      const int face = addTriangle(edge.from, edge.to, eye);
      faces_[edge.hidden].neighbour[edgeIndex(edge.hidden, edge.to, edge.from)] = face;
      faces_[face].neighbour[0] = edge.hidden;
      cone_.push_back(face);
    }
    const int count = static_cast<int>(cone_.size());
    for (int k = 0; k < count; ++k) {
      faces_[cone_[k]].neighbour[1] = cone_[(k + 1) % count];
      faces_[cone_[k]].neighbour[2] = cone_[(k + count - 1) % count];
    }
    for (int point : orphans_) assignToFarthestAbove(point, cone_);
    for (int face : cone_) {
      if (faces_[face].firstOutside >= 0) pending_.push_back(face);
    }
  }

  Triangulation triangulation() const {
    Triangulation result;
    std::vector<int> vertexIndex(points_.size(), -1), faceIndex(faces_.size(), -1);
    for (int face = 0; face < static_cast<int>(faces_.size()); ++face) {
      if (!faces_[face].alive) continue;
      faceIndex[face] = static_cast<int>(result.triangles.size());
      result.triangles.push_back(faces_[face].vertex);
      for (int v : faces_[face].vertex) vertexIndex[v] = 0;
    }
    for (int point = 0; point < static_cast<int>(points_.size()); ++point) {
      if (vertexIndex[point] < 0) continue;
      vertexIndex[point] = static_cast<int>(result.points.size());
      result.points.push_back(point);
    }
    for (int face = 0; face < static_cast<int>(faces_.size()); ++face) {
      if (!faces_[face].alive) continue;
      const Triangle& t = faces_[face];
      for (int& v : result.triangles[faceIndex[face]]) v = vertexIndex[v];
      result.neighbours.push_back({faceIndex[t.neighbour[0]], faceIndex[t.neighbour[1]], faceIndex[t.neighbour[2]]});
    }
    return result;
  }

  const std::vector<Vec3>& points_;
  const std::vector<GridPoint>& grid_;
  const double tolerance_, noiseTolerance_;
  std::vector<Triangle> faces_;
  std::vector<int> candidates_, nextOutside_;
  std::vector<int> free_, pending_, visible_, orphans_, cone_;
  std::vector<HorizonEdge> unordered_, horizon_;
  std::vector<int> vertexStamp_, edgeFrom_;
  int stamp_ = 0, horizonStamp_ = 0;
};

// A closed triangulated sphere: neighbours agree both ways and V - E + F = 2.
void requireClosedSurface(const Triangulation& mesh) {
  const int count = static_cast<int>(mesh.triangles.size());
  for (int t = 0; t < count; ++t) {
    for (int e = 0; e < 3; ++e) {
      const int other = mesh.neighbours[t][e];
      if (other < 0 || std::ranges::find(mesh.neighbours[other], t) == mesh.neighbours[other].end()) {
        reject("point cloud is too degenerate to triangulate consistently (broken adjacency)");
      }
    }
  }
  if (static_cast<int>(mesh.points.size()) - count / 2 != 2) {
    reject("point cloud is too degenerate to triangulate consistently (Euler characteristic is not 2)");
  }
}

// Coplanar regions, grown from the largest triangles first: a neighbour
// joins when its three vertices lie within the tolerance of the seed's plane.
// A fixed plane cannot drift around a curved surface, and thin triangles
// (whose own normals are rounding noise) join the face they lie in.
std::vector<int> coplanarRegions(const Triangulation& mesh, const std::vector<Vec3>& local,
                                 const std::vector<Vec3>& areaNormals, double tolerance) {
  std::vector<int> order(mesh.triangles.size()), region(mesh.triangles.size(), -1), queue;
  std::vector<double> area(mesh.triangles.size());
  for (std::size_t t = 0; t < area.size(); ++t) area[t] = areaNormals[t].squaredNorm();
  std::iota(order.begin(), order.end(), 0);
  std::ranges::stable_sort(order, std::greater{}, [&](int t) { return area[t]; });
  for (int seed : order) {
    if (region[seed] >= 0) continue;
    const Vec3 normal = areaNormals[seed].normalized();
    const double offset = normal.dot(local[mesh.triangles[seed][0]]);
    const auto onPlane = [&](int t) {
      return std::ranges::all_of(mesh.triangles[t],
                                 [&](int v) { return std::abs(normal.dot(local[v]) - offset) <= tolerance; });
    };
    queue.assign(1, seed);
    region[seed] = seed;
    for (std::size_t i = 0; i < queue.size(); ++i) {
      for (int next : mesh.neighbours[queue[i]]) {
        if (region[next] < 0 && onPlane(next)) region[next] = seed, queue.push_back(next);
      }
    }
  }
  return region;
}

// Boundary loop of a group of triangles (counter-clockwise from outside), or
// empty when it is not one simple loop. `next` is scratch, all -1 on entry and exit.
std::vector<int> boundaryLoop(const Triangulation& mesh, std::span<const int> group, const std::vector<int>& root,
                              std::vector<int>& next) {
  if (group.size() == 1) return {mesh.triangles[group[0]].begin(), mesh.triangles[group[0]].end()};
  std::vector<int> starts;
  bool simple = true;
  for (int t : group) {
    for (int e = 0; e < 3; ++e) {
      if (root[mesh.neighbours[t][e]] == root[t]) continue;
      const int from = mesh.triangles[t][e];
      simple = simple && next[from] < 0;
      if (next[from] < 0) starts.push_back(from);
      next[from] = mesh.triangles[t][(e + 1) % 3];
    }
  }
  std::vector<int> loop;
  for (int v = starts.empty() ? -1 : starts.front(); simple && v >= 0 && loop.size() < starts.size();) {
    loop.push_back(v);
    v = next[v];
    if (v == loop.front()) break;
  }
  const bool closed = simple && !loop.empty() && loop.size() == starts.size() && next[loop.back()] == loop.front();
  for (int v : starts) next[v] = -1;
  return closed ? loop : std::vector<int>{};
}

// Values grouped by key (0 .. keyCount - 1) in their order: row k is
// values[start[k] .. start[k + 1]).
struct Rows {
  std::vector<int> start, values;
  std::span<const int> row(int k) const { return {values.data() + start[k], values.data() + start[k + 1]}; }
};

Rows groupByKey(const std::vector<int>& keys, const std::vector<int>& values, int keyCount) {
  Rows rows;
  rows.start.assign(keyCount + 1, 0);
  for (int key : keys) ++rows.start[key + 1];
  std::partial_sum(rows.start.begin(), rows.start.end(), rows.start.begin());
  std::vector<int> fill(rows.start.begin(), rows.start.end() - 1);
  rows.values.resize(values.size());
  for (std::size_t i = 0; i < keys.size(); ++i) rows.values[fill[keys[i]]++] = values[i];
  return rows;
}

// Triangles by coplanar group, groups in the order of their first triangle.
Rows groupMembers(const std::vector<int>& root) {
  std::vector<int> groupOf(root.size(), -1), keys(root.size()), triangles(root.size());
  int count = 0;
  for (int t = 0; t < static_cast<int>(root.size()); ++t) {
    if (groupOf[root[t]] < 0) groupOf[root[t]] = count++;
    keys[t] = groupOf[root[t]];
    triangles[t] = t;
  }
  return groupByKey(keys, triangles, count);
}

// Coplanar groups of triangles, each with its boundary loop (counter-
// clockwise, mesh vertex indices) when that is one simple loop around a
// planar polygon; a group without one stays triangles.
struct FaceGroups {
  Rows members;
  std::vector<std::vector<int>> loops;
  std::vector<Vec3> normals;          // per group, unit, area-weighted
  std::vector<Vec3> triangleNormals;  // per triangle, unit
};

// The group's vertices lie within the tolerance of one plane.
bool isPlanar(const Triangulation& mesh, std::span<const int> group, const Vec3& normal, const std::vector<Vec3>& local,
              double tolerance) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (int t : group) {
    for (int v : mesh.triangles[t]) {
      low = std::min(low, normal.dot(local[v]));
      high = std::max(high, normal.dot(local[v]));
    }
  }
  return high - low <= 2.0 * tolerance;
}

// No corner of the loop is reflex by more than the tolerance.
bool isConvex(const std::vector<int>& loop, const Vec3& normal, const std::vector<Vec3>& local, double tolerance) {
  const std::size_t count = loop.size();
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3 &a = local[loop[i]], &b = local[loop[(i + 1) % count]], &c = local[loop[(i + 2) % count]];
    if ((b - a).cross(c - b).dot(normal) < -tolerance * (c - a).norm()) return false;
  }
  return true;
}

// Hull vertices in local units as given and in grid steps, by mesh vertex index.
struct MeshPoints {
  std::vector<Vec3> local;
  std::vector<GridPoint> grid;
};

MeshPoints meshPoints(const Triangulation& mesh, const LocalCloud& cloud) {
  MeshPoints result;
  result.local.reserve(mesh.points.size());
  result.grid.reserve(mesh.points.size());
  for (int point : mesh.points) result.local.push_back(cloud.points[point]), result.grid.push_back(cloud.grid[point]);
  return result;
}

// Normals are taken from the exact cross products, so a triangle too thin
// for rounding to say which way it faces still faces the way the hull does.
FaceGroups findFaceGroups(const Triangulation& mesh, const MeshPoints& points, double tolerance) {
  const std::vector<Vec3>& local = points.local;
  FaceGroups groups;
  std::vector<Vec3> areaNormals;
  areaNormals.reserve(mesh.triangles.size());
  groups.triangleNormals.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    areaNormals.push_back(gridNormal(points.grid[t[0]], points.grid[t[1]], points.grid[t[2]]));
    groups.triangleNormals.push_back(areaNormals.back().normalized());
  }
  const std::vector<int> root = coplanarRegions(mesh, local, areaNormals, tolerance);
  groups.members = groupMembers(root);
  groups.normals.reserve(groups.members.start.size() - 1);
  groups.loops.reserve(groups.members.start.size() - 1);
  std::vector<int> next(local.size(), -1);
  for (int g = 0; g + 1 < static_cast<int>(groups.members.start.size()); ++g) {
    Vec3 areaNormal = Vec3::Zero();
    for (int t : groups.members.row(g)) areaNormal += areaNormals[t];
    const Vec3 normal = areaNormal.normalized();
    std::vector<int> loop = boundaryLoop(mesh, groups.members.row(g), root, next);
    const bool polygon =
        groups.members.row(g).size() == 1 ||
        (isPlanar(mesh, groups.members.row(g), normal, local, tolerance) && isConvex(loop, normal, local, tolerance));
    groups.normals.push_back(normal);
    groups.loops.push_back(polygon ? std::move(loop) : std::vector<int>{});
  }
  return groups;
}

// Marks as kept every vertex of `loop` farther than the tolerance from the
// line between the kept vertices around it, or all of them if fewer than
// three are kept; true if it marked any.
bool keepLoopCorners(const std::vector<int>& loop, std::vector<char>& removable, const std::vector<Vec3>& local,
                     double tolerance) {
  if (std::ranges::none_of(loop, [&](int v) { return removable[v] != 0; })) return false;
  const int count = static_cast<int>(loop.size());
  std::vector<int> kept;
  for (int i = 0; i < count; ++i) {
    if (!removable[loop[i]]) kept.push_back(i);
  }
  bool marked = false;
  for (int k = 0; k < static_cast<int>(kept.size()) && kept.size() >= 3; ++k) {
    const Vec3& a = local[loop[kept[k]]];
    const Vec3 along = (local[loop[kept[(k + 1) % kept.size()]]] - a).normalized();
    for (int i = (kept[k] + 1) % count; i != kept[(k + 1) % kept.size()]; i = (i + 1) % count) {
      if ((local[loop[i]] - a).cross(along).norm() > tolerance) removable[loop[i]] = 0, marked = true;
    }
  }
  for (int v : loop) {
    if (kept.size() < 3 && removable[v]) removable[v] = 0, marked = true;
  }
  return marked;
}

// Hull vertices that are not corners: inside a planar face, or on a straight
// edge between two. Quickhull keeps such points when they were the farthest
// of their triangle's points along the way (grids, points on a cube's faces);
// without them the triangles join corners only.
std::vector<char> removableVertices(const Triangulation& mesh, const FaceGroups& groups, const std::vector<Vec3>& local,
                                    double tolerance) {
  std::vector<char> removable(local.size(), 1);
  std::vector<std::array<int, 2>> incidentGroups(local.size(), {-1, -1});
  for (int g = 0; g + 1 < static_cast<int>(groups.members.start.size()); ++g) {
    for (int t : groups.members.row(g)) {
      for (int v : mesh.triangles[t]) {
        auto& seen = incidentGroups[v];
        if (groups.loops[g].empty() || (seen[0] >= 0 && seen[0] != g && seen[1] >= 0 && seen[1] != g)) removable[v] = 0;
        if (seen[0] < 0) seen[0] = g;
        if (seen[0] != g && seen[1] < 0) seen[1] = g;
      }
    }
  }
  for (bool marked = true; marked;) {
    marked = false;
    for (const std::vector<int>& loop : groups.loops) {
      marked = keepLoopCorners(loop, removable, local, tolerance) || marked;
    }
  }
  return removable;
}

HullFace faceThrough(std::vector<int> loop, const Vec3& normal, const ConvexHull& hull) {
  double offset = 0.0;
  for (int v : loop) offset += normal.dot(hull.vertices[v]) / static_cast<double>(loop.size());
  return {std::move(loop), normal, offset};
}

// Vertices, triangles and faces of the hull: each planar convex group as one
// polygon face, every other group as one face per triangle.
ConvexHull assemble(const std::vector<Vec3>& points, const Triangulation& mesh, const FaceGroups& groups) {
  ConvexHull hull;
  hull.vertices.reserve(mesh.points.size());
  for (int point : mesh.points) hull.vertices.push_back(points[point]);
  hull.triangles = mesh.triangles;
  hull.faces.reserve(groups.loops.size());
  for (std::size_t g = 0; g < groups.loops.size(); ++g) {
    if (!groups.loops[g].empty()) {
      hull.faces.push_back(faceThrough(groups.loops[g], groups.normals[g], hull));
      continue;
    }
    for (int t : groups.members.row(static_cast<int>(g))) {
      const auto& tri = mesh.triangles[t];
      hull.faces.push_back(faceThrough({tri.begin(), tri.end()}, groups.triangleNormals[t], hull));
    }
  }
  return hull;
}

// On a closed surface each directed edge v -> w occurs once, so the
// neighbours of v are the ends of the edges leaving it, each once.
void buildAdjacency(ConvexHull& hull) {
  std::vector<int> from, to;
  from.reserve(3 * hull.triangles.size());
  to.reserve(3 * hull.triangles.size());
  for (const auto& t : hull.triangles) {
    for (int e = 0; e < 3; ++e) from.push_back(t[e]), to.push_back(t[(e + 1) % 3]);
  }
  Rows rows = groupByKey(from, to, static_cast<int>(hull.vertices.size()));
  for (std::size_t v = 0; v + 1 < rows.start.size(); ++v) {
    std::sort(rows.values.begin() + rows.start[v], rows.values.begin() + rows.start[v + 1]);
  }
  hull.neighbourStart = std::move(rows.start);
  hull.neighbours = std::move(rows.values);
  hull.neighbourPoints.reserve(hull.neighbours.size());
  for (int n : hull.neighbours) hull.neighbourPoints.push_back(hull.vertices[n]);
}

}  // namespace

ConvexHull buildConvexHull(const std::vector<Vec3>& points) {
  requireFourDistinctFinitePoints(points);
  const LocalCloud cloud = toLocalFrame(points);
  std::vector<int> candidates(points.size());
  std::iota(candidates.begin(), candidates.end(), 0);
  Triangulation mesh = QuickHull(cloud).build(std::move(candidates));
  requireClosedSurface(mesh);
  const MeshPoints vertices = meshPoints(mesh, cloud);
  FaceGroups groups = findFaceGroups(mesh, vertices, cloud.noiseTolerance);
  const std::vector<char> removable = removableVertices(mesh, groups, vertices.local, cloud.noiseTolerance);
  if (std::ranges::find(removable, 1) != removable.end()) {
    // Once more on the corners alone: exact, so no triangle can turn over.
    candidates.clear();
    for (std::size_t v = 0; v < removable.size(); ++v) {
      if (!removable[v]) candidates.push_back(mesh.points[v]);
    }
    mesh = QuickHull(cloud).build(std::move(candidates));
    requireClosedSurface(mesh);
    groups = findFaceGroups(mesh, meshPoints(mesh, cloud), cloud.noiseTolerance);
  }
  ConvexHull hull = assemble(points, mesh, groups);
  buildAdjacency(hull);
  return hull;
}

}  // namespace physdbg
