#pragma once
// Off-screen renderer for debug-draw frames. Knows nothing of physics: it draws
// the primitives of a Frame, each kind with one instanced draw call.
#include <memory>
#include <string>

#include "debugdraw/primitives.h"
#include "render/camera.h"
#include "render/image.h"

namespace physdbg::render {

// Where the GL context comes from. OSMesa is removed from Mesa 25.1 onwards;
// EGL (surfaceless or a device) works there and on GPU machines.
enum class Backend { OsMesa, Egl };

// "osmesa" or "egl"; throws std::invalid_argument naming the choices.
Backend parseBackend(const std::string& name);

struct RendererOptions {
  int width = 1280, height = 720;
  // MSAA samples, 0 = off. Off by default: on llvmpipe 4x costs several times
  // the draw time (see render/README.md for measurements).
  int samples = 0;
  Backend backend = Backend::OsMesa;
  // Outline markers with dark copies drawn before them, as MSAA does: four
  // shifted copies of the arrows instead of the outline layer
  // (render/outline_layer.h), and a grown copy of every point instead of one
  // pass that draws a point and its ring. The reference the faster ways are
  // tested against.
  bool outlineMarkersByCopies = false;
};

// Where the last render() spent its time: flattening the frame into arrays
// (our CPU work), issuing the draws and waiting for llvmpipe to rasterise
// them (glFinish), and glReadPixels with the row flip.
struct RenderTimings {
  double prepareSeconds = 0, drawSeconds = 0, readBackSeconds = 0;
};

struct GlIdentity {
  std::string renderer, version;
};

class Renderer {
 public:
  // Throws std::invalid_argument for bad options, std::runtime_error when no
  // GL 3.3 core context can be created.
  explicit Renderer(const RendererOptions& options);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Same frame and camera give the same bytes. Throws std::invalid_argument for
  // bad primitives or camera, std::runtime_error on GL failure.
  Image render(const debugdraw::Frame& frame, const Camera& camera);

  const RendererOptions& options() const;
  const RenderTimings& lastTimings() const;

  // GL_RENDERER and GL_VERSION of the context, e.g. "llvmpipe (LLVM 15.0.6,
  // 256 bits)" and "4.5 (Core Profile) Mesa 22.3.6": golden images are keyed by them.
  GlIdentity glIdentity() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace physdbg::render
