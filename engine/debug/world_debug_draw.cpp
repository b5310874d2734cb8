#include "engine/debug/world_debug_draw.h"

#include <cmath>
#include <cstdio>

#include <algorithm>
#include <array>
#include <string>

#include "engine/broadphase/dynamic_aabb_tree.h"
#include "engine/broadphase/tree_debug_draw.h"
#include "engine/collider_outline.h"
#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/heightfield_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/colliders/triangle_mesh_collider.h"
#include "engine/colliders/triangle_source.h"
#include "engine/world.h"

namespace physdbg {
namespace {

namespace dd = debugdraw;

// Distinct, deterministic body colours: hues spaced by the golden angle.
dd::Color bodyColor(std::size_t index) {
  const double hue = std::fmod(0.08 + 0.618033988749895 * static_cast<double>(index), 1.0) * 6.0;
  const double saturation = 0.55, value = 0.92;
  const int sector = static_cast<int>(hue) % 6;
  const double fraction = hue - std::floor(hue);
  const double p = value * (1 - saturation), q = value * (1 - saturation * fraction),
               t = value * (1 - saturation * (1 - fraction));
  double r = value, g = t, b = p;
  switch (sector) {
    case 1: r = q; g = value; b = p; break;
    case 2: r = p; g = value; b = t; break;
    case 3: r = p; g = q; b = value; break;
    case 4: r = t; g = p; b = value; break;
    case 5: r = value; g = p; b = q; break;
    default: break;
  }
  return {static_cast<float>(r), static_cast<float>(g), static_cast<float>(b), 1.0f};
}

std::shared_ptr<const dd::TriangleMesh> hullMesh(const ConvexMeshCollider& hull, std::uint64_t id) {
  auto mesh = std::make_shared<dd::TriangleMesh>();
  mesh->id = id;
  for (const Vec3& vertex : hull.hullVertices()) mesh->vertices.push_back(vertex.cast<float>());
  for (const auto& triangle : hull.hullTriangles())
    for (int corner : triangle) mesh->indices.push_back(static_cast<std::uint32_t>(corner));
  return mesh;
}

std::shared_ptr<const dd::TriangleMesh> levelMesh(const std::vector<Vec3>& vertices,
                                                  const std::vector<MeshTriangle>& triangles, std::uint64_t id) {
  auto mesh = std::make_shared<dd::TriangleMesh>();
  mesh->id = id;
  mesh->vertices.reserve(vertices.size());
  for (const Vec3& vertex : vertices) mesh->vertices.push_back(vertex.cast<float>());
  mesh->indices.reserve(3 * triangles.size());
  for (const MeshTriangle& triangle : triangles)
    for (const std::uint32_t corner : triangle) mesh->indices.push_back(corner);
  return mesh;
}

// Level geometry as a drawing mesh; a big heightfield sampled
// (heightfieldDrawnCells, collider_outline.h).
std::shared_ptr<const dd::TriangleMesh> levelMesh(const Collider& level, std::uint64_t id) {
  if (level.kind() == ColliderKind::TriangleMesh) {
    const auto& mesh = static_cast<const TriangleMeshCollider&>(level);
    return levelMesh(mesh.vertices(), mesh.triangles(), id);
  }
  std::vector<Vec3> vertices;
  std::vector<MeshTriangle> triangles;
  static_cast<const HeightfieldCollider&>(level).sampledGrid(heightfieldDrawnCells, vertices, triangles);
  return levelMesh(vertices, triangles, id);
}

void emitShape(const RigidBody& body, dd::Color color, const std::shared_ptr<const dd::TriangleMesh>& mesh,
               dd::Frame& frame) {
  const Collider& collider = body.collider();
  switch (collider.kind()) {
    case ColliderKind::Sphere:
      frame.spheres.push_back({body.position(), body.orientation(),
                               static_cast<const SphereCollider&>(collider).radius(), color});
      break;
    case ColliderKind::Box:
      frame.boxes.push_back({body.position(), body.orientation(),
                             static_cast<const BoxCollider&>(collider).halfExtents(), color});
      break;
    case ColliderKind::Capsule: {
      const auto& capsule = static_cast<const CapsuleCollider&>(collider);
      frame.capsules.push_back({body.position(), body.orientation(), capsule.radius(), capsule.halfHeight(), color});
      break;
    }
    case ColliderKind::ConvexMesh:
    case ColliderKind::TriangleMesh:
    case ColliderKind::Heightfield:
      if (mesh) frame.meshes.push_back({body.position(), body.orientation(), mesh, color});
      break;
    case ColliderKind::Triangle: break;  // made only inside the narrow phase
  }
}

// The collider's true outline (engine/collider_outline.h), near white.
void emitWire(const RigidBody& body, dd::Frame& frame) {
  emitOutline(body.collider(), body.transform(), {0.95f, 0.95f, 0.95f, 1.0f}, frame);
}

dd::Color shade(dd::Color color, float factor) {
  return {color.r * factor, color.g * factor, color.b * factor, color.a};
}

// The sleep layer's outline of a whole sleeping island: the darkened purple
// of a sleeping body's box, so the pile reads as one.
constexpr dd::Color sleepingIsland{0.4f, 0.25f, 0.6f, 1.0f};

// Contacts of sleeping bodies: still there, but nothing happens at them.
dd::Color dimmedIf(bool resting, dd::Color color) { return resting ? shade(color, 0.5f) : color; }

// A dot for every point that touched since the last frame, and one normal
// arrow per pair from the middle of its points, growing with the deepest one:
// a manifold's points share the normal, and four parallel arrows per face
// would only clutter the picture. Points sleeping bodies rest on are dimmed.
void emitShownContacts(const std::vector<ShownContact>& points, double scale, dd::Frame& frame) {
  for (std::size_t first = 0, last = 0; first < points.size(); first = last) {
    const dd::Tag tag = dd::tagOf(dd::Layer::Contacts, static_cast<int>(points[first].pair.a),
                                  static_cast<int>(points[first].pair.b));
    Vec3 middle = Vec3::Zero();
    double deepest = 0.0;
    for (last = first; last < points.size() && points[last].pair == points[first].pair; ++last) {
      const ShownContact& contact = points[last];
      frame.points.push_back({contact.point, 7.0f, dimmedIf(contact.resting, dd::colors::contactPoint), tag});
      middle += contact.point;
      deepest = std::max(deepest, contact.depth);
    }
    middle /= static_cast<double>(last - first);
    const double length = scale * (0.25 + 4.0 * deepest);
    frame.arrows.push_back({middle, middle + points[first].normal * length,
                            dimmedIf(points[first].resting, dd::colors::contactNormal), tag});
  }
}

// Each overlap of a sensor this step, as a cyan dot between the two
// surfaces: a sensor has no manifold (it pushes nothing), so the dots of
// emitShownContacts never show it.
template <typename Emit>
void emitSensorOverlaps(const World& world, const Emit& emit, dd::Frame& frame) {
  for (const Contact& contact : world.contacts()) {
    if (!world.bodies()[contact.a].isSensor() && !world.bodies()[contact.b].isSensor()) continue;
    emit(dd::tagOf(dd::Layer::Contacts, static_cast<int>(contact.a), static_cast<int>(contact.b)), [&] {
      const Vec3 middle = 0.5 * (contact.result.pointA + contact.result.pointB);
      frame.points.push_back({middle, 9.0f, dd::colors::sensorOverlap, {}});
    });
  }
}

// The mesh layer: each triangle of level geometry the narrow phase tested
// this step outlined in orange, and where a contact on it took the face
// normal instead of an inactive edge's (triangle_mesh_collider.h), that edge
// in magenta, or a magenta dot on the corner (or the face's middle).
template <typename Emit>
void emitMeshTests(const World& world, const Emit& emit, dd::Frame& frame) {
  for (const ContactPass::MeshTest& test : world.meshTests()) {
    const RigidBody& mesh = world.bodies()[test.mesh];
    const TriangleSource* source = triangleSourceOf(mesh.collider());
    if (source == nullptr) continue;
    const SourceTriangle triangle = source->triangleAt(test.test.triangle);
    std::array<Vec3, 3> corners;
    for (int c = 0; c < 3; ++c) corners[c] = mesh.transform().apply(triangle.corners[c]);
    emit(dd::tagOf(dd::Layer::Mesh, static_cast<int>(test.mesh), static_cast<int>(test.other)), [&] {
      for (int e = 0; e < 3; ++e) frame.lines.push_back({corners[e], corners[(e + 1) % 3], dd::colors::testedTriangle, {}});
      const int feature = static_cast<int>(test.test.corrected);
      if (feature >= 0 && feature < 3)
        frame.lines.push_back({corners[feature], corners[(feature + 1) % 3], dd::colors::correctedEdge, {}});
      else if (feature >= 3 && feature < 6)
        frame.points.push_back({corners[feature - 3], 8.0f, dd::colors::correctedEdge, {}});
      else if (feature == 6)
        frame.points.push_back({(corners[0] + corners[1] + corners[2]) / 3.0, 8.0f, dd::colors::correctedEdge, {}});
    });
  }
}

// The tree layer also draws each triangle mesh's own hierarchy, in the
// tree's blues by depth and tagged with its depth and body, so --tree-depth
// and highlighting pick its levels as they pick the broad phase's. (The
// legend counts the broad phase's nodes only.)
void emitMeshHierarchies(const World& world, dd::Frame& frame) {
  const std::vector<RigidBody>& bodies = world.bodies();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!world.isPresent(i) || bodies[i].collider().kind() != ColliderKind::TriangleMesh) continue;
    const RigidBody& body = bodies[i];
    const TriangleBvh& bvh = static_cast<const TriangleMeshCollider&>(body.collider()).bvh();
    if (bvh.nodes().empty()) continue;
    std::vector<std::pair<std::uint32_t, int>> stack{{0u, 0}};
    while (!stack.empty()) {
      const auto [index, depth] = stack.back();
      stack.pop_back();
      const TriangleBvh::Node& node = bvh.nodes()[index];
      dd::Tag tag = dd::tagOf(dd::Layer::Tree, static_cast<int>(i));
      tag.depth = depth;
      frame.wireBoxes.push_back({body.transform().apply(node.bounds.center()), body.orientation(),
                                 node.bounds.halfExtents(), treeNodeColor(depth), tag});
      if (node.isLeaf()) continue;
      stack.push_back({node.first + 1, depth + 1});
      stack.push_back({node.first, depth + 1});
    }
  }
}

