// The process runner behind render --video and the accuracy plots: argument
// vectors reach the program literally, no shell is involved, exit statuses
// and failures to start are reported.
#include "reports/child_process.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <csignal>
#include <filesystem>
#include <stdexcept>

#include "tests/support/visual_test_support.h"

namespace {

namespace fs = std::filesystem;

using physdbg::ChildCommand;
using physdbg::ChildProcess;
using physdbg::findExecutable;
using physdbg::runChild;
using physdbg::visualtesting::ScratchFolder;

ChildCommand command(const std::string& program, std::vector<std::string> arguments, const std::string& folder = "") {
  ChildCommand result;
  result.program = program;
  result.arguments = std::move(arguments);
  result.workingDirectory = folder;
  return result;
}

TEST(ChildProcess, FindsProgramsOnThePathAsAbsolutePaths) {
  const auto touch = findExecutable("touch");
  ASSERT_TRUE(touch.has_value());
  EXPECT_TRUE(fs::path(*touch).is_absolute()) << *touch;
  EXPECT_FALSE(findExecutable("physdbg-no-such-program").has_value());
  EXPECT_FALSE(findExecutable("").has_value());
}

TEST(ChildProcess, ReportsExitCodes) {
  EXPECT_TRUE(runChild(command("true", {})).succeeded());
  const physdbg::ChildExit failed = runChild(command("false", {}));
  EXPECT_FALSE(failed.succeeded());
  EXPECT_TRUE(failed.exited);
  EXPECT_EQ(failed.code, 1);
  EXPECT_EQ(failed.describe(), "exit code 1");
}

// With a shell, "a;touch b" would create two files.
TEST(ChildProcess, ArgumentsReachTheProgramLiterallyInItsFolder) {
  ScratchFolder folder;
  const std::string hostile = "a';touch b;'$(touch c)`touch d` e";
  ASSERT_TRUE(runChild(command("touch", {hostile}, folder / "")).succeeded());
  EXPECT_TRUE(fs::exists(folder / hostile));
  for (const char* name : {"b", "c", "d", "e"}) EXPECT_FALSE(fs::exists(folder / name)) << name;
}

TEST(ChildProcess, AMissingProgramIsAnErrorNamingIt) {
  try {
    runChild(command("physdbg-no-such-program", {}));
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("physdbg-no-such-program"), std::string::npos) << error.what();
  }
}

// An abandoned child (an exception between start and wait) is stopped, not waited for.
// Once destroyed, the child is gone and reaped: no process with its id is left.
TEST(ChildProcess, DestroyingAnUnwaitedChildStopsIt) {
  pid_t id = -1;
  {
    ChildProcess sleeper(command("sleep", {"30"}));
    id = sleeper.id();
    ASSERT_GT(id, 0);
    ASSERT_EQ(::kill(id, 0), 0) << "the child should be running";
  }
  errno = 0;
  EXPECT_EQ(::kill(id, 0), -1);
  EXPECT_EQ(errno, ESRCH);
}

}  // namespace
