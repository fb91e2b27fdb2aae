// JsonDocument's positions (core/json_document.hpp): a compact table of object members, array
// elements found from their array, line:column worked out on demand. Every lookup must give
// what a full per-value table gave.
#include <catch2/catch.hpp>

#include "core/json_document.hpp"

using namespace mb;

namespace {

std::string at(const SourceLocation& l) { return std::to_string(l.line) + ":" + std::to_string(l.column); }

const char* kText =
    "{\n"
    "  \"a\": {\"b\": [10, [20, 21], {\"c\": \"x\"}]},\n"
    "  \"s~/t\": 1,\n"
    "  \"esc\\u0041\": true,\n"
    "  \"dup\": {\"gone\": 1},\n"
    "  \"dup\": [5, 6]\n"
    "}\n";

}  // namespace

TEST_CASE("json positions: members, elements, nested elements and the root", "[json]") {
  const JsonDocument doc = JsonDocument::parse(kText, "t.json");
  CHECK(at(doc.valueAt("")) == "1:1");
  CHECK(at(doc.valueAt("/a")) == "2:8");
  CHECK(at(doc.keyAt("/a")) == "2:3");
  CHECK(at(doc.valueAt("/a/b")) == "2:14");
  CHECK(at(doc.valueAt("/a/b/0")) == "2:15");
  CHECK(at(doc.valueAt("/a/b/1")) == "2:19");
  CHECK(at(doc.valueAt("/a/b/1/1")) == "2:24");
  CHECK(at(doc.valueAt("/a/b/2/c")) == "2:35");
  CHECK(at(doc.keyAt("/a/b/2/c")) == "2:30");
  CHECK(at(doc.keyAt("/a/b/1")) == "2:19");  // an element has no key: its value
}

TEST_CASE("json positions: escaped pointer tokens and keys, a repeated key's later value", "[json]") {
  const JsonDocument doc = JsonDocument::parse(kText, "t.json");
  CHECK(at(doc.valueAt("/" + JsonDocument::escape("s~/t"))) == "3:11");
  CHECK(at(doc.keyAt("/escA")) == "4:3");
  CHECK(at(doc.valueAt("/dup")) == "6:10");
  CHECK(at(doc.valueAt("/dup/1")) == "6:14");
}

TEST_CASE("json positions: a path that leaves the tree falls back to its deepest value", "[json]") {
  const JsonDocument doc = JsonDocument::parse(kText, "t.json");
  CHECK(at(doc.valueAt("/a/missing")) == "2:8");
  CHECK(at(doc.keyAt("/a/missing")) == "2:8");
  CHECK(at(doc.valueAt("/a/b/7")) == "2:14");
  CHECK(at(doc.valueAt("/a/b/0/deeper")) == "2:15");
  CHECK(at(doc.valueAt("/nothing")) == "1:1");
}

TEST_CASE("json positions: copies and moves keep every position", "[json]") {
  JsonDocument original = JsonDocument::parse(kText, "t.json");
  const JsonDocument copy = original;
  CHECK(at(copy.valueAt("/a/b/2/c")) == "2:35");
  CHECK(at(copy.keyAt("/escA")) == "4:3");
  const JsonDocument moved = std::move(original);
  CHECK(at(moved.valueAt("/a/b/2/c")) == "2:35");
  CHECK(moved.valueAt("").file == "t.json");
}

TEST_CASE("json positions: lines far into a long file, across the 4 KiB blocks", "[json]") {
  std::string text = "[\n";
  for (int i = 0; i < 5000; ++i) text += "  " + std::to_string(i) + (i + 1 < 5000 ? ",\n" : "\n");
  text += "]\n";
  const JsonDocument doc = JsonDocument::parse(text, "long.json");
  CHECK(at(doc.valueAt("/0")) == "2:3");
  CHECK(at(doc.valueAt("/4097")) == "4099:3");
  CHECK(at(doc.valueAt("/4999")) == "5001:3");
}
