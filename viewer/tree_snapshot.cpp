#include "viewer/tree_snapshot.h"

#include <algorithm>
#include <stdexcept>

namespace physdbg::viewer {
namespace {

constexpr int none = DynamicAabbTree::nullNode;

bool holds(const TreeSnapshot& snapshot, int node) {
  return node >= 0 && node < static_cast<int>(snapshot.nodes.size()) && snapshot.nodes[node].used;
}

int& childSlot(TreeSnapshot& snapshot, int parent, int child) {
  TreeSnapshot::Node& node = snapshot.nodes[parent];
  if (node.child1 == child) return node.child1;
  if (node.child2 == child) return node.child2;
  throw std::invalid_argument("tree snapshot: node " + std::to_string(child) + " is not a child of " +
                              std::to_string(parent));
}

// Post-order refit, so children are exact before their parent.
void refit(TreeSnapshot& snapshot, int node) {
  TreeSnapshot::Node& current = snapshot.nodes[node];
  if (current.child1 == none) return;
  refit(snapshot, current.child1);
  refit(snapshot, current.child2);
  current.box = snapshot.nodes[current.child1].box.merged(snapshot.nodes[current.child2].box);
}

}  // namespace

TreeSnapshot snapshotTree(const DynamicAabbTree& tree) {
  TreeSnapshot snapshot;
  snapshot.root = tree.root();
  if (snapshot.root == none) return snapshot;
  std::vector<int> stack{snapshot.root};
  while (!stack.empty()) {
    const int node = stack.back();
    stack.pop_back();
    if (node >= static_cast<int>(snapshot.nodes.size())) snapshot.nodes.resize(node + 1);
    TreeSnapshot::Node& copy = snapshot.nodes[node];
    copy.used = true;
    copy.box = tree.box(node);
    if (tree.isLeaf(node)) continue;
    copy.child1 = tree.child1(node);
    copy.child2 = tree.child2(node);
    for (const int child : {copy.child1, copy.child2}) {
      if (child >= static_cast<int>(snapshot.nodes.size())) snapshot.nodes.resize(child + 1);
      snapshot.nodes[child].parent = node;
      stack.push_back(child);
    }
  }
  return snapshot;
}

void undoRotations(TreeSnapshot& snapshot, const std::vector<RotationEvent>& events) {
  for (auto event = events.rbegin(); event != events.rend(); ++event) {
    if (!holds(snapshot, event->first) || !holds(snapshot, event->second))
      throw std::invalid_argument("tree snapshot: rotation names nodes " + std::to_string(event->first) + " and " +
                                  std::to_string(event->second) + " that are not in the tree");
    const int firstParent = snapshot.nodes[event->first].parent;
    const int secondParent = snapshot.nodes[event->second].parent;
    if (firstParent == none || secondParent == none)
      throw std::invalid_argument("tree snapshot: a rotation cannot move the root");
    int& firstSlot = childSlot(snapshot, firstParent, event->first);
    int& secondSlot = childSlot(snapshot, secondParent, event->second);
    std::swap(firstSlot, secondSlot);
    snapshot.nodes[event->first].parent = secondParent;
    snapshot.nodes[event->second].parent = firstParent;
  }
  if (snapshot.root != none) refit(snapshot, snapshot.root);
}

int TreeSnapshot::height() const {
  if (root == none) return 0;
  const std::vector<int> depth = depths();
  return *std::max_element(depth.begin(), depth.end());
}

double TreeSnapshot::surfaceAreaRatio() const {
  if (root == none || isLeaf(root)) return 0.0;
  double internal = 0.0;
  for (const Node& node : nodes)
    if (node.used && node.child1 != none) internal += node.box.surfaceArea();
  const double rootArea = nodes[root].box.surfaceArea();
  return rootArea > 0.0 ? internal / rootArea : 0.0;
}

std::vector<int> TreeSnapshot::subtree(int node) const {
  std::vector<int> result;
  if (!holds(*this, node)) return result;
  std::vector<int> stack{node};
  while (!stack.empty()) {
    const int current = stack.back();
    stack.pop_back();
    result.push_back(current);
    if (nodes[current].child1 == none) continue;
    stack.push_back(nodes[current].child2);
    stack.push_back(nodes[current].child1);
  }
  return result;
}

std::vector<int> TreeSnapshot::depths() const {
  std::vector<int> depth(nodes.size(), -1);
  if (root == none) return depth;
  std::vector<int> stack{root};
  depth[root] = 0;
  while (!stack.empty()) {
    const int current = stack.back();
    stack.pop_back();
    if (nodes[current].child1 == none) continue;
    for (const int child : {nodes[current].child1, nodes[current].child2}) {
      depth[child] = depth[current] + 1;
      stack.push_back(child);
    }
  }
  return depth;
}

}  // namespace physdbg::viewer
