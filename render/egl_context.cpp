// EGL backend of GlContext: a GL 3.3 core context with no surface at all
// (EGL_KHR_surfaceless_context); the renderer draws into its own framebuffer
// objects. OSMesa is gone from Mesa 25.1 on; this path works there and on GPU
// machines. The display comes from the surfaceless platform, or else from the
// first EGL device (EGL_EXT_platform_device, e.g. a GPU or Mesa's software device).
#include "render/gl_headers.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "render/gl_context.h"

namespace physdbg::render {
namespace {

std::string eglErrorText(const char* what) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
  return std::string("EGL: ") + what + " (error " + code + ")";
}

bool hasExtension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t length = std::strlen(name);
  for (const char* at = std::strstr(list, name); at != nullptr; at = std::strstr(at + 1, name))
    if ((at == list || at[-1] == ' ') && (at[length] == ' ' || at[length] == '\0')) return true;
  return false;
}

EGLDisplay openDisplay() {
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto getPlatformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (getPlatformDisplay == nullptr) throw std::runtime_error("EGL: eglGetPlatformDisplayEXT is missing");
  if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY) return display;
  }
  if (hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    EGLDeviceEXT device = nullptr;
    EGLint count = 0;
    if (queryDevices != nullptr && queryDevices(1, &device, &count) && count > 0) {
      EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
      if (display != EGL_NO_DISPLAY) return display;
    }
  }
  throw std::runtime_error("EGL: neither a surfaceless platform nor an EGL device is available "
                           "(install libegl-mesa0, or use --backend osmesa)");
}

class EglContext final : public GlContext {
 public:
  EglContext() : display_(openDisplay()) {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display_, &major, &minor)) throw std::runtime_error(eglErrorText("cannot initialise the display"));
    createContext();
  }
  // No eglTerminate: Mesa hands every context of a platform the same display,
  // and terminating it would pull it from under the others (the renderer's
  // and the GPU collision stage's live side by side). It goes with the process.
  ~EglContext() override {
    if (eglGetCurrentContext() == context_) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
  }
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  void makeCurrent() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw std::runtime_error(eglErrorText("cannot make the context current"));
  }

  std::string description() const override {
    auto text = [](GLenum name) {
      const GLubyte* value = glGetString(name);
      return value ? std::string(reinterpret_cast<const char*>(value)) : std::string("?");
    };
    return "EGL " + text(GL_VERSION) + ", " + text(GL_RENDERER);
  }

 private:
  void createContext() {
    if (!hasExtension(eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
      throw std::runtime_error("EGL: the display lacks EGL_KHR_surfaceless_context");
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error(eglErrorText("desktop OpenGL is not supported"));
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    // No config: the context never draws to an EGL surface (EGL_KHR_no_config_context in Mesa).
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT) throw std::runtime_error(eglErrorText("cannot create a GL 3.3 core context"));
    makeCurrent();
    glewExperimental = GL_TRUE;
    glewInit();  // like OSMesa, GLEW's GLX step fails without an X display: check the version
    if (!GLEW_VERSION_3_3) {
      eglDestroyContext(display_, context_);
      throw std::runtime_error("GLEW could not load GL 3.3 entry points under EGL");
    }
    while (glGetError() != GL_NO_ERROR) {
    }
  }

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

GlProcedure eglProcedureIfCurrent(const char* name) {
  if (eglGetCurrentContext() == EGL_NO_CONTEXT) return nullptr;
  return reinterpret_cast<GlProcedure>(eglGetProcAddress(name));
}

std::unique_ptr<GlContext> createEglContext() { return std::make_unique<EglContext>(); }

}  // namespace physdbg::render
