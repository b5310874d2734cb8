#include "engine/narrowphase/contact_pass.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include "engine/contacts/manifold_builder.h"
#include "engine/narrowphase/analytic_contacts.h"
#include "engine/narrowphase/linear_cast.h"
#include "engine/narrowphase/narrow_phase.h"
#include "engine/parallel/task_system.h"
#include "engine/stage_timer.h"

namespace physdbg {
namespace {

// Indices per piece of a parallel loop: enough work that a piece outweighs
// handing it to a thread, about 10 us on the cheap side (handing over costs
// several us here, and the bodies' cache lines follow the piece). Screening
// a pair is 10-20 ns; a near pair runs the narrow phase, 0.05 us for two
// spheres to several us for GJK and EPA; measuring a body is ~0.1 us.
// A small scene's pair loops therefore stay on the calling thread.
constexpr std::size_t pairGrain = 1024;
constexpr std::size_t nearPairGrain = 128;
constexpr std::size_t bodyGrain = 256;

// A body's tight box grown by its reach share and padded well past the
// rounding of the exact test (which grows one box by the pair's reach), so
// pairs that miss here also miss there: the outcome is the same either way.
// A share that is not finite grows the box to everything and leaves the
// pair to the exact test.
Aabb paddedReachBounds(const Aabb& tight, double share) {
  const double size = std::max(tight.min.cwiseAbs().maxCoeff(), tight.max.cwiseAbs().maxCoeff());
  const double padded = share + 1e-9 * (1.0 + share + size);
  if (!(std::isfinite(padded)))
    return {Vec3::Constant(-std::numeric_limits<double>::infinity()),
            Vec3::Constant(std::numeric_limits<double>::infinity())};
  return tight.enlarged(padded);
}

}  // namespace

ContactPass::ContactPass(const ContactPassSettings& settings, CollisionOffload* offload)
    : settings_(settings), offload_(offload) {}

void ContactPass::parallelFor(std::size_t count, std::size_t grain,
                              const std::function<void(std::size_t, std::size_t)>& body) const {
  if (tasks_) tasks_->parallelFor(count, grain, body);
  else if (count > 0) body(0, count);
}

void ContactPass::run(const std::vector<RigidBody>& bodies, const std::vector<BodyPair>& pairs,
                      const MovingTest& moving, ContactSolver& solver, const StepContext& context,
                      StepProfile& profile, ContactPassCounts& counts) {
  bodies_ = &bodies;
  pairs_ = &pairs;
  moving_ = moving;
  solver_ = &solver;
  tasks_ = context.tasks;
  counts_ = ContactPassCounts{};
  contacts_.clear();
  meshTests_.clear();
  solver.clearContacts();
  {
    const StageTimer timer(profile.narrowPhase);
    testPairs(context);
  }
  {
    const StageTimer timer(profile.manifolds);
    gatherContacts(context);
  }
  counts.boundsRejected += counts_.boundsRejected;
  counts.manifoldPoints += counts_.manifoldPoints;
  counts.narrowPhase += counts_.narrowPhase;
}

// Fat boxes overlap long before the shapes can touch: when even the tight
// boxes, grown by how far the pair can close this step, stay apart, the
// narrow phase has nothing to say. Most pairs miss by more than the two
// bodies' reach shares, which settles them without the pair's own reach.
ContactPass::PairOutcome ContactPass::screenPair(const BodyPair& pair, const StepContext& context) const {
  // A kinematic body passes through static ones. (Dense per-body flags: most
  // pairs end at the bounds, and need not touch the bodies themselves.)
  const MeasuredBody &a = measured(pair.a), &b = measured(pair.b);
  if (!a.dynamic && !b.dynamic) return PairOutcome::Skipped;
  if (!a.reachBounds.overlaps(b.reachBounds)) return PairOutcome::BoundsRejected;
  const double reach = solver_->contactReach(a.reach, b.reach, context);
  if (!a.tight.enlarged(reach).overlaps(b.tight)) return PairOutcome::BoundsRejected;
  return PairOutcome::Near;
}

// Writes into `answer` in place.
ContactPass::PairOutcome ContactPass::answerPair(const BodyPair& pair, const StepContext& context, PairAnswer& answer,
                                                 MeshContactScratch& scratch, MeshContactCounts& meshCounts) const {
  const double reach = solver_->contactReach(measured(pair.a).reach, measured(pair.b).reach, context);
  answer.reach = reach;
  answer.kept = nullptr;
  answer.mesh = false;
  const RigidBody &a = bodies()[pair.a], &b = bodies()[pair.b];
  const TriangleSource* sourceA = triangleSourceOf(a.collider());
  const TriangleSource* source = sourceA ? sourceA : triangleSourceOf(b.collider());
  if (source) {
    const RigidBody &mesh = sourceA ? a : b, &other = sourceA ? b : a;
    answer.mesh = true;
    answer.meshManifolds.clear();
    answer.meshTests.clear();
    answer.result = collideWithMesh(*source, mesh.transform(), other.collider(), other.transform(), sourceA != nullptr,
                                    pair.a, pair.b, reach, settings_.narrowPhase, scratch, answer.meshManifolds,
                                    meshCounts, &answer.meshTests);
    return PairOutcome::Tested;
  }
  if (offload_ && offload_->handles(a.collider().kind(), b.collider().kind()) && !settings_.bothOrders)
    return PairOutcome::Offloaded;
  if (settings_.reuseContacts) {
    const ReusableContact* kept = kept_.find(pair);
    if (kept && stillHolds(*kept, a.transform(), b.transform(), ContactReuseTolerance{}) &&
        carryResult(*kept, a.transform(), b.transform(), answer.result)) {
      answer.kept = kept;
      return PairOutcome::Tested;
    }
  }
  answer.result = collide(a.collider(), a.transform(), b.collider(), b.transform(), settings_.narrowPhase);
  // The design's brute force ran the narrow phase for B-A too; it responded
  // once per pair, so that second answer is only counted (gatherContacts).
  if (settings_.bothOrders)
    answer.reversed = collide(b.collider(), b.transform(), a.collider(), a.transform(), settings_.narrowPhase);
  return PairOutcome::Tested;
}

// What screenPair and answerPair need of each body of a candidate pair
// alone, once per body: a body meets many pairs. Bodies do not move between
// the passes of a step, but a pass after a wake has other pairs, so each pass
// measures anew. Stored densely, in the order the pairs meet the bodies (pairPlace_), so
// the tables grow with the bodies in pairs, not with the world.
void ContactPass::measureBodies(const StepContext& context) {
  pairPlace_.resize(bodies().size(), notInPair);
  for (const std::uint32_t id : pairBodies_) pairPlace_[id] = notInPair;
  pairBodies_.clear();
  for (const BodyPair& pair : pairs())
    for (const std::uint32_t id : {pair.a, pair.b})
      if (pairPlace_[id] == notInPair) {
        pairPlace_[id] = static_cast<std::uint32_t>(pairBodies_.size());
        pairBodies_.push_back(id);
      }
  measured_.resize(pairBodies_.size());
  parallelFor(pairBodies_.size(), bodyGrain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const RigidBody& body = bodies()[pairBodies_[k]];
      MeasuredBody& measured = measured_[k];
      measured.dynamic = body.isDynamic();
      measured.tight = body.collider().worldBounds(body.transform());
      measured.reach = solver_->bodyReach(body, context);
      measured.reachBounds = paddedReachBounds(measured.tight, solver_->reachShare(measured.reach, context));
    }
  });
}

