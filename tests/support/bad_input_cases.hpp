// The bad-input corpus (tests/data/bad_inputs/cases.json): running one case through the CLI as
// a user would, parsing what it printed, and judging it against the case's expectations.
// Used by tests/test_bad_inputs.cpp; the table of docs/bad-inputs.md is built from these runs
// (bad_input_table.hpp).
#pragma once
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/pipeline_support.hpp"

namespace mb::test {

struct BadInputCase {
  std::string input;  // relative to the corpus directory
  std::string what;   // one line for the table
  std::string command = "compile";
  std::string extra;  // more arguments after the input; {corpus} = the corpus directory
  std::string env;    // extra "VAR=value ..." assignments
  int exit = 3;
  std::vector<std::string> codes;  // error codes in printed order
  bool positions = true;           // every error has line >= 1 and column >= 1 inside its file
  bool absent = false;             // the input deliberately does not exist
  std::string outputStarts;        // for failures that are not input errors (no device): stderr's start
  std::string suggests;            // some diagnostic's suggestion (json mode) contains this
  std::string knownFailure;        // non-empty: the expectation describes a fix not made yet
  // Output cases (docs/cli.md "Outputs"): `workdir` is a corpus directory copied to a scratch
  // WORK directory, where the command runs (input and arguments relative to it); every file
  // of the copy must keep its bytes and nothing may be added. `output` replaces compile's
  // automatic "-o OUT/pkg" ("" keeps it; "none": no -o at all).
  std::string workdir;
  std::string output;
  bool libraryCopy = false;  // WORK/lib: a copy of the shipped shader library
  // WORK-relative paths where a FIFO with no writer is made before the run (git holds no
  // FIFOs): an input that is one must be refused at once, never opened for a blocking read.
  std::vector<std::string> fifos;
};

// One printed diagnostic line, "file:line:column: error[CODE]: message" (line and column 0
// when the line has none).
struct PrintedDiagnostic {
  std::string file, severity, code, message;
  int line = 0, column = 0;
};

struct CaseRun {
  int exitCode = -1;                     // 124: timed out; >= 128: killed by a signal
  std::string out, err;                  // stdout, stderr, with scratch paths shown as OUT
  std::vector<std::string> leftovers;    // entries left in the output's parent directory
  std::vector<std::string> workChanges;  // WORK entries added, removed or changed
};

inline std::filesystem::path corpusDir() { return sourceDir() / "tests/data/bad_inputs"; }
inline std::string corpusRelative() { return "tests/data/bad_inputs"; }

inline std::vector<BadInputCase> loadBadInputCases() {
  auto j = nlohmann::json::parse(readFile(corpusDir() / "cases.json"));
  std::vector<BadInputCase> cases;
  for (const auto& e : j.at("cases")) {
    BadInputCase c;
    c.input = e.at("input");
    c.what = e.at("what");
    c.command = e.value("command", c.command);
    c.env = e.value("env", "");
    c.extra = e.value("extra", "");
    c.exit = e.value("exit", c.exit);
    c.codes = e.at("codes").get<std::vector<std::string>>();
    c.positions = e.value("positions", true);
    c.absent = e.value("absent", false);
    c.outputStarts = e.value("output_starts", "");
    c.suggests = e.value("suggests", "");
    c.knownFailure = e.value("known_failure", "");
    c.workdir = e.value("workdir", "");
    c.output = e.value("output", "");
    c.libraryCopy = e.value("library_copy", false);
    c.fifos = e.value("fifos", std::vector<std::string>{});
    cases.push_back(c);
  }
  return cases;
}

inline void replaceAll(std::string& s, const std::string& from, const std::string& to) {
  for (size_t at = s.find(from); !from.empty() && at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
}

// The command line as a user types it from the repository root; OUT is a scratch directory.
inline std::string commandArgs(const BadInputCase& c, const std::string& out, bool json) {
  std::string args = json ? "--diagnostics-format json " : "";
  // In a WORK case the input is relative to WORK; the WORK directory itself stands for a
  // command that takes no input file (lut, bricks, energy).
  const std::string input = c.workdir.empty()      ? corpusRelative() + "/" + c.input
                            : c.input == c.workdir ? ""
                                                   : c.input.substr(c.workdir.size() + 1);
  args += c.command + (input.empty() ? "" : " " + input);
  if (!c.extra.empty()) {
    std::string extra = c.extra;
    replaceAll(extra, "{corpus}", corpusRelative());
    args += " " + extra;
  }
  if (c.output == "none") return args;
  if (!c.output.empty())
    args += " -o " + c.output;
  else if (c.command == "compile")
    args += " -o " + out + "/pkg";
  return args;
}

inline std::string displayCommand(const BadInputCase& c) {
  return (c.workdir.empty() ? "" : "cd WORK && ") + (c.env.empty() ? "" : c.env + " ") + "matbricks " +
         commandArgs(c, "OUT", false);
}

// path -> bytes of every file under `dir` ("dir/" entries for directories).
inline std::map<std::string, std::string> treeBytes(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  if (!std::filesystem::exists(dir)) return files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    const std::string rel = std::filesystem::relative(e.path(), dir).string();
    if (e.is_symlink())
      files[rel] = "-> " + std::filesystem::read_symlink(e.path()).string();
    else if (e.is_directory())
      files[rel + "/"] = "";
    else if (!e.is_regular_file())  // a FIFO: reading it would wait for a writer
      files[rel] = "<not a regular file>";
    else
      files[rel] = readFile(e.path());
  }
  return files;
}

inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

// Runs the case's command from the repository root in a fresh scratch directory (the parent of
// -o OUT/pkg), which must be empty afterwards. `timeout` turns a hang into exit 124.
inline CaseRun runCase(const BadInputCase& c, bool json = false) {
  namespace fs = std::filesystem;
  static int serial = 0;
  fs::path scratch =
      fs::temp_directory_path() / ("mb_bad_inputs_" + std::to_string(::getpid()) + "_" + std::to_string(serial++));
  fs::path out = scratch / "out", capture = scratch / "capture", work = scratch / "work";
  fs::remove_all(scratch);
  fs::create_directories(out);
  fs::create_directories(capture);
  std::map<std::string, std::string> workBefore;
  if (!c.workdir.empty()) {
    fs::copy(corpusDir() / c.workdir, work, fs::copy_options::recursive | fs::copy_options::copy_symlinks);
    if (c.libraryCopy) fs::copy(sourceDir() / "shaderlib", work / "lib", fs::copy_options::recursive);
    for (const auto& fifo : c.fifos) {
      fs::create_directories((work / fifo).parent_path());
      if (::mkfifo((work / fifo).c_str(), 0600) != 0) throw std::runtime_error("mkfifo " + fifo + " failed");
    }
    workBefore = treeBytes(work);
  }
  const char* cli = std::getenv("MATBRICKS_CLI");
  std::string cmd = "cd '" + (c.workdir.empty() ? sourceDir() : work).string() + "' && env " + c.env + " timeout 60 " +
                    std::string(cli ? cli : "matbricks") + " " + commandArgs(c, out.string(), json) + " >'" +
                    (capture / "stdout").string() + "' 2>'" + (capture / "stderr").string() + "'";
  int status = std::system(cmd.c_str());
  CaseRun r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  r.out = readFile(capture / "stdout");
  r.err = readFile(capture / "stderr");
  for (std::string* s : {&r.out, &r.err}) {
    replaceAll(*s, work.string(), "WORK");
    replaceAll(*s, out.string(), "OUT");
    replaceAll(*s, sourceDir().string() + "/", "<repo>/");
  }
  for (const auto& e : fs::recursive_directory_iterator(out))
    r.leftovers.push_back(fs::relative(e.path(), out).string());
  if (!c.workdir.empty()) {
    const auto workAfter = treeBytes(work);
    for (const auto& [path, bytes] : workBefore) {
      auto it = workAfter.find(path);
      if (it == workAfter.end())
        r.workChanges.push_back("removed WORK/" + path);
      else if (it->second != bytes)
        r.workChanges.push_back("changed WORK/" + path);
    }
    for (const auto& [path, bytes] : workAfter)
      if (!workBefore.count(path)) r.workChanges.push_back("added WORK/" + path);
  }
  fs::remove_all(scratch);
  return r;
}

inline bool parseDiagnosticLine(const std::string& line, PrintedDiagnostic& d) {
  static const std::regex withPosition(R"(^(.+?):(\d+):(\d+): (error|warning)\[([A-Z0-9-]+)\]: (.+)$)");
  static const std::regex withoutPosition(R"(^(.+?): (error|warning)\[([A-Z0-9-]+)\]: (.+)$)");
  std::smatch m;
  if (std::regex_match(line, m, withPosition)) {
    d = {m[1], m[4], m[5], m[6], std::stoi(m[2]), std::stoi(m[3])};
    return true;
  }
  if (std::regex_match(line, m, withoutPosition)) {
    d = {m[1], m[2], m[3], m[4], 0, 0};
    return true;
  }
  return false;
}

// Length of the valid UTF-8 sequence at s[i], or 0 (overlongs and surrogates are not told apart:
// this only keeps binary junk that messages quote out of JSON comparisons and the Markdown).
inline size_t utf8SequenceAt(const std::string& s, size_t i) {
  auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  unsigned char b = byte(i);
  size_t len = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E ? 4 : 0;
  if (len == 0 || i + len > s.size()) return 0;
  for (size_t k = 1; k < len; ++k)
    if ((byte(i + k) >> 6) != 0x2) return 0;
  return len;
}

inline bool validUtf8(const std::string& s) {
  for (size_t i = 0; i < s.size();) {
    size_t n = utf8SequenceAt(s, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

// Invalid UTF-8 bytes written as \xNN, so a quoted binary input stays readable text.
inline std::string escapeInvalidUtf8(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size();) {
    size_t n = utf8SequenceAt(s, i);
    if (n == 0) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned char>(s[i]));
      out += buf;
      ++i;
    } else {
      out += s.substr(i, n);
      i += n;
    }
  }
  return out;
}

inline size_t lineCount(const std::filesystem::path& p) {
  std::string text = readFile(p);
  return static_cast<size_t>(std::count(text.begin(), text.end(), '\n')) +
         (text.empty() || text.back() == '\n' ? 0 : 1);
}

// Problems of a run against the case's expectations; `hard` ones (crash, hang, files left
// behind, more than one line per diagnostic) fail even a known-failure case.
struct Judgement {
  std::vector<std::string> problems, hard;
};

inline Judgement judgeTextRun(const BadInputCase& c, const CaseRun& r) {
  Judgement j;
  auto problem = [&](std::string s) { j.problems.push_back(std::move(s)); };
  if (r.exitCode >= 124) j.hard.push_back("crashed or hung: exit status " + std::to_string(r.exitCode));
  if (!r.leftovers.empty()) j.hard.push_back("left files behind, e.g. OUT/" + r.leftovers.front());
  for (const auto& change : r.workChanges) j.hard.push_back("touched the user's files: " + change);
  if (r.exitCode != c.exit) problem("exit " + std::to_string(r.exitCode) + ", expected " + std::to_string(c.exit));
  if (r.out.find("wrote ") != std::string::npos) problem("stdout says a package was written");
  if (!c.outputStarts.empty()) {
    if (r.err.rfind(c.outputStarts, 0) != 0) problem("stderr does not start with '" + c.outputStarts + "'");
    if (lines(r.err).size() != 1) problem("expected one line on stderr, got " + std::to_string(lines(r.err).size()));
    return j;
  }
  std::vector<std::string> codes;
  for (const auto& line : lines(r.err)) {
    PrintedDiagnostic d;
    if (!parseDiagnosticLine(line, d)) {
      problem("not a diagnostic line: " + line.substr(0, 200));
      continue;
    }
    if (d.severity != "error") continue;
    codes.push_back(d.code);
    if (!c.positions) continue;
    if (d.line < 1 || d.column < 1) {
      problem("no line:column in: " + line.substr(0, 200));
      continue;
    }
    std::filesystem::path file = sourceDir() / d.file;
    if (!std::filesystem::is_regular_file(file)) {
      problem("reported file does not exist: " + d.file);
    } else if (static_cast<size_t>(d.line) > std::max<size_t>(1, lineCount(file))) {
      problem(d.file + " has " + std::to_string(lineCount(file)) + " line(s), the error is at line " +
              std::to_string(d.line));
    }
  }
  if (codes != c.codes) {
    std::string got, want;
    for (const auto& s : codes) got += " " + s;
    for (const auto& s : c.codes) want += " " + s;
    problem("error codes [" + got + " ], expected [" + want + " ]");
  }
  return j;
}

inline std::vector<std::string> judgeJsonRun(const BadInputCase& c, const CaseRun& text, const CaseRun& json) {
  std::vector<std::string> problems;
  if (json.exitCode != text.exitCode) problems.push_back("json mode exits " + std::to_string(json.exitCode));
  nlohmann::json arr;
  try {
    arr = nlohmann::json::parse(json.err);
  } catch (const nlohmann::json::exception& e) {
    return {"--diagnostics-format json: stderr is not JSON (" + std::string(e.what()) +
            "): " + json.err.substr(0, 200)};
  }
  if (!arr.is_array()) return {"--diagnostics-format json: not an array"};
  std::vector<PrintedDiagnostic> printed;
  for (const auto& line : lines(text.err)) {
    PrintedDiagnostic d;
    if (parseDiagnosticLine(line, d)) printed.push_back(d);
  }
  if (arr.size() != printed.size()) {
    problems.push_back("json has " + std::to_string(arr.size()) + " diagnostics, text has " +
                       std::to_string(printed.size()));
    return problems;
  }
  for (size_t i = 0; i < arr.size(); ++i) {
    const auto& o = arr[i];
    bool shaped = o.is_object() && o.size() == 7;
    for (const char* key : {"code", "severity", "file", "message", "suggestion"})
      shaped = shaped && o.contains(key) && o[key].is_string();
    for (const char* key : {"line", "column"}) shaped = shaped && o.contains(key) && o[key].is_number_integer();
    if (!shaped) {
      problems.push_back("json diagnostic " + std::to_string(i) +
                         " is not {code, severity, file, line, column, message, suggestion}: " + o.dump());
      continue;
    }
    const auto& p = printed[i];
    std::string suggestion = o["suggestion"];
    std::string message = o["message"].get<std::string>() + (suggestion.empty() ? "" : " (" + suggestion + ")");
    std::replace(message.begin(), message.end(), '\n', ' ');
    if (o["code"] != p.code || o["severity"] != p.severity || o["line"] != p.line || o["column"] != p.column ||
        o["file"] != p.file || (validUtf8(p.message) && message != p.message))
      problems.push_back("json diagnostic " + std::to_string(i) + " differs from the text line: " + o.dump());
  }
  bool suggested = std::any_of(arr.begin(), arr.end(), [&](const nlohmann::json& o) {
    return o.value("suggestion", "").find(c.suggests) != std::string::npos;
  });
  if (!c.suggests.empty() && !suggested) problems.push_back("no diagnostic suggests '" + c.suggests + "'");
  return problems;
}

}  // namespace mb::test
