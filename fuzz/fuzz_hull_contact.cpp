// Fuzz target: the convex-hull build and the narrow phase (GJK, EPA, manifold
// clipping) on shapes and poses decoded from the input, across many orders of
// magnitude. A bad point cloud may be refused with std::invalid_argument;
// anything that is accepted must give a finite, unit-normal contact.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/contacts/manifold_builder.h"
#include "engine/narrowphase/narrow_phase.h"

namespace {

using namespace physdbg;

// A length between 1e-3 and 1e3, or a coordinate within +-range.
double length(FuzzedDataProvider& input) { return std::pow(10.0, input.ConsumeFloatingPointInRange(-3.0, 3.0)); }
double coordinate(FuzzedDataProvider& input, double range) {
  return input.ConsumeFloatingPointInRange(-range, range);
}

std::shared_ptr<const Collider> makeShape(FuzzedDataProvider& input) {
  switch (input.ConsumeIntegralInRange(0, 3)) {
    case 0: return std::make_shared<SphereCollider>(length(input));
    case 1: return std::make_shared<BoxCollider>(Vec3(length(input), length(input), length(input)));
    case 2: return std::make_shared<CapsuleCollider>(length(input), length(input));
    default: {
      const double scale = length(input);
      std::vector<Vec3> points(input.ConsumeIntegralInRange(4, 40));
      for (Vec3& p : points) p = Vec3(coordinate(input, scale), coordinate(input, scale), coordinate(input, scale));
      return std::make_shared<ConvexMeshCollider>(points);
    }
  }
}

Transform makePose(FuzzedDataProvider& input, double range) {
  Transform pose;
  pose.position = Vec3(coordinate(input, range), coordinate(input, range), coordinate(input, range));
  const Quat q(coordinate(input, 1), coordinate(input, 1), coordinate(input, 1), coordinate(input, 1));
  pose.rotation = q.norm() > 1e-6 ? q.normalized() : Quat::Identity();
  return pose;
}

void require(bool condition) {
  if (!condition) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider input(data, size);
  std::shared_ptr<const Collider> a, b;
  try {
    a = makeShape(input);
    b = makeShape(input);
  } catch (const std::invalid_argument&) {
    return 0;  // a flat or degenerate cloud, refused with a message
  }
  // Poses near each other, far from the origin (up to 1e7 m).
  const double offset = std::pow(10.0, input.ConsumeFloatingPointInRange(-1.0, 7.0));
  const Vec3 shift(coordinate(input, offset), coordinate(input, offset), coordinate(input, offset));
  Transform ta = makePose(input, 2.0), tb = makePose(input, 2.0);
  ta.position += shift;
  tb.position += shift;

  const ContactResult result = collide(*a, ta, *b, tb);
  require(std::isfinite(result.distance) && std::isfinite(result.depth) && result.depth >= 0);
  require(result.normal.allFinite() && std::abs(result.normal.norm() - 1.0) < 1e-6);
  require(result.pointA.allFinite() && result.pointB.allFinite());
  if (result.status == ContactStatus::Separated) return 0;

  ManifoldScratch scratch;
  ContactManifold manifold;
  manifold.a = 0;
  manifold.b = 1;
  buildManifold(*a, ta, *b, tb, result, 0.1, scratch, manifold);
  require(manifold.pointCount >= 0 && manifold.pointCount <= ContactManifold::maxPoints);
  for (int i = 0; i < manifold.pointCount; ++i)
    require(manifold.points[i].pointA.allFinite() && manifold.points[i].pointB.allFinite() &&
            std::isfinite(manifold.points[i].separation));
  return 0;
}
