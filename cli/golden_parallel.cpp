#include "cli/golden_parallel.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "cli/arguments.h"
#include "golden/result_file.h"
#include "reports/child_process.h"

namespace physdbg::cli {
namespace {

namespace fs = std::filesystem;

// A fresh folder for the result files, removed with everything in it.
class ResultFolder {
 public:
  explicit ResultFolder(const fs::path& parent) {
    std::string pattern = (parent / ".golden-results-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot create a result folder in " + parent.string());
    path_ = pattern;
  }
  ~ResultFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ResultFolder(const ResultFolder&) = delete;
  ResultFolder& operator=(const ResultFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// Results and pictures must reach this machine: with --report they go there
// (on a shared folder for several machines), else to the temporary folder.
fs::path resultParent(const ParallelCheck& check) {
  return check.reportDir.empty() ? fs::temp_directory_path() : fs::absolute(check.reportDir);
}

ChildCommand parallelCommand(const std::string& parallel, const ParallelCheck& check, const fs::path& results) {
  ChildCommand command{parallel, {"--will-cite", "--quote", "--jobs", std::to_string(check.jobs)}, "", false};
  if (!check.sshLoginFile.empty()) {
    for (const std::string word : {"--sshloginfile", check.sshLoginFile.c_str(), "--env", "LP_NUM_THREADS"})
      command.arguments.push_back(word);
  }
  const std::vector<std::string> child = {fs::read_symlink("/proc/self/exe").string(), "golden", "check",
                                          fs::absolute(check.manifest).string(), "--case", "{}", "--result",
                                          (results / "{}.json").string()};
  command.arguments.insert(command.arguments.end(), child.begin(), child.end());
  if (!check.reportDir.empty()) {
    command.arguments.push_back("--report");
    command.arguments.push_back(fs::absolute(check.reportDir).string());
  }
  command.arguments.push_back(":::");
  command.arguments.insert(command.arguments.end(), check.cases.begin(), check.cases.end());
  return command;
}

golden::CaseResult gatherResult(const fs::path& file, const std::string& name, const ParallelCheck& check) {
  std::string problem = "it holds another case";
  try {
    std::vector<golden::CaseResult> results = golden::readResultFile(file);
    if (results.size() == 1 && results.front().name == name) return results.front();
  } catch (const std::runtime_error& error) {
    problem = error.what();
  }
  return {name, "", golden::Verdict::Failed,
          "its process left no result (" + problem + "); run it alone: physdbg golden check " +
              check.manifest.string() + " --case " + name,
          {}, 0};
}

}  // namespace

std::vector<golden::CaseResult> checkThroughParallel(const ParallelCheck& check) {
  const std::optional<std::string> parallel = findExecutable("parallel");
  if (!parallel)
    throw UsageError("-j " + std::to_string(check.jobs) +
                     ": the cases run through GNU parallel, which is not on PATH (apt-get install parallel, or bash "
                     "scripts/setup.sh); -j 1 checks them in this process");
  const ResultFolder results(resultParent(check));
  std::printf("golden check: %zu cases through GNU parallel, %d at a time%s\n", check.cases.size(), check.jobs,
              check.sshLoginFile.empty() ? "" : (" on the machines of " + check.sshLoginFile).c_str());
  std::fflush(stdout);
  const ChildExit exit = runChild(parallelCommand(*parallel, check, results.path()));
  if (!exit.exited) std::fprintf(stderr, "physdbg golden: parallel ended by %s\n", exit.describe().c_str());
  std::vector<golden::CaseResult> gathered;
  for (const std::string& name : check.cases)
    gathered.push_back(gatherResult(results.path() / (name + ".json"), name, check));
  return gathered;
}

}  // namespace physdbg::cli
