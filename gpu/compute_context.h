#pragma once
// A GL context that can run compute shaders (GL 4.3: compute shaders and
// shader storage buffers), for the collision stage on the GPU. It is its own
// context, not the renderer's: physics may step on another thread than the
// one drawing (viewer/frame_pipeline.h), and a context is current on one
// thread at a time. OSMesa and EGL surfaceless run it on llvmpipe; EGL with a
// device runs the same shaders on a GPU.
#include <memory>
#include <stdexcept>
#include <string>

#include "render/renderer.h"

namespace physdbg::render {
class GlContext;
}

namespace physdbg::gpu {

// The context cannot run compute shaders: too old a GL, or no context at all.
// The message names what is missing; the CLI exits 2 with it.
class ComputeUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ComputeLimits {
  int workGroupCount[3] = {0, 0, 0};
  int workGroupSize[3] = {0, 0, 0};
  int workGroupInvocations = 0;
  int sharedMemoryBytes = 0;
  long long storageBlockBytes = 0;  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
  int storageBufferBindings = 0;
};

struct ComputeIdentity {
  std::string backend;  // "osmesa" or "egl"
  std::string vendor, renderer, version, shadingLanguage;
  int major = 0, minor = 0;
  ComputeLimits limits;
};

struct GlVersion {
  int major = 4, minor = 3;  // compute shaders and storage buffers
};

class ComputeContext {
 public:
  // Throws ComputeUnavailable when the backend gives no context, or one
  // below `required` (for example under MESA_GL_VERSION_OVERRIDE=3.3). A
  // caller may ask for more than 4.3; tests ask for a version no context has.
  explicit ComputeContext(render::Backend backend, GlVersion required = {});
  ~ComputeContext();
  ComputeContext(const ComputeContext&) = delete;
  ComputeContext& operator=(const ComputeContext&) = delete;

  // Makes the context current on the calling thread.
  void makeCurrent();
  // For destructors, which must not throw: false when it could not (the GL
  // objects then go with the context).
  bool tryMakeCurrent() noexcept;
  const ComputeIdentity& identity() const { return identity_; }

 private:
  std::unique_ptr<render::GlContext> context_;
  ComputeIdentity identity_;
};

// What a GL context of this backend is and can do, compute or not: for
// `physdbg gpu-info`. Throws ComputeUnavailable when no context can be made.
ComputeIdentity probeContext(render::Backend backend);

}  // namespace physdbg::gpu
