// Seeded mutations of every shipped material description (materials/*.json|.mat, the glTF
// examples) and scene (examples/scenes: JSON and glTF, loaded and planned) fed to the loader
// in-process (issue 4: "no input makes the compiler crash, hang,
// or leave a partial package"). Each mutant must load or throw DiagnosticError with coded
// diagnostics; anything else (another exception, a crash) fails, and a watchdog turns a hang
// into a failure naming the mutant. The mutations are the classic ones of file fuzzers:
// truncation, bit flips, inserted bytes, duplicated and deleted lines, and the numbers and
// nesting that break parsers (overflowing and denormal literals, NaN/Inf spellings, deep
// nesting).
#include <catch2/catch.hpp>

#include <chrono>
#include <functional>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <random>
#include <regex>
#include <thread>
#include <unistd.h>

#include "load/scene_desc.hpp"
#include "permute/scene_plan.hpp"
#include "support/bad_input_cases.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

struct Mutant {
  std::string description;
  std::string bytes;
};

std::vector<std::string> splitLines(const std::string& s) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= s.size()) {
    size_t end = s.find('\n', start);
    if (end == std::string::npos) {
      out.push_back(s.substr(start));
      break;
    }
    out.push_back(s.substr(start, end - start + 1));
    start = end + 1;
  }
  return out;
}

std::string joinLines(const std::vector<std::string>& ls) {
  std::string s;
  for (const auto& l : ls) s += l;
  return s;
}

// Byte offsets and lengths of the numeric literals of a text file.
std::vector<std::pair<size_t, size_t>> numbers(const std::string& s) {
  static const std::regex number(R"(-?[0-9]+(\.[0-9]+)?([eE][+-]?[0-9]+)?)");
  std::vector<std::pair<size_t, size_t>> out;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), number); it != std::sregex_iterator(); ++it)
    out.emplace_back(static_cast<size_t>(it->position()), static_cast<size_t>(it->length()));
  return out;
}

size_t pick(std::mt19937& rng, size_t n) { return n == 0 ? 0 : static_cast<size_t>(rng() % n); }

std::vector<Mutant> mutate(const std::string& seed, uint32_t seedValue) {
  std::mt19937 rng(seedValue);
  std::vector<Mutant> out;
  const size_t n = seed.size();
  // Truncation at every k-th byte (12 prefixes, the empty one included).
  size_t step = std::max<size_t>(1, n / 12);
  for (size_t k = 0; k < n; k += step)
    out.push_back({"truncated to " + std::to_string(k) + " bytes", seed.substr(0, k)});
  for (int i = 0; i < 12; ++i) {
    std::string s = seed;
    size_t at = pick(rng, n);
    int bit = static_cast<int>(rng() % 8);
    if (n) s[at] = static_cast<char>(s[at] ^ (1 << bit));
    out.push_back({"bit " + std::to_string(bit) + " of byte " + std::to_string(at) + " flipped", s});
  }
  for (int i = 0; i < 4; ++i) {
    std::string s = seed, junk;
    for (int b = 0; b < 8; ++b) junk += static_cast<char>(rng() % 256);
    size_t at = pick(rng, n + 1);
    s.insert(at, junk);
    out.push_back({"8 random bytes inserted at " + std::to_string(at), s});
  }
  auto ls = splitLines(seed);
  for (int i = 0; i < 4; ++i) {
    auto dup = ls, del = ls;
    size_t a = pick(rng, ls.size()), b = pick(rng, ls.size());
    dup.insert(dup.begin() + static_cast<long>(a), ls[a]);
    del.erase(del.begin() + static_cast<long>(b));
    out.push_back({"line " + std::to_string(a + 1) + " duplicated", joinLines(dup)});
    out.push_back({"line " + std::to_string(b + 1) + " deleted", joinLines(del)});
  }
  auto nums = numbers(seed);
  const std::vector<std::string> replacements{"1e999",
                                              "-1e999",
                                              "1e308",
                                              "123456789012345678901234567890",
                                              "4.9e-324",
                                              "-0",
                                              "NaN",
                                              "nan",
                                              "inf",
                                              "-Infinity",
                                              "0x1p3",
                                              std::string(65, '[') + "1" + std::string(65, ']'),
                                              std::string(5000, '[') + "1" + std::string(5000, ']'),
                                              "vec3(" + std::string(3000, '(') + "1" + std::string(3000, ')') + ")"};
  for (const auto& r : replacements) {
    if (nums.empty()) break;
    auto [at, len] = nums[pick(rng, nums.size())];
    std::string s = seed;
    s.replace(at, len, r);
    out.push_back({"number at byte " + std::to_string(at) + " replaced by " + r.substr(0, 24), s});
  }
  return out;
}

// Every shipped description, each with the directory it lives in (copied whole, so includes
// and surface files of a mutant still resolve).
std::vector<fs::path> seeds() {
  std::vector<fs::path> out;
  for (const char* dir : {"materials", "examples/gltf"})
    for (const auto& e : fs::directory_iterator(test::sourceDir() / dir)) {
      std::string ext = e.path().extension().string();
      if (ext == ".json" || ext == ".mat" || ext == ".gltf" || ext == ".glb") out.push_back(e.path());
    }
  std::sort(out.begin(), out.end());
  return out;
}

enum class Outcome { Loaded, Rejected };

using Loader = std::function<void(const std::string& path)>;

void loadMaterial(const std::string& path) { loadMaterialFile(path, test::shippedLibrary()); }

