// Outputs never destroy a user's files (docs/cli.md "Outputs"): a package directory is
// created, filled when empty, or replaced atomically only while it holds exactly what its
// marker lists (never across a mount point; through a symlink, the package it points to); no
// output may be, contain or lie inside an input, seen through symlinks, "..", hard links and
// bind mounts; a command killed at any moment leaves the old output or the new one, complete,
// and leftovers the next run recognises and removes. The one-line refusals themselves are
// rows of the bad-input corpus.
#include <catch2/catch.hpp>

#include <signal.h>
#include <spawn.h>
#include <sys/mount.h>
#include <sys/stat.h>
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
#include "write/package_writer.hpp"

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

  // `-o LINK` with LINK a symlink to a package: the package it points to is replaced, and the
  // link stays a link.
  fs::create_directory_symlink(root / "pkg", root / "link");
  CHECK(compileTo(kSetA, root / "link").exitCode == 0);
  CHECK(fs::is_symlink(root / "link"));
  CHECK(test::treeBytes(root / "pkg") == refA);
  CHECK(temporariesIn(root).empty());
  // A dangling link: the package is created where it points.
  fs::create_directory_symlink(root / "made", root / "dangling");
  CHECK(compileTo(kSetA, root / "dangling").exitCode == 0);
  CHECK(fs::is_symlink(root / "dangling"));
  CHECK(test::treeBytes(root / "made") == refA);
  fs::remove_all(root);
}

TEST_CASE("a package is replaced only while it holds exactly what its marker lists", "[cli][outputs][package]") {
  const fs::path root = test::freshTempDir("outputs", "listed");
  const auto refs = referencePackages(root);
  const fs::path pkg = root / "pkg";
  REQUIRE(compileTo(kSetA, pkg).exitCode == 0);
  auto refused = [&](const std::string& code, const std::string& names) {
    const auto before = test::treeBytes(pkg);
    auto r = compileTo(kSetB, pkg);
    INFO(r.output);
    CHECK(r.exitCode == 3);
    CHECK_THAT(r.output, Catch::Contains("error[" + code + "]") && Catch::Contains(names));
    CHECK(test::treeBytes(pkg) == before);
    CHECK(temporariesIn(root).empty());
  };
  // The user's notes put into the package directory, at the top and in a subdirectory.
  writeText(pkg / "notes.txt", "mine\n");
  refused("E-OUTPUT-UNLISTED", "notes.txt not listed");
  fs::remove(pkg / "notes.txt");
  writeText(pkg / "spirv/notes.txt", "mine\n");
  refused("E-OUTPUT-UNLISTED", "spirv/notes.txt not listed");
  fs::remove(pkg / "spirv/notes.txt");
  // A listed file the user edited, and one replaced by a symlink.
  const std::string manifest = test::readFile(pkg / "manifest.json");
  writeText(pkg / "manifest.json", manifest + " ");
  refused("E-OUTPUT-UNLISTED", "manifest.json changed since matbricks wrote it");
  fs::remove(pkg / "manifest.json");
  fs::create_symlink(root / "refA/manifest.json", pkg / "manifest.json");
  refused("E-OUTPUT-UNLISTED", "manifest.json is a symlink");
  fs::remove(pkg / "manifest.json");
  writeText(pkg / "manifest.json", manifest);
  // Its marker copied into a directory of the user's files.
  const fs::path user = root / "user";
  writeText(user / "README.md", "# mine\n");
  fs::copy_file(pkg / kOutputMarkerName, user / kOutputMarkerName);
  const auto userBefore = test::treeBytes(user);
  auto planted = compileTo(kSetB, user);
  CHECK(planted.exitCode == 3);
  CHECK_THAT(planted.output, Catch::Contains("error[E-OUTPUT-UNLISTED]") && Catch::Contains("README.md"));
  CHECK(test::treeBytes(user) == userBefore);
  // A listed file the user deleted is no reason to refuse; the package is replaced whole.
  fs::remove(pkg / "manifest.json");
  CHECK(compileTo(kSetB, pkg).exitCode == 0);
  CHECK(test::treeBytes(pkg) == refs.b);
  CHECK(temporariesIn(root).empty());
  fs::remove_all(root);
}

