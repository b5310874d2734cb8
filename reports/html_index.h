#pragma once
// index.html for a report's output folder: its plots (img tags, relative
// paths) and its Markdown tables, so a folder of PNGs and tables reads as
// one page in a browser. Deliberately small: pipe tables become <table>,
// other non-empty lines paragraphs; every piece of text is escaped, since
// scene and case names come from other people.
#include <filesystem>
#include <string>
#include <vector>

namespace physdbg::reports {

// &, <, >, " and ' as entities.
std::string escapeHtml(const std::string& text);

// `images` are file names relative to the page.
std::string htmlIndex(const std::string& title, const std::string& markdown, const std::vector<std::string>& images);

// Writes DIRECTORY/index.html; throws std::runtime_error naming the path.
void writeHtmlIndex(const std::filesystem::path& directory, const std::string& title, const std::string& markdown,
                    const std::vector<std::string>& images);

}  // namespace physdbg::reports