// Per body: 0 no contact since the last frame, 1 only contacts it rests on
// asleep, 2 a contact while awake. The aabbs layer colours boxes by it.
std::vector<int> contactStates(const std::vector<ShownContact>& points, std::size_t bodyCount) {
  std::vector<int> states(bodyCount, 0);
  for (const ShownContact& contact : points) {
    const int state = contact.resting ? 1 : 2;
    states[contact.pair.a] = std::max(states[contact.pair.a], state);
    states[contact.pair.b] = std::max(states[contact.pair.b], state);
  }
  return states;
}

// Sleeping bodies linked by the contacts they rest on fall asleep and wake
// together: one island. Static bodies link nothing (a floor would join every
// pile). Islands of two or more bodies, in order of their lowest body.
std::vector<Aabb> sleepingIslandBoxes(const std::vector<RigidBody>& bodies,
                                           const std::vector<ShownContact>& resting) {
  std::vector<std::size_t> root(bodies.size());
  for (std::size_t i = 0; i < root.size(); ++i) root[i] = i;
  const auto find = [&root](std::size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  for (const ShownContact& contact : resting) {
    if (bodies[contact.pair.a].isStatic() || bodies[contact.pair.b].isStatic()) continue;
    const std::size_t a = find(contact.pair.a), b = find(contact.pair.b);
    root[std::max(a, b)] = std::min(a, b);
  }
  std::vector<int> size(bodies.size(), 0);
  for (std::size_t i = 0; i < bodies.size(); ++i) ++size[find(i)];
  std::vector<Aabb> islands;
  std::vector<int> slot(bodies.size(), -1);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const std::size_t island = find(i);  // the island's lowest body, met first
    if (size[island] < 2) continue;
    const Aabb box = bodies[i].collider().worldBounds(bodies[i].transform());
    if (slot[island] < 0) {
      slot[island] = static_cast<int>(islands.size());
      islands.push_back(box);
    }
    islands[slot[island]] = islands[slot[island]].merged(box);
  }
  return islands;
}

