#include "golden/junit_report.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "golden/markup_escape.h"

namespace physdbg::golden {
namespace {

std::string seconds(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", value);
  return text;
}

std::string frameOutcome(const CaseResult& result, const FrameResult& frame) {
  if (frame.verdict == Verdict::Passed) return "";
  const std::string message = escapeMarkup(frame.figures.empty() ? result.message : frame.figures);
  if (frame.verdict == Verdict::Skipped) return "<skipped message=\"" + message + "\"/>";
  std::ostringstream xml;
  xml << "<failure message=\"" << message << "\">" << escapeMarkup(result.description);
  if (!result.message.empty()) xml << "\n" << escapeMarkup(result.message);
  if (!frame.images.empty()) xml << "\npictures: " << escapeMarkup(frame.images);
  xml << "</failure>";
  return xml.str();
}

// A case that failed as a whole (its process died) has no frames: it is one test.
std::vector<FrameResult> framesOrWhole(const CaseResult& result) {
  if (!result.frames.empty()) return result.frames;
  return {{"case", result.verdict, result.message, ""}};
}

std::string testCases(const CaseResult& result) {
  std::ostringstream xml;
  const std::vector<FrameResult> frames = framesOrWhole(result);
  const double share = result.seconds / double(frames.size());
  for (const FrameResult& frame : frames)
    xml << "  <testcase classname=\"" << escapeMarkup(result.name) << "\" name=\"" << escapeMarkup(frame.label)
        << "\" time=\"" << seconds(share) << "\">" << frameOutcome(result, frame) << "</testcase>\n";
  return xml.str();
}

struct FrameCounts {
  int tests = 0, failures = 0, skipped = 0;
  double seconds = 0;
};

FrameCounts countFrames(const std::vector<CaseResult>& results) {
  FrameCounts counts;
  for (const CaseResult& result : results) {
    counts.seconds += result.seconds;
    for (const FrameResult& frame : framesOrWhole(result)) {
      ++counts.tests;
      counts.failures += frame.verdict == Verdict::Failed;
      counts.skipped += frame.verdict == Verdict::Skipped;
    }
  }
  return counts;
}

}  // namespace

void writeJunitReport(const std::filesystem::path& path, const std::string& suiteName,
                      const std::vector<CaseResult>& results) {
  const FrameCounts counts = countFrames(results);
  std::ofstream file(path);
  file << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n<testsuite name=\"" << escapeMarkup(suiteName)
       << "\" tests=\"" << counts.tests << "\" failures=\"" << counts.failures << "\" errors=\"0\" skipped=\""
       << counts.skipped << "\" time=\"" << seconds(counts.seconds) << "\">\n";
  for (const CaseResult& result : results) file << testCases(result);
  file << "</testsuite>\n</testsuites>\n";
  if (!file) throw std::runtime_error("cannot write JUnit file '" + path.string() + "'");
}

}  // namespace physdbg::golden
