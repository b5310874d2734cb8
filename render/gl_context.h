#pragma once
// A GL 3.3 core context that can be made current. The renderer draws into its
// own framebuffer objects, so a backend only has to provide a current context
// with loaded entry points (OSMesa, or EGL without a surface).
#include <memory>
#include <string>

namespace physdbg::render {

class GlContext {
 public:
  virtual ~GlContext() = default;
  virtual void makeCurrent() = 0;
  virtual std::string description() const = 0;  // GL version and renderer strings
};

// Throws std::runtime_error when OSMesa or GLEW cannot give GL 3.3 core.
std::unique_ptr<GlContext> createOsMesaContext();
// Throws std::runtime_error naming what is missing when EGL cannot give GL 3.3 core.
std::unique_ptr<GlContext> createEglContext();

// GLEW looks entry points up through one glXGetProcAddressARB for both
// backends: this answers for EGL while an EGL context is current, else nullptr.
using GlProcedure = void (*)();
GlProcedure eglProcedureIfCurrent(const char* name);

}  // namespace physdbg::render