dd::Color boxColor(int contactState) {
  if (contactState == 0) return dd::colors::tightBox;
  return dimmedIf(contactState == 1, dd::colors::colliding);
}

// The parent of a body's tree leaf: -1 without a tree, without a leaf (a
// frozen body) or when the leaf is the root.
int leafParent(const DynamicAabbTree* tree, int proxy) { return tree && proxy >= 0 ? tree->parent(proxy) : -1; }

// The fat box is a tree leaf: tagged with it and its parent, so a viewer can
// walk from a body to the root.
dd::Tag fatTag(std::size_t body, const DynamicAabbTree* tree, int proxy) {
  dd::Tag tag = dd::tagOf(dd::Layer::Fat, static_cast<int>(body));
  if (tree) {
    tag.node = proxy;
    tag.parent = leafParent(tree, proxy);
  }
  return tag;
}

// Magenta-red: apart from the orange normals, the cyan velocities and the
// pale violet pairs.
constexpr dd::Color impulseColor{1.0f, 0.2f, 0.6f, 1.0f};

// The nearest value of 1, 2, 5 times a power of ten (nearest on a log scale).
double roundToOneTwoFive(double value) {
  const double decade = std::pow(10.0, std::floor(std::log10(value)));
  double best = decade;
  for (const double step : {2.0, 5.0, 10.0})
    if (std::abs(std::log(step * decade / value)) < std::abs(std::log(best / value))) best = step * decade;
  return best;
}

