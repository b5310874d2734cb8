#include <cstdio>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/collision_device.h"
#include "cli/commands.h"
#include "cli/common_options.h"
#include "cli/limits.h"
#include "cli/number_option.h"
#include "cli/numerical_faults.h"
#include "cli/overlapping_pairs.h"
#include "engine/narrowphase/narrow_phase.h"
#include "scenes/scene.h"

namespace physdbg::cli {
namespace {

nlohmann::json vectorJson(const Vec3& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

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

bool takesPart(const World& world, BodyId id) { return world.isPresent(id) && !world.isFrozen(id); }

// Pairs of bodies in the run whose tight boxes come within `separation` of
// each other (each box grown by half of it, and a hair more so rounding loses
// none; the narrow phase's distance decides). A separation that makes more
// box pairs than limits::maxSeparationPairs is refused naming the option.
std::vector<BodyPair> candidatePairs(const World& world, double separation, bool bounded) {
  const double grow = separation > 0.0 ? 0.5 * separation * (1.0 + 1e-9) + 1e-12 : 0.0;
  std::vector<Aabb> boxes;
  boxes.reserve(world.bodyCount());
  for (const RigidBody& body : world.bodies())
    boxes.push_back(body.collider().worldBounds(body.transform()).enlarged(grow));
  const auto most = static_cast<std::size_t>(limits::maxSeparationPairs);
  std::vector<BodyPair> pairs = overlappingPairs(boxes, bounded ? most : std::numeric_limits<std::size_t>::max());
  if (bounded && pairs.size() > most) {
    std::ostringstream message;
    message << "--max-separation: " << separation << " m puts more than " << most
            << " pairs of bodies that close; give a smaller distance";
    throw UsageError(message.str());
  }
  std::erase_if(pairs, [&](const BodyPair& pair) { return !takesPart(world, pair.a) || !takesPart(world, pair.b); });
  return pairs;
}

// Every touching or overlapping pair, and with a separation the pairs apart
// by at most that much (depth minus their distance), in (a, b) order.
nlohmann::json contactsJson(const std::vector<BodyPair>& pairs, const std::vector<ContactResult>& results,
                            double separation) {
  nlohmann::json contacts = nlohmann::json::array();
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const ContactResult& result = results[i];
    const bool apart = result.status == ContactStatus::Separated;
    if (apart && !(result.distance <= separation)) continue;
    contacts.push_back({{"a", pairs[i].a},
                        {"b", pairs[i].b},
                        {"status", contactStatusName(result.status)},
                        {"normal", vectorJson(result.normal)},
                        {"depth", apart ? -result.distance : result.depth},
                        {"point_a", vectorJson(result.pointA)},
                        {"point_b", vectorJson(result.pointB)}});
  }
  return contacts;
}

void printContacts(const nlohmann::json& contacts, const std::string& heading) {
  std::printf("%zu contacts in %s\n", contacts.size(), heading.c_str());
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
}

}  // namespace

// Every touching or overlapping pair of the scene's initial state, or with
// --step of the state after that many steps, static pairs included: this is
// for inspecting a configuration, so nothing is skipped. Pairs come sorted by
// (a, b) from the box tree (overlapping_pairs.h).
int runContacts(const std::vector<std::string>& args) {
  CommandSpec spec{
      "contacts",
      "SCENE [--json] [--step N] [--max-separation D]",
      "Prints every touching or overlapping pair of SCENE's initial state (or, with --step N, of the state "
      "after N steps):\nnormal (from a to b), depth, and the contact point on each body (world frame).",
      {{"--json", "", "", "print a JSON array of {a, b, status, normal, depth, point_a, point_b}"},
       {"--step", "", "N",
        "simulate N steps first (1 to 100000000, as simulate --steps) and list that state's contacts; "
        "exits 1 when a body became NaN or Inf"},
       {"--max-separation", "", "D",
        "also list pairs apart by at most D metres (0 to 1e6), status separated with depth minus "
        "their distance"}},
      1,
      1};
  addOptions(spec, {OptionGroup::Solver, OptionGroup::Threads, OptionGroup::Collision, OptionGroup::Backend});
  const auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const SceneDescription scene = readScene(*parsed);
  const int steps = parsed->has("--step") ? parsed->positiveInt("--step", 1, static_cast<int>(limits::maxSteps)) : 0;
  const double separation = numberOption(*parsed, "--max-separation", 0.0, 0.0, limits::maxSeparation);
  const std::shared_ptr<CollisionOffload> offload = collisionOffloadFor(scene, readBackend(*parsed));
  World world = buildWorld(scene, offload);
  for (int step = 0; step < steps; ++step) world.step();
  const std::vector<BodyPair> pairs = candidatePairs(world, separation, parsed->has("--max-separation"));
  const nlohmann::json contacts =
      contactsJson(pairs, testPairs(world, pairs, scene.world.narrowPhase, offload.get()), separation);
  if (parsed->has("--json"))
    std::cout << contacts.dump(2) << "\n";
  else
    printContacts(contacts, steps > 0 ? scene.name + " after " + std::to_string(steps) + " steps" : scene.name);
  return reportNumericalFaults("contacts", world);
}

}  // namespace physdbg::cli
