#pragma once
// Move-only owners of GL object names. The owning context must be current when
// they are created and destroyed (the Renderer keeps its context alive longer).
#include <string>
#include <utility>

#include "render/gl_headers.h"

namespace physdbg::render {

template <void (*destroy)(GLuint)>
class GlName {
 public:
  GlName() = default;
  explicit GlName(GLuint name) : name_(name) {}
  ~GlName() { reset(); }
  GlName(GlName&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  GlName& operator=(GlName&& other) noexcept {
    if (this != &other) {
      reset();
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;

  GLuint get() const { return name_; }
  void reset() {
    if (name_ != 0) destroy(name_);
    name_ = 0;
  }

 private:
  GLuint name_ = 0;
};

namespace detail {
void deleteBuffer(GLuint name);
void deleteVertexArray(GLuint name);
void deleteProgram(GLuint name);
void deleteFramebuffer(GLuint name);
void deleteRenderbuffer(GLuint name);
void deleteTexture(GLuint name);
}  // namespace detail

using GlBuffer = GlName<detail::deleteBuffer>;
using GlVertexArray = GlName<detail::deleteVertexArray>;
using GlProgram = GlName<detail::deleteProgram>;
using GlFramebuffer = GlName<detail::deleteFramebuffer>;
using GlRenderbuffer = GlName<detail::deleteRenderbuffer>;
using GlTexture = GlName<detail::deleteTexture>;

GlBuffer createBuffer();
GlVertexArray createVertexArray();
GlFramebuffer createFramebuffer();
GlRenderbuffer createRenderbuffer();
GlTexture createTexture();
// Compiles and links; throws std::runtime_error with the info log on failure.
GlProgram createProgram(const char* vertexSource, const char* fragmentSource, const std::string& label);
// A compute shader program (GL 4.3); throws std::runtime_error with the info log on failure.
GlProgram createComputeProgram(const char* source, const std::string& label);

// Throws std::runtime_error naming `what` if GL recorded an error.
void checkGlError(const char* what);

}  // namespace physdbg::render
