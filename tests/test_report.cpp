// matbricks report (docs/report.md): what it writes, where it may write, and its pictures'
// encoding. The report in a real browser: tests/test_report_browser.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <regex>
#include <string>

#include "lut/dfg_lut.hpp"
#include "report/lut_images.hpp"
#include "write/png_image.hpp"
#include "support/cli_support.hpp"
#include "write/output_paths.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

// Small but complete: one material, one light and environment, one slot, a 16x16 LUT, 16-pixel
// previews (their double reference is per pixel, and the test reads only that they decode).
const char* kQuickOptions =
    " --lights dir --environment none --slot fresnel --samples 256 --repeats 1 --target-ms 0.5"
    " --lut-size 16 --preview-size 16";

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("PNG encoding round-trips through stb, and the LUT image is the table, texel for texel", "[report]") {
  Image8 im{3, 2, 3, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 250, 251, 252, 253, 254, 255}};
  Image8 back = decodePng(encodePng(im));
  CHECK(back.width == 3);
  CHECK(back.height == 2);
  CHECK(back.channels == 3);
  CHECK(back.pixels == im.pixels);
  CHECK_THROWS(decodePng("not a png"));

  lut::LutTable t{4, 0, {}};
  for (uint32_t j = 0; j < 4; ++j)
    for (uint32_t i = 0; i < 4; ++i)
      for (uint32_t c = 0; c < lut::kChannels; ++c) t.values.push_back(float(i * 0.25 + j * 0.05 + c * 0.01));
  Image8 rgb = report::lutRgbImage(t), grey = report::lutChannelImage(t, 1);
  // x = n.v index i, y = roughness index j with row 0 (smoothest) at the top.
  for (uint32_t j = 0; j < 4; ++j)
    for (uint32_t i = 0; i < 4; ++i) {
      CHECK(rgb.pixels[(j * 4 + i) * 3 + 2] == toByte(t.at(i, j, 2)));
      CHECK(grey.pixels[j * 4 + i] == toByte(t.at(i, j, 1)));
    }
  CHECK(toByte(-1) == 0);
  CHECK(toByte(std::nan("")) == 0);
  CHECK(toByte(2) == 255);
  CHECK(toByte(0.5) == 128);
}

TEST_CASE("report writes index.html and every image it references, from this run's measurements", "[report][vulkan]") {
  const fs::path out = test::freshTempDir("report", "content") / "report";
  auto r =
      test::runCli("report " + test::materialPath("filament_plastic.json") + kQuickOptions + " -o " + out.string());
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("report: " + (out / "index.html").string()));
  CHECK(carriesOutputMarker(out));
  const std::string html = test::readFile(out / "index.html");
  // The one permutation asked for, with its measured row, and every section.
  CHECK(count(html, "<td class=\"l\">filament_plastic.standard.dir.none.fp32</td>") == 1);
  CHECK_THAT(html, Catch::Contains("id=\"slots\"") && Catch::Contains("id=\"energy\"") &&
                       Catch::Contains("id=\"lut\"") && Catch::Contains("All checks passed."));
  CHECK_THAT(html, !Catch::Contains("http://") && !Catch::Contains("https://"));  // nothing fetched
  // Every <img> names a file the report wrote; each PNG decodes, each SVG is an SVG.
  static const std::regex img(R"re(<img src="([^"]+)")re");
  size_t images = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), img); it != std::sregex_iterator(); ++it, ++images) {
    const fs::path file = out / (*it)[1].str();
    INFO(file);
    REQUIRE(fs::is_regular_file(file));
    const std::string bytes = test::readFile(file);
    if (file.extension() == ".png")
      CHECK(decodePng(bytes).width > 0);
    else
      CHECK_THAT(bytes, Catch::Contains("<svg"));
  }
  CHECK(images >= 6);  // the fresnel chart, at least one lobe, the LUT and its three channels
  CHECK(decodePng(test::readFile(out / "lut/dfg.png")).width == 16);
  CHECK(fs::is_regular_file(out / "slots/fresnel.svg"));

  // Written again over its own output: replaced as a whole.
  auto again = test::runCli("report " + test::materialPath("filament_plastic.json") +
                            " --lights dir --environment none --samples 256 --repeats 1 --target-ms 0.5 --lut-size 8"
                            " --preview-size 16 --no-slots --no-energy -o " +
                            out.string());
  INFO(again.output);
  CHECK(again.exitCode == 0);
  CHECK(!fs::exists(out / "slots"));
  CHECK(fs::exists(out / "lut/dfg.png"));
  fs::remove_all(out.parent_path());
}

