#include "golden/result_file.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace physdbg::golden {
namespace {

using nlohmann::json;

json frameJson(const FrameResult& frame) {
  return {{"label", frame.label},
          {"verdict", verdictName(frame.verdict)},
          {"figures", frame.figures},
          {"images", frame.images}};
}

FrameResult frameFromJson(const json& value) {
  return {value.at("label").get<std::string>(), parseVerdict(value.at("verdict").get<std::string>()),
          value.at("figures").get<std::string>(), value.at("images").get<std::string>()};
}

json caseJson(const CaseResult& result) {
  json frames = json::array();
  for (const FrameResult& frame : result.frames) frames.push_back(frameJson(frame));
  return {{"name", result.name},       {"description", result.description},
          {"verdict", verdictName(result.verdict)}, {"message", result.message},
          {"frames", frames},          {"seconds", result.seconds}};
}

CaseResult caseFromJson(const json& value) {
  CaseResult result;
  result.name = value.at("name").get<std::string>();
  result.description = value.at("description").get<std::string>();
  result.verdict = parseVerdict(value.at("verdict").get<std::string>());
  result.message = value.at("message").get<std::string>();
  for (const json& frame : value.at("frames")) result.frames.push_back(frameFromJson(frame));
  result.seconds = value.at("seconds").get<double>();
  return result;
}

}  // namespace

void writeResultFile(const std::filesystem::path& path, const std::vector<CaseResult>& results) {
  json cases = json::array();
  for (const CaseResult& result : results) cases.push_back(caseJson(result));
  // Through a temporary file and a rename: another process may read it any time.
  const std::filesystem::path temporary = path.string() + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream file(temporary);
    file << json{{"cases", cases}}.dump(1) << "\n";
    if (!file) throw std::runtime_error("cannot write result file '" + temporary.string() + "'");
  }
  std::filesystem::rename(temporary, path);
}

std::vector<CaseResult> readResultFile(const std::filesystem::path& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot read result file '" + path.string() + "'");
  std::stringstream text;
  text << file.rdbuf();
  try {
    std::vector<CaseResult> results;
    const json document = json::parse(text.str());  // named: a range over a temporary's member dangles
    for (const json& value : document.at("cases")) results.push_back(caseFromJson(value));
    return results;
  } catch (const std::exception& error) {
    throw std::runtime_error("result file '" + path.string() + "' is malformed: " + error.what());
  }
}

}  // namespace physdbg::golden
