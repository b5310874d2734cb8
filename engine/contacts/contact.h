#pragma once
// The contact vocabulary every stage shares (narrow phase, solvers, events,
// the debugger's history). What the narrow phase reports for one pair. Conventions: the normal points
// from A to B; moving B by depth * normal separates the pair; pointA is A's
// deepest point inside B (or A's closest point when separated) and pointB is
// B's, both in world space.
#include <cstdint>

#include "engine/math.h"

namespace physdbg {

enum class ContactStatus { Separated, Touching, Penetrating };

const char* contactStatusName(ContactStatus status);

struct ContactResult {
  ContactStatus status = ContactStatus::Separated;
  double distance = 0.0;  // > 0 when separated, 0 otherwise
  Vec3 normal = Vec3::UnitY();
  double depth = 0.0;  // > 0 when penetrating, 0 otherwise
  Vec3 pointA = Vec3::Zero();
  Vec3 pointB = Vec3::Zero();
  int gjkIterations = 0;
  int epaIterations = 0;
  bool usedGeneralPath = false;
  // The box-box separating-axis test decided the pair (usedGeneralPath too
  // when it handed a separated pair to GJK for the exact distance); the
  // manifold builder then takes the box-box route.
  bool usedBoxBox = false;
};

// A touching or penetrating pair, as the world lists it after the narrow phase.
struct Contact {
  std::uint32_t a = 0, b = 0;  // body ids, a < b
  ContactResult result;
};

}  // namespace physdbg
