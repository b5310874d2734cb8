#include "reports/html_index.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace physdbg::reports {
namespace {

bool isTableLine(const std::string& line) { return !line.empty() && line.front() == '|'; }

// "| --- | --- |": the header rule of a Markdown table.
bool isRule(const std::string& line) { return line.find_first_not_of("|-: ") == std::string::npos; }

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] != '|') {
      cell += line[i];
      continue;
    }
    const auto first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
    out.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
    cell.clear();
  }
  return out;
}

std::string tableRow(const std::string& line, const char* tag) {
  std::string row = "<tr>";
  for (const std::string& cell : cells(line)) row += std::string("<") + tag + ">" + escapeHtml(cell) + "</" + tag + ">";
  return row + "</tr>\n";
}

std::string body(const std::string& markdown) {
  std::istringstream lines(markdown);
  std::string html, line;
  bool inTable = false;
  while (std::getline(lines, line)) {
    if (isTableLine(line)) {
      if (isRule(line)) continue;
      html += inTable ? tableRow(line, "td") : "<table>\n" + tableRow(line, "th");
      inTable = true;
      continue;
    }
    if (inTable) html += "</table>\n";
    inTable = false;
    if (line.rfind("# ", 0) == 0) {
      html += "<h1>" + escapeHtml(line.substr(2)) + "</h1>\n";
    } else if (!line.empty()) {
      html += "<p>" + escapeHtml(line) + "</p>\n";
    }
  }
  return inTable ? html + "</table>\n" : html;
}

}  // namespace

std::string escapeHtml(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string htmlIndex(const std::string& title, const std::string& markdown, const std::vector<std::string>& images) {
  std::string html = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + escapeHtml(title) +
                     "</title>\n<style>body{font-family:sans-serif}table{border-collapse:collapse}"
                     "td,th{border:1px solid #999;padding:2px 6px}</style></head><body>\n";
  for (const std::string& image : images) {
    html += "<img src=\"" + escapeHtml(image) + "\" alt=\"" + escapeHtml(image) + "\">\n";
  }
  return html + body(markdown) + "</body></html>\n";
}

void writeHtmlIndex(const std::filesystem::path& directory, const std::string& title, const std::string& markdown,
                    const std::vector<std::string>& images) {
  const std::filesystem::path path = directory / "index.html";
  std::ofstream file(path);
  file << htmlIndex(title, markdown, images);
  file.close();
  if (!file) throw std::runtime_error("cannot write '" + path.string() + "'");
}

}  // namespace physdbg::reports
