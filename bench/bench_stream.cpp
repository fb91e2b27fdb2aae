// Memory and time of `matbricks compile --scene` as the scene grows (issue 15, item 4;
// docs/targets.md "Memory"). It writes synthetic scenes of M materials (copies of one shipped
// material under new names, each used at every environment mode, both precisions and all
// three quality levels: 24 permutations per material), runs the real CLI on each as a child
// process and reads the child's peak RSS from wait4(2).
//
//   mb_bench_stream MATBRICKS WORKDIR JOBS M1[,M2...] [WINDOWS=256,0]
//
// Per scene size: one cold compile (empty cache) at the default window, then one warm compile
// (every unit from the cache) per window size; window 0 holds every permutation's GLSL and
// artifacts at once, as the compile did before it streamed. Prints one JSON object per run.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "child_run.hpp"

namespace fs = std::filesystem;

namespace {

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

// A scene of `materials` copies of filament_plastic (standard model: every environment mode).
fs::path writeScene(const fs::path& dir, size_t materials) {
  std::ifstream src(fs::path(MB_SOURCE_DIR) / "materials/filament_plastic.json");
  const nlohmann::json base = nlohmann::json::parse(src);
  fs::create_directories(dir / "materials");
  nlohmann::json scene{{"name", "stream_" + std::to_string(materials)},
                       {"lights", {{{"type", "dir"}}, {{"type", "point"}}}},
                       {"environment", {"none", "sh", "ibl_lut", "ibl_analytic"}},
                       {"precision", {"fp32", "fp16"}},
                       {"quality", {"low", "medium", "high"}},
                       {"targets", {"spirv"}},
                       {"materials", nlohmann::json::array()}};
  for (size_t i = 0; i < materials; ++i) {
    nlohmann::json m = base;
    const std::string name = "plastic_" + std::to_string(i);
    m["name"] = name;
    std::ofstream(dir / "materials" / (name + ".json")) << m.dump(2);
    scene["materials"].push_back({{"file", "materials/" + name + ".json"}});
  }
  const fs::path file = dir / "scene.json";
  std::ofstream(file) << scene.dump(2);
  return file;
}

// "counts" is the manifest's first key: read the head only. Parsing the whole manifest here
// would grow this process, and a forked child's peak RSS (ru_maxrss) includes its parent's
// at the fork (Linux keeps the pre-exec high-water mark).
size_t requiredCount(const fs::path& manifest) {
  std::ifstream in(manifest);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  const size_t at = head.find("\"required\": ");
  return at == std::string::npos ? 0 : std::stoul(head.substr(at + 12));
}

using Run = mb::bench::ChildRun;
using mb::bench::runChild;

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s MATBRICKS WORKDIR JOBS M1[,M2...] [WINDOWS=256,0]\n", argv[0]);
    return 2;
  }
  const std::string cli = fs::absolute(argv[1]).string();
  const fs::path work = fs::absolute(argv[2]);
  const std::string jobs = argv[3];
  const std::vector<std::string> windows = splitList(argc > 5 ? argv[5] : "256,0");
  for (const auto& m : splitList(argv[4])) {
    const size_t materials = std::stoul(m);
    const fs::path dir = work / ("scene_" + m);
    fs::remove_all(dir);
    const fs::path scene = writeScene(dir, materials);
    const std::string cache = (dir / "cache").string();
    auto run = [&](const std::string& kind, const std::string& window) {
      const std::string out = (dir / ("package_" + kind + "_" + window)).string();
      Run r = runChild({cli, "compile", "-q", "--scene", scene.string(), "-j", jobs, "--cache-dir", cache,
                        "--stream-window", window, "-o", out},
                       dir / ("log_" + kind + "_" + window + ".txt"));
      const size_t perms = requiredCount(fs::path(out) / "manifest.json");
      nlohmann::json j{{"materials", materials},
                       {"permutations", perms},
                       {"cache", kind},
                       {"window", std::stoul(window)},
                       {"jobs", std::stoul(jobs)},
                       {"exit_status", WIFEXITED(r.status) ? WEXITSTATUS(r.status) : -1},
                       {"wall_s", r.wallS},
                       {"peak_rss_mb", r.peakRssKb / 1024.0},
                       {"permutations_per_s", r.wallS > 0 ? perms / r.wallS : 0}};
      std::printf("%s\n", j.dump().c_str());
      std::fflush(stdout);
      fs::remove_all(out);
    };
    run("cold", windows.front());
    for (const auto& w : windows) run("warm", w);
    fs::remove_all(dir);
  }
  return 0;
}
