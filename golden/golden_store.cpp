#include "golden/golden_store.h"

#include <cctype>
#include <cstdio>
#include <stdexcept>

namespace physdbg::golden {
namespace {

std::string sanitize(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const bool keep = std::isalnum(static_cast<unsigned char>(lower)) || lower == '.';
    if (keep) out += lower;
    else if (!out.empty() && out.back() != '-') out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out;
}

std::string firstWord(const std::string& text) {
  const std::size_t end = text.find_first_of(" (");
  return text.substr(0, end);
}

}  // namespace

std::string goldenKey(const render::GlIdentity& identity) {
  if (identity.renderer.empty() || identity.version.empty())
    throw std::invalid_argument("goldenKey: empty GL_RENDERER or GL_VERSION string");
  const std::size_t mesa = identity.version.find("Mesa ");
  const std::string version =
      mesa == std::string::npos ? identity.version : "mesa-" + firstWord(identity.version.substr(mesa + 5));
  return sanitize(version) + "-" + sanitize(firstWord(identity.renderer));
}

std::filesystem::path goldenPath(const std::filesystem::path& root, const std::string& key,
                                 const std::string& caseName) {
  return root / key / (caseName + ".png");
}

std::filesystem::path caseFolder(const std::filesystem::path& root, const std::string& key,
                                 const std::string& caseName) {
  return root / key / caseName;
}

std::string frameFileName(int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", frame);
  return name;
}

}  // namespace physdbg::golden