void ContactPass::testPairs(const StepContext& context) {
  measureBodies(context);
  pairOutcomes_.resize(pairs().size());
  parallelFor(pairs().size(), pairGrain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) pairOutcomes_[i] = screenPair(pairs()[i], context);
  });
  nearPairs_.clear();
  for (std::size_t i = 0; i < pairs().size(); ++i)
    if (pairOutcomes_[i] == PairOutcome::Near) nearPairs_.push_back(static_cast<std::uint32_t>(i));
  pairAnswers_.resize(nearPairs_.size());
  std::mutex countsMutex;
  parallelFor(nearPairs_.size(), nearPairGrain, [&](std::size_t begin, std::size_t end) {
    MeshContactScratch scratch;
    MeshContactCounts meshCounts;
    for (std::size_t k = begin; k < end; ++k) {
      const std::uint32_t i = nearPairs_[k];
      pairOutcomes_[i] = answerPair(pairs()[i], context, pairAnswers_[k], scratch, meshCounts);
    }
    if (meshCounts.triangles == 0) return;
    const std::lock_guard lock(countsMutex);
    counts_.narrowPhase.meshTriangles += meshCounts.triangles;
    counts_.narrowPhase.meshCorrected += meshCounts.corrected;
  });
  if (offload_) testOffloadedPairs();
  if (settings_.castFastPairs) castFastPairs(context);
}

// How far a body moves over the step, as the broad phase predicts it.
Vec3 ContactPass::stepMotion(std::uint32_t id, const StepContext& context) const {
  if (!moving_(id)) return Vec3::Zero();
  const RigidBody& body = bodies()[id];
  return (body.linearVelocity() + body.stepAcceleration() * context.dt) * context.dt;
}

