#pragma once
// One function per physdbg subcommand; each returns the process exit code.
#include <functional>
#include <string>
#include <vector>

namespace physdbg::cli {

struct Subcommand {
  std::string name;
  std::string summary;
  std::function<int(const std::vector<std::string>& args)> run;
};

int runScenes(const std::vector<std::string>& args);
int runSimulate(const std::vector<std::string>& args);
int runRender(const std::vector<std::string>& args);
int runContacts(const std::vector<std::string>& args);
int runBench(const std::vector<std::string>& args);
int runCompare(const std::vector<std::string>& args);
int runTree(const std::vector<std::string>& args);
int runRecord(const std::vector<std::string>& args);
int runReplay(const std::vector<std::string>& args);
int runReport(const std::vector<std::string>& args);
int runDiff(const std::vector<std::string>& args);
int runPlot(const std::vector<std::string>& args);
int runGolden(const std::vector<std::string>& args);
int runGpuInfo(const std::vector<std::string>& args);

}  // namespace physdbg::cli