// "200", "0.5": newtons as the legend writes them.
std::string newtonsText(double newtons) {
  char text[32];
  std::snprintf(text, sizeof text, newtons >= 1 ? "%.0f" : "%g", newtons);
  return text;
}

// One arrow per point that pushed: from the point along the normal (the force
// on b), force = impulse / dt times metresPerNewton long, and a legend that
// reads the scale. The impulse is the step's total at the point, so the
// force is the step's mean whatever substeps the solver took there.
void emitImpulses(const std::vector<ShownContact>& points, double dt, double metresPerNewton, dd::Frame& frame) {
  bool drawn = false;
  for (const ShownContact& contact : points) {
    if (!(contact.impulse > 0.0)) continue;
    const Vec3 arrow = contact.normal * (contact.impulse / dt * metresPerNewton);
    frame.arrows.push_back({contact.point, contact.point + arrow, dimmedIf(contact.resting, impulseColor),
                            dd::tagOf(dd::Layer::Impulses, static_cast<int>(contact.pair.a),
                                      static_cast<int>(contact.pair.b))});
    drawn = true;
  }
  if (!drawn) return;
  // Left, under the tree legend's reach: the same place whatever the tree draws.
  frame.texts.push_back({6, treeLegendBottom() + 6, 1, "impulses: 1 m = " + newtonsText(1.0 / metresPerNewton) + " N",
                         impulseColor, dd::tagOf(dd::Layer::Impulses)});
}

// Contact points shown per body, as a or b.
std::vector<int> shownContactCounts(const std::vector<ShownContact>& points, std::size_t bodyCount) {
  std::vector<int> counts(bodyCount, 0);
  for (const ShownContact& contact : points) {
    ++counts[contact.pair.a];
    ++counts[contact.pair.b];
  }
  return counts;
}

// One drawing mesh per convex or triangle-mesh collider, shared by the
// bodies that share it; ids follow body order so they are the same run
// after run.
std::vector<std::shared_ptr<const dd::TriangleMesh>> hullMeshes(const std::vector<RigidBody>& bodies) {
  std::vector<std::shared_ptr<const dd::TriangleMesh>> meshes(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const Collider* collider = &bodies[i].collider();
    const ColliderKind kind = collider->kind();
    if (kind != ColliderKind::ConvexMesh && kind != ColliderKind::TriangleMesh && kind != ColliderKind::Heightfield)
      continue;
    for (std::size_t j = 0; j < i && !meshes[i]; ++j) {
      if (&bodies[j].collider() == collider) meshes[i] = meshes[j];
    }
    if (meshes[i]) continue;
    meshes[i] = kind == ColliderKind::ConvexMesh ? hullMesh(static_cast<const ConvexMeshCollider&>(*collider), i + 1)
                                                 : levelMesh(*collider, i + 1);
  }
  return meshes;
}

}  // namespace

