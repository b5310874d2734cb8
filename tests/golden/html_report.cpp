#include "tests/golden/html_report.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "reports/html_index.h"

namespace physdbg::golden {
namespace {

namespace fs = std::filesystem;
using reports::escapeHtml;

std::string readText(const fs::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string caseSection(const fs::path& folder) {
  const std::string name = folder.filename().string();
  std::ostringstream html;
  html << "<section><h2>" << escapeHtml(name) << "</h2><p>" << escapeHtml(readText(folder / "figures.txt"))
       << "</p><div class=row>";
  for (const char* image : {"expected", "actual", "diff"})
    html << "<figure><img src=\"" << escapeHtml(name) << "/" << image << ".png\"><figcaption>" << image
         << "</figcaption></figure>";
  html << "</div></section>\n";
  return html.str();
}

// Written to a temporary file and renamed, so a reader never sees half a page.
void writeIndex(const fs::path& reportRoot, const std::string& writer) {
  std::vector<fs::path> folders;
  if (fs::is_directory(reportRoot))
    for (const fs::directory_entry& entry : fs::directory_iterator(reportRoot))
      if (entry.is_directory() && fs::exists(entry.path() / "figures.txt")) folders.push_back(entry.path());
  std::sort(folders.begin(), folders.end());
  fs::create_directories(reportRoot);
  const fs::path temporary = reportRoot / (".index-" + writer + ".html");
  {
    std::ofstream page(temporary);
    page << "<!doctype html><meta charset=utf-8><title>physdbg golden failures</title>\n"
            "<style>body{font-family:sans-serif;background:#222;color:#ddd} .row{display:flex;gap:12px}"
            " img{width:480px;image-rendering:pixelated;border:1px solid #555} figure{margin:0}</style>\n"
            "<h1>Golden-image failures: "
         << folders.size()
         << "</h1><p>diff: red = different, yellow = within one pixel of a match, blue = below the threshold "
            "(amplified), grey = equal. Regenerate goldens after an intended change with "
            "<code>bash scripts/update-goldens.sh</code>.</p>\n";
    for (const fs::path& folder : folders) page << caseSection(folder);
    if (!page) throw std::runtime_error("cannot write " + temporary.string());
  }
  fs::rename(temporary, reportIndex(reportRoot));
}

}  // namespace

fs::path reportIndex(const fs::path& reportRoot) { return reportRoot / "index.html"; }

fs::path recordFailure(const fs::path& reportRoot, const FailedComparison& failure) {
  if (!failure.expected || !failure.actual || !failure.diff)
    throw std::invalid_argument("recordFailure: expected, actual and diff images are all needed");
  const fs::path folder = reportRoot / failure.caseName;
  fs::create_directories(folder);
  render::writePng((folder / "expected.png").string(), *failure.expected);
  render::writePng((folder / "actual.png").string(), *failure.actual);
  render::writePng((folder / "diff.png").string(), *failure.diff);
  std::ofstream(folder / "figures.txt") << failure.figures;
  writeIndex(reportRoot, failure.caseName);
  return folder;
}

void clearFailure(const fs::path& reportRoot, const std::string& caseName) {
  if (!fs::exists(reportRoot / caseName)) return;
  fs::remove_all(reportRoot / caseName);
  writeIndex(reportRoot, caseName);
}

}  // namespace physdbg::golden
