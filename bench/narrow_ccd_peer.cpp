#include "bench/narrow_ccd_peer.h"

#ifdef PHYSDBG_HAVE_CCD
#include <ccd/ccd.h>
#endif

namespace physdbg::bench {

const char* ccdMethodName(CcdMethod method) {
  return method == CcdMethod::GjkEpa ? "libccd-gjk-epa" : "libccd-mpr";
}

#ifdef PHYSDBG_HAVE_CCD
namespace {

struct CcdShape {
  const Collider* collider;
  Transform transform;
};

void ccdSupport(const void* object, const ccd_vec3_t* direction, ccd_vec3_t* out) {
  const auto* shape = static_cast<const CcdShape*>(object);
  const Vec3 p = shape->collider->support(shape->transform, Vec3(direction->v[0], direction->v[1], direction->v[2]));
  out->v[0] = p.x(), out->v[1] = p.y(), out->v[2] = p.z();
}

void ccdCentre(const void* object, ccd_vec3_t* out) {
  const auto* shape = static_cast<const CcdShape*>(object);
  const Vec3 p = shape->transform.apply(shape->collider->localBounds().center());
  out->v[0] = p.x(), out->v[1] = p.y(), out->v[2] = p.z();
}

}  // namespace

bool ccdAvailable() { return true; }

PeerContact ccdPenetration(CcdMethod method, const Collider& a, const Transform& ta, const Collider& b,
                           const Transform& tb) {
  // libccd's defaults (tolerances 1e-4 for EPA and MPR, 1e-6 for distance).
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = ccdSupport;
  ccd.support2 = ccdSupport;
  ccd.center1 = ccdCentre;
  ccd.center2 = ccdCentre;
  ccd.max_iterations = 100;
  const CcdShape shapeA{&a, ta}, shapeB{&b, tb};
  ccd_real_t depth = 0.0;
  ccd_vec3_t direction, position;
  const int status = method == CcdMethod::GjkEpa ? ccdGJKPenetration(&shapeA, &shapeB, &ccd, &depth, &direction, &position)
                                                 : ccdMPRPenetration(&shapeA, &shapeB, &ccd, &depth, &direction, &position);
  PeerContact contact;
  contact.hit = status == 0;
  if (contact.hit) {
    contact.depth = depth;
    contact.normal = Vec3(direction.v[0], direction.v[1], direction.v[2]);
  }
  return contact;
}
#else
bool ccdAvailable() { return false; }

PeerContact ccdPenetration(CcdMethod, const Collider&, const Transform&, const Collider&, const Transform&) { return {}; }
#endif

}  // namespace physdbg::bench