void emitDebugDraw(const World& world, dd::LayerSet layers, dd::Frame& frame, dd::LayerCounts* counts) {
  const std::vector<RigidBody>& bodies = world.bodies();
  if (layers.empty()) return;
  // Runs one emission, gives what it appended the fields of `tag` it did not
  // set itself (the layer always) and, when counting, counts it for the layer.
  const auto emit = [&frame, counts](const dd::Tag& tag, const auto& draw) {
    const dd::FrameMark mark = dd::markOf(frame);
    const std::size_t before = frame.primitiveCount();
    draw();
    dd::fillTagsSince(frame, mark, tag);
    if (counts) counts->add(static_cast<dd::Layer>(tag.layer), frame.primitiveCount() - before);
  };
  std::vector<std::shared_ptr<const dd::TriangleMesh>> meshes;
  if (layers.has(dd::Layer::Shapes)) meshes = hullMeshes(bodies);
  double typicalSize = 0;
  const bool showContacts =
      layers.has(dd::Layer::Contacts) || layers.has(dd::Layer::Aabbs) || layers.has(dd::Layer::Impulses);
  const std::vector<ShownContact> shown = showContacts ? world.shownContacts() : std::vector<ShownContact>{};
  const std::vector<int> contactState = contactStates(shown, bodies.size());
  const DynamicAabbTree* broadPhaseTree = world.tree();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const RigidBody& body = bodies[i];
    if (!body.hasFiniteState() || !world.isPresent(i)) continue;
    const Aabb box = body.collider().worldBounds(body.transform());
    if (!body.isStatic()) typicalSize = std::max(typicalSize, box.halfExtents().maxCoeff());
    const auto tagOfBody = [i](dd::Layer layer) { return dd::tagOf(layer, static_cast<int>(i)); };
    if (layers.has(dd::Layer::Shapes)) {
      dd::Color color = body.isStatic() ? dd::colors::staticBody : bodyColor(i);
      if (body.isSensor()) color.a = dd::colors::sensorAlpha;
      emit(tagOfBody(dd::Layer::Shapes), [&] { emitShape(body, color, meshes[i], frame); });
    }
    if (layers.has(dd::Layer::Wire)) emit(tagOfBody(dd::Layer::Wire), [&] { emitWire(body, frame); });
    if (layers.has(dd::Layer::Aabbs))
      emit(tagOfBody(dd::Layer::Aabbs), [&] {
        frame.wireBoxes.push_back({box.center(), Quat::Identity(), box.halfExtents(), boxColor(contactState[i])});
      });
    if (layers.has(dd::Layer::Fat) && world.proxyOf(i) >= 0)
      emit(fatTag(i, broadPhaseTree, world.proxyOf(i)), [&] {
        const Aabb& fat = world.fatBox(i);
        frame.wireBoxes.push_back({fat.center(), Quat::Identity(), fat.halfExtents(), dd::colors::fatLayer});
      });
    if (layers.has(dd::Layer::Velocities) && !body.isStatic() && body.linearVelocity() != Vec3::Zero())
      emit(tagOfBody(dd::Layer::Velocities), [&] {
        frame.arrows.push_back({body.position(), body.position() + body.linearVelocity() * 0.1, {0.3f, 0.9f, 1.0f, 1}});
      });
    // Each layer's primitives do not depend on the others requested, so a
    // recording of every layer replays any choice of them: the viewer darkens
    // the solids of sleeping bodies instead of these outlines when shapes show
    // (debugdraw/frame_view.cpp).
    if (layers.has(dd::Layer::Sleep) && world.isAsleep(i))
      emit(tagOfBody(dd::Layer::Sleep), [&] {
        frame.wireBoxes.push_back({box.center(), Quat::Identity(), box.halfExtents(), {0.5f, 0.3f, 0.7f, 1}});
      });
  }
  if (layers.has(dd::Layer::Sleep))
    for (const Aabb& island : sleepingIslandBoxes(bodies, world.restingContacts()))
      emit(dd::tagOf(dd::Layer::Sleep), [&] {  // a whole island, no one body
        frame.wireBoxes.push_back({island.center(), Quat::Identity(), island.halfExtents() + Vec3::Constant(0.05),
                                   sleepingIsland});
      });
  if (layers.has(dd::Layer::Tree) && broadPhaseTree)
    emit(dd::tagOf(dd::Layer::Tree), [&] {
      TreeDrawOptions options;
      options.leaves = false;  // the fat boxes are the `fat` layer
      drawTree(*broadPhaseTree, options, frame);
    });
  if (layers.has(dd::Layer::Tree)) emit(dd::tagOf(dd::Layer::Tree), [&] { emitMeshHierarchies(world, frame); });
  if (layers.has(dd::Layer::Contacts)) {
    emit(dd::tagOf(dd::Layer::Contacts), [&] { emitShownContacts(shown, std::max(typicalSize, 0.2), frame); });
    emitSensorOverlaps(world, emit, frame);
  }
  if (layers.has(dd::Layer::Mesh)) emitMeshTests(world, emit, frame);
  if (layers.has(dd::Layer::Impulses))
    emit(dd::tagOf(dd::Layer::Impulses), [&] { emitImpulses(shown, world.settings().dt, impulseScale(world), frame); });
  if (layers.has(dd::Layer::Pairs))
    emit(dd::tagOf(dd::Layer::Pairs), [&] {
      for (const BodyPair& pair : world.candidatePairs()) {
        // Found before a removal, or before a body was frozen (its position may be NaN).
        if (!world.isPresent(pair.a) || !world.isPresent(pair.b) || world.isFrozen(pair.a) || world.isFrozen(pair.b)) continue;
        frame.lines.push_back({bodies[pair.a].position(), bodies[pair.b].position(), {0.9f, 0.5f, 0.9f, 1},
                               dd::tagOf(dd::Layer::Pairs, static_cast<int>(pair.a), static_cast<int>(pair.b))});
      }
    });
}

