#include "golden/approval_record.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace physdbg::golden {
namespace {

using nlohmann::json;

std::string sizeText(const ManifestCase& golden) {
  return std::to_string(golden.width) + "x" + std::to_string(golden.height);
}

void noteChange(std::string& text, const std::string& what, const std::string& was, const std::string& now) {
  if (was == now) return;
  text += (text.empty() ? "" : "; ") + what + " was '" + was + "' at approval, now '" + now + "'";
}

}  // namespace

std::string physdbgVersion() { return PHYSDBG_VERSION; }

ApprovalRecord approvalRecordOf(const ManifestCase& golden, const std::string& key, const render::GlIdentity& gl) {
  return {golden.name,      key,          gl.renderer,   gl.version,
          physdbgVersion(), golden.sceneName, golden.sceneHash, sizeText(golden),
          golden.layers,    solverKindName(golden.scene.world.solver.kind), golden.frames};
}

void writeApprovalRecord(const std::filesystem::path& path, const ApprovalRecord& record) {
  const json value = {{"case", record.caseName},
                      {"renderer_key", record.rendererKey},
                      {"gl_renderer", record.glRenderer},
                      {"gl_version", record.glVersion},
                      {"physdbg_version", record.physdbgVersion},
                      {"scene", record.scene},
                      {"scene_hash", record.sceneHash},
                      {"size", record.size},
                      {"layers", record.layers},
                      {"solver", record.solver},
                      {"frames", record.frames}};
  std::ofstream file(path);
  file << value.dump(1) << "\n";
  if (!file) throw std::runtime_error("cannot write approval record '" + path.string() + "'");
}

std::optional<ApprovalRecord> readApprovalRecord(const std::filesystem::path& path) {
  std::ifstream file(path);
  if (!file) return std::nullopt;
  std::stringstream text;
  text << file.rdbuf();
  try {
    const json value = json::parse(text.str());
    return ApprovalRecord{value.at("case"),       value.at("renderer_key"), value.at("gl_renderer"),
                          value.at("gl_version"), value.at("physdbg_version"), value.at("scene"),
                          value.at("scene_hash"), value.at("size"),         value.at("layers"),
                          value.at("solver"),     value.at("frames").get<std::vector<int>>()};
  } catch (const json::exception&) {
    return std::nullopt;
  }
}

std::string describeChanges(const ApprovalRecord& approved, const ApprovalRecord& now) {
  std::string text;
  noteChange(text, "scene", approved.scene, now.scene);
  if (approved.scene == now.scene && approved.sceneHash != now.sceneHash)
    text += std::string(text.empty() ? "" : "; ") + "the scene changed since approval (hash " + approved.sceneHash +
            ", now " + now.sceneHash + ")";
  noteChange(text, "size", approved.size, now.size);
  noteChange(text, "layers", approved.layers, now.layers);
  noteChange(text, "solver", approved.solver, now.solver);
  noteChange(text, "physdbg version", approved.physdbgVersion, now.physdbgVersion);
  return text;
}

}  // namespace physdbg::golden