// A scene is read and planned (its materials loaded, folding and validity decided); nothing
// is compiled.
void loadAndPlanScene(const std::string& path) {
  planScene(loadScene(path, test::shippedLibrary()), test::shippedLibrary());
}

// Loads `path` on a worker thread; a load that takes longer than the bound is a hang: the
// mutant is printed and the process ends, because a stuck thread cannot be stopped.
Outcome loadWithin(const std::string& path, const std::string& what, std::chrono::seconds bound, const Loader& load) {
  std::packaged_task<Outcome()> task([path, load] {
    try {
      load(path);
      return Outcome::Loaded;
    } catch (const DiagnosticError& e) {
      for (const auto& d : e.diagnostics()) {
        if (d.code.empty() || d.message.empty())
          throw std::runtime_error("diagnostic without code or message: " + formatDiagnostic(d));
      }
      if (e.diagnostics().empty()) throw std::runtime_error("DiagnosticError without diagnostics");
      return Outcome::Rejected;
    }
  });
  auto result = task.get_future();
  std::thread worker(std::move(task));
  if (result.wait_for(bound) != std::future_status::ready) {
    std::fprintf(stderr, "HANG: loading %s (%s) took more than %lld s\n", path.c_str(), what.c_str(),
                 static_cast<long long>(bound.count()));
    std::fflush(stderr);
    std::_Exit(1);
  }
  worker.join();
  return result.get();  // rethrows anything but DiagnosticError
}

struct FuzzCount {
  size_t total = 0, rejected = 0;
};

// Every mutant of every seed, written to `mutantDir` (a copy of the seed's own directory, so
// that its relative paths resolve) and loaded with `load`.
FuzzCount fuzzSeeds(const std::vector<fs::path>& seedFiles, const fs::path& mutantDir, const Loader& load) {
  FuzzCount count;
  auto slowest = std::chrono::nanoseconds::zero();
  for (const auto& seed : seedFiles) {
    std::string bytes = test::readFile(seed);
    // Seeded by the file name (FNV-1a): a file's mutants do not change when others are added.
    uint32_t seedValue = 2166136261u;
    for (unsigned char ch : seed.filename().string()) seedValue = (seedValue ^ ch) * 16777619u;
    fs::path mutantPath = mutantDir / ("fuzz_mutant" + seed.extension().string());
    for (const auto& m : mutate(bytes, seedValue)) {
      INFO(seed.filename().string() << ": " << m.description);
      { std::ofstream(mutantPath, std::ios::binary | std::ios::trunc) << m.bytes; }
      auto t0 = std::chrono::steady_clock::now();
      Outcome o = Outcome::Loaded;
      try {
        o = loadWithin(mutantPath.string(), seed.filename().string() + ": " + m.description, std::chrono::seconds(20),
                       load);
      } catch (const std::exception& e) {
        FAIL_CHECK("threw " << e.what());
      }
      auto dt = std::chrono::steady_clock::now() - t0;
      slowest = std::max(slowest, std::chrono::duration_cast<std::chrono::nanoseconds>(dt));
      // 2 s per input: a hang detector with a wide margin (inputs take milliseconds), not a
      // performance assertion.
      CHECK(dt < std::chrono::seconds(2));
      ++count.total;
      count.rejected += o == Outcome::Rejected ? 1 : 0;
    }
  }
  UNSCOPED_INFO(count.total << " mutants, " << count.rejected << " rejected, slowest " << slowest.count() / 1e6
                            << " ms");
  return count;
}

fs::path scratchDir(const std::string& what) {
  fs::path scratch = fs::temp_directory_path() / ("mb_fuzz_" + what + "_" + std::to_string(::getpid()));
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  return scratch;
}

}  // namespace

TEST_CASE("seeded mutations of every shipped material load or give coded diagnostics, never crash or hang", "[fuzz]") {
  fs::path scratch = scratchDir("materials");
  (void)test::shippedLibrary();  // loaded once, before any input is timed
  FuzzCount count;
  for (const auto& seed : seeds()) {
    fs::path dir = scratch / seed.parent_path().filename();
    if (!fs::exists(dir)) fs::copy(seed.parent_path(), dir, fs::copy_options::recursive);
    FuzzCount c = fuzzSeeds({seed}, dir, loadMaterial);
    count.total += c.total;
    count.rejected += c.rejected;
  }
  fs::remove_all(scratch);
  CHECK(count.total >= 300);
  CHECK(count.rejected > count.total / 2);
}

TEST_CASE("seeded mutations of every shipped scene load and plan or give coded diagnostics, never crash or hang",
          "[fuzz][scene]") {
  // The scenes name materials as ../../materials/<file>: mirror that layout.
  fs::path scratch = scratchDir("scenes");
  fs::copy(test::sourceDir() / "materials", scratch / "materials", fs::copy_options::recursive);
  fs::create_directories(scratch / "examples");
  fs::copy(test::sourceDir() / "examples" / "scenes", scratch / "examples" / "scenes", fs::copy_options::recursive);
  std::vector<fs::path> scenes;
  for (const auto& e : fs::directory_iterator(test::sourceDir() / "examples" / "scenes"))
    if (e.path().extension() == ".json" || e.path().extension() == ".gltf") scenes.push_back(e.path());
  std::sort(scenes.begin(), scenes.end());
  REQUIRE(scenes.size() >= 4);
  FuzzCount count = fuzzSeeds(scenes, scratch / "examples" / "scenes", loadAndPlanScene);
  fs::remove_all(scratch);
  CHECK(count.total >= 150);
  CHECK(count.rejected > count.total / 2);
}
