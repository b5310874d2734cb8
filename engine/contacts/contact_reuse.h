#pragma once
// Resting pairs barely move from one step to the next: a column of boxes
// settled on a floor shifts by micrometres. Their separating-axis test, face
// clipping and point reduction would give the same answer again, so a pair
// whose two bodies have both stayed within a tight tolerance of where they
// were when the pair was last computed takes that answer, carried along with
// each body: points move with their own body and the normal with body A, and
// every distance is measured anew at the current poses. Only the box-box and
// GJK/EPA answers are kept: the analytic ones (spheres) cost less than the
// check.
#include <cmath>
#include <cstdint>
#include <vector>

#include "engine/broadphase/broad_phase.h"
#include "engine/contacts/contact.h"
#include "engine/contacts/contact_manifold.h"
#include "engine/math.h"

namespace physdbg {

// How far a body may have moved since its pair was computed for the answer
// to be taken again. A tenth of a millimetre and 2e-4 rad (a tenth of a
// millimetre at half a metre from the centre): far below the 5 mm slop within
// which contacts are found and the tolerances of the tests that check them.
struct ContactReuseTolerance {
  double distance = 1e-4;  // m
  double angle = 2e-4;     // rad
};

// One pair's answer as computed, with the poses it was computed at.
struct ReusableContact {
  BodyPair pair{0, 0};
  Transform a, b;
  ContactResult result;
  ContactManifold manifold;  // geometry only: impulses are the solver's
};

// Whether an answer of this kind is worth keeping (box-box or GJK/EPA).
bool worthReusing(const ContactResult& result);

// Whether a pose is within `tolerance` of another: |q . q0| >= cos(angle / 2)
// is the rotation between them being at most `angle`. Inline, so that with
// a constant tolerance the compiler takes the cosine once, at compile time
// (it was two calls to cos a pair, on every pair a resting pile tests).
inline bool nearPose(const Transform& now, const Transform& then, const ContactReuseTolerance& tolerance) {
  if ((now.position - then.position).squaredNorm() > tolerance.distance * tolerance.distance) return false;
  return std::abs(now.rotation.coeffs().dot(then.rotation.coeffs())) >= std::cos(0.5 * tolerance.angle);
}

// Whether both bodies are still within `tolerance` of the poses the answer
// was computed at.
inline bool stillHolds(const ReusableContact& kept, const Transform& a, const Transform& b,
                       const ContactReuseTolerance& tolerance) {
  return nearPose(a, kept.a, tolerance) && nearPose(b, kept.b, tolerance);
}

// The kept answer at the current poses: false when its distance changed sign
// (a separated pair now touching, a penetrating one now apart), which only a
// new test may say.
bool carryResult(const ReusableContact& kept, const Transform& a, const Transform& b, ContactResult& result);
void carryManifold(const ReusableContact& kept, const Transform& a, const Transform& b, ContactManifold& manifold);

// The answers kept from one pass to the next, looked up by pair. A resting
// pile takes almost every answer again every step; each answer (about 900
// bytes with its manifold) stays in its slot, and the sorted index that finds
// it is all that is rebuilt. Building the next pass's list:
//   beginNext(); then carry(pair) or fresh(pair), in ascending pair order;
//   then endNext().
// fresh() may move the slots: pointers from find() do not survive it.
class KeptAnswers {
 public:
  const ReusableContact* find(const BodyPair& pair) const;
  void beginNext() {
    next_.clear();
    cursor_ = 0;
  }
  void carry(const BodyPair& pair);  // a pair find() answered this pass
  ReusableContact& fresh(const BodyPair& pair);
  void endNext();
  std::size_t size() const { return current_.size(); }

 private:
  struct Entry {
    BodyPair pair;
    std::uint32_t slot;
  };
  std::vector<ReusableContact> slots_;
  std::vector<std::uint32_t> free_;    // slots no entry uses
  std::vector<Entry> current_, next_;  // sorted by pair
  std::vector<char> inNext_;           // per slot, while endNext runs
  std::size_t cursor_ = 0;             // carry's walk through current_ (pairs come ascending)
};

}  // namespace physdbg
