// Outputs never destroy a user's files (docs/cli.md "Outputs"): a package directory is
// created, filled when empty, or replaced atomically only when it carries matbricks' marker;
// no output may be, contain or lie inside an input, seen through symlinks, "..", hard links
// and bind mounts; and a compile killed at any moment leaves the old package or the new one,
// complete. The one-line refusals themselves are rows of the bad-input corpus.
#include <catch2/catch.hpp>

#include <signal.h>
#include <spawn.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include "support/bad_input_cases.hpp"
#include "support/cli_support.hpp"
#include "write/output_paths.hpp"

extern char** environ;

using namespace mb;
namespace fs = std::filesystem;

namespace {

void writeText(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

// A user's project: a material, a README and some code.
fs::path makeProject(const fs::path& root) {
  const fs::path project = root / "project";
  writeText(project / "README.md", "# my engine\n");
  writeText(project / "src/engine.cpp", "int main() { return 0; }\n");
  fs::copy_file(test::materialPath("filament_plastic.json"), project / "filament_plastic.json");
  return project;
}

// Entries of `dir` that a writer left beside its outputs: our temporaries' names.
std::vector<std::string> temporariesIn(const fs::path& dir) {
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".matbricks-") != std::string::npos)
      left.push_back(e.path().filename().string());
  return left;
}

const std::string kSetA = test::materialPath("filament_plastic.json");
const std::string kSetB = test::materialPath("filament_plastic.json") + " " + test::materialPath("ue4_metal.json");

test::CliResult compileTo(const std::string& materials, const fs::path& out, const std::string& env = "") {
  return test::runCli("compile " + materials + " -o " + q(out) + " -q --no-cache", env);
}

// The two packages the tests switch between, compiled once each into `root`.
struct ReferencePackages {
  std::map<std::string, std::string> a, b;
};
ReferencePackages referencePackages(const fs::path& root) {
  REQUIRE(compileTo(kSetA, root / "refA").exitCode == 0);
  REQUIRE(compileTo(kSetB, root / "refB").exitCode == 0);
  ReferencePackages refs{test::treeBytes(root / "refA"), test::treeBytes(root / "refB")};
  REQUIRE(refs.a != refs.b);
  return refs;
}

}  // namespace

TEST_CASE("compile -o . in a project directory refuses and leaves every file byte-identical", "[cli][outputs]") {
  const fs::path root = test::freshTempDir("outputs", "dot");
  const fs::path project = makeProject(root);
  const auto before = test::treeBytes(project);
  // From the project directory, as a user types it.
  auto r = test::runCli("compile filament_plastic.json -o . -q", "", project.string());
  INFO(r.output);
  CHECK(r.exitCode == 3);
  CHECK_THAT(r.output, Catch::Contains("error[E-OUTPUT-NOT-PACKAGE]") && Catch::Contains("README.md") &&
                           Catch::Contains("filament_plastic.json") && Catch::Contains("src/"));
  CHECK(test::treeBytes(project) == before);
  fs::remove_all(root);
}

TEST_CASE("a package directory is created, filled when empty, and replaced atomically when it is ours",
          "[cli][outputs][package]") {
  const fs::path root = test::freshTempDir("outputs", "replace");
  const auto [refA, refB] = referencePackages(root);
  CHECK(refA.count(".matbricks-package") == 1);

  fs::create_directories(root / "empty");
  CHECK(compileTo(kSetA, root / "empty").exitCode == 0);
  CHECK(test::treeBytes(root / "empty") == refA);

  // Twice to one directory: the second run replaces the first package whole.
  CHECK(compileTo(kSetA, root / "pkg").exitCode == 0);
  CHECK(test::treeBytes(root / "pkg") == refA);
  CHECK(compileTo(kSetB, root / "pkg").exitCode == 0);
  CHECK(test::treeBytes(root / "pkg") == refB);
  CHECK(temporariesIn(root).empty());

  // A package the user put a file into is still ours to replace, but the user's file would
  // go: that is what the marker means (docs/cli.md "Outputs").
  CHECK(carriesOutputMarker(root / "pkg"));
  fs::remove_all(root);
}

