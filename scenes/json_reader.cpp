#include "scenes/json_reader.h"

#include <cmath>
#include <sstream>

#include "scenes/scene.h"
#include "scenes/scene_limits.h"

namespace physdbg {
namespace {

using nlohmann::json;

std::string typeName(const json& value) {
  if (value.is_number()) return "a number";
  if (value.is_boolean()) return "a boolean";
  if (value.is_string()) return "a string";
  if (value.is_array()) return "an array";
  if (value.is_object()) return "an object";
  return "null";
}

// A value as it would appear in the file, for messages. Containers are not
// dumped (they may be huge or deep); strings are shortened.
std::string shown(const json& value) {
  if (value.is_array() || value.is_object()) return typeName(value);
  if (value.is_string()) return "\"" + excerpt(value.get_ref<const std::string&>()) + "\"";
  return excerpt(value.dump());
}

// 1-based line of a byte offset, for messages about the raw text.
std::size_t lineOf(const std::string& text, std::size_t offset) {
  std::size_t line = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}

// Offset of the first bracket that opens a level deeper than the limit, or npos.
std::size_t tooDeepAt(const std::string& text) {
  int depth = 0;
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
      continue;
    }
    if (c == '"') inString = true;
    else if (c == '[' || c == '{') {
      if (++depth > scene_limits::maxNesting) return i;
    } else if (c == ']' || c == '}') --depth;
  }
  return std::string::npos;
}

}  // namespace