TEST_CASE("a mount point inside a package is never removed across: refused, the mounted files kept",
          "[cli][outputs][package]") {
  const fs::path root = test::freshTempDir("outputs", "mount");
  const fs::path pkg = root / "pkg", user = root / "user";
  REQUIRE(compileTo(kSetA, pkg).exitCode == 0);
  writeText(user / "photos/cat.txt", "a cat\n");
  const auto userBefore = test::treeBytes(user);
  // Onto a directory of the package's own (listed files beneath it) and onto a new one. Bind
  // mounts need CAP_SYS_ADMIN, which a container may not grant: then this is skipped, loudly.
  for (const fs::path& at : {pkg / "spirv", pkg / "mnt"}) {
    fs::create_directories(at);
    if (::mount(user.c_str(), at.c_str(), nullptr, MS_BIND, nullptr) != 0) {
      WARN("bind mount not permitted here (" << std::strerror(errno) << "): the mount-point case was not run");
      break;
    }
    auto r = compileTo(kSetB, pkg);
    ::umount(at.c_str());
    INFO(r.output);
    CHECK(r.exitCode == 3);
    CHECK_THAT(r.output, Catch::Contains("error[E-OUTPUT-MOUNT]") && Catch::Contains(at.filename().string() + "/"));
    CHECK(test::treeBytes(user) == userBefore);
    if (at.filename() == "mnt") fs::remove(at);
  }
  CHECK(compileTo(kSetB, pkg).exitCode == 0);
  CHECK(test::treeBytes(user) == userBefore);
  fs::remove_all(root);
}