TEST_CASE("report places each area light's methods on a run-time-against-error chart", "[report][vulkan]") {
  // A sphere light: the chart's rows are its two methods (docs/models/lights.md "Light methods");
  // without an area light among the reported lights, or with --no-light-methods, no section.
  const fs::path out = test::freshTempDir("report", "light-methods") / "report";
  const std::string common =
      " --environment none --no-slots --no-energy --no-lut --no-previews --samples 64"
      " --repeats 6 --target-ms 0.5 -o " +
      out.string();
  auto r = test::runCli("report " + test::materialPath("filament_plastic.json") + " --lights sphere" + common);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  const std::string html = test::readFile(out / "index.html");
  CHECK_THAT(html, Catch::Contains("id=\"light-methods\""));
  CHECK(count(html, "<td class=\"l\">sphere: ltc</td>") == 1);
  CHECK(count(html, "<td class=\"l\">sphere: representative_point</td>") == 1);
  CHECK(count(html, "<td class=\"l\">tube") == 0);  // not reported
  CHECK_THAT(test::readFile(out / "light_methods.svg"), Catch::Contains("<svg") && Catch::Contains("sphere: ltc"));
  for (const char* options : {" --lights dir", " --lights sphere --no-light-methods"}) {
    auto without = test::runCli("report " + test::materialPath("filament_plastic.json") + options + common);
    INFO(without.output);
    REQUIRE(without.exitCode == 0);
    CHECK_THAT(test::readFile(out / "index.html"), !Catch::Contains("id=\"light-methods\""));
    CHECK(!fs::exists(out / "light_methods.svg"));
  }
  fs::remove_all(out.parent_path());
}

TEST_CASE("report refuses bad input and unsafe outputs before any work, writing nothing", "[report]") {
  const fs::path dir = test::freshTempDir("report", "refusals");
  const std::string material = test::materialPath("filament_plastic.json");
  SECTION("a directory matbricks did not write") {
    fs::create_directories(dir / "mine");
    std::FILE* f = std::fopen((dir / "mine/notes.txt").c_str(), "w");
    std::fputs("keep me", f);
    std::fclose(f);
    auto r = test::runCli("report " + material + " -o " + (dir / "mine").string());
    INFO(r.output);
    CHECK(r.exitCode == 3);
    CHECK_THAT(r.output, Catch::Contains("error[E-OUTPUT-NOT-PACKAGE]"));
    CHECK(test::readFile(dir / "mine/notes.txt") == "keep me");
    CHECK(std::distance(fs::directory_iterator(dir / "mine"), fs::directory_iterator()) == 1);
  }
  SECTION("an output inside the inputs") {
    auto r = test::runCli("report " + material + " -o " + (test::sourceDir() / "shaderlib/report").string());
    INFO(r.output);
    CHECK(r.exitCode == 3);
    CHECK_THAT(r.output, Catch::Contains("error[E-OUTPUT-OVERLAPS-INPUT]"));
    CHECK(!fs::exists(test::sourceDir() / "shaderlib/report"));
  }
  SECTION("an unknown slot, a missing material, a missing -o, both a scene and materials") {
    auto slot = test::runCli("report " + material + " --slot fresnell -o " + (dir / "a").string());
    INFO(slot.output);
    CHECK(slot.exitCode == 3);
    CHECK_THAT(slot.output, Catch::Contains("error[E-UNKNOWN-SLOT]") && Catch::Contains("fresnel"));
    auto missing = test::runCli("report " + (dir / "nope.json").string() + " -o " + (dir / "b").string());
    INFO(missing.output);
    CHECK(missing.exitCode == 3);
    CHECK(test::runCli("report " + material).exitCode == 2);
    CHECK(test::runCli("report " + material + " --scene " +
                       (test::sourceDir() / "examples/scenes/showroom.json").string() + " -o " + (dir / "c").string())
              .exitCode == 2);
    CHECK(!fs::exists(dir / "a"));
    CHECK(!fs::exists(dir / "b"));
    CHECK(!fs::exists(dir / "c"));
  }
  fs::remove_all(dir);
}
