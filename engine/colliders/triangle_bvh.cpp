#include "engine/colliders/triangle_bvh.h"

#include <algorithm>
#include <array>
#include <limits>

namespace physdbg {
namespace {

// Twelve bins find a split within a few percent of the best sweep's cost at
// a fraction of its time; more bins buy nothing measurable for meshes.
constexpr int binCount = 12;
// Deeper than any tree the heuristic makes for a real mesh (a million
// triangles in leaves of four is about 20 levels when balanced).
constexpr int medianDepth = 48;

Aabb emptyBox() {
  const double big = std::numeric_limits<double>::infinity();
  return {Vec3::Constant(big), Vec3::Constant(-big)};
}

double areaOf(const Aabb& box) { return box.min.x() > box.max.x() ? 0.0 : box.surfaceArea(); }

struct Split {
  int axis = -1;
  double position = 0.0;
  double cost = std::numeric_limits<double>::infinity();
};

// The cheapest bin boundary by the surface-area heuristic: the triangles on
// each side weighted by the area of their box.
Split bestSplit(std::span<const Aabb> bounds, std::span<const Vec3> centres, std::span<const std::uint32_t> triangles) {
  Aabb centreBox = emptyBox();
  for (const std::uint32_t t : triangles) centreBox = {centreBox.min.cwiseMin(centres[t]), centreBox.max.cwiseMax(centres[t])};
  Split best;
  for (int axis = 0; axis < 3; ++axis) {
    const double low = centreBox.min[axis], extent = centreBox.max[axis] - low;
    if (!(extent > 0.0)) continue;
    std::array<Aabb, binCount> boxes;
    boxes.fill(emptyBox());
    std::array<std::uint32_t, binCount> counts{};
    const auto binOf = [&](std::uint32_t t) {
      return std::min(binCount - 1, static_cast<int>(binCount * (centres[t][axis] - low) / extent));
    };
    for (const std::uint32_t t : triangles) {
      const int bin = binOf(t);
      boxes[bin] = boxes[bin].merged(bounds[t]);
      ++counts[bin];
    }
    std::array<double, binCount> rightArea{};
    std::array<std::uint32_t, binCount> rightCount{};
    Aabb right = emptyBox();
    std::uint32_t rightTotal = 0;
    for (int bin = binCount - 1; bin > 0; --bin) {
      right = right.merged(boxes[bin]);
      rightTotal += counts[bin];
      rightArea[bin] = areaOf(right);
      rightCount[bin] = rightTotal;
    }
    Aabb left = emptyBox();
    std::uint32_t leftTotal = 0;
    for (int bin = 1; bin < binCount; ++bin) {
      left = left.merged(boxes[bin - 1]);
      leftTotal += counts[bin - 1];
      if (leftTotal == 0 || rightCount[bin] == 0) continue;
      const double cost = areaOf(left) * leftTotal + rightArea[bin] * rightCount[bin];
      if (cost < best.cost) best = {axis, low + extent * bin / binCount, cost};
    }
  }
  return best;
}

}  // namespace

TriangleBvh::TriangleBvh(std::span<const Aabb> bounds) {
  if (bounds.empty()) return;
  std::vector<Vec3> centres(bounds.size());
  for (std::size_t t = 0; t < bounds.size(); ++t) centres[t] = bounds[t].center();
  order_.resize(bounds.size());
  for (std::size_t t = 0; t < bounds.size(); ++t) order_[t] = static_cast<std::uint32_t>(t);
  nodes_.reserve(2 * bounds.size() / maxLeafTriangles + 1);
  nodes_.emplace_back();
  build(0, bounds, centres, 0, static_cast<std::uint32_t>(bounds.size()), 1);
  nodes_.shrink_to_fit();
}

// Fills node `index` for the triangles order_[first, first + count). Leaves
// hold at most maxLeafTriangles: where the heuristic would rather test more
// at once, the split it found best is taken anyway, and triangles whose
// centres coincide are split at the median.
void TriangleBvh::build(std::uint32_t index, std::span<const Aabb> bounds, std::span<const Vec3> centres,
                        std::uint32_t first, std::uint32_t count, int depth) {
  depth_ = std::max(depth_, depth);
  const std::span<std::uint32_t> triangles(order_.data() + first, count);
  Aabb box = emptyBox();
  for (const std::uint32_t t : triangles) box = box.merged(bounds[t]);
  nodes_[index].bounds = box;
  if (count <= maxLeafTriangles) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return;
  }
  // Past medianDepth the split is the median along the widest axis: the
  // heuristic can peel one triangle a level off a list of exponentially
  // spaced ones, which would recurse as deep as the list is long.
  const Split split = depth < medianDepth ? bestSplit(bounds, centres, triangles) : Split{};
  std::uint32_t leftCount = count / 2;
  if (split.axis < 0) {
    int axis = 0;
    box.halfExtents().maxCoeff(&axis);
    std::nth_element(triangles.begin(), triangles.begin() + leftCount, triangles.end(),
                     [&](std::uint32_t s, std::uint32_t t) {
                       return centres[s][axis] < centres[t][axis] || (centres[s][axis] == centres[t][axis] && s < t);
                     });
  } else {
    const auto below = std::stable_partition(triangles.begin(), triangles.end(), [&](std::uint32_t t) {
      return centres[t][split.axis] < split.position;
    });
    leftCount = static_cast<std::uint32_t>(below - triangles.begin());
  }
  const auto children = static_cast<std::uint32_t>(nodes_.size());
  nodes_[index].first = children;
  nodes_[index].count = 0;
  nodes_.emplace_back();
  nodes_.emplace_back();
  build(children, bounds, centres, first, leftCount, depth + 1);
  build(children + 1, bounds, centres, first + leftCount, count - leftCount, depth + 1);
}

void TriangleBvh::query(const Aabb& box, std::vector<std::uint32_t>& out) const {
  if (nodes_.empty()) return;
  // The stack never holds more than one node a level plus one: a fixed
  // array for any sane tree, the heap only for a degenerate deep one.
  std::uint32_t fixed[64];
  std::vector<std::uint32_t> deep;
  std::uint32_t* stack = fixed;
  if (depth_ + 2 > 64) {
    deep.resize(static_cast<std::size_t>(depth_) + 2);
    stack = deep.data();
  }
  std::size_t size = 0;
  stack[size++] = 0;
  while (size > 0) {
    const Node& node = nodes_[stack[--size]];
    if (!node.bounds.overlaps(box)) continue;
    if (node.isLeaf()) {
      out.insert(out.end(), order_.begin() + node.first, order_.begin() + node.first + node.count);
      continue;
    }
    stack[size++] = node.first + 1;
    stack[size++] = node.first;
  }
}

}  // namespace physdbg