TEST_CASE(
    "outputs that are, contain or lie inside an input are refused through symlinks, .., hard links and bind mounts",
    "[cli][outputs]") {
  const fs::path root = test::freshTempDir("outputs", "overlap");
  const fs::path project = makeProject(root);
  const fs::path material = project / "filament_plastic.json";
  fs::create_directory_symlink(project, root / "alias");
  fs::create_directories(root / "links");
  fs::create_hard_link(material, root / "links/hard.json");
  const auto before = test::treeBytes(project);

  auto refused = [&](const std::string& args, const std::string& code = "E-OUTPUT-OVERLAPS-INPUT") {
    auto r = test::runCli("compile " + q(material) + " -q " + args);
    INFO(args << "\n" << r.output);
    CHECK(r.exitCode == 3);
    CHECK_THAT(r.output, Catch::Contains("error[" + code + "]"));
    CHECK(test::treeBytes(project) == before);
    for (const char* written : {"out", "alias/pkg", "cache"}) CHECK_FALSE(fs::exists(root / written));
  };
  refused("-o " + q(root / "out") + " --depfile " + q(root / "alias/filament_plastic.json"));  // symlinked directory
  refused("-o " + q(root / "out") + " --depfile " + q(project / "src/../filament_plastic.json"));  // ..
  refused("-o " + q(root / "out") + " --depfile " + q(root / "links/hard.json"));                  // hard link
  refused("-o " + q(root / "alias/src/../pkg") + " --depfile " + q(root / "alias/pkg/deps.d"));    // depfile inside -o
  refused("-o " + q(root / "cache/pkg") + " --cache-dir " + q(root / "cache"));                    // inside the cache
  refused("-o " + q(root / "alias"), "E-OUTPUT-NOT-PACKAGE");  // a symlink to the project directory

  // A bind mount shows the project under a second path with the same device and inode. It
  // needs CAP_SYS_ADMIN, which a container may not grant: then this part is skipped, loudly.
  fs::create_directories(root / "bound");
  if (::mount(project.c_str(), (root / "bound").c_str(), nullptr, MS_BIND, nullptr) == 0) {
    refused("-o " + q(root / "out") + " --depfile " + q(root / "bound/filament_plastic.json"));
    ::umount((root / "bound").c_str());
  } else {
    WARN("bind mount not permitted here (" << std::strerror(errno) << "): the bind-mount case was not run");
  }
  fs::remove_all(root);
}

TEST_CASE("single-file outputs go through a symlink to its target and never replace a directory or device",
          "[cli][outputs][vulkan]") {
  const fs::path root = test::freshTempDir("outputs", "files");
  writeText(root / "notes/real.md", "old\n");
  fs::create_symlink(root / "notes/real.md", root / "link.md");
  auto r = test::runCli("stress --brick d_ggx --samples 16 --markdown -o " + q(root / "link.md"));
  INFO(r.output);
  CHECK(r.exitCode == 0);
  CHECK(fs::is_symlink(root / "link.md"));
  CHECK(test::readFile(root / "notes/real.md").find("d_ggx") != std::string::npos);
  CHECK(temporariesIn(root / "notes").empty());

  for (const fs::path& bad : {root / "notes", fs::path("/dev/null")}) {
    auto refused = test::runCli("stress --brick d_ggx --samples 16 --markdown -o " + q(bad));
    INFO(refused.output);
    CHECK(refused.exitCode == 3);
    CHECK_THAT(refused.output, Catch::Contains("error[E-OUTPUT-NOT-FILE]"));
  }
  CHECK(fs::is_character_file("/dev/null"));
  fs::remove_all(root);
}

