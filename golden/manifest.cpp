#include "golden/manifest.h"

#include <fstream>
#include <set>
#include <sstream>

#include "golden/content_hash.h"
#include "golden/manifest_limits.h"
#include "scenes/json_reader.h"

namespace physdbg::golden {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// render's layers when neither the case nor the scene names any (cli/common_options.h).
constexpr char kDefaultLayers[] = "shapes,aabbs,overlay";

std::string indexed(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

// Reads one manifest file; every error names it and the key path.
class ManifestReader {
 public:
  explicit ManifestReader(fs::path file) : file_(std::move(file)), reader_(file_.string()) {}

  Manifest read() const {
    const json root = parseBoundedJson(fileText(), file_.string());
    reader_.requireObject(root, "");
    reader_.checkKeys(root, "", {"cases"});
    const json& cases = boundedArray(reader_.required(root, "", "cases"), "cases", limits::maxCases);
    Manifest manifest{file_, file_.parent_path(), {}};
    std::set<std::string> names;
    for (std::size_t index = 0; index < cases.size(); ++index) {
      ManifestCase parsed = readCase(cases[index], indexed("cases", index));
      if (!names.insert(parsed.name).second)
        reader_.fail(indexed("cases", index) + ".name", "'" + parsed.name + "' names two cases");
      manifest.cases.push_back(std::move(parsed));
    }
    return manifest;
  }

 private:
  std::string fileText() const {
    std::error_code error;
    const std::uintmax_t bytes = fs::file_size(file_, error);
    if (error) reader_.fail("", "cannot read the manifest: " + error.message());
    if (bytes > limits::maxManifestBytes)
      reader_.fail("", "manifest of " + std::to_string(bytes) + " bytes (at most " +
                           std::to_string(limits::maxManifestBytes) + ")");
    std::ifstream file(file_, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    if (text.str().size() > limits::maxManifestBytes) reader_.fail("", "manifest grew while being read");
    return text.str();
  }

  // An array of 1 to `most` elements.
  const json& boundedArray(const json& value, const std::string& path, int most) const {
    reader_.array(value, path, 0);
    if (value.empty() || value.size() > std::size_t(most))
      reader_.fail(path, "must have 1 to " + std::to_string(most) + " elements, got " + std::to_string(value.size()));
    return value;
  }

  ManifestCase readCase(const json& value, const std::string& path) const {
    reader_.requireObject(value, path);
    reader_.checkKeys(value, path, {"name", "scene", "frames", "size", "layers", "camera", "solver"});
    ManifestCase parsed;
    parsed.name = readName(reader_.required(value, path, "name"), path + ".name");
    parsed.frames = readFrames(reader_.required(value, path, "frames"), path + ".frames");
    if (value.contains("size")) readSize(value["size"], path + ".size", parsed);
    if (value.contains("camera")) parsed.camera = readCamera(value["camera"], path + ".camera");
    if (value.contains("solver")) parsed.solver = readSolver(value["solver"], path + ".solver");
    parsed.sceneName = reader_.string(reader_.required(value, path, "scene"), path + ".scene");
    loadScene(parsed, path + ".scene");
    parsed.layers = value.contains("layers") ? reader_.string(value["layers"], path + ".layers")
                                             : parsed.scene.layers.value_or(kDefaultLayers);
    checkLayers(parsed.layers, path + ".layers");
    return parsed;
  }

  std::string readName(const json& value, const std::string& path) const {
    const std::string name = reader_.string(value, path);
    if (!isValidCaseName(name))
      reader_.fail(path, "'" + excerpt(name) +
                             "' is not a plain name: it becomes a folder name, so it may hold only letters, digits, "
                             "'_', '-' and '.', must not start with '.' and has at most " +
                             std::to_string(limits::maxCaseNameLength) + " characters");
    return name;
  }

  std::vector<int> readFrames(const json& value, const std::string& path) const {
    boundedArray(value, path, limits::maxFramesPerCase);
    std::vector<int> frames;
    for (std::size_t index = 0; index < value.size(); ++index) {
      const int frame = static_cast<int>(reader_.integer(value[index], indexed(path, index), 0, limits::maxFrameIndex));
      if (!frames.empty() && frame <= frames.back())
        reader_.fail(indexed(path, index), "frames must increase: " + std::to_string(frame) + " follows " +
                                                std::to_string(frames.back()));
      frames.push_back(frame);
    }
    return frames;
  }

  void readSize(const json& value, const std::string& path, ManifestCase& parsed) const {
    const std::string text = reader_.string(value, path);
    const std::string expected = "must be \"WIDTHxHEIGHT\" with sides " + std::to_string(limits::minImageSide) +
                                 " to " + std::to_string(limits::maxImageSide) + " and at most " +
                                 std::to_string(limits::maxImagePixels) + " pixels, got '" + excerpt(text) + "'";
    std::istringstream in(text);
    long long width = 0, height = 0;
    char times = 0;
    const bool digitsOnly = text.find_first_not_of("0123456789x") == std::string::npos;
    if (!digitsOnly || !(in >> width >> times >> height) || times != 'x' || !in.eof()) reader_.fail(path, expected);
    const auto inRange = [](long long side) { return side >= limits::minImageSide && side <= limits::maxImageSide; };
    if (!inRange(width) || !inRange(height) || width * height > limits::maxImagePixels) reader_.fail(path, expected);
    parsed.width = static_cast<int>(width);
    parsed.height = static_cast<int>(height);
  }

  viewer::CameraOptions readCamera(const json& value, const std::string& path) const {
    reader_.requireObject(value, path);
    reader_.checkKeys(value, path, {"eye", "target", "fov", "ortho"});
    viewer::CameraOptions camera;
    if (value.contains("eye")) camera.eye = reader_.vec3(value["eye"], path + ".eye");
    if (value.contains("target")) camera.target = reader_.vec3(value["target"], path + ".target");
    if (value.contains("fov")) {
      camera.fovYDegrees = reader_.inRange(value["fov"], path + ".fov", 0, 180);
      if (*camera.fovYDegrees <= 0 || *camera.fovYDegrees >= 180)
        reader_.fail(path + ".fov", "must be above 0 and below 180 degrees");
    }
    if (value.contains("ortho")) camera.orthographic = reader_.boolean(value["ortho"], path + ".ortho");
    return camera;
  }

  SolverKind readSolver(const json& value, const std::string& path) const {
    const std::string name = reader_.string(value, path);
    for (const SolverKind kind : {SolverKind::Seed, SolverKind::SequentialImpulse})
      if (name == solverKindName(kind)) return kind;
    reader_.fail(path, "must be seed or sequential_impulse, got '" + excerpt(name) + "'");
  }

  // A built-in scene by name, else a scene file relative to the manifest's folder.
  void loadScene(ManifestCase& parsed, const std::string& path) const {
    for (const BuiltinScene& builtin : builtinScenes()) {
      if (builtin.name != parsed.sceneName) continue;
      parsed.scene = builtin.make();
      parsed.sceneHash = textHash("builtin:" + builtin.name);
    }
    if (parsed.sceneHash.empty()) {
      const fs::path file = file_.parent_path() / parsed.sceneName;
      if (!fs::is_regular_file(file))
        reader_.fail(path, "'" + excerpt(parsed.sceneName) +
                               "' is neither a built-in scene (physdbg scenes) nor a scene file ('" +
                               excerpt(file.string()) + "' does not exist)");
      parsed.scene = loadSceneFile(file.string());
      parsed.sceneHash = fileHash(file);
    }
    if (parsed.solver) parsed.scene.world.solver.kind = *parsed.solver;
  }

  void checkLayers(const std::string& layers, const std::string& path) const {
    try {
      debugdraw::parseLayers(layers);
    } catch (const std::invalid_argument& error) {
      reader_.fail(path, error.what());
    }
  }

  fs::path file_;
  JsonReader reader_;
};

}  // namespace

bool isValidCaseName(const std::string& name) {
  if (name.empty() || name.size() > std::size_t(limits::maxCaseNameLength) || name.front() == '.') return false;
  for (const char c : name) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                       c == '-' || c == '.';
    if (!plain) return false;
  }
  return true;
}

Manifest readManifest(const std::filesystem::path& file) { return ManifestReader(file).read(); }

}  // namespace physdbg::golden
