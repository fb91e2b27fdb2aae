// The report in a real browser (issue 13, docs/report.md): headless Chromium (Debian
// `chromium`, installed by scripts/install-deps.sh) opens a generated report from file://,
// and the test fails if an image did not load, the console shows an error, or the screenshot
// is blank; and the same check, given a report with a broken image, a console error, an
// exception or a blank page, catches each. Hidden tag: CTest runs these once under the label
// `chromium` (tests/CMakeLists.txt), as `mb_tests "[chromium]"`.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/browser_check.hpp"
#include "support/cli_support.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

// Chromium's first start on a loaded two-core machine has taken over 20 s; each step gets
// this long before the test gives up.
constexpr double kBrowserTimeoutSeconds = 120;

std::string chromiumOrFail() {
  std::string chromium = test::findChromium();
  INFO("chromium is not on PATH: scripts/install-deps.sh installs Debian's `chromium`");
  REQUIRE(!chromium.empty());
  return chromium;
}

// One report for the whole test process: two materials (two shading models), one slot chart,
// the albedo charts of their lobes, a small LUT and 16-pixel previews (the page loads them as
// it loads any image; their double reference costs per pixel).
const fs::path& generatedReport() {
  static const fs::path out = [] {
    fs::path dir = test::freshTempDir("report", "browser") / "report";
    auto r = test::runCli("report " + test::materialPath("filament_plastic.json") + " " +
                          test::materialPath("velvet_green.json") +
                          " --lights dir --environment none --slot fresnel --samples 256 --repeats 1 --target-ms 0.5"
                          " --lut-size 16 --preview-size 16 -o " +
                          dir.string());
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    return dir;
  }();
  return out;
}

void writeText(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

std::string fileUrl(const fs::path& p) { return "file://" + fs::absolute(p).string(); }

}  // namespace

TEST_CASE("a generated report renders in headless Chromium: every image loaded, no console error, not blank",
          "[.][chromium][report][vulkan]") {
  const std::string chromium = chromiumOrFail();
  const fs::path& report = generatedReport();
  test::ChromiumPipe browser(chromium, test::freshTempDir("report", "chromium-profile-ok"), 1280, 1600);
  test::PageCheck c = test::checkPage(browser, fileUrl(report / "index.html"), kBrowserTimeoutSeconds);
  INFO(c.describe());
  CHECK(c.ok());
  CHECK(c.images >= 7);  // the fresnel chart, lobes of both models, the LUT and its channels
  CHECK(c.brokenImages.empty());
  CHECK(c.consoleErrors.empty());
  CHECK(c.screenshotColours > 16);  // text, tables and charts: many colours, antialiased
}

TEST_CASE("the browser check catches a missing image, a console error, an exception and a blank page",
          "[.][chromium][report][vulkan]") {
  const std::string chromium = chromiumOrFail();
  const fs::path dir = test::freshTempDir("report", "browser-broken");
  // The generated report with one image gone, as if copied without it.
  fs::copy(generatedReport(), dir / "broken", fs::copy_options::recursive);
  fs::remove(dir / "broken/lut/dfg.png");
  writeText(dir / "console.html", "<!DOCTYPE html><p>text</p><script>console.error('report: broken');</script>");
  writeText(dir / "throws.html", "<!DOCTYPE html><p>text</p><script>undefinedFunction();</script>");
  writeText(dir / "blank.html", "<!DOCTYPE html><html><body style=\"background:#fff\"></body></html>");

  test::ChromiumPipe browser(chromium, dir / "profile", 1280, 1600);
  test::PageCheck broken = test::checkPage(browser, fileUrl(dir / "broken/index.html"), kBrowserTimeoutSeconds);
  INFO("broken report: " << broken.describe());
  CHECK(!broken.ok());
  REQUIRE(broken.brokenImages.size() == 1);
  CHECK(broken.brokenImages[0] == "lut/dfg.png");
  // Chromium logs the failed load itself: "Failed to load resource: net::ERR_FILE_NOT_FOUND".
  REQUIRE(!broken.consoleErrors.empty());
  CHECK_THAT(broken.consoleErrors[0], Catch::Contains("ERR_FILE_NOT_FOUND") && Catch::Contains("lut/dfg.png"));
  CHECK(!broken.blank());

  test::PageCheck console = test::checkPage(browser, fileUrl(dir / "console.html"), kBrowserTimeoutSeconds);
  INFO("console.error page: " << console.describe());
  CHECK(!console.ok());
  REQUIRE(!console.consoleErrors.empty());
  CHECK_THAT(console.consoleErrors[0], Catch::Contains("console.error: report: broken"));

  test::PageCheck throws = test::checkPage(browser, fileUrl(dir / "throws.html"), kBrowserTimeoutSeconds);
  INFO("throwing page: " << throws.describe());
  REQUIRE(!throws.consoleErrors.empty());
  CHECK_THAT(throws.consoleErrors[0], Catch::Contains("uncaught") && Catch::Contains("undefinedFunction"));

  test::PageCheck blank = test::checkPage(browser, fileUrl(dir / "blank.html"), kBrowserTimeoutSeconds);
  INFO("blank page: " << blank.describe());
  CHECK(blank.blank());
  CHECK(!blank.ok());
  CHECK(blank.consoleErrors.empty());
  CHECK(blank.brokenImages.empty());
  fs::remove_all(dir);
}
