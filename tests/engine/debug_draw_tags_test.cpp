// Tags on what emitDebugDraw (engine/debug/world_debug_draw.h) emits: a viewer (replay --layers,
// --highlight, --tree-depth) filters recorded frames by them with no engine,
// so every primitive must name its layer, its bodies and its tree node.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>

#include "engine/broadphase/dynamic_aabb_tree.h"
#include "engine/broadphase/tree_debug_draw.h"
#include "engine/colliders/box_collider.h"
#include "engine/debug/world_debug_draw.h"
#include "engine/world.h"
#include "scenes/scene.h"
#include "tests/engine/broadphase/broad_phase_test_helpers.h"

namespace physdbg {
namespace {

namespace dd = debugdraw;

constexpr std::uint32_t bitOf(dd::Layer layer) { return static_cast<std::uint32_t>(layer); }

// The layers the engine draws (overlay and grid are drawn by the command line).
const std::vector<dd::Layer>& engineLayers() {
  static const std::vector<dd::Layer> layers = {
      dd::Layer::Shapes,   dd::Layer::Wire,       dd::Layer::Aabbs, dd::Layer::Fat,   dd::Layer::Tree,
      dd::Layer::Contacts, dd::Layer::Velocities, dd::Layer::Sleep, dd::Layer::Pairs, dd::Layer::Impulses};
  return layers;
}

dd::LayerSet allLayers() {
  dd::LayerSet set;
  for (const auto& [name, layer] : dd::allLayers()) set.add(layer);
  return set;
}

// Calls visit(tag) for every primitive of the frame.
void forEachTag(const dd::Frame& frame, const std::function<void(const dd::Tag&)>& visit) {
  for (const auto& item : frame.boxes) visit(item.tag);
  for (const auto& item : frame.spheres) visit(item.tag);
  for (const auto& item : frame.capsules) visit(item.tag);
  for (const auto& item : frame.meshes) visit(item.tag);
  for (const auto& item : frame.wireBoxes) visit(item.tag);
  for (const auto& item : frame.lines) visit(item.tag);
  for (const auto& item : frame.points) visit(item.tag);
  for (const auto& item : frame.arrows) visit(item.tag);
  for (const auto& item : frame.texts) visit(item.tag);
  for (const auto& item : frame.labels) visit(item.tag);
}

// A scene after `steps` steps, with the history a debugger keeps.
World steppedScene(const std::string& name, int steps) {
  World world = buildWorld(resolveScene(name));
  world.keepContactHistory(true);
  for (int step = 0; step < steps; ++step) world.step();
  return world;
}

dd::Frame drawn(const World& world, dd::LayerSet layers, dd::LayerCounts* counts = nullptr) {
  dd::Frame frame;
  emitDebugDraw(world, layers, frame, counts);
  return frame;
}

// Scenes with boxes, spheres, hulls, a brute-force broad phase and sleeping
// piles, at frame 0 (contacts found without a step) and in motion.
struct Case {
  std::string scene;
  int steps;
};
const std::vector<Case>& cases() {
  static const std::vector<Case> all = {{"default", 0},     {"default", 40}, {"stack", 0},
                                        {"stack", 90},      {"balls24", 30}, {"balls48_bruteforce", 30},
                                        {"mass_stack", 20}, {"bounce", 70}};
  return all;
}

std::string describe(const Case& c) { return c.scene + " after " + std::to_string(c.steps) + " steps"; }

TEST(DebugDrawTags, EveryPrimitiveHasOneRequestedLayerAndTheCountsAgree) {
  dd::LayerCounts overAll;  // so the checks below meet every layer somewhere
  for (const Case& c : cases()) {
    const World world = steppedScene(c.scene, c.steps);
    dd::LayerCounts counts;
    const dd::Frame frame = drawn(world, allLayers(), &counts);
    for (const dd::Layer layer : engineLayers()) overAll.add(layer, counts.of(layer));
    ASSERT_FALSE(frame.empty()) << describe(c);
    std::map<std::uint32_t, std::size_t> tagged;
    forEachTag(frame, [&](const dd::Tag& tag) {
      EXPECT_EQ(std::popcount(tag.layer), 1) << describe(c);
      ++tagged[tag.layer];
      if (tag.body >= 0) {
        EXPECT_LT(static_cast<std::size_t>(tag.body), world.bodyCount()) << describe(c);
      }
      if (tag.otherBody >= 0) {
        EXPECT_LT(static_cast<std::size_t>(tag.otherBody), world.bodyCount()) << describe(c);
      }
    });
    // The sleep layer also counts the darkened shapes it asked for (tagged shapes).
    for (const dd::Layer layer : engineLayers())
      if (layer != dd::Layer::Sleep) {
        EXPECT_EQ(tagged[bitOf(layer)], counts.of(layer)) << describe(c) << " " << bitOf(layer);
      }
  }
  for (const dd::Layer layer : engineLayers()) EXPECT_GT(overAll.of(layer), 0u) << bitOf(layer);
}

TEST(DebugDrawTags, ALayerNotRequestedEmitsNothing) {
  for (const Case& c : cases()) {
    const World world = steppedScene(c.scene, c.steps);
    for (const dd::Layer missing : engineLayers()) {
      dd::LayerSet layers = allLayers();
      layers.bits &= ~bitOf(missing);
      forEachTag(drawn(world, layers),
                 [&](const dd::Tag& tag) { EXPECT_NE(tag.layer, bitOf(missing)) << describe(c); });
      dd::LayerSet only;
      only.add(missing);
      forEachTag(drawn(world, only), [&](const dd::Tag& tag) { EXPECT_EQ(tag.layer, bitOf(missing)) << describe(c); });
    }
  }
}

TEST(DebugDrawTags, BodyPrimitivesSitOnTheirBody) {
  for (const Case& c : cases()) {
    const World world = steppedScene(c.scene, c.steps);
    const dd::Frame frame = drawn(world, allLayers());
    const auto at = [&](const dd::Tag& tag, const Vec3& center) {
      ASSERT_GE(tag.body, 0) << describe(c);
      EXPECT_TRUE(center.isApprox(world.body(tag.body).position(), 1e-9)) << describe(c) << " body " << tag.body;
    };
    for (const auto& box : frame.boxes) at(box.tag, box.center);
    for (const auto& sphere : frame.spheres) at(sphere.tag, sphere.center);
    for (const auto& capsule : frame.capsules) at(capsule.tag, capsule.center);
    for (const auto& mesh : frame.meshes) at(mesh.tag, mesh.center);
    for (const auto& arrow : frame.arrows)
      if (arrow.tag.layer == bitOf(dd::Layer::Velocities)) at(arrow.tag, arrow.from);
    for (const auto& box : frame.wireBoxes) {
      if (box.tag.layer != bitOf(dd::Layer::Aabbs) && box.tag.layer != bitOf(dd::Layer::Fat)) continue;
      const RigidBody& body = world.body(box.tag.body);
      const Aabb bounds = body.collider().worldBounds(body.transform());
      EXPECT_TRUE(bounds.overlaps(Aabb{box.center - box.halfExtents, box.center + box.halfExtents})) << describe(c);
    }
    for (const auto& line : frame.lines)
      if (line.tag.layer == bitOf(dd::Layer::Pairs)) {
        at(line.tag, line.from);
        EXPECT_TRUE(line.to.isApprox(world.body(line.tag.otherBody).position(), 1e-9)) << describe(c);
      }
  }
}

// Contact dots and arrows name a pair the world shows as touching, a < b,
// and each dot is one of that pair's points.
TEST(DebugDrawTags, ContactsNameATouchingPair) {
  for (const Case& c : cases()) {
    const World world = steppedScene(c.scene, c.steps);
    const std::vector<ShownContact> shown = world.shownContacts();
    std::multimap<BodyPair, Vec3> pointsOf;
    for (const ShownContact& point : shown) pointsOf.insert({point.pair, point.point});
    const dd::Frame frame = drawn(world, allLayers());
    const auto touching = [&](const dd::Tag& tag) {
      EXPECT_LT(tag.body, tag.otherBody) << describe(c);
      const BodyPair pair{static_cast<std::uint32_t>(tag.body), static_cast<std::uint32_t>(tag.otherBody)};
      EXPECT_TRUE(pointsOf.count(pair)) << describe(c) << " " << tag.body << "-" << tag.otherBody;
      return pair;
    };
    std::size_t dots = 0;
    for (const auto& point : frame.points) {
      if (point.tag.layer != bitOf(dd::Layer::Contacts)) continue;
      const auto [first, last] = pointsOf.equal_range(touching(point.tag));
      bool found = false;
      for (auto it = first; it != last; ++it) found = found || it->second == point.position;
      EXPECT_TRUE(found) << describe(c);
      ++dots;
    }
    EXPECT_EQ(dots, shown.size()) << describe(c);
    for (const auto& arrow : frame.arrows)
      if (arrow.tag.layer == bitOf(dd::Layer::Contacts) || arrow.tag.layer == bitOf(dd::Layer::Impulses))
        touching(arrow.tag);
  }
}

// Tree nodes drawn with the default options form one tree: a single root at
// depth 0, every other node's parent drawn one level up; each fat box hangs
// from a drawn internal node; legend lines name drawn depths.
void expectTreeTags(const World& world, const dd::Frame& frame, const std::string& what) {
  std::map<int, dd::Tag> nodes;
  for (const auto& box : frame.wireBoxes)
    if (box.tag.layer == bitOf(dd::Layer::Tree)) {
      EXPECT_TRUE(nodes.insert({box.tag.node, box.tag}).second) << what;
    }
  const DynamicAabbTree* tree = world.tree();
  ASSERT_NE(tree, nullptr) << what;
  EXPECT_EQ(static_cast<int>(nodes.size()), tree->nodeCount() - tree->proxyCount()) << what;
  int roots = 0;
  std::set<int> depths;
  for (const auto& [node, tag] : nodes) {
    EXPECT_GE(node, 0) << what;
    depths.insert(tag.depth);
    if (tag.parent < 0) {
      ++roots;
      EXPECT_EQ(tag.depth, 0) << what;
      continue;
    }
    ASSERT_TRUE(nodes.count(tag.parent)) << what << " node " << node;
    EXPECT_EQ(tag.depth, nodes.at(tag.parent).depth + 1) << what << " node " << node;
  }
  EXPECT_EQ(roots, nodes.empty() ? 0 : 1) << what;
  int fatBoxes = 0;
  for (const auto& box : frame.wireBoxes) {
    if (box.tag.layer != bitOf(dd::Layer::Fat)) continue;
    ++fatBoxes;
    EXPECT_EQ(box.tag.parent, tree->parent(box.tag.node)) << what;
    if (box.tag.parent >= 0) {
      EXPECT_TRUE(nodes.count(box.tag.parent)) << what;
    }
  }
  EXPECT_EQ(fatBoxes, tree->proxyCount()) << what;
  for (const auto& text : frame.texts) {
    if (text.tag.layer != bitOf(dd::Layer::Tree)) continue;
    if (text.text == "tree depth")
      EXPECT_EQ(text.tag.depth, -1) << what;
    else
      EXPECT_TRUE(depths.count(text.tag.depth)) << what << ": " << text.text;
  }
}

TEST(DebugDrawTags, TreeNodesFormATreeAndFatBoxesHangFromIt) {
  for (const Case& c : cases()) {
    const World world = steppedScene(c.scene, c.steps);
    if (!world.tree()) continue;  // the brute-force scenes have none
    expectTreeTags(world, drawn(world, allLayers()), describe(c));
  }
}

TEST(DebugDrawTags, DrawTreeTagsLeavesAsFatWithTheirParents) {
  DynamicAabbTree tree;
  for (const Aabb& box : testing::sortedGrid(5)) tree.createProxy(box, 0);
  dd::Frame frame;
  drawTree(tree, {}, frame);
  std::map<int, int> depthOf;
  for (const auto& box : frame.wireBoxes) depthOf[box.tag.node] = box.tag.depth;
  for (const auto& box : frame.wireBoxes) {
    EXPECT_EQ(box.tag.layer, bitOf(tree.isLeaf(box.tag.node) ? dd::Layer::Fat : dd::Layer::Tree));
    EXPECT_EQ(box.tag.parent, tree.parent(box.tag.node));
    if (box.tag.parent >= 0) {
      EXPECT_EQ(box.tag.depth, depthOf.at(box.tag.parent) + 1);
    }
  }
}

TEST(DebugDrawTags, BodyInfoPerBodyMatchesTheFrame) {
  for (const Case& c : cases()) {
    const World world = steppedScene(c.scene, c.steps);
    dd::Frame frame = drawn(world, allLayers());
    emitBodies(world, frame);
    ASSERT_EQ(frame.bodies.size(), world.bodyCount()) << describe(c);
    std::map<int, dd::Tag> fatOf;
    for (const auto& box : frame.wireBoxes)
      if (box.tag.layer == bitOf(dd::Layer::Fat)) fatOf[box.tag.body] = box.tag;
    const std::vector<ShownContact> shown = world.shownContacts();
    int contacts = 0;
    for (std::size_t i = 0; i < frame.bodies.size(); ++i) {
      const dd::BodyInfo& info = frame.bodies[i];
      const RigidBody& body = world.body(static_cast<BodyId>(i));
      EXPECT_EQ(info.index, static_cast<int>(i)) << describe(c);
      EXPECT_TRUE(info.name.empty());
      EXPECT_EQ(info.position, body.position()) << describe(c);
      EXPECT_EQ(info.linearVelocity, body.linearVelocity()) << describe(c);
      EXPECT_EQ(info.isStatic, body.isStatic()) << describe(c);
      EXPECT_EQ(info.asleep, world.isAsleep(static_cast<BodyId>(i))) << describe(c);
      EXPECT_TRUE((info.boundsMin.array() <= info.position.array()).all()) << describe(c);
      EXPECT_TRUE((info.position.array() <= info.boundsMax.array()).all()) << describe(c);
      contacts += info.contacts;
      if (!world.tree()) {
        EXPECT_EQ(info.treeLeaf, -1) << describe(c);
        EXPECT_EQ(info.treeParent, -1) << describe(c);
        continue;
      }
      ASSERT_TRUE(fatOf.count(info.index)) << describe(c);
      EXPECT_EQ(info.treeLeaf, fatOf.at(info.index).node) << describe(c);
      EXPECT_EQ(info.treeParent, fatOf.at(info.index).parent) << describe(c);
    }
    EXPECT_EQ(contacts, 2 * static_cast<int>(shown.size())) << describe(c);
  }
}

TEST(DebugDrawTags, BodyInfoOfANonFiniteBodyKeepsItsIndexAndZeroVectors) {
  World world;
  const auto box = std::make_shared<BoxCollider>(Vec3(0.5, 0.5, 0.5));
  world.addBody({box, Vec3(0, 0, 0)});
  world.addBody({box, Vec3(5, 0, 0)});
  world.body(1).setLinearVelocity(Vec3(std::nan(""), 0, 0));
  dd::Frame frame;
  emitBodies(world, frame);
  ASSERT_EQ(frame.bodies.size(), 2u);
  EXPECT_EQ(frame.bodies[1].index, 1);
  EXPECT_EQ(frame.bodies[1].position, Vec3::Zero());
  EXPECT_EQ(frame.bodies[1].linearVelocity, Vec3::Zero());
  EXPECT_EQ(frame.bodies[1].boundsMax, Vec3::Zero());
  EXPECT_EQ(frame.bodies[0].position, Vec3::Zero());
  EXPECT_EQ(frame.bodies[0].boundsMax, Vec3(0.5, 0.5, 0.5));
}

// A unit box of `mass` kg resting on a static floor.
World restingBox(double mass) {
  World world;
  world.addBody({std::make_shared<BoxCollider>(Vec3(5, 0.5, 5)), Vec3(0, -0.5, 0), Quat::Identity(), Vec3::Zero(),
                 Vec3::Zero(), 1.0, true});
  BodyDefinition box{std::make_shared<BoxCollider>(Vec3(0.5, 0.5, 0.5)), Vec3(0, 0.5, 0)};
  box.mass = mass;
  world.addBody(box);
  world.keepContactHistory(true);
  return world;
}

dd::LayerSet only(dd::Layer layer) {
  dd::LayerSet set;
  set.add(layer);
  return set;
}

// The arrows of a resting box add up to its weight. At rest each substep's
// impulse cancels gravity's m g h, so the force is m g up to what the soft
// contact still corrects and the two velocity iterations leave unconverged.
// The new contact starts at its resting load (resting_load.h), so that is
// 2e-4 of the weight on the first step and less after: 0.5% allows for it.
TEST(DebugDrawTags, ImpulseArrowsOfARestingBoxAddUpToItsWeight) {
  constexpr double mass = 3.0;
  World world = restingBox(mass);
  for (int step = 0; step < 60; ++step) {
    world.clearContactHistory();
    world.step();
  }
  EXPECT_DOUBLE_EQ(impulseScale(world), 1.0 / 20.0);  // 29.4 N over a 1 m box, to 1-2-5: 1 m = 20 N
  dd::LayerCounts counts;
  const dd::Frame frame = drawn(world, only(dd::Layer::Impulses), &counts);
  ASSERT_EQ(frame.arrows.size(), 4u);  // the four corners of the bottom face
  Vec3 total = Vec3::Zero();
  for (const auto& arrow : frame.arrows) {
    EXPECT_EQ(arrow.tag, dd::tagOf(dd::Layer::Impulses, 0, 1));
    total += arrow.to - arrow.from;
  }
  const double weight = mass * 9.81;
  EXPECT_NEAR(total.y() / impulseScale(world), weight, 0.005 * weight);
  EXPECT_NEAR(total.x(), 0.0, 1e-9);
  EXPECT_NEAR(total.z(), 0.0, 1e-9);
  ASSERT_EQ(frame.texts.size(), 1u);
  EXPECT_EQ(frame.texts[0].text, "impulses: 1 m = 20 N");
  EXPECT_EQ(frame.texts[0].tag, dd::tagOf(dd::Layer::Impulses));
  EXPECT_EQ(counts.of(dd::Layer::Impulses), 5u);
}

TEST(DebugDrawTags, ImpulseScaleIsTheSameEveryFrame) {
  World world = buildWorld(resolveScene("default"));
  const double scale = impulseScale(world);
  for (int step = 0; step < 50; ++step) world.step();
  EXPECT_EQ(impulseScale(world), scale);
  const double newtonsPerMetre = 1.0 / scale, decade = std::pow(10.0, std::floor(std::log10(newtonsPerMetre)));
  const double leading = newtonsPerMetre / decade;
  EXPECT_TRUE(std::abs(leading - 1) < 1e-9 || std::abs(leading - 2) < 1e-9 || std::abs(leading - 5) < 1e-9)
      << newtonsPerMetre;
}

TEST(DebugDrawTags, ImpulsesDrawNothingWithoutContacts) {
  World falling;
  falling.addBody({std::make_shared<BoxCollider>(Vec3(0.5, 0.5, 0.5)), Vec3(0, 10, 0)});
  for (int step = 0; step < 10; ++step) falling.step();
  dd::LayerCounts counts;
  EXPECT_TRUE(drawn(falling, only(dd::Layer::Impulses), &counts).empty());
  EXPECT_EQ(counts.of(dd::Layer::Impulses), 0u);
  // Frame 0 has contacts but no solver has pushed yet: nothing to draw.
  EXPECT_TRUE(drawn(restingBox(3.0), only(dd::Layer::Impulses)).empty());
}

}  // namespace
}  // namespace physdbg
