// The one file reader for every input (core/input_file.hpp): regular files only, refused at
// once otherwise (a FIFO with no writer must not hang), the kind's size limit checked before
// reading and never read past.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/input_file.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

constexpr InputKind kTiny{"test file", 10};

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("mb-input-file-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
  fs::path write(const std::string& name, const std::string& bytes) const {
    std::ofstream(dir / name, std::ios::binary) << bytes;
    return dir / name;
  }
};

std::string errorCode(const fs::path& p, const InputKind& kind = kTiny) {
  InputFileError error;
  auto text = readInputFile(p, kind, error);
  return text ? std::string("ok:") + *text : error.code;
}

}  // namespace

TEST_CASE("input files: a regular file within its limit is read whole, byte for byte", "[input-file]") {
  Scratch s;
  CHECK(errorCode(s.write("a", std::string("ab\0c", 4))) == std::string("ok:ab\0c", 7));
  CHECK(errorCode(s.write("exact", "0123456789")) == "ok:0123456789");  // exactly at the limit
  CHECK(errorCode(s.write("empty", "")) == "ok:");
}

TEST_CASE("input files: too large, missing, directories, FIFOs and devices are coded errors", "[input-file]") {
  Scratch s;
  CHECK(errorCode(s.write("big", "01234567890")) == "E-FILE-TOO-LARGE");
  CHECK(errorCode(s.dir / "missing") == "E-FILE-NOT-FOUND");
  CHECK(errorCode(s.dir) == "E-FILE-NOT-REGULAR");
  const fs::path fifo = s.dir / "fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK(errorCode(fifo) == "E-FILE-NOT-REGULAR");  // returns at once: no writer needed
  fs::create_symlink("/dev/zero", s.dir / "zero");
  CHECK(errorCode(s.dir / "zero", input_kind::kCacheEntry) == "E-FILE-NOT-REGULAR");
  CHECK(errorCode("/dev/null") == "E-FILE-NOT-REGULAR");
  InputFileError error;
  readInputFile(fifo, kTiny, error);
  CHECK(error.message.find("FIFO") != std::string::npos);
  CHECK(error.message.find(fifo.string()) != std::string::npos);
}

TEST_CASE("input files: a file that grows past its limit after the open is refused, not followed", "[input-file]") {
  Scratch s;
  const fs::path p = s.write("grows", "0123");
  InputFileError error;
  auto file = InputFile::open(p, kTiny, error);
  REQUIRE(file);
  std::ofstream(p, std::ios::binary | std::ios::app) << "456789abcdef";
  CHECK_FALSE(file->readAll(error));
  CHECK(error.code == "E-FILE-TOO-LARGE");
}

TEST_CASE("input files: readInputFileOrThrow reports at the file, or where it was named", "[input-file]") {
  Scratch s;
  try {
    readInputFileOrThrow(s.dir / "missing", kTiny);
    FAIL("no error");
  } catch (const DiagnosticError& e) {
    CHECK(e.diagnostics().at(0).code == "E-FILE-NOT-FOUND");
    CHECK(e.diagnostics().at(0).where.file == (s.dir / "missing").string());
  }
  try {
    readInputFileOrThrow(s.dir, kTiny, SourceLocation("scene.json", 3, 7));
    FAIL("no error");
  } catch (const DiagnosticError& e) {
    CHECK(e.diagnostics().at(0).where.line == 3);
  }
}
