#include "engine/contacts/contact.h"

namespace physdbg {

const char* contactStatusName(ContactStatus status) {
  switch (status) {
    case ContactStatus::Separated: return "separated";
    case ContactStatus::Touching: return "touching";
    case ContactStatus::Penetrating: return "penetrating";
  }
  return "unknown";
}

}  // namespace physdbg
