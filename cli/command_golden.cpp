// physdbg golden approve|check MANIFEST: golden images of a user's own
// scenes, stored, judged and reported by the golden/ library exactly as the
// project's own golden tests are. Exit 0 all matched (skipped cases, which
// compared nothing, are counted and shown but fail only with --fail-on-skip),
// 1 a frame differs, 2 bad usage or a bad manifest (the message names the
// file and key).
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/golden_parallel.h"
#include "cli/output_folder.h"
#include "golden/case_check.h"
#include "golden/html_report.h"
#include "golden/junit_report.h"
#include "golden/result_file.h"

namespace physdbg::cli {
namespace {

namespace fs = std::filesystem;
using golden::CaseResult;
using golden::ManifestCase;

// At most this many cases run at once: each holds a GL context and its frames.
constexpr int kMaxJobs = 64;

const OptionSpec kCaseOption{"--case", "", "NAME", "only the case NAME"};

const char kUsage[] =
    "usage: physdbg golden approve MANIFEST [--case NAME]\n"
    "       physdbg golden check MANIFEST [--report DIR] [--junit FILE] [-j N] [--sshloginfile FILE]\n"
    "                                     [--case NAME] [--result FILE] [--fail-on-skip]\n\n"
    "Golden images of your own scenes: 'approve' renders each case of MANIFEST and stores its frames\n"
    "in MANIFEST_DIR/golden/KEY/CASE/ (KEY names this machine's renderer); 'check' renders them again\n"
    "and compares. Run 'physdbg golden approve --help' or 'physdbg golden check --help' for options.\n";

std::vector<const ManifestCase*> selectCases(const golden::Manifest& manifest, const Arguments& arguments) {
  std::vector<const ManifestCase*> cases;
  const std::string only = arguments.value("--case");
  for (const ManifestCase& candidate : manifest.cases)
    if (!arguments.has("--case") || candidate.name == only) cases.push_back(&candidate);
  if (cases.empty())
    throw UsageError("--case: '" + only + "' is not a case of " + manifest.file.string());
  return cases;
}

int runApprove(const std::vector<std::string>& args) {
  const CommandSpec spec{"golden approve", "MANIFEST [--case NAME]",
                         "Renders each case of MANIFEST and stores its frames and an approval record (renderer,\n"
                         "physdbg version, scene hash) in MANIFEST_DIR/golden/KEY/CASE/.",
                         {kCaseOption}, 1, 1};
  const auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const golden::Manifest manifest = golden::readManifest(parsed->positional()[0]);
  golden::RendererPool renderers;
  for (const ManifestCase* golden : selectCases(manifest, *parsed)) {
    const std::vector<fs::path> written =
        asUsageError([&] { return golden::approveCase(*golden, renderers, golden::storeRoot(manifest)); });
    std::printf("approved %s: %zu frames in %s\n", golden->name.c_str(), golden->frames.size(),
                written.front().parent_path().c_str());
  }
  return 0;
}

void printResult(const CaseResult& result) {
  std::printf("%s: %s (%zu frames, %.2f s)%s%s\n", result.name.c_str(), golden::verdictName(result.verdict),
              result.frames.size(), result.seconds, result.message.empty() ? "" : ": ", result.message.c_str());
  for (const golden::FrameResult& frame : result.frames)
    if (frame.verdict == golden::Verdict::Failed)
      std::printf("  %s: %s\n", frame.label.c_str(), frame.figures.c_str());
  std::fflush(stdout);
}

// Each case in this process; its old pictures in the report go first.
std::vector<CaseResult> checkHere(const golden::Manifest& manifest, const std::vector<const ManifestCase*>& cases,
                                  const std::string& reportDir) {
  golden::RendererPool renderers;
  std::vector<CaseResult> results;
  for (const ManifestCase* golden : cases) {
    if (!reportDir.empty()) fs::remove_all(fs::path(reportDir) / golden::reportCaseFolder(golden->name));
    results.push_back(asUsageError(
        [&] { return golden::checkCase(*golden, renderers, golden::storeRoot(manifest), reportDir); }));
    printResult(results.back());
  }
  return results;
}

// Cases on other machines report back through the report folder, which they must share.
void checkMachines(const Arguments& arguments) {
  const std::string file = arguments.value("--sshloginfile");
  if (!fs::is_regular_file(file)) throw UsageError("--sshloginfile: '" + file + "' is not a file");
  if (!arguments.has("--report"))
    throw UsageError("--sshloginfile: needs --report DIR on a folder every machine shares at the same path (the "
                     "cases' results and pictures come back through it)");
}

std::vector<CaseResult> checkCases(const golden::Manifest& manifest, const std::vector<const ManifestCase*>& cases,
                                   const Arguments& arguments) {
  const int jobs = arguments.positiveInt("--jobs", 1, kMaxJobs);
  const std::string reportDir = arguments.value("--report");
  if (jobs == 1 && !arguments.has("--sshloginfile")) return checkHere(manifest, cases, reportDir);
  if (arguments.has("--sshloginfile")) checkMachines(arguments);
  ParallelCheck check{manifest.file, {}, jobs, arguments.value("--sshloginfile"), reportDir};
  for (const ManifestCase* golden : cases) check.cases.push_back(golden->name);
  std::vector<CaseResult> results = checkThroughParallel(check);
  for (const CaseResult& result : results)
    if (result.frames.empty()) printResult(result);  // its process said nothing
  return results;
}

void writeOutputs(const Arguments& arguments, const golden::Manifest& manifest,
                  const std::vector<CaseResult>& results) {
  const golden::ReportPage page{"physdbg golden check " + manifest.file.string(),
                                "After an intended change: physdbg golden approve " + manifest.file.string() +
                                    ", then review the new frames."};
  // A part of a -j run (--result) leaves the page to the process that gathers all parts.
  if (arguments.has("--report") && !arguments.has("--result")) {
    golden::writeHtmlReport(arguments.value("--report"), page, results);
    std::printf("report: %s\n", golden::reportIndex(arguments.value("--report")).c_str());
  }
  if (arguments.has("--junit")) golden::writeJunitReport(arguments.value("--junit"), "physdbg golden", results);
  if (arguments.has("--result")) golden::writeResultFile(arguments.value("--result"), results);
}

int runCheck(const std::vector<std::string>& args) {
  const CommandSpec spec{
      "golden check",
      "MANIFEST [--report DIR] [--junit FILE] [-j N] [--sshloginfile FILE] [--case NAME] [--result FILE] "
      "[--fail-on-skip]",
      "Renders each case of MANIFEST and compares its frames with the approved ones, like the golden tests.\n"
      "Exit 0 all matched, 1 a frame differs, 2 bad input. A case whose renderer key has no approved frames\n"
      "is skipped (nothing compared): counted, in the report and the JUnit file, exit 0 unless --fail-on-skip.",
      {{"--report", "", "DIR", "write DIR/index.html: every case, and each failed frame's expected, actual and "
                               "diff pictures with a flicker and a slider view"},
       {"--junit", "", "FILE", "write JUnit XML: one test per frame, <skipped/> for skipped ones"},
       {"--jobs", "-j", "N", "check N cases at a time, each in its own process, through GNU parallel (default 1: "
                             "all in this process)"},
       {"--sshloginfile", "", "FILE", "spread the cases over the machines in FILE (GNU parallel's --sshloginfile)"},
       kCaseOption,
       {"--result", "", "FILE", "write the verdicts as JSON (how -j gathers its cases)"},
       {"--fail-on-skip", "", "", "exit 1 when a case was skipped"}},
      1,
      1};
  const auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const golden::Manifest manifest = golden::readManifest(parsed->positional()[0]);
  const std::vector<const ManifestCase*> cases = selectCases(manifest, *parsed);
  if (parsed->has("--report")) prepareOutputDirectory(parsed->value("--report"), "--report");
  for (const std::string option : {"--junit", "--result"})
    if (parsed->has(option)) checkOutputFile(parsed->value(option), option);
  const std::vector<CaseResult> results = checkCases(manifest, cases, *parsed);
  writeOutputs(*parsed, manifest, results);
  const golden::Tally counts = golden::tally(results);
  if (!parsed->has("--result"))
    std::printf("golden check: %d passed, %d failed, %d skipped\n", counts.passed, counts.failed, counts.skipped);
  const bool skipFails = parsed->has("--fail-on-skip") && counts.skipped > 0;
  return counts.failed > 0 || skipFails ? 1 : 0;
}

}  // namespace

int runGolden(const std::vector<std::string>& args) {
  const std::string action = args.empty() ? "" : args.front();
  const std::vector<std::string> rest(args.begin() + (args.empty() ? 0 : 1), args.end());
  if (action == "approve") return runApprove(rest);
  if (action == "check") return runCheck(rest);
  if (action == "--help" || action == "-h") {
    std::cout << kUsage;
    return 0;
  }
  std::cerr << kUsage;
  throw UsageError(action.empty() ? "expected approve or check" : "expected approve or check, got '" + action + "'");
}

}  // namespace physdbg::cli