// Pairs apart now that close by more than a quarter of the smaller body's
// smallest extent this step (a thin wall is hit, not passed) are cast along
// their motion; one that meets within the step gets the manifold built at
// the time of impact, carried back to the start of the step: its points'
// anchors are where the bodies meet, their gaps how far they have to close.
void ContactPass::castFastPairs(const StepContext& context) {
  castPairs_.clear();
  for (std::size_t k = 0; k < nearPairs_.size(); ++k) {
    const BodyPair& pair = pairs()[nearPairs_[k]];
    const PairAnswer& answer = pairAnswers_[k];
    pairAnswers_[k].cast = -1;
    if (answer.kept || answer.mesh || answer.result.status != ContactStatus::Separated ||
        bodies()[pair.a].isSensor() || bodies()[pair.b].isSensor() ||
        pairOutcomes_[nearPairs_[k]] == PairOutcome::Offloaded)
      continue;
    const double smallest = std::min(bodies()[pair.a].collider().localBounds().halfExtents().minCoeff(),
                                     bodies()[pair.b].collider().localBounds().halfExtents().minCoeff());
    if ((stepMotion(pair.b, context) - stepMotion(pair.a, context)).norm() > 0.5 * smallest) castPairs_.push_back(k);
  }
  castManifolds_.resize(castPairs_.size());
  const double tolerance = 0.1 * solver_->touchingGap();
  parallelFor(castPairs_.size(), 1, [&](std::size_t begin, std::size_t end) {
    ManifoldScratch scratch;
    for (std::size_t j = begin; j < end; ++j) {
      PairAnswer& answer = pairAnswers_[castPairs_[j]];
      const BodyPair& pair = pairs()[nearPairs_[castPairs_[j]]];
      const RigidBody &a = bodies()[pair.a], &b = bodies()[pair.b];
      const std::optional<LinearCastHit> hit =
          linearCast(a.collider(), a.transform(), stepMotion(pair.a, context), b.collider(), b.transform(),
                     stepMotion(pair.b, context), tolerance, settings_.narrowPhase);
      if (!hit || hit->fraction == 0.0) continue;
      ContactManifold& manifold = castManifolds_[j];
      manifold = ContactManifold{};
      manifold.a = pair.a;
      manifold.b = pair.b;
      buildManifold(a.collider(), hit->a, b.collider(), hit->b, hit->result, answer.reach, scratch, manifold);
      for (int p = 0; p < manifold.pointCount; ++p) {
        ManifoldPoint& point = manifold.points[p];
        point.pointA = a.transform().apply(point.localA);
        point.pointB = b.transform().apply(point.localB);
        point.separation = (point.pointB - point.pointA).dot(manifold.normal);
      }
      answer.cast = static_cast<int>(j);
    }
  });
}

// One batch for the whole pass: a GPU pays per dispatch and readback, not per pair.
void ContactPass::testOffloadedPairs() {
  offloadRequests_.clear();
  offloadPairs_.clear();
  for (std::size_t k = 0; k < nearPairs_.size(); ++k) {
    if (pairOutcomes_[nearPairs_[k]] != PairOutcome::Offloaded) continue;
    const BodyPair& pair = pairs()[nearPairs_[k]];
    offloadRequests_.push_back({pair.a, pair.b, pairAnswers_[k].reach});
    offloadPairs_.push_back(k);
  }
  offloaded_.clear();
  if (offloadRequests_.empty()) return;
  offload_->collide(bodies(), offloadRequests_, offloaded_);
  for (std::size_t k = 0; k < offloadPairs_.size(); ++k) pairAnswers_[offloadPairs_[k]].result = offloaded_[k].result;
}

