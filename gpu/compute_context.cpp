#include "gpu/compute_context.h"

#include "render/gl_context.h"
#include "render/gl_headers.h"

namespace physdbg::gpu {
namespace {

std::string glText(GLenum name) {
  const GLubyte* value = glGetString(name);
  return value ? std::string(reinterpret_cast<const char*>(value)) : std::string();
}

int glInteger(GLenum name) {
  GLint value = 0;
  glGetIntegerv(name, &value);
  return value;
}

int glIndexedInteger(GLenum name, GLuint index) {
  GLint value = 0;
  glGetIntegeri_v(name, index, &value);
  return value;
}

bool reaches(const ComputeIdentity& identity, GlVersion version) {
  return identity.major > version.major || (identity.major == version.major && identity.minor >= version.minor);
}

std::unique_ptr<render::GlContext> openContext(render::Backend backend) {
  try {
    return backend == render::Backend::Egl ? render::createEglContext() : render::createOsMesaContext();
  } catch (const std::exception& error) {
    throw ComputeUnavailable(std::string("no GL context for compute shaders: ") + error.what());
  }
}

// Reads the current context's strings and, when it has compute, its limits.
ComputeIdentity readIdentity(render::Backend backend) {
  ComputeIdentity identity;
  identity.backend = backend == render::Backend::Egl ? "egl" : "osmesa";
  identity.vendor = glText(GL_VENDOR);
  identity.renderer = glText(GL_RENDERER);
  identity.version = glText(GL_VERSION);
  identity.shadingLanguage = glText(GL_SHADING_LANGUAGE_VERSION);
  identity.major = glInteger(GL_MAJOR_VERSION);
  identity.minor = glInteger(GL_MINOR_VERSION);
  if (!reaches(identity, GlVersion{})) return identity;
  ComputeLimits& limits = identity.limits;
  for (GLuint axis = 0; axis < 3; ++axis) {
    limits.workGroupCount[axis] = glIndexedInteger(GL_MAX_COMPUTE_WORK_GROUP_COUNT, axis);
    limits.workGroupSize[axis] = glIndexedInteger(GL_MAX_COMPUTE_WORK_GROUP_SIZE, axis);
  }
  limits.workGroupInvocations = glInteger(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS);
  limits.sharedMemoryBytes = glInteger(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE);
  GLint64 blockBytes = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &blockBytes);
  limits.storageBlockBytes = blockBytes;
  limits.storageBufferBindings = glInteger(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS);
  while (glGetError() != GL_NO_ERROR) {
  }
  return identity;
}

}  // namespace

ComputeContext::ComputeContext(render::Backend backend, GlVersion required) : context_(openContext(backend)) {
  identity_ = readIdentity(backend);
  if (!reaches(identity_, required))
    throw ComputeUnavailable("the collision stage's compute shaders need OpenGL " + std::to_string(required.major) +
                             "." + std::to_string(required.minor) + " or later, but the " + identity_.backend +
                             " context is OpenGL " + std::to_string(identity_.major) + "." +
                             std::to_string(identity_.minor) + " (" + identity_.version + ", " +
                             identity_.renderer + ")");
}

ComputeContext::~ComputeContext() = default;

void ComputeContext::makeCurrent() { context_->makeCurrent(); }

bool ComputeContext::tryMakeCurrent() noexcept {
  try {
    context_->makeCurrent();
    return true;
  } catch (...) {
    return false;
  }
}

ComputeIdentity probeContext(render::Backend backend) {
  auto context = openContext(backend);
  return readIdentity(backend);
}

}  // namespace physdbg::gpu
