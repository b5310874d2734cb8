// OSMesa backend of GlContext. Debian's GLEW resolves entry points through
// glXGetProcAddressARB; with no X display we provide that symbol ourselves,
// here in the translation unit that creates the context so the linker keeps it
// (executables must be linked with ENABLE_EXPORTS for GLEW to see it).
#include "render/gl_headers.h"
#ifndef GLAPI
#define GLAPI extern
#endif
#include <GL/osmesa.h>

#include <cstring>
#include <stdexcept>
#include <vector>

#include "render/gl_context.h"

// With an EGL context current (the EGL backend), GL names go to EGL; GLX names
// never do, since EGL hands out dispatch stubs that crash without an X display.
extern "C" __attribute__((visibility("default"))) void (*glXGetProcAddressARB(const GLubyte* name))() {
  const char* text = reinterpret_cast<const char*>(name);
  if (std::strncmp(text, "glX", 3) != 0)
    if (auto procedure = physdbg::render::eglProcedureIfCurrent(text)) return procedure;
  return reinterpret_cast<void (*)()>(OSMesaGetProcAddress(text));
}

namespace physdbg::render {
namespace {

// The renderer draws into framebuffer objects; OSMesa only needs some buffer
// to make the context current, so a tiny one is enough.
constexpr int kDummySize = 16;

class OsMesaContext final : public GlContext {
 public:
  OsMesaContext() : buffer_(kDummySize * kDummySize * 4) {
    const int attributes[] = {OSMESA_FORMAT,       OSMESA_RGBA,         OSMESA_DEPTH_BITS,
                              24,                  OSMESA_PROFILE,      OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION,
                              3,                   0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr) throw std::runtime_error("OSMesa: cannot create a GL 3.3 core context");
    makeCurrent();
    glewExperimental = GL_TRUE;
    glewInit();  // returns "GLX unsupported" under OSMesa even on success: check the version
    if (!GLEW_VERSION_3_3) {
      OSMesaDestroyContext(context_);
      throw std::runtime_error(
          "GLEW could not load GL 3.3 entry points (is the executable linked with ENABLE_EXPORTS?)");
    }
    while (glGetError() != GL_NO_ERROR) {
    }
  }
  ~OsMesaContext() override { OSMesaDestroyContext(context_); }
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  void makeCurrent() override {
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kDummySize, kDummySize))
      throw std::runtime_error("OSMesa: cannot make the context current");
  }

  std::string description() const override {
    auto text = [](GLenum name) {
      const GLubyte* value = glGetString(name);
      return value ? std::string(reinterpret_cast<const char*>(value)) : std::string("?");
    };
    return "OSMesa " + text(GL_VERSION) + ", " + text(GL_RENDERER);
  }

 private:
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlContext> createOsMesaContext() { return std::make_unique<OsMesaContext>(); }

}  // namespace physdbg::render
