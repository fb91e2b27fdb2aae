#include "webgl/webgl_draw.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "webgl/base64.hpp"
#include "webgl/chromium_pipe.hpp"
#include "webgl/webgl_runner.hpp"

namespace mb::webgl {
namespace {

// Chromium's start on a loaded two-core machine takes seconds; SwiftShader compiles a large
// fragment shader (a permutation with every light) in tens of seconds.
constexpr double kStartSeconds = 60;
constexpr double kDrawSeconds = 900;

template <typename T>
std::string encoded(const std::vector<T>& values) {
  return base64Encode(std::string_view(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)));
}

nlohmann::json jobJson(const gl::DrawJob& job) {
  nlohmann::json attributes = nlohmann::json::array();
  for (const auto& a : job.mesh.attributes)
    attributes.push_back({{"location", a.location}, {"components", a.components}, {"offset", a.offset}});
  nlohmann::json textures = nlohmann::json::array();
  for (const auto& t : job.textures) {
    nlohmann::json levels = nlohmann::json::array();
    for (const auto& l : t.levels)
      levels.push_back({{"width", l.width}, {"height", l.height}, {"rgba", encoded(l.rgba)}});
    textures.push_back({{"cube", t.cube}, {"levels", std::move(levels)}});
  }
  nlohmann::json draws = nlohmann::json::array();
  for (const auto& d : job.draws) {
    nlohmann::json blocks = nlohmann::json::object();
    for (const auto& [name, bytes] : d.uniformBlocks) blocks[name] = encoded(bytes);
    draws.push_back({{"uniformBlocks", std::move(blocks)}, {"samplers", d.samplers}, {"viewport", d.viewport}});
  }
  return {{"vertexSource", job.vertexSource},
          {"fragmentSource", job.fragmentSource},
          {"width", job.width},
          {"height", job.height},
          {"colorTargets", job.colorTargets},
          {"clearColors", job.clearColors},
          {"mesh",
           {{"vertices", encoded(job.mesh.vertices)},
            {"floatsPerVertex", job.mesh.floatsPerVertex},
            {"attributes", std::move(attributes)},
            {"indices", encoded(job.mesh.indices)}}},
          {"textures", std::move(textures)},
          {"draws", std::move(draws)}};
}

// A fresh profile directory for one browser, removed with it.
class ProfileDir {
 public:
  ProfileDir() {
    static std::atomic<unsigned> count{0};
    path_ = std::filesystem::temp_directory_path() /
            ("matbricks-webgl-" + std::to_string(::getpid()) + "-" + std::to_string(count++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ProfileDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ProfileDir(const ProfileDir&) = delete;
  ProfileDir& operator=(const ProfileDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

std::string oneLine(std::string s) {
  if (const size_t nl = s.find('\n'); nl != std::string::npos) s.resize(nl);
  return s;
}

// The value of `expression` in the page, or WebglError with the exception's first line.
nlohmann::json evaluate(ChromiumPipe& browser, const std::string& session, const std::string& expression,
                        double seconds) {
  const nlohmann::json reply =
      browser.call("Runtime.evaluate", {{"expression", expression}, {"returnByValue", true}}, session, seconds);
  if (reply.contains("exceptionDetails")) {
    const nlohmann::json& d = reply["exceptionDetails"];
    const std::string what = d.contains("exception") ? d["exception"].value("description", "") : d.value("text", "");
    throw WebglError(oneLine(what.rfind("Error: ", 0) == 0 ? what.substr(7) : what));
  }
  return reply.value("result", nlohmann::json::object()).value("value", nlohmann::json());
}

gl::DrawResult resultOf(const nlohmann::json& value, const gl::DrawJob& job) {
  gl::DrawResult r;
  r.device = value.value("device", "");
  r.compileMs = value.value("compileMs", 0.0);
  r.renderMs = value.value("renderMs", 0.0);
  const size_t floats = size_t{job.width} * job.height * 4;
  for (const auto& t : value.at("targets")) {
    const std::string raw = base64Decode(t.get<std::string>());
    if (raw.size() != floats * sizeof(float))
      throw WebglError("WebGL 2.0 read back " + std::to_string(raw.size()) + " bytes for " +
                       std::to_string(floats * sizeof(float)));
    std::vector<float>& pixels = r.targets.emplace_back(floats);
    std::memcpy(pixels.data(), raw.data(), raw.size());
  }
  return r;
}

}  // namespace

std::string chromiumProgram() {
  if (const char* env = std::getenv("MATBRICKS_CHROMIUM"); env && *env) {
    if (::access(env, X_OK) != 0) throw WebglError(std::string("MATBRICKS_CHROMIUM=") + env + " is not an executable");
    return env;
  }
  return findChromium();
}

std::vector<gl::DrawResult> drawInBrowser(const std::vector<gl::DrawJob>& jobs) {
  const std::string chromium = chromiumProgram();
  if (chromium.empty())
    throw WebglError(
        "no chromium to run WebGL 2.0 in: install Debian's chromium (scripts/install-deps.sh) or set "
        "MATBRICKS_CHROMIUM");
  ProfileDir profile;
  std::vector<gl::DrawResult> results;
  try {
    // WebGL 2.0 on ANGLE over Chromium's own SwiftShader Vulkan: the same device with or without
    // a GPU (--disable-gpu, which the pipe always passes, leaves WebGL on it).
    ChromiumPipe browser(chromium, profile.path(), 64, 64, {"--use-angle=swiftshader", "--enable-unsafe-swiftshader"});
    const std::string target = browser.call("Target.createTarget", {{"url", "about:blank"}}, "", kStartSeconds)
                                   .at("targetId")
                                   .get<std::string>();
    const std::string session =
        browser.call("Target.attachToTarget", {{"targetId", target}, {"flatten", true}}, "", kStartSeconds)
            .at("sessionId")
            .get<std::string>();
    evaluate(browser, session, webglRunnerScript(), kStartSeconds);
    for (const gl::DrawJob& job : jobs)
      results.push_back(resultOf(evaluate(browser, session, "mbDraw(" + jobJson(job).dump() + ")", kDrawSeconds), job));
  } catch (const WebglError&) {
    throw;
  } catch (const std::exception& e) {
    throw WebglError("WebGL 2.0 in chromium: " + oneLine(e.what()));
  }
  return results;
}

}  // namespace mb::webgl
