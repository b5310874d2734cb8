#pragma once
// Contact begin / stay / end per pair, the design's OnColliderEnter/Exit.
// A pair "touches" on a step when the narrow phase reports it touching or
// penetrating. Events are delivered in pair order, so they are deterministic.
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
// `dormant` pairs (sorted, both bodies asleep or static) were touching when
// they fell asleep: they stay touching without events, so sleeping does not
// end a contact and waking does not begin it again.
class ContactEventTracker {
 public:
  void update(const std::vector<Contact>& contacts, const std::vector<BodyPair>& dormant, ContactListener* listener);
  const std::vector<BodyPair>& touchingPairs() const { return touching_; }
  // A body left the run: its pairs end now, in pair order, dormant or not.
  void endPairsWith(std::uint32_t body, ContactListener* listener);

 private:
  std::vector<BodyPair> touching_;
};

}  // namespace physdbg
