#include "engine/contacts/supporting_feature.h"

#include <cmath>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/colliders/triangle_collider.h"
#include "engine/contacts/box_face.h"

namespace physdbg {
namespace {

// A segment (capsule) counts as lying across the direction when its axis is
// within this sine of perpendicular: then both ends touch a face together.
constexpr double segmentAlignment = 0.05;

void boxFace(const BoxCollider& box, const Transform& transform, const Vec3& localDirection,
             SupportingFeature& feature) {
  const BoxFace face = boxFaceAlong(box.halfExtents(), localDirection);
  feature.points.clear();
  for (const Vec3& corner : face.corners) feature.points.push_back(transform.apply(corner));
  feature.normal = transform.rotation * face.normal();
  feature.index = face.index;
}

void hullFace(const ConvexMeshCollider& hull, const Transform& transform, const Vec3& localDirection,
              SupportingFeature& feature) {
  const auto& faces = hull.hullFaces();
  int best = 0;
  double bestDot = -2.0;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const double dot = faces[i].normal.dot(localDirection);
    if (dot > bestDot) {
      bestDot = dot;
      best = static_cast<int>(i);
    }
  }
  feature.points.clear();
  for (int vertex : faces[best].vertices) feature.points.push_back(transform.apply(hull.hullVertices()[vertex]));
  feature.normal = transform.rotation * faces[best].normal;
  feature.index = best;
}

void capsuleFeature(const CapsuleCollider& capsule, const Transform& transform, const Vec3& localDirection,
                    SupportingFeature& feature) {
  feature.points.clear();
  const Vec3 offset = localDirection * capsule.radius();
  if (std::abs(localDirection.y()) <= segmentAlignment && capsule.halfHeight() > 0.0) {
    feature.points.push_back(transform.apply(Vec3(0, capsule.halfHeight(), 0) + offset));
    feature.points.push_back(transform.apply(Vec3(0, -capsule.halfHeight(), 0) + offset));
    feature.index = 0;
    return;
  }
  feature.points.push_back(transform.apply(capsule.localSupport(localDirection)));
  feature.index = localDirection.y() < 0 ? 2 : 1;
}

// Either side of a mesh's triangle can be touched: the face toward the
// direction, wound counter-clockwise seen from that side.
void triangleFace(const TriangleCollider& triangle, const Transform& transform, const Vec3& localDirection,
                  SupportingFeature& feature) {
  const auto& corners = triangle.corners();
  const bool front = triangle.normal().dot(localDirection) >= 0.0;
  feature.points.clear();
  for (int i = 0; i < 3; ++i) feature.points.push_back(transform.apply(corners[front ? i : 2 - i]));
  feature.normal = transform.rotation * (front ? triangle.normal() : Vec3(-triangle.normal()));
  feature.index = front ? 0 : 1;
}

}  // namespace

void findSupportingFeature(const Collider& collider, const Transform& transform, const Vec3& direction,
                           SupportingFeature& feature) {
  const Vec3 localDirection = (transform.rotation.conjugate() * direction).normalized();
  feature.normal = direction.normalized();
  switch (collider.kind()) {
    case ColliderKind::Box:
      boxFace(static_cast<const BoxCollider&>(collider), transform, localDirection, feature);
      return;
    case ColliderKind::ConvexMesh:
      hullFace(static_cast<const ConvexMeshCollider&>(collider), transform, localDirection, feature);
      return;
    case ColliderKind::Capsule:
      capsuleFeature(static_cast<const CapsuleCollider&>(collider), transform, localDirection, feature);
      return;
    case ColliderKind::Triangle:
      triangleFace(static_cast<const TriangleCollider&>(collider), transform, localDirection, feature);
      return;
    case ColliderKind::Sphere:
    case ColliderKind::TriangleMesh:  // met one triangle at a time (mesh_contacts.h); a point if asked
    case ColliderKind::Heightfield:
      feature.points.assign(1, collider.support(transform, direction));
      feature.index = 0;
      return;
  }
}

}  // namespace physdbg
