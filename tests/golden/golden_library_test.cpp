// The golden/ library's pieces that need no renderer: case names that may
// become folder names, result files surviving a round trip (how -j hands
// verdicts back), and the JUnit and HTML text escaping hostile names.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>

#include "golden/html_report.h"
#include "golden/junit_report.h"
#include "golden/manifest.h"
#include "golden/result_file.h"

namespace physdbg::golden {
namespace {

namespace fs = std::filesystem;

std::string fileText(const fs::path& path) {
  std::ifstream file(path);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

class GoldenLibrary : public ::testing::Test {
 protected:
  fs::path folder = fs::temp_directory_path() / ("physdbg-golden-library-" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(folder); }
  void TearDown() override { fs::remove_all(folder); }

  // A hostile name (the manifest would refuse it; a result file might not).
  const std::vector<CaseResult> results = {
      {"a\"<b>&'c\x01", "scene 'x'", Verdict::Failed, "note", {{"frame 3", Verdict::Failed, "DIFFERENT: 1", "a/f"}}, 1.5},
      {"skip", "scene 'y'", Verdict::Skipped, "no key", {{"frame 0", Verdict::Skipped, "no key", ""}}, 0}};
};

TEST_F(GoldenLibrary, CaseNamesArePlainFileNames) {
  for (const char* good : {"drop", "stack_4.x", "A-1", "a..b"}) EXPECT_TRUE(isValidCaseName(good)) << good;
  for (const char* bad : {"", ".", "..", "../../x", "a/b", "a\\b", ".hidden", "a b", "caf\xc3\xa9"})
    EXPECT_FALSE(isValidCaseName(bad)) << bad;
  EXPECT_TRUE(isValidCaseName(std::string(64, 'a')));
  EXPECT_FALSE(isValidCaseName(std::string(65, 'a')));
}

TEST_F(GoldenLibrary, ResultFileRoundTrips) {
  writeResultFile(folder / "r.json", results);
  const std::vector<CaseResult> read = readResultFile(folder / "r.json");
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0].name, results[0].name);
  EXPECT_EQ(read[0].frames[0].images, "a/f");
  EXPECT_EQ(read[1].verdict, Verdict::Skipped);
  std::ofstream(folder / "bad.json") << "{\"cases\": [{\"name\": 1}]}";
  EXPECT_THROW(readResultFile(folder / "bad.json"), std::runtime_error);
}

TEST_F(GoldenLibrary, JunitEscapesNamesAndMarksSkipped) {
  writeJunitReport(folder / "j.xml", "suite", results);
  const std::string xml = fileText(folder / "j.xml");
  EXPECT_NE(xml.find("classname=\"a&quot;&lt;b&gt;&amp;&#39;c?\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("tests=\"2\" failures=\"1\" errors=\"0\" skipped=\"1\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("<skipped message=\"no key\"/>"), std::string::npos) << xml;
}

TEST_F(GoldenLibrary, HtmlReportEscapesNamesAndCountsVerdicts) {
  writeHtmlReport(folder, {"title <x>", "hint"}, results);
  const std::string page = fileText(reportIndex(folder));
  EXPECT_EQ(page.find("<b>"), std::string::npos);
  EXPECT_NE(page.find("0 passed</span>, <span class=failed>1 failed</span>, <span class=skipped>1 skipped"),
            std::string::npos);
  EXPECT_NE(page.find("src=\"a/f/diff.png\""), std::string::npos);
}

}  // namespace
}  // namespace physdbg::golden
