#include "engine/broadphase/dynamic_aabb_tree.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/broadphase/fat_box.h"

namespace physdbg {

DynamicAabbTree::DynamicAabbTree(const DynamicAabbTreeOptions& options) : options_(options) {
  if (!(options.margin >= 0.0) || !std::isfinite(options.margin)) {
    throw std::invalid_argument("DynamicAabbTree: margin must be finite and >= 0");
  }
  if (!(options.velocityPrediction >= 0.0) || !std::isfinite(options.velocityPrediction)) {
    throw std::invalid_argument("DynamicAabbTree: velocityPrediction must be finite and >= 0");
  }
}

void DynamicAabbTree::requireValidBox(const Aabb& box, const char* operation) {
  if (!box.isValid()) {
    throw std::invalid_argument(std::string("DynamicAabbTree::") + operation + ": box must be finite with min <= max");
  }
}

void DynamicAabbTree::requireProxy(int proxy, const char* operation) const {
  if (!isProxy(proxy)) {
    throw std::invalid_argument(std::string("DynamicAabbTree::") + operation + ": " + std::to_string(proxy) +
                                " is not a live proxy");
  }
}

bool DynamicAabbTree::isProxy(int proxy) const {
  return proxy >= 0 && proxy < static_cast<int>(nodes_.size()) && nodes_[proxy].height == 0;
}

const Aabb& DynamicAabbTree::fatBox(int proxy) const {
  requireProxy(proxy, "fatBox");
  return nodes_[proxy].box;
}

std::uint32_t DynamicAabbTree::userData(int proxy) const {
  requireProxy(proxy, "userData");
  return userData_[proxy];
}

int DynamicAabbTree::allocateNode() {
  int node = freeList_;
  if (node == nullNode) {
    node = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    userData_.push_back(0);
  } else {
    freeList_ = nodes_[node].parent;
  }
  nodes_[node] = Node{};
  ++nodeCount_;
  return node;
}

void DynamicAabbTree::freeNode(int node) {
  nodes_[node].parent = freeList_;
  nodes_[node].child1 = nullNode;
  nodes_[node].child2 = nullNode;
  nodes_[node].height = -1;
  freeList_ = node;
  --nodeCount_;
}

int DynamicAabbTree::createProxy(const Aabb& tightBox, std::uint32_t userData) {
  requireValidBox(tightBox, "createProxy");
  const int leaf = allocateNode();
  nodes_[leaf].box = fattenBox(tightBox, Vec3::Zero(), options_.margin, options_.velocityPrediction);
  userData_[leaf] = userData;
  insertLeaf(leaf);
  ++proxyCount_;
  return leaf;
}

// A proxy removed for good is not reinserted, and the reinsertion is what
// rotates a moved leaf's path: the walk up from its old place rotates by the
// insertion's rules instead, so removals do not leave the tree worse.
void DynamicAabbTree::destroyProxy(int proxy) {
  requireProxy(proxy, "destroyProxy");
  const int formerSibling = removeLeaf(proxy);
  freeNode(proxy);
  --proxyCount_;
  if (formerSibling != nullNode) refitAncestors(nodes_[formerSibling].parent);
}

bool DynamicAabbTree::moveProxy(int proxy, const Aabb& tightBox, const Vec3& displacement) {
  requireProxy(proxy, "moveProxy");
  requireValidBox(tightBox, "moveProxy");
  if (!displacement.allFinite()) throw std::invalid_argument("DynamicAabbTree::moveProxy: displacement not finite");
  if (nodes_[proxy].box.contains(tightBox)) return false;
  const int formerSibling = removeLeaf(proxy);
  nodes_[proxy].box = fattenBox(tightBox, displacement, options_.margin, options_.velocityPrediction);
  insertLeaf(proxy, formerSibling);
  return true;
}

void DynamicAabbTree::insertLeaf(int leaf, int hint) {
  if (root_ == nullNode) {
    root_ = leaf;
    nodes_[leaf].parent = nullNode;
    return;
  }
  const Aabb& box = nodes_[leaf].box;
  const int sibling = options_.insertion == InsertionMethod::BranchAndBound ? findBestSiblingBranchAndBound(box, hint)
                                                                            : findBestSiblingGreedy(box);
  const int oldParent = nodes_[sibling].parent;
  const int newParent = allocateNode();
  Node& parent = nodes_[newParent];
  parent.parent = oldParent;
  parent.child1 = sibling;
  parent.child2 = leaf;
  parent.box = nodes_[sibling].box.merged(nodes_[leaf].box);
  parent.height = nodes_[sibling].height + 1;
  if (oldParent == nullNode) {
    root_ = newParent;
  } else if (nodes_[oldParent].child1 == sibling) {
    nodes_[oldParent].child1 = newParent;
  } else {
    nodes_[oldParent].child2 = newParent;
  }
  nodes_[sibling].parent = newParent;
  nodes_[leaf].parent = newParent;
  refitAncestors(newParent);
}

int DynamicAabbTree::removeLeaf(int leaf) {
  if (leaf == root_) {
    root_ = nullNode;
    return nullNode;
  }
  const int parent = nodes_[leaf].parent;
  const int grandParent = nodes_[parent].parent;
  const int sibling = nodes_[parent].child1 == leaf ? nodes_[parent].child2 : nodes_[parent].child1;
  nodes_[sibling].parent = grandParent;
  if (grandParent == nullNode) {
    root_ = sibling;
  } else if (nodes_[grandParent].child1 == parent) {
    nodes_[grandParent].child1 = sibling;
  } else {
    nodes_[grandParent].child2 = sibling;
  }
  freeNode(parent);
  nodes_[leaf].parent = nullNode;
  shrinkAncestors(grandParent);
  return sibling;
}

// After a removal boxes can only shrink; once one stays the same, so do all above
// it. No rotations here: the reinsertion that usually follows rotates its own path.
void DynamicAabbTree::shrinkAncestors(int node) {
  while (node != nullNode) {
    const Aabb before = nodes_[node].box;
    const int heightBefore = nodes_[node].height;
    refitNode(node);
    const Aabb& after = nodes_[node].box;
    if (after.min == before.min && after.max == before.max && nodes_[node].height == heightBefore) return;
    node = nodes_[node].parent;
  }
}

void DynamicAabbTree::refitNode(int node) {
  Node& current = nodes_[node];
  const Node& first = nodes_[current.child1];
  const Node& second = nodes_[current.child2];
  current.box = first.box.merged(second.box);
  current.height = 1 + std::max(first.height, second.height);
}

void DynamicAabbTree::refitAncestors(int node) {
  while (node != nullNode) {
    refitNode(node);
    // A rotation hands both children new subtrees; each gets one more try.
    if (options_.rotations && rotate(node)) {
      for (int child : {nodes_[node].child1, nodes_[node].child2})
        if (nodes_[child].child1 != nullNode) rotate(child);
      refitNode(node);  // same box; the height may have changed below
    }
    node = nodes_[node].parent;
  }
}

}  // namespace physdbg
