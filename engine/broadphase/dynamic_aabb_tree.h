#pragma once
// Dynamic AABB tree: a binary bounding-volume hierarchy over fat (enlarged)
// leaf boxes, kept good incrementally. Leaves are inserted next to the sibling
// that adds the least surface area (branch-and-bound or greedy descent), and the
// refit walk up to the root applies local tree rotations so that sorted input
// (rows, grids) does not degenerate into a list. Proxy ids are node indices of
// leaves and stay valid until the proxy is destroyed, also across rebuilds.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "engine/aabb.h"
#include "engine/broadphase/tree_options.h"

namespace physdbg {


// One rotation applied during a refit walk: subtree `first` moved down and
// `second` moved up, below `node`. Only recorded while the log is enabled,
// which is when the O(n) SAR figures are paid for.
struct RotationEvent {
  int node = -1;
  int first = -1;
  int second = -1;
  Aabb firstBox;   // the two swapped subtrees' boxes, for drawing
  Aabb secondBox;
  double areaBefore = 0.0;  // total area of the one or two nodes whose boxes the swap changes
  double areaAfter = 0.0;
  double sarBefore = 0.0;
  double sarAfter = 0.0;
};

class DynamicAabbTree {
 public:
  static constexpr int nullNode = -1;

  explicit DynamicAabbTree(const DynamicAabbTreeOptions& options = {});

  const DynamicAabbTreeOptions& options() const { return options_; }
  int createProxy(const Aabb& tightBox, std::uint32_t userData);
  void destroyProxy(int proxy);
  // Returns true when the tight box left the fat box and the proxy was reinserted.
  bool moveProxy(int proxy, const Aabb& tightBox, const Vec3& displacement = Vec3::Zero());

  bool isProxy(int proxy) const;
  const Aabb& fatBox(int proxy) const;
  std::uint32_t userData(int proxy) const;
  int proxyCount() const { return proxyCount_; }
  int root() const { return root_; }

  // Visits every leaf whose fat box overlaps `box`; callback(int proxy) returns false to stop.
  template <typename Callback>
  void query(const Aabb& box, Callback&& callback) const;

  // Segment origin + t * direction, t in [0, maxFraction]. callback(int proxy, double maxFraction)
  // returns a value v: v < 0 ignores the proxy, otherwise maxFraction = min(maxFraction, v) and the
  // traversal clips to it (v = 0 stops). Nearer children are visited first, so the closest hit
  // shrinks the search early.
  template <typename Callback>
  void rayCast(const Vec3& origin, const Vec3& direction, double maxFraction, Callback&& callback) const;

  // Inspection.
  std::string validate() const;  // empty when the tree is consistent, else what is wrong
  int height() const;
  int nodeCount() const { return nodeCount_; }
  double surfaceAreaRatio() const;  // sum of internal nodes' areas / root area (0 below two leaves)
  double internalArea() const;      // sum of internal nodes' areas
  template <typename Callback>
  void forEachNode(Callback&& callback) const;  // callback(const Aabb&, int depth, bool isLeaf)

  // Top-down binned-SAH rebuild of all internal nodes; proxy ids are kept.
  void rebuildTopDown();

  void setRotationLogEnabled(bool enabled) { logRotations_ = enabled; }
  const std::vector<RotationEvent>& rotationLog() const { return rotationLog_; }
  void clearRotationLog() { rotationLog_.clear(); }

  // Raw node access for traversals that live outside the tree (pair finding).
  bool isLeaf(int node) const { return nodes_[node].child1 == nullNode; }
  int child1(int node) const { return nodes_[node].child1; }
  int child2(int node) const { return nodes_[node].child2; }
  int parent(int node) const { return nodes_[node].parent; }  // nullNode at the root
  const Aabb& box(int node) const { return nodes_[node].box; }

 private:
  // One cache line per node, aligned to it: a traversal that reads a node's
  // box finds its child ids in the same line and never straddles two. User
  // data, read only when a pair is reported, lives apart (userData_).
  struct alignas(64) Node {
    Aabb box;
    int parent = nullNode;  // next free node while on the free list
    int child1 = nullNode;
    int child2 = nullNode;
    int height = 0;  // leaves 0; -1 marks a free node
  };
  static_assert(sizeof(Node) == 64, "a node should fill exactly one cache line");

  int allocateNode();
  void freeNode(int node);
  // hint: a node near where the leaf should go (its old sibling on a move), or nullNode.
  void insertLeaf(int leaf, int hint = nullNode);
  int removeLeaf(int leaf);  // returns the removed leaf's former sibling, or nullNode
  int findBestSiblingBranchAndBound(const Aabb& box, int hint);
  double insertionCost(const Aabb& box, int sibling) const;
  int findBestSiblingGreedy(const Aabb& box) const;
  void refitAncestors(int node);
  void shrinkAncestors(int node);
  void refitNode(int node);
  bool rotate(int node);
  void swapSubtrees(int node, int first, int second);
  int buildTopDown(std::vector<int>& leaves, int begin, int end);
  void requireProxy(int proxy, const char* operation) const;
  static void requireValidBox(const Aabb& box, const char* operation);