// In pair order: the counters, the candidates the solver turns into
// manifolds (all at once, so it can build them in parallel) and the touching
// contacts.
void ContactPass::gatherContacts(const StepContext& context) {
  const double touchingGap = solver_->touchingGap();
  candidates_.clear();
  reaches_.clear();
  manifoldSources_.clear();
  std::size_t offloadedSoFar = 0;
  for (std::size_t i = 0, k = 0; i < pairs().size(); ++i) {
    const PairOutcome outcome = pairOutcomes_[i];
    if (outcome == PairOutcome::Skipped) continue;
    if (outcome == PairOutcome::BoundsRejected) {
      ++counts_.boundsRejected;
      continue;
    }
    const PairAnswer& test = pairAnswers_[k++];
    const BodyPair& pair = pairs()[i];
    if (test.mesh) {
      const bool meshIsA = triangleSourceOf(bodies()[pair.a].collider()) != nullptr;
      for (const MeshTriangleTest& tested : test.meshTests)
        meshTests_.push_back({meshIsA ? pair.a : pair.b, meshIsA ? pair.b : pair.a, tested});
    }
    if (bodies()[pair.a].isSensor() || bodies()[pair.b].isSensor()) {
      gatherSensorPair(pair, test);
      continue;
    }
    if (test.mesh) {
      gatherMeshPair(pair, test);
      continue;
    }
    const Contact contact{pair.a, pair.b, test.result};
    if (test.kept)
      counts_.narrowPhase.addReused();
    else
      counts_.narrowPhase.add(contact.result);
    if (settings_.bothOrders) counts_.narrowPhase.add(test.reversed);
    candidates_.push_back(contact);
    reaches_.push_back(test.reach);
    if (outcome == PairOutcome::Offloaded)
      manifoldSources_.push_back({&offloaded_[offloadedSoFar++].manifold, test.kept});
    else if (test.cast >= 0)
      manifoldSources_.push_back({&castManifolds_[static_cast<std::size_t>(test.cast)], nullptr});
    else
      manifoldSources_.push_back({nullptr, test.kept});
    if (contact.result.status == ContactStatus::Separated && contact.result.distance > touchingGap) continue;
    contacts_.push_back(contact);
  }
  counts_.manifoldPoints += solver_->addCandidates(candidates_, reaches_, bodies(), context, manifoldSources_);
}

// A sensor pushes nothing: its pair is a contact (for events and the
// contacts layer) while the shapes overlap or touch, and never a candidate
// for the solver. Speculative gaps do not count: a trigger fires on overlap.
void ContactPass::gatherSensorPair(const BodyPair& pair, const PairAnswer& answer) {
  if (answer.kept) counts_.narrowPhase.addReused();
  else counts_.narrowPhase.add(answer.result);
  if (answer.result.status == ContactStatus::Separated) return;
  contacts_.push_back({pair.a, pair.b, answer.result});
}

// A mesh pair's manifolds go to the solver prebuilt, each as a candidate
// whose result is its deepest point; the pair counts once, as its deepest
// answer, among the contacts.
void ContactPass::gatherMeshPair(const BodyPair& pair, const PairAnswer& answer) {
  counts_.narrowPhase.add(answer.result);
  for (const ContactManifold& manifold : answer.meshManifolds) {
    const ManifoldPoint* deepest = &manifold.points[0];
    for (int p = 1; p < manifold.pointCount; ++p)
      if (manifold.points[p].separation < deepest->separation) deepest = &manifold.points[p];
    candidates_.push_back({pair.a, pair.b,
                           classifyContact(deepest->separation, manifold.normal, deepest->pointA, deepest->pointB,
                                           settings_.narrowPhase.touchingTolerance)});
    reaches_.push_back(answer.reach);
    manifoldSources_.push_back({&manifold, nullptr});
  }
  const ContactResult& result = answer.result;
  if (result.status == ContactStatus::Separated && result.distance > solver_->touchingGap()) return;
  contacts_.push_back({pair.a, pair.b, result});
}

// The answers worth taking again next pass: this pass's manifolds (in pair
// order, as the candidates) whose pair was tested anew with the box-box or
// GJK/EPA route, at today's poses; those taken again keep their old poses.
void ContactPass::keepAnswers(const std::vector<RigidBody>& bodies, const std::vector<ContactManifold>& manifolds) {
  if (!settings_.reuseContacts) return;
  kept_.beginNext();
  std::size_t candidate = 0;
  for (const ContactManifold& manifold : manifolds) {
    while (candidate < candidates_.size() &&
           (candidates_[candidate].a != manifold.a || candidates_[candidate].b != manifold.b))
      ++candidate;
    if (candidate == candidates_.size()) break;
    const ManifoldSource& source = manifoldSources_[candidate];
    if (source.kept) {
      kept_.carry({manifold.a, manifold.b});
      continue;
    }
    if (source.built || !worthReusing(candidates_[candidate].result)) continue;
    ReusableContact& entry = kept_.fresh({manifold.a, manifold.b});
    entry.a = bodies[manifold.a].transform();
    entry.b = bodies[manifold.b].transform();
    entry.result = candidates_[candidate].result;
    entry.manifold = manifold;
    for (int p = 0; p < manifold.pointCount; ++p) {
      ManifoldPoint& point = entry.manifold.points[p];
      point.normalImpulse = point.tangentImpulse[0] = point.tangentImpulse[1] = point.stepNormalImpulse = 0.0;
    }
  }
  kept_.endNext();
}

}  // namespace physdbg
