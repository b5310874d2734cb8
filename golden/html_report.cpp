#include "golden/html_report.h"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

#include "golden/markup_escape.h"

namespace physdbg::golden {
namespace {

namespace fs = std::filesystem;

constexpr char kStyle[] =
    "<style>body{font-family:sans-serif;background:#222;color:#ddd;margin:16px}"
    " table{border-collapse:collapse;margin:8px 0 24px} td,th{border:1px solid #555;padding:4px 8px;text-align:left;"
    "vertical-align:top}"
    " .passed{color:#7c7} .failed{color:#f66;font-weight:bold} .skipped{color:#fc5;font-weight:bold}"
    " .row{display:flex;gap:12px;flex-wrap:wrap;align-items:flex-start} figure{margin:0}"
    " img{width:360px;image-rendering:pixelated;border:1px solid #555;display:block}"
    " .stack{position:relative;width:362px} .stack img.over{position:absolute;left:0;top:0}"
    " .flicker img.over{animation:flicker 1s steps(1) infinite} @keyframes flicker{50%{opacity:0}}"
    " .slider input{width:362px} figcaption{font-size:90%;color:#aaa;max-width:360px}"
    " section{border-top:1px solid #555;padding-top:8px;margin-top:16px} a{color:#9cf}</style>\n";

std::string verdictCell(Verdict verdict) {
  return "<td class=" + std::string(verdictName(verdict)) + ">" + verdictName(verdict) + "</td>";
}

std::string picture(const std::string& source, const std::string& caption) {
  return "<figure><img src=\"" + escapeMarkup(source) + "\" alt=\"" + caption + "\"><figcaption>" + caption +
         "</figcaption></figure>";
}

// Actual over expected: the flicker shows them in turn, the slider clips the
// actual picture at the handle.
std::string comparisonViews(const std::string& folder) {
  const std::string expected = escapeMarkup(folder + "/expected.png"), actual = escapeMarkup(folder + "/actual.png");
  const std::string stacked = "<img src=\"" + expected + "\" alt=expected><img class=over src=\"" + actual + "\"";
  return "<figure><div class=\"stack flicker\">" + stacked +
         " alt=actual></div><figcaption>flicker: actual and expected in turn, half a second each</figcaption>"
         "</figure><figure><div class=\"stack slider\">" +
         stacked +
         " alt=actual style=\"clip-path:inset(0 50% 0 0)\"><input type=range min=0 max=100 value=50 "
         "aria-label=\"slider position\" oninput=\"this.previousElementSibling.style.clipPath="
         "'inset(0 '+(100-this.value)+'% 0 0)'\"></div><figcaption>slider: actual left of the handle, "
         "expected right</figcaption></figure>";
}

std::string frameSection(const CaseResult& result, const FrameResult& frame) {
  std::ostringstream html;
  html << "<section id=\"" << escapeMarkup(frame.images) << "\"><h2>" << escapeMarkup(result.name) << ", "
       << escapeMarkup(frame.label) << "</h2><p>" << escapeMarkup(frame.figures) << "</p><div class=row>"
       << picture(frame.images + "/expected.png", "expected (approved)")
       << picture(frame.images + "/actual.png", "actual (rendered now)")
       << picture(frame.images + "/diff.png",
                  "diff: red different, yellow within 1 px of a match, blue below the threshold (amplified)")
       << "</div><div class=row>" << comparisonViews(frame.images) << "</div></section>\n";
  return html.str();
}

// The case's message, then one line per failed frame, linked to its pictures.
std::string details(const CaseResult& result) {
  std::string html = escapeMarkup(result.message);
  for (const FrameResult& frame : result.frames) {
    if (frame.verdict != Verdict::Failed) continue;
    if (!html.empty()) html += "<br>";
    const std::string label = escapeMarkup(frame.label);
    html += (frame.images.empty() ? label : "<a href=\"#" + escapeMarkup(frame.images) + "\">" + label + "</a>") +
            ": " + escapeMarkup(frame.figures);
  }
  return html;
}

std::string summaryRow(const CaseResult& result) {
  std::ostringstream html;
  html << "<tr><td>" << escapeMarkup(result.name) << "</td>" << verdictCell(result.verdict) << "<td>"
       << result.frames.size() << "</td><td>" << escapeMarkup(result.description) << "</td><td>" << details(result)
       << "</td></tr>\n";
  return html.str();
}

std::string pageText(const ReportPage& page, const std::vector<CaseResult>& results) {
  const Tally counts = tally(results);
  std::ostringstream html;
  html << "<!doctype html><meta charset=utf-8><title>" << escapeMarkup(page.title) << "</title>\n"
       << kStyle << "<h1>" << escapeMarkup(page.title) << "</h1>\n<p>";
  if (page.failuresOnly)
    html << "<span class=failed>" << counts.failed << " failed</span> (passing cases are not listed). ";
  else
    html << "<span class=passed>" << counts.passed << " passed</span>, <span class=failed>" << counts.failed
         << " failed</span>, <span class=skipped>" << counts.skipped
         << " skipped</span> (skipped: nothing was compared). ";
  html << escapeMarkup(page.hint) << "</p>\n<table><tr><th>case</th><th>verdict</th><th>frames</th><th>drawn</th><th>details</th></tr>\n";
  for (const CaseResult& result : results) html << summaryRow(result);
  html << "</table>\n";
  for (const CaseResult& result : results)
    for (const FrameResult& frame : result.frames)
      if (!frame.images.empty()) html << frameSection(result, frame);
  return html.str();
}

}  // namespace

fs::path reportIndex(const fs::path& reportRoot) { return reportRoot / "index.html"; }

void writeHtmlReport(const fs::path& reportRoot, const ReportPage& page, const std::vector<CaseResult>& results) {
  fs::create_directories(reportRoot);
  const fs::path temporary = reportRoot / (".index-" + std::to_string(::getpid()) + ".html");
  {
    std::ofstream file(temporary);
    file << pageText(page, results);
    if (!file) throw std::runtime_error("cannot write report page '" + temporary.string() + "'");
  }
  fs::rename(temporary, reportIndex(reportRoot));
}

}  // namespace physdbg::golden
