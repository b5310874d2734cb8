// What the GL context of a backend is, and whether (and how far) it can run
// the collision stage's compute shaders: the first thing to ask on a new
// machine before --collision gpu.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/common_options.h"
#include "gpu/compute_context.h"

namespace physdbg::cli {
namespace {

bool computeCapable(const gpu::ComputeIdentity& identity) {
  return identity.major > 4 || (identity.major == 4 && identity.minor >= 3);
}

nlohmann::json identityJson(const gpu::ComputeIdentity& identity) {
  const gpu::ComputeLimits& limits = identity.limits;
  nlohmann::json json{{"backend", identity.backend},
                      {"vendor", identity.vendor},
                      {"renderer", identity.renderer},
                      {"version", identity.version},
                      {"glsl", identity.shadingLanguage},
                      {"gl_major", identity.major},
                      {"gl_minor", identity.minor},
                      {"compute", computeCapable(identity)}};
  if (computeCapable(identity))
    json["limits"] = {{"work_group_count", {limits.workGroupCount[0], limits.workGroupCount[1], limits.workGroupCount[2]}},
                      {"work_group_size", {limits.workGroupSize[0], limits.workGroupSize[1], limits.workGroupSize[2]}},
                      {"work_group_invocations", limits.workGroupInvocations},
                      {"shared_memory_bytes", limits.sharedMemoryBytes},
                      {"storage_block_bytes", limits.storageBlockBytes},
                      {"storage_buffer_bindings", limits.storageBufferBindings}};
  return json;
}

void printIdentity(const gpu::ComputeIdentity& identity) {
  std::printf("backend   %s\nvendor    %s\nrenderer  %s\nversion   %s\nGLSL      %s\n", identity.backend.c_str(),
              identity.vendor.c_str(), identity.renderer.c_str(), identity.version.c_str(),
              identity.shadingLanguage.c_str());
  if (!computeCapable(identity)) return;
  const gpu::ComputeLimits& limits = identity.limits;
  std::printf("compute   work groups up to %d x %d x %d, of up to %d x %d x %d (%d invocations), %d bytes shared\n",
              limits.workGroupCount[0], limits.workGroupCount[1], limits.workGroupCount[2], limits.workGroupSize[0],
              limits.workGroupSize[1], limits.workGroupSize[2], limits.workGroupInvocations, limits.sharedMemoryBytes);
  std::printf("storage   %d buffer bindings, blocks up to %lld bytes\n", limits.storageBufferBindings,
              limits.storageBlockBytes);
}

}  // namespace

int runGpuInfo(const std::vector<std::string>& args) {
  CommandSpec spec{"gpu-info",
                   "[--json]",
                   "Prints the GL context's vendor, renderer, version and compute limits. Exits with 2 when the\n"
                   "context cannot run compute shaders (OpenGL 4.3), which --collision gpu needs.",
                   {{"--json", "", "", "print a JSON object instead"}},
                   0,
                   0};
  addOptions(spec, {OptionGroup::Backend});
  const auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  gpu::ComputeIdentity identity;
  try {
    identity = gpu::probeContext(readBackend(*parsed));
  } catch (const gpu::ComputeUnavailable& error) {
    throw UsageError(error.what());
  }
  if (parsed->has("--json")) std::cout << identityJson(identity).dump(2) << "\n";
  else printIdentity(identity);
  if (computeCapable(identity)) return 0;
  std::cerr << "physdbg gpu-info: this context cannot run compute shaders: it is OpenGL " << identity.major << "."
            << identity.minor << ", and --collision gpu needs OpenGL 4.3\n";
  return 2;
}

}  // namespace physdbg::cli
