#include "viewer/tree_events.h"

#include "engine/world.h"

namespace physdbg::viewer {
namespace {

std::vector<Aabb> bodyBoxes(const World& world) {
  std::vector<Aabb> boxes;
  for (const RigidBody& body : world.bodies()) boxes.push_back(body.collider().worldBounds(body.transform()));
  return boxes;
}

// Runs `change` with the log cleared; reports an event when it rotated.
template <typename Change>
void observe(DynamicAabbTree& tree, const std::string& what, Change&& change, TreeEventStream& stream) {
  tree.clearRotationLog();
  const int leaf = change();
  if (tree.rotationLog().empty()) return;
  const int index = stream.count++;
  if (index >= stream.keep) return;
  TreeEvent event;
  event.what = what;
  event.leaf = leaf;
  event.rotations = tree.rotationLog();
  event.after = snapshotTree(tree);
  event.before = event.after;
  undoRotations(event.before, event.rotations);
  stream.onEvent(event, index);
}

}  // namespace

std::vector<int> reshapedBy(const RotationEvent& rotation, const TreeSnapshot& after) {
  std::vector<int> nodes;
  for (int moved : {rotation.first, rotation.second}) {
    const int parent = after.nodes[moved].parent;
    if (parent != rotation.node) nodes.push_back(parent);
  }
  return nodes;
}

TreeCurves insertionCurves(const std::vector<Aabb>& boxes, const DynamicAabbTreeOptions& options) {
  DynamicAabbTree tree(options);
  TreeCurves curves;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    tree.createProxy(boxes[i], static_cast<std::uint32_t>(i));
    curves.sar.push_back(tree.surfaceAreaRatio());
    curves.height.push_back(tree.height());
  }
  return curves;
}

void collectTreeEvents(const SceneDescription& scene, int steps, double margin, std::vector<Aabb>& initialBoxes,
                       TreeEventStream& stream) {
  World world = buildWorld(scene);
  DynamicAabbTreeOptions options;
  options.margin = margin;
  DynamicAabbTree tree(options);
  tree.setRotationLogEnabled(true);
  initialBoxes = bodyBoxes(world);
  std::vector<int> proxies;
  for (std::size_t i = 0; i < initialBoxes.size(); ++i) {
    const std::string what = "insertion " + std::to_string(i + 1) + " (body " + std::to_string(i) + ")";
    observe(
        tree, what,
        [&] {
          proxies.push_back(tree.createProxy(initialBoxes[i], static_cast<std::uint32_t>(i)));
          return proxies.back();
        },
        stream);
  }
  for (int step = 1; step <= steps; ++step) {
    world.step();
    const std::vector<Aabb> boxes = bodyBoxes(world);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const std::string what = "step " + std::to_string(step) + " reinsertion (body " + std::to_string(i) + ")";
      observe(
          tree, what,
          [&] {
            tree.moveProxy(proxies[i], boxes[i]);
            return proxies[i];
          },
          stream);
    }
  }
}

}  // namespace physdbg::viewer
