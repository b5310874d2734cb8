#pragma once
// Sleep islands: awake bodies joined by the step's touching contacts, each
// labelled with its lowest id. Static, sleeping and frozen bodies do not
// link, so piles resting on one floor stay apart. An island sleeps as a
// whole once its most recently moving body has been slow for timeToSleep;
// deciding per island, not per contact, keeps the answer independent of
// contact order: a body never sleeps while anything it is linked to, however
// indirectly, still moves. A sleeping body keeps the label it fell asleep
// with, and the members of each sleeping island of several bodies are listed
// under it, so a wake visits its island, not the world.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "engine/contacts/contact.h"
#include "engine/contacts/contact_manifold.h"
#include "engine/dynamics/rigid_body.h"
#include "engine/solver/contact_solver.h"

namespace physdbg {

struct SleepSettings {
  bool allowSleep = true;
  double linearSpeed = 0.05;   // m/s
  double angularSpeed = 0.05;  // rad/s
  double timeToSleep = 0.5;    // s below both speeds before sleeping
};

struct Sleeper {
  std::uint32_t body = 0;
  bool alone = false;  // its island is itself (not listed)
};

class SleepIslands {
 public:
  void reserve(std::size_t count);
  void addBody(std::uint32_t id);  // alone, never slow
  std::uint32_t label(std::uint32_t id) const { return island_.at(id); }
  // Its own island, never slow: a body put to sleep by hand or taken out.
  void makeAlone(std::uint32_t id);
  void resetSlowTime(std::uint32_t id) { slowTime_[id] = 0.0; }

  // Labels the movable bodies by the touching contacts that join them.
  void link(const std::vector<Contact>& contacts, const MovableBodies& movable);
  // Advances the movable bodies' slow times by dt; with sleep allowed, fills
  // `sleepers` (in id order) with those whose island has been slow long
  // enough, each listed under its label unless alone.
  void findSleepers(const std::vector<RigidBody>& bodies, const MovableBodies& movable,
                    const SleepSettings& settings, double dt, std::vector<Sleeper>& sleepers);
  // The listed members of a sleeping island, in id order, taken out of the
  // list (the island wakes); empty for a body asleep alone. Members that
  // woke, left or fell asleep elsewhere since are the caller's to skip.
  std::vector<std::uint32_t> takeIsland(std::uint32_t label);

 private:
  std::vector<double> slowTime_;       // per body: seconds below the sleep speeds
  std::vector<std::uint32_t> island_;  // per body: its island's lowest id
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> sleeping_;  // by label
};

// A sleeping body touched by an awake one wakes before the response, so the
// response sees it as the dynamic body it is: touching now, or reached
// within this step by a speculative contact. This says whether `mover`, one
// body of `manifold`, can close any of its points' gaps this step: its speed
// at the point towards the other body, plus what its forces add in the step,
// over the step, reaches the gap (less the touching gap).
bool closesOnSleeper(const ContactManifold& manifold, const RigidBody& mover, bool moverIsA, double dt,
                     double touchingGap);

}  // namespace physdbg