TEST_CASE("a FIFO as an output's marker is refused at once, never read", "[cli][outputs]") {
  const fs::path root = test::freshTempDir("outputs", "fifo");
  fs::create_directories(root / "pkg");
  REQUIRE(::mkfifo((root / "pkg" / kOutputMarkerName).c_str(), 0600) == 0);
  auto r = compileTo(kSetA, root / "pkg");  // a hang would be killed by the test's timeout
  INFO(r.output);
  CHECK(r.exitCode == 3);
  CHECK_THAT(r.output, Catch::Contains("error[E-OUTPUT-NOT-PACKAGE]") && Catch::Contains("FIFO"));
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
  const std::string marker = outputMarkerHeader("package") + outputMarkerEnd(0);
  const std::string dead = "999999999";  // above Linux's pid_max: no such process
  // An old package swapped out and killed while being removed: its marker lists its files.
  writeText(root / (".pkg.matbricks-new." + dead + ".0") / ".matbricks-package",
            outputMarkerHeader("package") + outputMarkerLine("manifest.json", {2, contentHash("{}", 2)}) +
                outputMarkerEnd(1));
  writeText(root / (".pkg.matbricks-new." + dead + ".0") / "manifest.json", "{}");
  writeText(root / (".pkg.matbricks-new." + dead + ".1") / "mine.txt", "not matbricks'\n");  // no marker
  writeText(root / (".pkg.matbricks-old." + std::to_string(::getpid()) + ".0") / ".matbricks-package",
            marker);  // alive
  // A staging directory killed while it streamed (its marker has no end line yet), one
  // killed while writing the marker itself, and a single file's temporary.
  writeText(root / (".pkg.matbricks-new." + dead + ".2") / ".matbricks-package", outputMarkerHeader("package"));
  writeText(root / (".pkg.matbricks-new." + dead + ".2") / "spirv/ab.spv", "half");
  writeText(root / (".pkg.matbricks-new." + dead + ".3") / ".matbricks-package", "{\"form");
  writeText(root / (".pkg.matbricks-tmp." + dead + ".4") / ".matbricks-package", outputMarkerHeader("temporary"));
  writeText(root / (".pkg.matbricks-tmp." + dead + ".4") / "content", "half");
  // Ours by name but not by marker, and a name that only looks like ours.
  writeText(root / (".pkg.matbricks-new." + dead + ".5") / ".matbricks-package", "{\"form");
  writeText(root / (".pkg.matbricks-new." + dead + ".5") / "mine.txt", "not matbricks'\n");
  writeText(root / (".pkg.matbricks-new." + dead + ".x") / ".matbricks-package", marker);
  REQUIRE(compileTo(kSetA, root / "pkg").exitCode == 0);
  for (const char* gone : {".0", ".2", ".3"}) {
    INFO(gone);
    CHECK_FALSE(fs::exists(root / (".pkg.matbricks-new." + dead + gone)));
  }
  CHECK_FALSE(fs::exists(root / (".pkg.matbricks-tmp." + dead + ".4")));
  CHECK(test::readFile(root / (".pkg.matbricks-new." + dead + ".1") / "mine.txt") == "not matbricks'\n");
  CHECK(test::readFile(root / (".pkg.matbricks-new." + dead + ".5") / "mine.txt") == "not matbricks'\n");
  CHECK(fs::exists(root / (".pkg.matbricks-new." + dead + ".x")));
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

  // 1. At each step of the commit, by the writer's fault points (SIGKILL sent to itself):
  // "removing-old" is part way through removing the old package after the swap.
  for (const char* point : {"staging-half", "before-swap", "after-swap", "removing-old"}) {
    const char before = state();
    auto r = compileTo(before == 'A' ? kSetB : kSetA, pkg, std::string("MATBRICKS_FAULT_KILL_AT=") + point);
    INFO(point << ": exit " << r.exitCode << "\n" << r.output);
    CHECK(r.exitCode == 128 + SIGKILL);
    const char after = state();
    CHECK(after != '?');
    // Before the swap the old package stands; from the swap on, the new one.
    const bool swapped = std::string(point) == "after-swap" || std::string(point) == "removing-old";
    CHECK((swapped ? after != before : after == before));
    // Whatever a kill left beside the package is recognisably ours (our marker inside), so
    // the next run removes it.
    for (const auto& left : temporariesIn(pkg.parent_path())) CHECK(carriesOutputMarker(pkg.parent_path() / left));
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
  const fs::path bench = test::sourceDir() / "bench" / "results" / "bench";
  CHECK(carriesOutputMarker(bench));
  CHECK_NOTHROW(checkOutputDirectory(bench));  // it lists every file there, with its hash
}

TEST_CASE("a single-file write killed before its rename leaves a marked temporary, which the next write removes",
          "[cli][outputs][kill]") {
  const fs::path root = test::freshTempDir("outputs", "filekill");
  writeText(root / "deps.d", "old\n");
  const std::string args =
      "compile " + kSetA + " -o " + q(root / "pkg") + " -q --no-cache --depfile " + q(root / "deps.d");
  auto killed = test::runCli(args, "MATBRICKS_FAULT_KILL_AT=file-written");
  CHECK(killed.exitCode == 128 + SIGKILL);
  CHECK(test::readFile(root / "deps.d") == "old\n");
  const auto left = temporariesIn(root);
  REQUIRE(left.size() == 1);
  CHECK(left.front().rfind(".deps.d.matbricks-tmp.", 0) == 0);
  CHECK(carriesOutputMarker(root / left.front()));
  auto r = test::runCli(args);
  INFO(r.output);
  CHECK(r.exitCode == 0);
  CHECK(test::readFile(root / "deps.d").find("manifest.json") != std::string::npos);
  CHECK(temporariesIn(root).empty());
  fs::remove_all(root);
}

TEST_CASE("preview -o X.png writes X.png only; the other pictures go where they are named", "[cli][outputs][vulkan]") {
  const fs::path root = test::freshTempDir("outputs", "preview");
  writeText(root / "shot.reference.png", "the user's own picture\n");
  writeText(root / "shot.diff.png", "another\n");
  fs::create_directories(root / "pictures");
  // One render (the device is slow to start): the named pictures are written, the files
  // beside X.png that earlier versions wrote unasked keep their bytes.
  auto r = test::runCli("preview " + q(test::materialPath("filament_plastic.json")) + " --size 8 -o " +
                        q(root / "shot.png") + " --reference-image " + q(root / "pictures/ref.png") + " --diff-image " +
                        q(root / "diff.png"));
  INFO(r.output);
  CHECK(r.exitCode == 0);
  for (const char* written : {"shot.png", "pictures/ref.png", "diff.png"}) CHECK(fs::file_size(root / written) > 0);
  CHECK(test::readFile(root / "shot.reference.png") == "the user's own picture\n");
  CHECK(test::readFile(root / "shot.diff.png") == "another\n");
  CHECK(temporariesIn(root).empty());
  fs::remove_all(root);
}
