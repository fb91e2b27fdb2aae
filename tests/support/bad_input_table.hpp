// docs/bad-inputs.md: every case of the bad-input corpus with the command, exit code and the
// exact text the CLI printed (tests/test_bad_inputs.cpp checks the committed file is current
// and writes it with `mb_tests "[.bad-inputs-doc]"`).
#pragma once
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "support/build_paths.hpp"
#include "support/bad_input_cases.hpp"

namespace mb::test {

inline const char* kBadInputsDocCommand = "build/bin/mb_tests \"[.bad-inputs-doc]\"";

// A Markdown table cell holding `text` as code: pipes escaped, backticks fenced.
inline std::string codeCell(const std::string& text) {
  std::string s = escapeInvalidUtf8(text);
  replaceAll(s, "|", "\\|");
  std::string fence = s.find('`') == std::string::npos ? "`" : "``";
  return fence + (fence.size() > 1 ? " " : "") + s + (fence.size() > 1 ? " " : "") + fence;
}

// The coverage-guided fuzzing section: what runs, and the latest counts and rates that
// scripts/fuzz.sh measured (fuzz/results.md, copied there from build-asan/fuzz-results.md).
inline std::string fuzzingSection() {
  std::ifstream in(mb::test::fuzzDir() / "results.md", std::ios::binary);
  std::string results((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return "\n## Coverage-guided fuzzing\n\n"
         "Five libFuzzer targets ([fuzz/](../fuzz/), [fuzzing.md](fuzzing.md)) feed the loaders inputs\n"
         "that grow toward new code: the JSON material reader, the macro form (with `#include`s in a\n"
         "scratch project), glTF (.gltf and .glb, materials resolved), scene JSON (loaded and planned)\n"
         "and the CSV reader of `eval`. They are built with AddressSanitizer and\n"
         "UndefinedBehaviorSanitizer, seeded from the shipped files and this corpus, and guided by a\n"
         "dictionary each. A finding is any crash, sanitizer report, leak, hang (20 s) or an error\n"
         "without a code and a file; each is fixed and kept in `fuzz/regressions/<target>/`, which\n"
         "`tests/test_fuzz_regressions.cpp` replays in every build and `.ci/run` replays under the\n"
         "sanitizers.\n\n" +
         results;
}

inline std::string badInputsMarkdown(const std::vector<BadInputCase>& cases, const std::vector<CaseRun>& runs) {
  size_t known = 0;
  for (const auto& c : cases) known += c.knownFailure.empty() ? 0 : 1;
  std::string md =
      "# Bad inputs and the messages they get\n\n"
      "<!-- Generated: do not edit. Regenerate with `" +
      std::string(kBadInputsDocCommand) +
      "`;\n"
      "     tests/test_bad_inputs.cpp fails when this file is stale. -->\n\n"
      "Every case of the bad-input corpus ([tests/data/bad_inputs/](../tests/data/bad_inputs/), listed\n"
      "in its `cases.json`) run through the CLI from the repository root, with the exit code and the\n"
      "exact text it printed to stderr. `OUT` stands for a scratch directory (the test checks it is\n"
      "still empty afterwards: no package, no staging directory) and `<repo>` for the absolute path\n"
      "of the checkout. `WORK` is a scratch copy of a corpus directory (a user's project: a\n"
      "material, a README, code) where the output cases run; the test checks that every file in\n"
      "it keeps its bytes and that nothing is added ([cli.md](cli.md#outputs)). Exit codes: 3 bad\n"
      "input, 4 no Vulkan device ([cli.md](cli.md)). Every input is read only as a regular file within\n"
      "its kind's size limit: a FIFO with no writer or a link to `/dev/zero` is refused at once\n"
      "(`E-FILE-NOT-REGULAR`), and the memory a JSON, glTF or CSV input may take is bounded and\n"
      "measured ([formats.md](formats.md#input-files)).\n\n"
      "`tests/test_bad_inputs.cpp` (`[bad-input]`) checks each case: the exit code, that no run\n"
      "crashes, hangs or leaves files behind, that every stderr line reads\n"
      "`file:line:column: error[CODE]: message` with the expected codes in order, the line and\n"
      "column at least 1 and the line inside the named file, that `--diagnostics-format json` prints\n"
      "the same diagnostics as a JSON array of `{code, severity, file, line, column, message,\n"
      "suggestion}`, and where the case names one, that a did-you-mean suggestion is given.\n"
      "`tests/test_fuzz_inputs.cpp` (`[fuzz]`) adds seeded mutations of every shipped material and scene (scenes are loaded and planned).\n\n" +
      std::to_string(cases.size()) + " cases; " + std::to_string(known) +
      (known == 1 ? " is a **known failure**" : " are **known failures**") +
      ": the CLI does not yet do what the case expects (the note says what\n"
      "is wrong; the test warns while the failure lasts and fails once it is fixed, so the mark is\n"
      "removed).\n\n"
      "| case | what | command | exit | message(s) |\n"
      "|---|---|---|---|---|\n";
  for (size_t i = 0; i < cases.size(); ++i) {
    const auto& c = cases[i];
    std::string link = "[" + c.input + "](../" + corpusRelative() + "/" + c.input + ")";
    std::string messages;
    for (const auto& line : lines(runs[i].err)) messages += (messages.empty() ? "" : "<br>") + codeCell(line);
    std::string what = c.what;
    replaceAll(what, "|", "\\|");
    if (!c.knownFailure.empty()) {
      std::string note = c.knownFailure;
      replaceAll(note, "|", "\\|");
      what += "<br>**known failure**: " + note;
    }
    md += "| " + (c.absent ? c.input + " (absent)" : link) + " | " + what + " | " + codeCell(displayCommand(c)) +
          " | " + std::to_string(runs[i].exitCode) + " | " + messages + " |\n";
  }
  return md + fuzzingSection();
}

}  // namespace mb::test
