// Opens a page in headless Chromium (webgl/chromium_pipe.hpp) and reports what a person
// would notice: images that did not load (naturalWidth == 0), errors on the console (console
// error/assert calls, uncaught exceptions, and the browser's own log errors such as a file
// that failed to load), and a blank screenshot (decoded with stb_image: a single colour).
#pragma once
#include <set>
#include <string>
#include <vector>

#include "write/png_image.hpp"
#include "webgl/base64.hpp"
#include "webgl/chromium_pipe.hpp"

namespace mb::test {

using webgl::base64Decode;
using webgl::ChromiumPipe;
using webgl::findChromium;

struct PageCheck {
  size_t images = 0;
  std::vector<std::string> brokenImages;   // src of each <img> with naturalWidth == 0
  std::vector<std::string> consoleErrors;  // one line each
  std::string screenshotPng;
  size_t screenshotColours = 0;  // distinct RGBA values in the screenshot
  bool blank() const { return screenshotColours <= 1; }
  bool ok() const { return brokenImages.empty() && consoleErrors.empty() && !blank(); }
  std::string describe() const {
    std::string s = std::to_string(images) + " images, " + std::to_string(brokenImages.size()) + " broken";
    for (const auto& b : brokenImages) s += " [" + b + "]";
    s += "; " + std::to_string(consoleErrors.size()) + " console errors";
    for (const auto& e : consoleErrors) s += " [" + e + "]";
    return s + "; screenshot " + std::to_string(screenshotColours) + " colours";
  }
};

// The console and log errors among the browser's events for `sessionId`.
inline std::vector<std::string> consoleErrors(const std::vector<nlohmann::json>& events, const std::string& sessionId) {
  std::vector<std::string> out;
  for (const auto& e : events) {
    if (e.value("sessionId", "") != sessionId) continue;
    const std::string method = e.value("method", "");
    const nlohmann::json& p = e["params"];
    if (method == "Runtime.consoleAPICalled" && (p.value("type", "") == "error" || p.value("type", "") == "assert")) {
      std::string text = "console." + p.value("type", "") + ":";
      for (const auto& arg : p["args"])
        text += " " + (arg.contains("value")
                           ? (arg["value"].is_string() ? arg["value"].get<std::string>() : arg["value"].dump())
                           : arg.value("description", ""));
      out.push_back(text);
    } else if (method == "Runtime.exceptionThrown") {
      const auto& d = p["exceptionDetails"];
      out.push_back("uncaught: " + d.value("text", "") + " " +
                    (d.contains("exception") ? d["exception"].value("description", "") : ""));
    } else if (method == "Log.entryAdded" && p["entry"].value("level", "") == "error") {
      out.push_back("log: " + p["entry"].value("text", "") + " " + p["entry"].value("url", ""));
    }
  }
  return out;
}

// Loads `url` in a new tab, waits for its load event (every image loaded or failed), then
// inspects it. Throws std::runtime_error when the browser does not answer in time.
inline PageCheck checkPage(ChromiumPipe& browser, const std::string& url, double timeoutSeconds) {
  const std::string target = browser.call("Target.createTarget", {{"url", "about:blank"}}, "", timeoutSeconds)
                                 .at("targetId")
                                 .get<std::string>();
  const std::string session =
      browser.call("Target.attachToTarget", {{"targetId", target}, {"flatten", true}}, "", timeoutSeconds)
          .at("sessionId")
          .get<std::string>();
  for (const char* domain : {"Page.enable", "Runtime.enable", "Log.enable"})
    browser.call(domain, {}, session, timeoutSeconds);
  nlohmann::json nav = browser.call("Page.navigate", {{"url", url}}, session, timeoutSeconds);
  if (nav.contains("errorText")) throw std::runtime_error("navigate " + url + ": " + nav["errorText"].dump());
  browser.waitFor(
      [&](const nlohmann::json& m) {
        return m.value("method", "") == "Page.loadEventFired" && m.value("sessionId", "") == session;
      },
      timeoutSeconds, "load event of " + url);

  PageCheck c;
  nlohmann::json images = browser.call(
      "Runtime.evaluate",
      {{"expression",
        "Array.from(document.images).map(i => ({src: i.getAttribute('src'), ok: i.complete && i.naturalWidth > 0}))"},
       {"returnByValue", true}},
      session, timeoutSeconds)["result"]["value"];
  for (const auto& i : images) {
    ++c.images;
    if (!i.value("ok", false)) c.brokenImages.push_back(i.value("src", ""));
  }
  nlohmann::json shot = browser.call("Page.captureScreenshot", {{"format", "png"}}, session, timeoutSeconds);
  c.screenshotPng = base64Decode(shot.value("data", ""));
  Image8 im = decodePng(c.screenshotPng);
  std::set<uint32_t> colours;
  for (size_t p = 0; p + im.channels <= im.pixels.size() && colours.size() < 1000; p += im.channels) {
    uint32_t rgba = 0;
    for (uint32_t k = 0; k < im.channels; ++k) rgba = (rgba << 8) | im.pixels[p + k];
    colours.insert(rgba);
  }
  c.screenshotColours = colours.size();
  c.consoleErrors = consoleErrors(browser.events(), session);
  browser.call("Target.closeTarget", {{"targetId", target}}, "", timeoutSeconds);
  return c;
}

}  // namespace mb::test
