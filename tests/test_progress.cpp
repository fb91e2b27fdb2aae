// cli/progress.hpp: the plain lines a long command writes to a non-terminal stderr, the
// redrawn bar on a terminal, thread-safe counting, and -q on the commands (docs/cli.md
// "Progress").
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <sstream>
#include <thread>
#include <vector>

#include "cli/progress.hpp"
#include "support/cli_support.hpp"
#include "support/pipeline_support.hpp"

using mb::cli::Progress;

namespace {

// A clock the test moves by hand.
struct FakeClock {
  Progress::Clock::time_point t{};
  std::function<Progress::Clock::time_point()> fn() {
    return [this] { return t; };
  }
  void advanceSeconds(double s) {
    t += std::chrono::duration_cast<Progress::Clock::duration>(std::chrono::duration<double>(s));
  }
};

struct Line {
  size_t done, total;
  int percent;
  bool last;
};

// Every line must be one of the two documented forms.
std::vector<Line> parseLines(const std::string& text) {
  static const std::regex kStep(R"(^work: (\d+)/(\d+) \((\d+)%\), ETA (\d+:\d\d|\?)$)");
  static const std::regex kLast(R"(^work: (\d+)/(\d+) \((\d+)%\) in \d+\.\d s$)");
  std::vector<Line> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    const bool last = std::regex_match(line, m, kLast);
    INFO(line);
    REQUIRE((last || std::regex_match(line, m, kStep)));
    out.push_back({std::stoul(m[1]), std::stoul(m[2]), std::stoi(m[3]), last});
  }
  return out;
}

}  // namespace

TEST_CASE("progress lines off a terminal: few, monotonic, ending at the total", "[progress]") {
  std::ostringstream out;
  FakeClock clock;
  {
    Progress p("work", 1000, out, false, clock.fn());
    for (int i = 0; i < 1000; ++i) {
      clock.advanceSeconds(0.05);  // 50 s in all
      p.advance();
    }
  }  // the destructor finishes
  const std::vector<Line> lines = parseLines(out.str());
  REQUIRE(lines.size() >= 5);
  CHECK(lines.size() <= 12);  // a line per tenth (plus the 5 s rule), never one per unit
  for (size_t i = 1; i < lines.size(); ++i) CHECK(lines[i].done > lines[i - 1].done);
  CHECK(lines.back().last);
  CHECK(lines.back().done == 1000);
  CHECK(lines.back().total == 1000);
  CHECK(lines.back().percent == 100);
  for (size_t i = 0; i + 1 < lines.size(); ++i) CHECK(!lines[i].last);
}

TEST_CASE("progress: a slow unit still shows a line every few seconds; a fast command only its last", "[progress]") {
  std::ostringstream slow, fast;
  FakeClock clock;
  {
    Progress p("work", 100, slow, false, clock.fn());
    for (int i = 0; i < 5; ++i) {
      clock.advanceSeconds(6.0);
      p.advance();  // 5% each: no new tenth, but 6 s since the last line
    }
  }
  CHECK(parseLines(slow.str()).size() == 6);
  {
    Progress p("work", 100, fast, false, clock.fn());
    for (int i = 0; i < 100; ++i) p.advance();  // no time passes
  }
  const auto lines = parseLines(fast.str());
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].last);
}

TEST_CASE("progress counts every unit from many threads", "[progress]") {
  std::ostringstream out;
  FakeClock clock;
  {
    Progress p("work", 0, out, false, clock.fn());
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
      threads.emplace_back([&] {
        p.addToTotal(250);
        for (int i = 0; i < 250; ++i) p.advance();
      });
    for (auto& t : threads) t.join();
  }
  const auto lines = parseLines(out.str());
  REQUIRE(!lines.empty());
  CHECK(lines.back().done == 1000);
  CHECK(lines.back().total == 1000);
}

TEST_CASE("progress on a terminal redraws one line and ends it", "[progress]") {
  std::ostringstream out;
  FakeClock clock;
  {
    Progress p("work", 10, out, true, clock.fn());
    for (int i = 0; i < 10; ++i) {
      clock.advanceSeconds(1.0);
      p.advance();
    }
  }
  const std::string s = out.str();
  CHECK(std::count(s.begin(), s.end(), '\n') == 1);
  CHECK(s.back() == '\n');
  CHECK(s.find("\rwork [############............] 5/10  50%  ETA 0:05\x1b[K") != std::string::npos);
  CHECK(s.find("\rwork [########################] 10/10  100%  0:10\x1b[K\n") != std::string::npos);
  CHECK(Progress::formatDuration(3725) == "1:02:05");
}

TEST_CASE("quiet long commands (-q) print nothing on success", "[progress][vulkan]") {
  namespace fs = std::filesystem;
  const fs::path dir = mb::test::freshTempDir("progress", "quiet");
  const std::string mat = (mb::test::sourceDir() / "materials" / "ue4_metal.json").string();
  for (const std::string& args : std::vector<std::string>{
           "lut --size 8 --check-grid 4 -q -o " + (dir / "dfg.bin").string(),
           "validate -q --samples 64 " + mat + " --environment none",
           "bench -q --brick d_ggx --repeats 1 --samples 64 --records 64 -o " + (dir / "bench").string()}) {
    INFO(args);
    const auto quiet = mb::test::runCli(args);
    CHECK(quiet.exitCode == 0);
    CHECK(quiet.output == "");
  }
  // Without -q, off a terminal: plain progress lines on stderr, the last at the total.
  const auto loud = mb::test::runCli("lut --size 8 --check-grid 4 -o " + (dir / "dfg2.bin").string());
  CHECK(loud.exitCode == 0);
  CHECK(std::regex_search(loud.output, std::regex(R"((^|\n)lut: 17/17 \(100%\) in \d+\.\d s\n)")));
  fs::remove_all(dir);
}
