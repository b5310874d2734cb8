#include "golden/case_check.h"

#include <chrono>
#include <set>
#include <stdexcept>

#include "golden/approval_record.h"
#include "golden/frame_check.h"
#include "golden/golden_store.h"

namespace physdbg::golden {
namespace {

namespace fs = std::filesystem;

constexpr char kRecordFile[] = "approved.json";

std::string frameLabel(int frame) { return "frame " + std::to_string(frame); }

std::string frameFolder(const ManifestCase& golden, int frame) {
  return (reportCaseFolder(golden.name) / fs::path(frameFileName(frame)).stem()).string();
}

// Every frame skipped for one reason: nothing was compared.
CaseResult skippedCase(const ManifestCase& golden, const std::string& reason) {
  CaseResult result{golden.name, describeCase(golden), Verdict::Skipped, reason, {}, 0};
  for (const int frame : golden.frames) result.frames.push_back({frameLabel(frame), Verdict::Skipped, reason, ""});
  return result;
}

FrameResult checkOneFrame(const ManifestCase& golden, int frame, const render::Image& actual, const fs::path& folder,
                          const fs::path& reportRoot) {
  const fs::path approved = folder / frameFileName(frame);
  if (!fs::exists(approved))
    return {frameLabel(frame), Verdict::Failed,
            "no approved picture " + approved.string() + ": approve the case again (physdbg golden approve)", ""};
  render::Image expected;
  try {
    expected = render::readPng(approved.string());
  } catch (const std::runtime_error& error) {
    return {frameLabel(frame), Verdict::Failed, std::string("approved picture unreadable: ") + error.what(), ""};
  }
  return checkFrame({frameLabel(frame), &expected, &actual}, reportRoot, frameFolder(golden, frame));
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void removeUnlistedFrames(const ManifestCase& golden, const fs::path& folder) {
  std::set<std::string> listed;
  for (const int frame : golden.frames) listed.insert(frameFileName(frame));
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with("frame_") && name.ends_with(".png") && !listed.count(name)) fs::remove(entry.path());
  }
}

}  // namespace

fs::path storeRoot(const Manifest& manifest) { return manifest.folder / "golden"; }

fs::path reportCaseFolder(const std::string& caseName) { return fs::path("cases") / caseName; }

std::string describeCase(const ManifestCase& golden) {
  std::string text = "scene '" + golden.sceneName + "', " + std::to_string(golden.width) + "x" +
                     std::to_string(golden.height) + ", layers " + golden.layers;
  if (golden.solver) text += ", solver " + std::string(solverKindName(*golden.solver));
  return text;
}

std::vector<fs::path> approveCase(const ManifestCase& golden, RendererPool& renderers, const fs::path& store) {
  const std::vector<render::Image> images = renderCaseFrames(golden, renderers);
  const std::string key = renderers.key();
  const fs::path folder = caseFolder(store, key, golden.name);
  fs::create_directories(folder);
  removeUnlistedFrames(golden, folder);
  std::vector<fs::path> written;
  for (std::size_t index = 0; index < images.size(); ++index) {
    written.push_back(folder / frameFileName(golden.frames[index]));
    render::writePng(written.back().string(), images[index], 9);
  }
  written.push_back(folder / kRecordFile);
  writeApprovalRecord(written.back(), approvalRecordOf(golden, key, renderers.identity()));
  return written;
}

CaseResult checkCase(const ManifestCase& golden, RendererPool& renderers, const fs::path& store,
                     const fs::path& reportRoot) {
  const auto start = std::chrono::steady_clock::now();
  const std::string key = renderers.key();
  if (!fs::is_directory(store / key))
    return skippedCase(golden, "no approved frames for renderer key '" + key + "' (" + renderers.identity().renderer +
                                   "): " + (store / key).string() + " does not exist");
  const fs::path folder = caseFolder(store, key, golden.name);
  CaseResult result{golden.name, describeCase(golden), Verdict::Passed, "", {}, 0};
  if (!fs::is_directory(folder)) result.message = "not approved for renderer key '" + key + "': no " + folder.string();
  const std::vector<render::Image> images = renderCaseFrames(golden, renderers);
  for (std::size_t index = 0; index < images.size(); ++index)
    result.frames.push_back(checkOneFrame(golden, golden.frames[index], images[index], folder, reportRoot));
  result.verdict = combinedVerdict(result.frames);
  const std::optional<ApprovalRecord> approved = readApprovalRecord(folder / kRecordFile);
  if (approved && result.verdict == Verdict::Failed) {
    const std::string changes = describeChanges(*approved, approvalRecordOf(golden, key, renderers.identity()));
    if (!changes.empty()) result.message += (result.message.empty() ? "" : "; ") + changes;
  }
  result.seconds = secondsSince(start);
  return result;
}

}  // namespace physdbg::golden
