#include "bench/bullet_world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/heightfield_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/colliders/triangle_mesh_collider.h"

#ifdef PHYSDBG_HAVE_BULLET
#include "bench/bullet_convert.h"
#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>
#include <btBulletDynamicsCommon.h>
#endif

namespace physdbg::bench {

#ifdef PHYSDBG_HAVE_BULLET
namespace {

// What a Bullet mesh or heightfield shape reads from but does not own.
struct ShapeData {
  std::vector<int> indices;
  std::vector<btScalar> vertices;  // also a heightfield's heights
  std::unique_ptr<btTriangleIndexVertexArray> triangles;
};

std::unique_ptr<btCollisionShape> meshShape(const TriangleMeshCollider& mesh, ShapeData& data) {
  for (const Vec3& vertex : mesh.vertices())
    for (int axis = 0; axis < 3; ++axis) data.vertices.push_back(btScalar(vertex[axis]));
  for (const MeshTriangle& triangle : mesh.triangles())
    for (const std::uint32_t corner : triangle) data.indices.push_back(static_cast<int>(corner));
  data.triangles = std::make_unique<btTriangleIndexVertexArray>(
      static_cast<int>(mesh.triangles().size()), data.indices.data(), 3 * static_cast<int>(sizeof(int)),
      static_cast<int>(mesh.vertices().size()), data.vertices.data(), 3 * static_cast<int>(sizeof(btScalar)));
  return std::make_unique<btBvhTriangleMeshShape>(data.triangles.get(), true);
}

// Bullet centres a field on the middle of its height range; the body is
// moved up by that much to match (heightfieldOffset).
std::unique_ptr<btCollisionShape> fieldShape(const HeightfieldCollider& field, ShapeData& data) {
  for (int row = 0; row < field.rows(); ++row)
    for (int column = 0; column < field.columns(); ++column)
      data.vertices.push_back(btScalar(field.samplePoint(column, row).y()));
  const Aabb bounds = field.localBounds();
  auto shape = std::make_unique<btHeightfieldTerrainShape>(field.columns(), field.rows(), data.vertices.data(), 1.0,
                                                           btScalar(bounds.min.y()), btScalar(bounds.max.y()), 1,
                                                           PHY_FLOAT, false);
  shape->setLocalScaling(btVector3(btScalar(field.spacingX()), 1, btScalar(field.spacingZ())));
  return shape;
}

std::unique_ptr<btCollisionShape> makeShape(const Collider& collider, ShapeData& data) {
  switch (collider.kind()) {
    case ColliderKind::Sphere:
      return std::make_unique<btSphereShape>(btScalar(static_cast<const SphereCollider&>(collider).radius()));
    case ColliderKind::Box:
      return std::make_unique<btBoxShape>(toBullet(static_cast<const BoxCollider&>(collider).halfExtents()));
    case ColliderKind::Capsule: {
      const auto& capsule = static_cast<const CapsuleCollider&>(collider);
      return std::make_unique<btCapsuleShape>(btScalar(capsule.radius()), btScalar(2 * capsule.halfHeight()));
    }
    case ColliderKind::ConvexMesh: {
      auto hull = std::make_unique<btConvexHullShape>();
      for (const Vec3& vertex : static_cast<const ConvexMeshCollider&>(collider).hullVertices())
        hull->addPoint(toBullet(vertex), false);
      hull->recalcLocalAabb();
      return hull;
    }
    case ColliderKind::TriangleMesh: return meshShape(static_cast<const TriangleMeshCollider&>(collider), data);
    case ColliderKind::Heightfield: return fieldShape(static_cast<const HeightfieldCollider&>(collider), data);
    case ColliderKind::Triangle: break;
  }
  throw std::invalid_argument(std::string("BulletWorld: unsupported collider kind ") +
                              colliderKindName(collider.kind()));
}

// Bullet's heightfield origin is the middle of its height range, physdbg's the sample plane's y = 0.
Vec3 heightfieldOffset(const Collider& collider) {
  if (collider.kind() != ColliderKind::Heightfield) return Vec3::Zero();
  const Aabb bounds = collider.localBounds();
  return Vec3(0, 0.5 * (bounds.min.y() + bounds.max.y()), 0);
}

}  // namespace

// Members are destroyed in reverse order: bodies leave the world first.
struct BulletWorld::Impl {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  btScalar dt = 1.0f / 60.0f;
  std::vector<std::unique_ptr<ShapeData>> shapeData;  // before the shapes: they read it
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btDefaultMotionState>> motionStates;
  std::vector<std::unique_ptr<btRigidBody>> bodies;

  ~Impl() {
    for (auto& body : bodies) world.removeRigidBody(body.get());
  }

  // One Bullet shape per distinct physdbg collider, as the scene shares them.
  btCollisionShape* shapeFor(const Collider& collider, std::vector<const Collider*>& sources) {
    for (std::size_t i = 0; i < sources.size(); ++i) {
      if (sources[i] == &collider) return shapes[i].get();
    }
    shapeData.push_back(std::make_unique<ShapeData>());
    shapes.push_back(makeShape(collider, *shapeData.back()));
    sources.push_back(&collider);
    return shapes.back().get();
  }