TEST_CASE("leftovers of a killed run are removed only when they are ours and their process is gone", "[cli][outputs]") {
  const fs::path root = test::freshTempDir("outputs", "leftovers");
  const std::string marker = outputMarkerText("package");
  const std::string dead = "999999999";  // above Linux's pid_max: no such process
  writeText(root / (".pkg.matbricks-new." + dead + ".0") / ".matbricks-package", marker);
  writeText(root / (".pkg.matbricks-new." + dead + ".0") / "manifest.json", "{}");
  writeText(root / (".pkg.matbricks-new." + dead + ".1") / "mine.txt", "not matbricks'\n");  // no marker
  writeText(root / (".pkg.matbricks-old." + std::to_string(::getpid()) + ".0") / ".matbricks-package",
            marker);  // alive
  REQUIRE(compileTo(kSetA, root / "pkg").exitCode == 0);
  CHECK_FALSE(fs::exists(root / (".pkg.matbricks-new." + dead + ".0")));
  CHECK(test::readFile(root / (".pkg.matbricks-new." + dead + ".1") / "mine.txt") == "not matbricks'\n");
  CHECK(fs::exists(root / (".pkg.matbricks-old." + std::to_string(::getpid()) + ".0")));
  fs::remove_all(root);
}

TEST_CASE("a compile killed at any moment leaves the old package or the new one, complete", "[cli][outputs][kill]") {
  const fs::path root = test::freshTempDir("outputs", "kill");
  const ReferencePackages refs = referencePackages(root);  // a struct, not a structured binding:
  const fs::path pkg = root / "work/pkg";                  // clang 14 cannot capture those
  fs::create_directories(pkg.parent_path());
  REQUIRE(compileTo(kSetA, pkg).exitCode == 0);
  auto state = [&] {
    const auto now = test::treeBytes(pkg);
    return now == refs.a ? 'A' : now == refs.b ? 'B' : '?';
  };

  // 1. At each step of the commit, by the writer's fault points (SIGKILL sent to itself).
  for (const char* point : {"staging-half", "before-swap", "after-swap"}) {
    const char before = state();
    auto r = compileTo(before == 'A' ? kSetB : kSetA, pkg, std::string("MATBRICKS_FAULT_KILL_AT=") + point);
    INFO(point << ": exit " << r.exitCode << "\n" << r.output);
    CHECK(r.exitCode == 128 + SIGKILL);
    const char after = state();
    CHECK(after != '?');
    // Before the swap the old package stands; from the swap on, the new one.
    CHECK((std::string(point) == "after-swap" ? after != before : after == before));
  }

  // 2. At times spread over a whole run, by an outside SIGKILL.
  const char* cli = std::getenv("MATBRICKS_CLI");
  auto spawnCompile = [&](const std::string& set) {
    std::vector<std::string> args{cli, "compile"};
    for (size_t at = 0, next; at < set.size(); at = next + 1) {
      next = set.find(' ', at);
      if (next == std::string::npos) next = set.size();
      args.push_back(set.substr(at, next - at));
    }
    for (const char* a : {"-o", pkg.c_str(), "-q", "--no-cache"}) args.push_back(a);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    REQUIRE(posix_spawn(&pid, cli, nullptr, nullptr, argv.data(), environ) == 0);
    return pid;
  };
  auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  pid_t timed = spawnCompile(state() == 'A' ? kSetB : kSetA);
  waitpid(timed, &status, 0);
  const double runMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  REQUIRE(WIFEXITED(status));
  int killed = 0;
  for (int k = 0; k <= 16; ++k) {
    const double delayMs = runMs * k / 14.0;  // the last two land after the run has ended
    pid_t pid = spawnCompile(state() == 'A' ? kSetB : kSetA);
    std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(delayMs));
    ::kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    killed += WIFSIGNALED(status) ? 1 : 0;
    INFO("killed after " << delayMs << " ms of a " << runMs << " ms run");
    CHECK(state() != '?');
  }
  CHECK(killed >= 8);  // most kills landed while the compile ran

  // 3. The next complete run cleans up whatever the killed ones left beside the package.
  REQUIRE(compileTo(kSetB, pkg).exitCode == 0);
  CHECK(state() == 'B');
  CHECK(temporariesIn(pkg.parent_path()).empty());
  fs::remove_all(root);
}

TEST_CASE("the committed bench results carry the output marker, so their documented command can replace them",
          "[outputs]") {
  // bench/README.md regenerates bench/results/bench with `matbricks bench -o bench/results/bench`;
  // without the marker that command refuses the directory (E-OUTPUT-NOT-PACKAGE).
  CHECK(carriesOutputMarker(test::sourceDir() / "bench" / "results" / "bench"));
}
