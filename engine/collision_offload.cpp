#include "engine/collision_offload.h"

namespace physdbg {

const char* collisionDeviceName(CollisionDevice device) {
  return device == CollisionDevice::Gpu ? "gpu" : "cpu";
}

}  // namespace physdbg
