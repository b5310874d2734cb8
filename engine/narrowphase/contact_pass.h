#pragma once
// The narrow-phase pass of a step: the broad phase's candidate pairs in, the
// touching contacts and the solver's manifold candidates out. World::step
// runs one pass, and another after a touch woke a body.
//
// Candidate pairs go through two parallel passes, gathered in pair order
// (gatherContacts), so contacts, manifolds and counters come out as a serial
// pass makes them. A pair with a triangle mesh gives a manifold per normal
// (mesh_contacts.h), each handed to the solver as a candidate of its own,
// and one contact, its deepest. screenPair settles most pairs at the bounds and writes one
// byte each; answerPair runs the narrow phase on the few left (nearPairs_),
// each into a dense slot. (A whole answer per pair, written by one thread and
// read by another, was megabytes of cache lines crossing cores each step;
// slots per candidate pair, 0.85 KB each and one in ten written, spread 4000
// boxes' answers over 36 MB.) Pairs that close fast are cast to their time of
// impact (linear_cast.h); pairs a collision offload handles go to it in one
// batch; a resting pair takes its last answer again (contact_reuse.h).
#include <cstdint>
#include <functional>
#include <vector>

#include "engine/broadphase/broad_phase.h"
#include "engine/collision_offload.h"
#include "engine/contacts/contact.h"
#include "engine/contacts/contact_manifold.h"
#include "engine/contacts/contact_reuse.h"
#include "engine/dynamics/rigid_body.h"
#include "engine/narrowphase/mesh_contacts.h"
#include "engine/narrowphase/narrow_phase_options.h"
#include "engine/solver/contact_solver.h"
#include "engine/step_profile.h"

namespace physdbg {

class TaskSystem;

struct ContactPassSettings {
  NarrowPhaseOptions narrowPhase;
  // The design's brute force tests B-A too; that answer is only counted.
  bool bothOrders = false;
  // A resting pair takes its last answer again (contact_reuse.h).
  bool reuseContacts = true;
  // Pairs that close by more than a quarter of the smaller body in a step
  // are cast to their time of impact.
  bool castFastPairs = true;
};

// What passes counted, summed over a step's passes.
struct ContactPassCounts {
  int boundsRejected = 0;  // candidate pairs whose tight boxes were too far apart for the narrow phase
  int manifoldPoints = 0;
  NarrowPhaseCounters narrowPhase;
};

class ContactPass {
 public:
  using MovingTest = std::function<bool(std::uint32_t body)>;

  // `offload` may be null; not owned.
  ContactPass(const ContactPassSettings& settings, CollisionOffload* offload);

  // One pass over `pairs` (sorted): the solver's candidates are cleared and
  // refilled; `moving(id)` says which bodies move this step (only theirs are
  // cast). Stage times go to `profile` (narrowPhase, manifolds), counts are
  // added to `counts`. The references must outlive the pass.
  void run(const std::vector<RigidBody>& bodies, const std::vector<BodyPair>& pairs, const MovingTest& moving,
           ContactSolver& solver, const StepContext& context, StepProfile& profile, ContactPassCounts& counts);
  // The pairs within the solver's touching gap, in pair order.
  const std::vector<Contact>& contacts() const { return contacts_; }
  // This pass's tests of level geometry's triangles, in pair order.
  struct MeshTest {
    std::uint32_t mesh, other;  // body ids
    MeshTriangleTest test;
  };
  const std::vector<MeshTest>& meshTests() const { return meshTests_; }
  // After a step's last pass: the answers worth taking again next step,
  // from the solver's manifolds (in pair order, as the candidates).
  void keepAnswers(const std::vector<RigidBody>& bodies, const std::vector<ContactManifold>& manifolds);

