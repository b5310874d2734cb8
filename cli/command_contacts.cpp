#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/common_options.h"
#include "cli/overlapping_pairs.h"
#include "engine/narrowphase/narrow_phase.h"
#include "scenes/scene.h"

namespace physdbg::cli {
namespace {

nlohmann::json vectorJson(const Vec3& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

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
  addOptions(spec, {OptionGroup::Threads});
  const auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const SceneDescription scene = readScene(*parsed);
  const World world = buildWorld(scene);
  std::vector<Aabb> boxes;
  boxes.reserve(world.bodyCount());
  for (const RigidBody& body : world.bodies()) boxes.push_back(body.collider().worldBounds(body.transform()));
  nlohmann::json contacts = nlohmann::json::array();
  for (const BodyPair& pair : overlappingPairs(boxes)) {
    const RigidBody &bodyA = world.body(pair.a), &bodyB = world.body(pair.b);
    const ContactResult result =
        collide(bodyA.collider(), bodyA.transform(), bodyB.collider(), bodyB.transform(), scene.world.narrowPhase);
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