// The heaviest dynamic body's weight drawn about as long as that body is big,
// rounded so the legend reads "1 m = 200 N". From masses and shapes only, so
// the scale stays the same from frame to frame and arrows compare.
double impulseScale(const World& world) {
  const RigidBody* heaviest = nullptr;
  for (const RigidBody& body : world.bodies())
    if (!body.isStatic() && (!heaviest || body.mass() > heaviest->mass())) heaviest = &body;
  const double gravity = world.settings().gravity.norm() > 0.0 ? world.settings().gravity.norm() : 9.81;
  double weight = gravity, size = 1.0;  // 1 kg, 1 m without a dynamic body
  if (heaviest) {
    const Aabb local = heaviest->collider().localBounds();
    weight = heaviest->mass() * gravity;
    size = (local.max - local.min).maxCoeff();
  }
  if (!(weight > 0.0 && size > 0.0 && std::isfinite(weight / size))) return 0.1;
  return 1.0 / roundToOneTwoFive(weight / size);
}

// State, not drawing: what a viewer needs to label, follow and highlight a
// body without the engine. A body whose state stopped being finite keeps its
// index and flags, and zero vectors (a recording holds no NaN). A removed
// body is listed too, marked absent, so indices mean the same in every frame.
void emitBodies(const World& world, dd::Frame& frame) {
  const std::vector<RigidBody>& bodies = world.bodies();
  const std::vector<int> contactCounts = shownContactCounts(world.shownContacts(), bodies.size());
  const DynamicAabbTree* broadPhaseTree = world.tree();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const RigidBody& body = bodies[i];
    dd::BodyInfo& info = frame.bodies.emplace_back();
    info.index = static_cast<std::int32_t>(i);
    info.contacts = contactCounts[i];
    info.treeLeaf = broadPhaseTree ? world.proxyOf(i) : -1;
    info.treeParent = leafParent(broadPhaseTree, world.proxyOf(i));
    info.isStatic = body.isStatic();
    info.asleep = world.isAsleep(i);
    info.absent = !world.isPresent(i);
    if (!body.hasFiniteState()) continue;
    const Aabb bounds = body.collider().worldBounds(body.transform());
    info.position = body.position();
    info.linearVelocity = body.linearVelocity();
    info.angularVelocity = body.angularVelocity();
    info.boundsMin = bounds.min;
    info.boundsMax = bounds.max;
  }
}

}  // namespace physdbg