  void addBody(const BodyDefinition& definition, btCollisionShape* shape, bool allowSleep) {
    const btScalar mass = definition.isStatic ? btScalar(0) : btScalar(definition.mass);
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(mass, inertia);
    const Quat& q = definition.orientation;
    const btTransform start(btQuaternion(btScalar(q.x()), btScalar(q.y()), btScalar(q.z()), btScalar(q.w())),
                            toBullet(definition.position + q * heightfieldOffset(*definition.collider)));
    motionStates.push_back(std::make_unique<btDefaultMotionState>(start));
    btRigidBody::btRigidBodyConstructionInfo info(mass, motionStates.back().get(), shape, inertia);
    info.m_friction = btScalar(std::sqrt(definition.material.dynamicFriction));
    info.m_restitution = btScalar(std::sqrt(definition.material.restitution));
    bodies.push_back(std::make_unique<btRigidBody>(info));
    btRigidBody& body = *bodies.back();
    body.setLinearVelocity(toBullet(definition.linearVelocity));
    body.setAngularVelocity(toBullet(definition.angularVelocity));
    if (!definition.isStatic && !allowSleep) body.setActivationState(DISABLE_DEACTIVATION);
    world.addRigidBody(&body);
  }
};

bool BulletWorld::available() { return true; }

double BulletWorld::meshBuildMilliseconds(const TriangleMeshCollider& mesh) {
  const auto start = std::chrono::steady_clock::now();
  ShapeData data;
  const std::unique_ptr<btCollisionShape> shape = meshShape(mesh, data);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

BulletWorld::BulletWorld(const SceneDescription& scene, bool allowSleep) : impl_(std::make_unique<Impl>()) {
  impl_->world.setGravity(toBullet(scene.world.gravity));
  impl_->dt = btScalar(scene.world.dt);
  std::vector<const Collider*> sources;
  for (const BodyDefinition& definition : scene.bodies) {
    if (!definition.collider) throw std::invalid_argument("BulletWorld: body without a collider");
    impl_->addBody(definition, impl_->shapeFor(*definition.collider, sources), allowSleep);
  }
  // The scene's sleepers start asleep here too, so both engines skip the same bodies.
  if (allowSleep)
    for (const BodyId id : scene.sleeping) impl_->bodies.at(id)->setActivationState(ISLAND_SLEEPING);
}

BulletWorld::~BulletWorld() = default;

void BulletWorld::step() { impl_->world.stepSimulation(impl_->dt, 1, impl_->dt); }

void BulletWorld::setSolverIterations(int iterations) { impl_->world.getSolverInfo().m_numIterations = iterations; }

std::size_t BulletWorld::bodyCount() const { return impl_->bodies.size(); }

Vec3 BulletWorld::linearVelocity(std::size_t body) const {
  const btVector3& v = impl_->bodies.at(body)->getLinearVelocity();
  return Vec3(v.x(), v.y(), v.z());
}

double BulletWorld::largestPenetration() const {
  double deepest = 0.0;
  btDispatcher& dispatcher = impl_->dispatcher;
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    for (int c = 0; c < manifold->getNumContacts(); ++c) {
      deepest = std::max(deepest, -double(manifold->getContactPoint(c).getDistance()));
    }
  }
  return deepest;
}

Vec3 BulletWorld::position(std::size_t body) const {
  const btVector3& p = impl_->bodies.at(body)->getCenterOfMassPosition();
  return Vec3(p.x(), p.y(), p.z());
}

int BulletWorld::touchingPairs(double gap) const {
  int touching = 0;
  btDispatcher& dispatcher = impl_->dispatcher;
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    for (int c = 0; c < manifold->getNumContacts(); ++c)
      if (double(manifold->getContactPoint(c).getDistance()) <= gap) {
        ++touching;
        break;
      }
  }
  return touching;
}

double BulletWorld::kineticEnergy() const {
  double energy = 0.0;
  for (const auto& body : impl_->bodies) {
    if (body->getInvMass() == 0) continue;
    const btVector3 v = body->getLinearVelocity();
    const btVector3 w = body->getWorldTransform().getBasis().transpose() * body->getAngularVelocity();
    const btVector3 inverseInertia = body->getInvInertiaDiagLocal();
    energy += 0.5 * double(v.length2()) / double(body->getInvMass());
    for (int axis = 0; axis < 3; ++axis) {
      if (inverseInertia[axis] > 0) energy += 0.5 * double(w[axis]) * double(w[axis]) / double(inverseInertia[axis]);
    }
  }
  return energy;
}

#else

struct BulletWorld::Impl {};

bool BulletWorld::available() { return false; }
double BulletWorld::meshBuildMilliseconds(const TriangleMeshCollider&) { return 0.0; }
BulletWorld::BulletWorld(const SceneDescription&, bool) {
  throw std::runtime_error("BulletWorld: physdbg was built without Bullet");
}
BulletWorld::~BulletWorld() = default;
void BulletWorld::step() {}
void BulletWorld::setSolverIterations(int) {}
std::size_t BulletWorld::bodyCount() const { return 0; }
Vec3 BulletWorld::position(std::size_t) const { return Vec3::Zero(); }
Vec3 BulletWorld::linearVelocity(std::size_t) const { return Vec3::Zero(); }
double BulletWorld::largestPenetration() const { return 0.0; }
int BulletWorld::touchingPairs(double) const { return 0; }
double BulletWorld::kineticEnergy() const { return 0.0; }

#endif

}  // namespace physdbg::bench
