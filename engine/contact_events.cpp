#include "engine/contact_events.h"

namespace physdbg {

void ContactEventTracker::update(const std::vector<Contact>& contacts, ContactListener* listener) {
  std::vector<BodyPair> now;
  now.reserve(contacts.size());
  for (const Contact& contact : contacts) now.push_back({contact.a, contact.b});
  if (listener) {
    std::size_t previous = 0;
    for (const Contact& contact : contacts) {
      const BodyPair pair{contact.a, contact.b};
      while (previous < touching_.size() && touching_[previous] < pair) {
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
    for (; previous < touching_.size(); ++previous) listener->onContactEnd(touching_[previous].a, touching_[previous].b);
  }
  touching_ = std::move(now);
}

}  // namespace physdbg
