#pragma once
// A GL 3.3 core context that can be made current. The renderer draws into its
// own framebuffer objects, so a backend only has to provide a current context
// with loaded entry points (OSMesa now; EGL surfaceless later).
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

}  // namespace physdbg::render
