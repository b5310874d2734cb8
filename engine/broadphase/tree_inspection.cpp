// Read-only views of the tree for tests and the visual debugger.
#include <cmath>
#include <limits>
#include <sstream>

#include "engine/broadphase/dynamic_aabb_tree.h"

namespace physdbg {

int DynamicAabbTree::height() const { return root_ == nullNode ? 0 : nodes_[root_].height; }

double DynamicAabbTree::internalArea() const {
  double area = 0.0;
  for (const Node& node : nodes_) {
    if (node.height > 0) area += node.box.surfaceArea();
  }
  return area;
}

double DynamicAabbTree::surfaceAreaRatio() const {
  if (root_ == nullNode || nodes_[root_].child1 == nullNode) return 0.0;
  const double rootArea = nodes_[root_].box.surfaceArea();
  return rootArea > 0.0 ? internalArea() / rootArea : 0.0;
}

std::string DynamicAabbTree::validate() const {
  std::ostringstream problems;
  if (root_ != nullNode && nodes_[root_].parent != nullNode) problems << "root has a parent; ";
  int reached = 0;
  int leaves = 0;
  std::vector<int> stack;
  if (root_ != nullNode) stack.push_back(root_);
  while (!stack.empty() && reached <= static_cast<int>(nodes_.size())) {
    const int index = stack.back();
    stack.pop_back();
    ++reached;
    const Node& node = nodes_[index];
    if (node.height < 0) {
      problems << "node " << index << " is reachable but free; ";
      continue;
    }
    if (node.child1 == nullNode) {
      ++leaves;
      if (node.child2 != nullNode || node.height != 0) problems << "leaf " << index << " malformed; ";
      continue;
    }
    for (const int child : {node.child1, node.child2}) {
      if (child < 0 || child >= static_cast<int>(nodes_.size())) {
        problems << "node " << index << " has child out of range; ";
        continue;
      }
      if (nodes_[child].parent != index) problems << "child " << child << " does not point back to " << index << "; ";
      if (!node.box.contains(nodes_[child].box)) problems << "node " << index << " does not contain " << child << "; ";
      stack.push_back(child);
    }
    const int expected = 1 + std::max(nodes_[node.child1].height, nodes_[node.child2].height);
    if (node.height != expected) problems << "node " << index << " height " << node.height << " != " << expected << "; ";
  }
  if (reached > static_cast<int>(nodes_.size())) problems << "cycle; ";
  if (reached != nodeCount_) problems << "reached " << reached << " nodes, count says " << nodeCount_ << "; ";
  if (leaves != proxyCount_) problems << leaves << " leaves, " << proxyCount_ << " proxies; ";
  if (proxyCount_ > 0 && nodeCount_ != 2 * proxyCount_ - 1) problems << "not a full binary tree; ";
  int freeNodes = 0;
  for (int index = freeList_; index != nullNode && freeNodes <= static_cast<int>(nodes_.size());
       index = nodes_[index].parent) {
    if (nodes_[index].height != -1) problems << "free node " << index << " not marked free; ";
    ++freeNodes;
  }
  if (freeNodes + nodeCount_ != static_cast<int>(nodes_.size())) problems << "free list leaks nodes; ";
  return problems.str();
}

double segmentEntry(const Aabb& box, const Vec3& origin, const Vec3& inverseDirection, double maxFraction) {
  double enter = 0.0;
  double leave = maxFraction;
  for (int axis = 0; axis < 3; ++axis) {
    const double inverse = inverseDirection[axis];
    if (std::isinf(inverse)) {
      // Parallel to this slab: inside it or never.
      if (origin[axis] < box.min[axis] || origin[axis] > box.max[axis]) return -1.0;
      continue;
    }
    double near = (box.min[axis] - origin[axis]) * inverse;
    double far = (box.max[axis] - origin[axis]) * inverse;
    if (near > far) std::swap(near, far);
    enter = std::max(enter, near);
    leave = std::min(leave, far);
    if (enter > leave) return -1.0;
  }
  return enter;
}

}  // namespace physdbg
