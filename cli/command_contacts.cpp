#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/arguments.h"
#include "cli/collision_device.h"
#include "cli/commands.h"
#include "cli/common_options.h"
#include "cli/overlapping_pairs.h"
#include "engine/narrowphase/narrow_phase.h"
#include "scenes/scene.h"

namespace physdbg::cli {
namespace {

nlohmann::json vectorJson(const Vec3& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

}  // namespace

namespace {

// The narrow phase on each pair: the offload's device for the shapes it
// handles (one batch), the CPU for the rest.
std::vector<ContactResult> testPairs(const World& world, const std::vector<BodyPair>& pairs,
                                     const NarrowPhaseOptions& options, CollisionOffload* offload) {
  std::vector<ContactResult> results(pairs.size());
  std::vector<OffloadRequest> requests;
  std::vector<std::size_t> offloaded;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const RigidBody &a = world.body(pairs[i].a), &b = world.body(pairs[i].b);
    if (offload != nullptr && offload->handles(a.collider().kind(), b.collider().kind())) {
      requests.push_back({pairs[i].a, pairs[i].b, 0.0});
      offloaded.push_back(i);
      continue;
    }
    results[i] = collide(a.collider(), a.transform(), b.collider(), b.transform(), options);
  }
  if (requests.empty()) return results;
  std::vector<OffloadedContact> answers;
  offload->collide(world.bodies(), requests, answers);
  for (std::size_t k = 0; k < offloaded.size(); ++k) results[offloaded[k]] = answers[k].result;
  return results;
}

}  // namespace

// Every touching or overlapping pair of the scene's initial state, static
// pairs included: this is for inspecting a configuration, so nothing is
// skipped. Pairs come sorted by (a, b) from the box tree (overlapping_pairs.h).
int runContacts(const std::vector<std::string>& args) {
  CommandSpec spec{"contacts",
                         "SCENE [--json]",
                         "Prints every touching or overlapping pair of SCENE's initial state: normal (from a to b), "
                         "depth,\nand the contact point on each body (world frame).",
                         {{"--json", "", "", "print a JSON array of {a, b, status, normal, depth, point_a, point_b}"}},
                         1,
                         1};
  addOptions(spec, {OptionGroup::Threads, OptionGroup::Collision, OptionGroup::Backend});
  const auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const SceneDescription scene = readScene(*parsed);
  const std::shared_ptr<CollisionOffload> offload = collisionOffloadFor(scene, readBackend(*parsed));
  const World world = buildWorld(scene, offload);
  std::vector<Aabb> boxes;
  boxes.reserve(world.bodyCount());
  for (const RigidBody& body : world.bodies()) boxes.push_back(body.collider().worldBounds(body.transform()));
  const std::vector<BodyPair> pairs = overlappingPairs(boxes);
  const std::vector<ContactResult> results = testPairs(world, pairs, scene.world.narrowPhase, offload.get());
  nlohmann::json contacts = nlohmann::json::array();
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const BodyPair& pair = pairs[i];
    const ContactResult& result = results[i];
    if (result.status == ContactStatus::Separated) continue;
    contacts.push_back({{"a", pair.a},
                        {"b", pair.b},
                        {"status", contactStatusName(result.status)},
                        {"normal", vectorJson(result.normal)},
                        {"depth", result.depth},
                        {"point_a", vectorJson(result.pointA)},
                        {"point_b", vectorJson(result.pointB)}});
  }
  if (parsed->has("--json")) {
    std::cout << contacts.dump(2) << "\n";
    return 0;
  }
  std::printf("%zu contacts in %s\n", contacts.size(), scene.name.c_str());
  for (const auto& contact : contacts) {
    const auto& n = contact["normal"];
    const auto& pa = contact["point_a"];
    const auto& pb = contact["point_b"];
    std::printf("%4d %4d  %-11s depth %.9g  normal (%.6g, %.6g, %.6g)  a (%.6g, %.6g, %.6g)  b (%.6g, %.6g, %.6g)\n",
                contact["a"].get<int>(), contact["b"].get<int>(), contact["status"].get<std::string>().c_str(),
                contact["depth"].get<double>(), n[0].get<double>(), n[1].get<double>(), n[2].get<double>(),
                pa[0].get<double>(), pa[1].get<double>(), pa[2].get<double>(), pb[0].get<double>(),
                pb[1].get<double>(), pb[2].get<double>());
  }
  return 0;
}

}  // namespace physdbg::cli
