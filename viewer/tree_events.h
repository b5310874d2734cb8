#pragma once
// The tree view's events: a scene's bodies inserted one by one into a
// dynamic AABB tree of our own with the rotation log on (and, with steps,
// reinserted as the world moves). Every insertion or reinsertion that rotates
// is an event: the tree just before and just after its rotations.
#include <functional>
#include <string>
#include <vector>

#include "engine/broadphase/dynamic_aabb_tree.h"
#include "scenes/scene.h"
#include "viewer/tree_snapshot.h"

namespace physdbg::viewer {

struct TreeEvent {
  std::string what;  // "insertion 12 (body 11)"
  TreeSnapshot before, after;
  std::vector<RotationEvent> rotations;
  int leaf = DynamicAabbTree::nullNode;
};

// Rotating events as they happen: the first `keep` are snapshotted and handed
// to `onEvent`, the rest only counted. Nothing is kept per event, so memory is
// one tree whatever the scene's size and however many events it makes.
struct TreeEventStream {
  long long keep = 0;
  std::function<void(const TreeEvent& event, int index)> onEvent;
  int count = 0;
};

// Inserts the scene's bodies (fat-box `margin`), then simulates `steps` steps
// reinserting every body after each; `initialBoxes` receives the bodies' boxes
// as first inserted.
void collectTreeEvents(const SceneDescription& scene, int steps, double margin, std::vector<Aabb>& initialBoxes,
                       TreeEventStream& stream);

// Internal nodes whose boxes a rotation changed: the new parents of the two
// swapped subtrees, except the pivot (its box never changes). One for a
// child-grandchild swap, two for a grandchild-grandchild swap.
std::vector<int> reshapedBy(const RotationEvent& rotation, const TreeSnapshot& after);

// Surface area ratio and height after each of `boxes` is inserted in turn.
struct TreeCurves {
  std::vector<double> sar, height;
};
TreeCurves insertionCurves(const std::vector<Aabb>& boxes, const DynamicAabbTreeOptions& options);

}  // namespace physdbg::viewer