  DynamicAabbTreeOptions options_;
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> userData_;  // indexed like nodes_, meaningful for leaves
  int root_ = nullNode;
  int freeList_ = nullNode;
  int nodeCount_ = 0;
  int proxyCount_ = 0;
  bool logRotations_ = false;
  std::vector<RotationEvent> rotationLog_;
  struct Candidate {
    double lowerBound;
    int node;
    double inherited;
  };
  std::vector<Candidate> heap_;  // scratch of the branch-and-bound search, kept to avoid reallocations
};

// Aabb::overlaps without branches: traversals test two boxes per node, and
// six comparisons combined with & cost less than the mispredicted jumps of
// an early exit (whether a box overlaps is close to a coin toss there).
// (The comparisons are counted as ints so compilers see the & is meant.)
inline bool overlapping(const Aabb& a, const Aabb& b) {
  const auto bit = [](bool value) { return static_cast<int>(value); };
  return (bit(a.min.x() <= b.max.x()) & bit(b.min.x() <= a.max.x()) & bit(a.min.y() <= b.max.y()) &
          bit(b.min.y() <= a.max.y()) & bit(a.min.z() <= b.max.z()) & bit(b.min.z() <= a.max.z())) != 0;
}

// Entry parameter t of the segment origin + t * direction into box, or a negative value when it misses
// within [0, maxFraction]. inverseDirection components may be infinite (axis-parallel rays).
double segmentEntry(const Aabb& box, const Vec3& origin, const Vec3& inverseDirection, double maxFraction);

template <typename Callback>
void DynamicAabbTree::query(const Aabb& box, Callback&& callback) const {
  if (root_ == nullNode) return;
  std::vector<int> stack;
  stack.reserve(64);
  stack.push_back(root_);
  while (!stack.empty()) {
    const int node = stack.back();
    stack.pop_back();
    const Node& current = nodes_[node];
    if (!overlapping(current.box, box)) continue;
    if (current.child1 == nullNode) {
      if (!callback(node)) return;
    } else {
      stack.push_back(current.child2);
      stack.push_back(current.child1);
    }
  }
}

template <typename Callback>
void DynamicAabbTree::rayCast(const Vec3& origin, const Vec3& direction, double maxFraction,
                              Callback&& callback) const {
  if (root_ == nullNode || !(maxFraction >= 0.0)) return;
  const Vec3 inverse = direction.cwiseInverse();
  std::vector<int> stack;
  stack.reserve(64);
  if (segmentEntry(nodes_[root_].box, origin, inverse, maxFraction) >= 0.0) stack.push_back(root_);
  while (!stack.empty()) {
    const int node = stack.back();
    stack.pop_back();
    const Node& current = nodes_[node];
    // Re-test: maxFraction may have shrunk since the node was pushed.
    if (segmentEntry(current.box, origin, inverse, maxFraction) < 0.0) continue;
    if (current.child1 == nullNode) {
      const double value = callback(node, maxFraction);
      if (value < 0.0) continue;
      if (value < maxFraction) maxFraction = value;
      if (maxFraction <= 0.0) return;
      continue;
    }
    const double entry1 = segmentEntry(nodes_[current.child1].box, origin, inverse, maxFraction);
    const double entry2 = segmentEntry(nodes_[current.child2].box, origin, inverse, maxFraction);
    // Push the farther child first so the nearer one is visited first.
    const bool firstIsNearer = entry2 < 0.0 || (entry1 >= 0.0 && entry1 <= entry2);
    const int nearer = firstIsNearer ? current.child1 : current.child2;
    const int farther = firstIsNearer ? current.child2 : current.child1;
    const double nearEntry = firstIsNearer ? entry1 : entry2;
    const double farEntry = firstIsNearer ? entry2 : entry1;
    if (farEntry >= 0.0) stack.push_back(farther);
    if (nearEntry >= 0.0) stack.push_back(nearer);
  }
}

template <typename Callback>
void DynamicAabbTree::forEachNode(Callback&& callback) const {
  if (root_ == nullNode) return;
  std::vector<std::pair<int, int>> stack{{root_, 0}};
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    const Node& current = nodes_[node];
    const bool leaf = current.child1 == nullNode;
    callback(current.box, depth, leaf);
    if (!leaf) {
      stack.emplace_back(current.child2, depth + 1);
      stack.emplace_back(current.child1, depth + 1);
    }
  }
}

}  // namespace physdbg
