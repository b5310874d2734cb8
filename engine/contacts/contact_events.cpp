#include "engine/contacts/contact_events.h"

#include <algorithm>

namespace physdbg {
namespace {

std::vector<BodyPair> mergedPairs(const std::vector<BodyPair>& x, const std::vector<BodyPair>& y) {
  std::vector<BodyPair> merged;
  merged.reserve(x.size() + y.size());
  std::merge(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(merged));
  return merged;
}

}  // namespace

// Dormant pairs no longer at rest are touching pairs again: not reported
// this step, they end.
void ContactEventTracker::reviveWoken(const RestTest& atRest) {
  std::vector<BodyPair> woken;
  std::erase_if(dormant_, [&](const BodyPair& pair) {
    if (atRest(pair)) return false;
    woken.push_back(pair);
    return true;
  });
  if (!woken.empty()) touching_ = mergedPairs(touching_, woken);
}

void ContactEventTracker::update(const std::vector<Contact>& contacts, const RestTest& atRest, bool restChanged,
                                 ContactListener* listener) {
  if (restChanged && !dormant_.empty()) reviveWoken(atRest);
  std::vector<BodyPair> now, fellDormant, revived;
  now.reserve(contacts.size());
  std::size_t previous = 0;
  // A pair of last step's that is not reported now: dormant when at rest, else ended.
  const auto unreported = [&](const BodyPair& pair) {
    if (atRest(pair)) fellDormant.push_back(pair);
    else if (listener) listener->onContactEnd(pair.a, pair.b);
  };
  for (const Contact& contact : contacts) {
    const BodyPair pair{contact.a, contact.b};
    now.push_back(pair);
    while (previous < touching_.size() && touching_[previous] < pair) unreported(touching_[previous++]);
    if (previous < touching_.size() && touching_[previous] == pair) {
      ++previous;
      if (listener) listener->onContactStay(contact);
    } else if (std::binary_search(dormant_.begin(), dormant_.end(), pair)) {
      revived.push_back(pair);  // an awake body's contact that is about to wake the sleeper
      if (listener) listener->onContactStay(contact);
    } else if (listener) {
      listener->onContactBegin(contact);
    }
  }
  for (; previous < touching_.size(); ++previous) unreported(touching_[previous]);
  touching_ = std::move(now);
  if (!revived.empty())
    std::erase_if(dormant_, [&](const BodyPair& pair) {
      return std::binary_search(revived.begin(), revived.end(), pair);
    });
  if (!fellDormant.empty()) dormant_ = mergedPairs(dormant_, fellDormant);
}

std::vector<BodyPair> ContactEventTracker::touchingPairs() const { return mergedPairs(touching_, dormant_); }

void ContactEventTracker::endPairsWith(std::uint32_t body, ContactListener* listener) {
  // In pair order across both lists, as touchingPairs lists them.
  std::vector<BodyPair> ended;
  const auto leaves = [&](const BodyPair& pair) {
    if (pair.a != body && pair.b != body) return false;
    ended.push_back(pair);
    return true;
  };
  std::erase_if(touching_, leaves);
  std::erase_if(dormant_, leaves);
  std::sort(ended.begin(), ended.end());
  if (listener)
    for (const BodyPair& pair : ended) listener->onContactEnd(pair.a, pair.b);
}

}  // namespace physdbg
