// The bad-input corpus (tests/data/bad_inputs/, issue 4 "Diagnostics"): every case runs
// through the CLI as a user would, and must exit with its code, print one well-formed
// diagnostic line per error with the expected codes and positions, say the same in
// --diagnostics-format json, and leave nothing behind. docs/bad-inputs.md tabulates the runs.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "support/bad_input_table.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

// path -> size of every file under the corpus: the runs must not touch it.
std::map<std::string, uintmax_t> corpusSnapshot() {
  std::map<std::string, uintmax_t> files;
  for (const auto& e : fs::recursive_directory_iterator(test::corpusDir()))
    files[fs::relative(e.path(), test::corpusDir()).string()] = e.is_regular_file() ? e.file_size() : 0;
  return files;
}

std::vector<test::CaseRun> runAll(const std::vector<test::BadInputCase>& cases) {
  std::vector<test::CaseRun> runs;
  for (const auto& c : cases) runs.push_back(test::runCase(c));
  return runs;
}

}  // namespace

TEST_CASE("every file of the bad-input corpus belongs to a case, and every case's input exists", "[bad-input]") {
  auto cases = test::loadBadInputCases();
  REQUIRE(cases.size() >= 60);
  std::set<std::string> owners{"cases.json"};  // top-level entries some case uses
  for (const auto& c : cases) {
    INFO(c.input);
    owners.insert(fs::path(c.input).begin()->string());
    CHECK(fs::exists(test::corpusDir() / c.input) != c.absent);
    CHECK((c.exit == 3 || c.exit == 4));
    CHECK((c.exit != 3 || !c.codes.empty()));
  }
  for (const auto& e : fs::directory_iterator(test::corpusDir())) {
    INFO(e.path().filename().string());
    CHECK(owners.count(e.path().filename().string()) == 1);
  }
}

// One run of each case serves both checks: its diagnostics, and the row docs/bad-inputs.md
// shows for it (the table is made from the text runs, as `[.bad-inputs-doc]` writes it).
TEST_CASE(
    "every bad input gets its expected diagnostics, in text and json, leaves nothing behind, and is "
    "shown as docs/bad-inputs.md has it",
    "[bad-input][cli]") {
  auto cases = test::loadBadInputCases();
  auto before = corpusSnapshot();
  std::vector<test::CaseRun> textRuns;
  for (const auto& c : cases) {
    INFO("case " << c.input << ": " << test::displayCommand(c));
    const test::CaseRun& text = textRuns.emplace_back(test::runCase(c));
    INFO("stderr:\n" << text.err);
    test::Judgement j = test::judgeTextRun(c, text);
    if (c.outputStarts.empty()) {
      test::CaseRun json = test::runCase(c, true);
      INFO("json stderr:\n" << json.err);
      for (auto& p : test::judgeJsonRun(c, text, json)) j.problems.push_back(p);
      for (const auto& left : json.leftovers) j.hard.push_back("json run left OUT/" + left);
    }
    for (const auto& h : j.hard) FAIL_CHECK(h);
    if (c.knownFailure.empty()) {
      for (const auto& p : j.problems) FAIL_CHECK(p);
    } else if (j.problems.empty()) {
      FAIL_CHECK(
          "known failure is fixed: remove \"known_failure\" from the case in tests/data/bad_inputs/cases.json and regenerate docs/bad-inputs.md");
    } else {
      WARN("known failure " << c.input << ": " << j.problems.front());
    }
  }
  CHECK(corpusSnapshot() == before);
  INFO("regenerate docs/bad-inputs.md with: " << test::kBadInputsDocCommand);
  CHECK(test::badInputsMarkdown(cases, textRuns) == test::readFile(test::sourceDir() / "docs/bad-inputs.md"));
}

// Hidden: writes docs/bad-inputs.md (temp file, then rename).
TEST_CASE("write docs/bad-inputs.md", "[.bad-inputs-doc]") {
  auto cases = test::loadBadInputCases();
  std::string md = test::badInputsMarkdown(cases, runAll(cases));
  fs::path doc = test::sourceDir() / "docs/bad-inputs.md", tmp = doc.string() + ".tmp";
  { std::ofstream(tmp, std::ios::binary) << md; }
  fs::rename(tmp, doc);
  SUCCEED("wrote " << doc.string());
}
