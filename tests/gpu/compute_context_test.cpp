// The compute context on this machine's llvmpipe, and its refusal of a GL
// that cannot run compute shaders.
#include "gpu/compute_context.h"

#include <gtest/gtest.h>

namespace physdbg::gpu {
namespace {

TEST(ComputeContext, OsMesaGivesGl43AndReportsLimits) {
  ComputeContext context(render::Backend::OsMesa);
  const ComputeIdentity& identity = context.identity();
  EXPECT_GE(identity.major * 10 + identity.minor, 43) << identity.version;
  EXPECT_FALSE(identity.renderer.empty());
  EXPECT_GE(identity.limits.workGroupInvocations, 1024);  // GL 4.3's guaranteed minimum
  EXPECT_GE(identity.limits.workGroupCount[0], 65535);
  EXPECT_GE(identity.limits.storageBufferBindings, 8);
  EXPECT_GE(identity.limits.storageBlockBytes, 1LL << 24);
}

TEST(ComputeContext, RefusesAContextBelowTheVersionAskedAndSaysWhatIsMissing) {
  // No context has GL 9.0: the refusal path, as a GL 3.3 machine meets it
  // (the CLI test runs that one under MESA_GL_VERSION_OVERRIDE=3.3).
  try {
    ComputeContext context(render::Backend::OsMesa, GlVersion{9, 0});
    FAIL() << "a context below GL 9.0 was accepted";
  } catch (const ComputeUnavailable& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("need OpenGL 9.0"), std::string::npos) << message;
    EXPECT_NE(message.find("context is OpenGL 4."), std::string::npos) << message;
    EXPECT_NE(message.find("llvmpipe"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace physdbg::gpu
