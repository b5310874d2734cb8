#include "engine/contacts/contact_events.h"

#include <algorithm>

namespace physdbg {

void ContactEventTracker::update(const std::vector<Contact>& contacts, const std::vector<BodyPair>& dormant,
                                 ContactListener* listener) {
  std::vector<BodyPair> now;
  now.reserve(contacts.size() + dormant.size());
  for (const Contact& contact : contacts) now.push_back({contact.a, contact.b});
  if (listener) {
    std::size_t previous = 0;
    for (const Contact& contact : contacts) {
      const BodyPair pair{contact.a, contact.b};
      while (previous < touching_.size() && touching_[previous] < pair) {
        if (!std::binary_search(dormant.begin(), dormant.end(), touching_[previous]))
          listener->onContactEnd(touching_[previous].a, touching_[previous].b);
        ++previous;
      }
      if (previous < touching_.size() && touching_[previous] == pair) {
        listener->onContactStay(contact);
        ++previous;
      } else {
        listener->onContactBegin(contact);
      }
    }
    for (; previous < touching_.size(); ++previous) {
      if (!std::binary_search(dormant.begin(), dormant.end(), touching_[previous]))
        listener->onContactEnd(touching_[previous].a, touching_[previous].b);
    }
  }
  // A pair can be both dormant and reported (an awake body's contact that is
  // about to wake the sleeper): keep it once.
  const std::size_t reported = now.size();
  now.insert(now.end(), dormant.begin(), dormant.end());
  std::inplace_merge(now.begin(), now.begin() + static_cast<std::ptrdiff_t>(reported), now.end());
  now.erase(std::unique(now.begin(), now.end()), now.end());
  touching_ = std::move(now);
}

void ContactEventTracker::endPairsWith(std::uint32_t body, ContactListener* listener) {
  std::erase_if(touching_, [body, listener](const BodyPair& pair) {
    if (pair.a != body && pair.b != body) return false;
    if (listener) listener->onContactEnd(pair.a, pair.b);
    return true;
  });
}

}  // namespace physdbg
