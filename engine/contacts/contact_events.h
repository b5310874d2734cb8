#pragma once
// Contact begin / stay / end per pair, the design's OnColliderEnter/Exit.
// A pair "touches" on a step when the narrow phase reports it touching or
// penetrating. Events are delivered in pair order, so they are deterministic.
#include <functional>
#include <vector>

#include "engine/broadphase/broad_phase.h"
#include "engine/contacts/contact.h"

namespace physdbg {

class ContactListener {
 public:
  virtual ~ContactListener() = default;
  virtual void onContactBegin(const Contact& contact) = 0;
  virtual void onContactStay(const Contact& contact) = 0;
  virtual void onContactEnd(std::uint32_t a, std::uint32_t b) = 0;
};

// Compares this step's touching pairs (sorted) with the previous step's.
// A pair that stops being reported while at rest (both bodies still, one
// asleep: `atRest`) was touching when it fell asleep: it stays touching
// without events, so sleeping does not end a contact and waking does not
// begin it again. Such dormant pairs are kept apart from the awake ones, so
// a step costs what its awake pairs cost; they are looked at again only when
// `restChanged` says a body woke, left or started moving since the last update.
class ContactEventTracker {
 public:
  using RestTest = std::function<bool(const BodyPair&)>;
  void update(const std::vector<Contact>& contacts, const RestTest& atRest, bool restChanged,
              ContactListener* listener);
  // Every touching pair, awake or dormant, sorted.
  std::vector<BodyPair> touchingPairs() const;
  // A body left the run: its pairs end now, in pair order, dormant or not.
  void endPairsWith(std::uint32_t body, ContactListener* listener);

 private:
  void reviveWoken(const RestTest& atRest);
  std::vector<BodyPair> touching_;  // reported by the last update, sorted
  std::vector<BodyPair> dormant_;   // at rest and not reported since, sorted
};

}  // namespace physdbg