 private:
  enum class PairOutcome : std::uint8_t {
    Skipped,
    BoundsRejected,
    Near,  // passed screenPair; answerPair turns it into one of the two below
    Tested,
    Offloaded,  // the collision offload answers it (testOffloadedPairs)
  };
  struct PairAnswer {  // one per near pair, in pair order (nearPairs_)
    double reach = 0.0;
    ContactResult result;
    ContactResult reversed;                 // B-A, tested only with bothOrders
    const ReusableContact* kept = nullptr;  // the last answer, carried to now (result here, manifold by the solver)
    int cast = -1;                          // its manifold at the time of impact, in castManifolds_
    bool mesh = false;                      // a body against a triangle mesh: its manifolds are below
    std::vector<ContactManifold> meshManifolds;  // one per normal (mesh_contacts.h); storage kept between passes
    std::vector<MeshTriangleTest> meshTests;     // the triangles tested, for the mesh debug layer
  };
  // What the pair screen needs of each body in a pair, this pass (measureBodies).
  struct MeasuredBody {
    Aabb tight;
    Aabb reachBounds;  // tight box grown by the body's reach share, padded
    BodyReach reach;
    bool dynamic = false;
  };
  static constexpr std::uint32_t notInPair = ~0u;

  const std::vector<RigidBody>& bodies() const { return *bodies_; }
  const std::vector<BodyPair>& pairs() const { return *pairs_; }
  const MeasuredBody& measured(std::uint32_t id) const { return measured_[pairPlace_[id]]; }
  void parallelFor(std::size_t count, std::size_t grain,
                   const std::function<void(std::size_t, std::size_t)>& body) const;
  PairOutcome screenPair(const BodyPair& pair, const StepContext& context) const;
  PairOutcome answerPair(const BodyPair& pair, const StepContext& context, PairAnswer& answer,
                         MeshContactScratch& scratch, MeshContactCounts& meshCounts) const;
  void gatherMeshPair(const BodyPair& pair, const PairAnswer& answer);
  void gatherSensorPair(const BodyPair& pair, const PairAnswer& answer);
  void measureBodies(const StepContext& context);
  void testPairs(const StepContext& context);
  void testOffloadedPairs();
  void castFastPairs(const StepContext& context);
  Vec3 stepMotion(std::uint32_t id, const StepContext& context) const;
  void gatherContacts(const StepContext& context);

  ContactPassSettings settings_;
  CollisionOffload* offload_ = nullptr;
  // This pass's inputs (run).
  const std::vector<RigidBody>* bodies_ = nullptr;
  const std::vector<BodyPair>* pairs_ = nullptr;
  MovingTest moving_;
  ContactSolver* solver_ = nullptr;
  const TaskSystem* tasks_ = nullptr;
  ContactPassCounts counts_;  // this pass's, added to the caller's at the end

  std::vector<PairOutcome> pairOutcomes_;       // per candidate pair
  std::vector<std::uint32_t> nearPairs_;        // candidate pairs that passed screenPair, ascending
  std::vector<PairAnswer> pairAnswers_;         // per near pair
  std::vector<std::uint32_t> castPairs_;        // near pairs (their k) cast this pass
  std::vector<ContactManifold> castManifolds_;  // per cast pair, at the start of the step
  std::vector<std::uint32_t> pairPlace_;        // per body: its place in pairBodies_ and measured_, or notInPair
  std::vector<std::uint32_t> pairBodies_;       // bodies in a candidate pair
  std::vector<MeasuredBody> measured_;          // per body in a pair
  std::vector<Contact> candidates_;             // tested pairs, for the solver (gatherContacts)
  std::vector<double> reaches_;                 // their contactReach
  std::vector<OffloadRequest> offloadRequests_;  // this pass's offloaded pairs (testOffloadedPairs)
  std::vector<std::size_t> offloadPairs_;        // their index in nearPairs_
  std::vector<OffloadedContact> offloaded_;      // the offload's answers
  std::vector<ManifoldSource> manifoldSources_;  // per candidate: its offloaded manifold or kept answer, if any
  KeptAnswers kept_;                             // answers worth taking again
  std::vector<Contact> contacts_;                // this pass's touching pairs
  std::vector<MeshTest> meshTests_;
};

}  // namespace physdbg