std::string formatNumber(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string excerpt(const std::string& text) {
  const std::size_t limit = scene_limits::maxEchoedChars;
  if (text.size() <= limit) return text;
  return text.substr(0, limit) + "... (" + std::to_string(text.size()) + " bytes)";
}

json parseBoundedJson(const std::string& text, const std::string& source) {
  const JsonReader reader(source);
  const std::size_t nul = text.find('\0');
  if (nul != std::string::npos)
    reader.fail("", "line " + std::to_string(lineOf(text, nul)) + ": contains a NUL byte (not a text file?)");
  const std::size_t deep = tooDeepAt(text);
  if (deep != std::string::npos)
    reader.fail("", "line " + std::to_string(lineOf(text, deep)) + ": arrays and objects nested deeper than " +
                        std::to_string(scene_limits::maxNesting) + " levels");
  try {
    return json::parse(text);
  } catch (const json::exception& error) {  // parse errors and number overflow (1e999)
    // The parser quotes the token it stopped at, which may be a whole long string.
    const std::string what = error.what();
    reader.fail("", "malformed JSON: " + (what.size() > 300 ? what.substr(0, 300) + "..." : what));
  }
}

void JsonReader::fail(const std::string& path, const std::string& what) const {
  throw SceneError(source_ + ": " + (path.empty() ? "" : path + ": ") + what);
}

void JsonReader::requireObject(const json& value, const std::string& path) const {
  if (!value.is_object()) fail(path, "must be an object, got " + typeName(value));
}

std::string JsonReader::child(const std::string& path, const std::string& key) {
  return path.empty() ? excerpt(key) : path + "." + excerpt(key);
}

void JsonReader::checkKeys(const json& object, const std::string& path, const std::set<std::string>& allowed) const {
  for (auto entry = object.begin(); entry != object.end(); ++entry) {
    if (allowed.count(entry.key())) continue;
    std::string list;
    for (const auto& name : allowed) list += (list.empty() ? "" : ", ") + name;
    fail(child(path, entry.key()), "unknown key (allowed here: " + list + ")");
  }
}

const json& JsonReader::required(const json& object, const std::string& path, const char* key) const {
  const auto found = object.find(key);
  if (found == object.end()) fail(path, std::string("missing key ") + key);
  return *found;
}

double JsonReader::finite(const json& value, const std::string& path) const {
  if (!value.is_number()) fail(path, "must be a number, got " + typeName(value));
  const double result = value.get<double>();
  if (!std::isfinite(result)) fail(path, "must be finite");
  return result;
}

double JsonReader::number(const json& value, const std::string& path) const {
  const double result = finite(value, path);
  if (std::abs(result) > scene_limits::maxMagnitude)
    fail(path, "must be at most " + formatNumber(scene_limits::maxMagnitude) + " in size, got " + shown(value));
  return result;
}

double JsonReader::size(const json& value, const std::string& path) const {
  const double result = number(value, path);
  if (!(result > 0.0)) fail(path, "must be positive, got " + shown(value));
  if (result < scene_limits::minSize)
    fail(path, "must be at least " + formatNumber(scene_limits::minSize) + ", got " + shown(value));
  return result;
}

double JsonReader::nonNegative(const json& value, const std::string& path) const {
  const double result = number(value, path);
  if (result < 0.0) fail(path, "must not be negative, got " + shown(value));
  return result;
}

double JsonReader::inRange(const json& value, const std::string& path, double low, double high) const {
  const double result = finite(value, path);
  if (result < low || result > high)
    fail(path, "must be between " + formatNumber(low) + " and " + formatNumber(high) + ", got " + shown(value));
  return result;
}

long long JsonReader::integer(const json& value, const std::string& path, long long low, long long high) const {
  const auto range = [&] { return "must be an integer from " + std::to_string(low) + " to " + std::to_string(high); };
  if (!value.is_number_integer()) fail(path, range() + ", got " + shown(value));
  // Unsigned values above LLONG_MAX must not wrap to negative numbers.
  if (value.is_number_unsigned() && value.get<unsigned long long>() > static_cast<unsigned long long>(high))
    fail(path, range() + ", got " + shown(value));
  const auto result = value.get<long long>();
  if (result < low || result > high) fail(path, range() + ", got " + shown(value));
  return result;
}

bool JsonReader::boolean(const json& value, const std::string& path) const {
  if (!value.is_boolean()) fail(path, "must be true or false, got " + typeName(value));
  return value.get<bool>();
}

std::string JsonReader::string(const json& value, const std::string& path) const {
  if (!value.is_string()) fail(path, "must be a string, got " + typeName(value));
  return value.get<std::string>();
}

const json& JsonReader::array(const json& value, const std::string& path, std::size_t length) const {
  if (!value.is_array()) fail(path, "must be an array, got " + typeName(value));
  if (length != 0 && value.size() != length)
    fail(path, "must have " + std::to_string(length) + " elements, got " + std::to_string(value.size()));
  return value;
}

Vec3 JsonReader::vec3(const json& value, const std::string& path) const {
  array(value, path, 3);
  return {number(value[0], path + "[0]"), number(value[1], path + "[1]"), number(value[2], path + "[2]")};
}

Vec3 JsonReader::sizeVec3(const json& value, const std::string& path) const {
  array(value, path, 3);
  return {size(value[0], path + "[0]"), size(value[1], path + "[1]"), size(value[2], path + "[2]")};
}

Quat JsonReader::quaternion(const json& value, const std::string& path) const {
  array(value, path, 4);
  const Quat q(number(value[0], path + "[0]"), number(value[1], path + "[1]"), number(value[2], path + "[2]"),
               number(value[3], path + "[3]"));
  // Relative to the largest component: [1e-9, 0, 0, 0] is a valid rotation.
  if (q.coeffs().cwiseAbs().maxCoeff() == 0.0)
    fail(path, "must not be a zero quaternion (use [1,0,0,0] for no rotation)");
  return Quat(q.coeffs() / q.coeffs().cwiseAbs().maxCoeff()).normalized();
}

std::array<bool, 3> JsonReader::bool3(const json& value, const std::string& path) const {
  array(value, path, 3);
  return {boolean(value[0], path + "[0]"), boolean(value[1], path + "[1]"), boolean(value[2], path + "[2]")};
}

}  // namespace physdbg
