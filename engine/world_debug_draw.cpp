// Turns the world's state into debug-draw primitives, one function per layer.
// Only the requested layers are computed.
#include <cmath>

#include <algorithm>

#include "engine/broadphase/dynamic_aabb_tree.h"
#include "engine/broadphase/tree_debug_draw.h"
#include "engine/collider_outline.h"
#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/sphere_collider.h"
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
      if (mesh) frame.meshes.push_back({body.position(), body.orientation(), mesh, color});
      break;
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
    Vec3 middle = Vec3::Zero();
    double deepest = 0.0;
    for (last = first; last < points.size() && points[last].pair == points[first].pair; ++last) {
      const ShownContact& contact = points[last];
      frame.points.push_back({contact.point, 7.0f, dimmedIf(contact.resting, dd::colors::contactPoint)});
      middle += contact.point;
      deepest = std::max(deepest, contact.depth);
    }
    middle /= static_cast<double>(last - first);
    const double length = scale * (0.25 + 4.0 * deepest);
    frame.arrows.push_back({middle, middle + points[first].normal * length,
                            dimmedIf(points[first].resting, dd::colors::contactNormal)});
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
std::vector<Aabb> sleepingIslandBoxes(const std::vector<RigidBody>& bodies, const std::vector<ShownContact>& resting) {
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
  std::vector<Aabb> boxes;
  std::vector<int> slot(bodies.size(), -1);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const std::size_t island = find(i);  // the island's lowest body, met first
    if (size[island] < 2) continue;
    const Aabb box = bodies[i].collider().worldBounds(bodies[i].transform());
    if (slot[island] < 0) {
      slot[island] = static_cast<int>(boxes.size());
      boxes.push_back(box);
    }
    boxes[slot[island]] = boxes[slot[island]].merged(box);
  }
  return boxes;
}

dd::Color boxColor(int contactState) {
  if (contactState == 0) return dd::colors::tightBox;
  return dimmedIf(contactState == 1, dd::colors::colliding);
}

}  // namespace

void World::emitDebugDraw(dd::LayerSet layers, dd::Frame& frame, dd::LayerCounts* counts) const {
  if (layers.empty()) return;
  // Runs one layer's emission; when counting, adds what it put in the frame to that layer.
  const auto counted = [&frame, counts](dd::Layer layer, const auto& emit) {
    const std::size_t before = counts ? frame.primitiveCount() : 0;
    emit();
    if (counts) counts->add(layer, frame.primitiveCount() - before);
  };
  std::vector<std::shared_ptr<const dd::TriangleMesh>> meshes;
  if (layers.has(dd::Layer::Shapes)) meshes = hullMeshes();
  double typicalSize = 0;
  const bool showContacts = layers.has(dd::Layer::Contacts) || layers.has(dd::Layer::Aabbs);
  const std::vector<ShownContact> shown = showContacts ? shownContacts() : std::vector<ShownContact>{};
  const std::vector<int> contactState = contactStates(shown, bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const RigidBody& body = bodies_[i];
    if (!body.hasFiniteState()) continue;
    const Aabb box = body.collider().worldBounds(body.transform());
    if (!body.isStatic()) typicalSize = std::max(typicalSize, box.halfExtents().maxCoeff());
    if (layers.has(dd::Layer::Shapes)) {
      dd::Color color = body.isStatic() ? dd::colors::staticBody : bodyColor(i);
      if (layers.has(dd::Layer::Sleep) && asleep_[i]) {
        color = shade(color, 0.35f);
        if (counts) counts->add(dd::Layer::Sleep, 1);  // the darkened body is what the layer drew
      }
      counted(dd::Layer::Shapes, [&] { emitShape(body, color, meshes[i], frame); });
    }
    if (layers.has(dd::Layer::Wire)) counted(dd::Layer::Wire, [&] { emitWire(body, frame); });
    if (layers.has(dd::Layer::Aabbs))
      counted(dd::Layer::Aabbs, [&] {
        frame.wireBoxes.push_back({box.center(), Quat::Identity(), box.halfExtents(), boxColor(contactState[i])});
      });
    if (layers.has(dd::Layer::Fat) && proxies_[i] >= 0)
      counted(dd::Layer::Fat, [&] {
        const Aabb& fat = broadPhase_->fatBox(proxies_[i]);
        frame.wireBoxes.push_back({fat.center(), Quat::Identity(), fat.halfExtents(), dd::colors::fatLayer});
      });
    if (layers.has(dd::Layer::Velocities) && !body.isStatic() && body.linearVelocity() != Vec3::Zero())
      counted(dd::Layer::Velocities, [&] {
        frame.arrows.push_back({body.position(), body.position() + body.linearVelocity() * 0.1, {0.3f, 0.9f, 1.0f, 1}});
      });
    if (layers.has(dd::Layer::Sleep) && !layers.has(dd::Layer::Shapes) && asleep_[i])
      counted(dd::Layer::Sleep, [&] {
        frame.wireBoxes.push_back({box.center(), Quat::Identity(), box.halfExtents(), {0.5f, 0.3f, 0.7f, 1}});
      });
  }
  if (layers.has(dd::Layer::Sleep))
    counted(dd::Layer::Sleep, [&] {
      for (const Aabb& island : sleepingIslandBoxes(bodies_, resting_))
        frame.wireBoxes.push_back({island.center(), Quat::Identity(), island.halfExtents() + Vec3::Constant(0.05),
                                   sleepingIsland});
    });
  if (layers.has(dd::Layer::Tree))
    counted(dd::Layer::Tree, [&] {
      TreeDrawOptions options;
      options.leaves = false;  // the fat boxes are the `fat` layer
      if (const DynamicAabbTree* broadPhaseTree = tree()) drawTree(*broadPhaseTree, options, frame);
    });
  if (layers.has(dd::Layer::Contacts))
    counted(dd::Layer::Contacts, [&] {
      emitShownContacts(shown, std::max(typicalSize, 0.2), frame);
    });
  if (layers.has(dd::Layer::Pairs))
    counted(dd::Layer::Pairs, [&] {
      for (const BodyPair& pair : pairs_)
        frame.lines.push_back({bodies_[pair.a].position(), bodies_[pair.b].position(), {0.9f, 0.5f, 0.9f, 1}});
    });
}

// One drawing mesh per convex collider, shared by the bodies that share it;
// ids follow body order so they are the same run after run.
std::vector<std::shared_ptr<const dd::TriangleMesh>> World::hullMeshes() const {
  std::vector<std::shared_ptr<const dd::TriangleMesh>> meshes(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const Collider* collider = &bodies_[i].collider();
    if (collider->kind() != ColliderKind::ConvexMesh) continue;
    for (std::size_t j = 0; j < i && !meshes[i]; ++j) {
      if (&bodies_[j].collider() == collider) meshes[i] = meshes[j];
    }
    if (!meshes[i]) meshes[i] = hullMesh(static_cast<const ConvexMeshCollider&>(*collider), i + 1);
  }
  return meshes;
}

}  // namespace physdbg
