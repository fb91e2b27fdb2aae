// Headless Chromium driven over its DevTools protocol on a pipe (--remote-debugging-pipe:
// the browser reads commands on fd 3 and writes replies and events on fd 4, each one JSON
// message ending in a NUL byte; https://chromedevtools.github.io/devtools-protocol/). No
// network port, no download: the Debian `chromium` package and this file. Used to run the
// webgl2 target in WebGL 2.0 (webgl_draw.hpp) and by tests/test_report_browser.cpp to open a
// report the way a person would.
#pragma once
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace mb::webgl {

// The chromium program on $PATH, or "" when there is none.
inline std::string findChromium() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  size_t start = 0;
  while (start <= dirs.size()) {
    size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    std::filesystem::path p = std::filesystem::path(dirs.substr(start, end - start)) / "chromium";
    if (::access(p.c_str(), X_OK) == 0) return p.string();
    start = end + 1;
  }
  return "";
}

class ChromiumPipe {
 public:
  using Clock = std::chrono::steady_clock;

  // Starts `chromium` headless with a fresh profile in `profileDir` (its log goes to
  // profileDir/chromium.log). As root Chromium refuses to start without --no-sandbox.
  // `extraArgs` go before the start page (e.g. the WebGL backend's flags).
  ChromiumPipe(const std::string& chromium, const std::filesystem::path& profileDir, int width, int height,
               const std::vector<std::string>& extraArgs = {})
      : log_(profileDir / "chromium.log") {
    ::signal(SIGPIPE, SIG_IGN);  // a browser that died must fail a write, not kill the tests
    std::filesystem::create_directories(profileDir);
    int toBrowser[2], fromBrowser[2];
    if (::pipe2(toBrowser, O_CLOEXEC) != 0 || ::pipe2(fromBrowser, O_CLOEXEC) != 0)
      throw std::runtime_error("pipe2 failed");
    std::vector<std::string> args{chromium,
                                  "--headless",
                                  "--no-sandbox",
                                  "--disable-gpu",
                                  "--remote-debugging-pipe",
                                  "--user-data-dir=" + profileDir.string(),
                                  "--window-size=" + std::to_string(width) + "," + std::to_string(height),
                                  "--no-first-run",
                                  "--no-default-browser-check",
                                  "--disable-extensions",
                                  "--disable-background-networking",
                                  "--hide-scrollbars"};
    args.insert(args.end(), extraArgs.begin(), extraArgs.end());
    args.push_back("about:blank");
    pid_ = ::fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      // Above 4 first, so that placing them on 3 and 4 cannot overwrite one with the other.
      int in = ::fcntl(toBrowser[0], F_DUPFD, 10), out = ::fcntl(fromBrowser[1], F_DUPFD, 10);
      int logFd = ::open(log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (in < 0 || out < 0 || logFd < 0 || ::dup2(in, 3) < 0 || ::dup2(out, 4) < 0 || ::dup2(logFd, 1) < 0 ||
          ::dup2(logFd, 2) < 0)
        ::_exit(127);
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execv(chromium.c_str(), argv.data());
      ::_exit(127);
    }
    ::close(toBrowser[0]);
    ::close(fromBrowser[1]);
    write_ = toBrowser[1];
    read_ = fromBrowser[0];
  }

  ~ChromiumPipe() {
    try {
      if (running()) call("Browser.close", {}, "", 15);
    } catch (const std::exception&) {
    }
    ::close(write_);
    ::close(read_);
    // Give it 15 s to exit after Browser.close (or the closed pipe), then kill it.
    auto until = Clock::now() + std::chrono::seconds(15);
    int status = 0;
    while (::waitpid(pid_, &status, WNOHANG) == 0) {
      if (Clock::now() > until) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, &status, 0);
        break;
      }
      ::usleep(50000);
    }
  }
  ChromiumPipe(const ChromiumPipe&) = delete;
  ChromiumPipe& operator=(const ChromiumPipe&) = delete;

  // Sends a command and returns its "result"; events that arrive meanwhile are kept (events()).
  // Throws std::runtime_error on a protocol error, when the browser exits, or after
  // `timeoutSeconds` (the browser's startup on a loaded two-core machine takes seconds).
  nlohmann::json call(const std::string& method, const nlohmann::json& params, const std::string& sessionId,
                      double timeoutSeconds) {
    const int id = ++lastId_;
    nlohmann::json msg{
        {"id", id}, {"method", method}, {"params", params.is_null() ? nlohmann::json::object() : params}};
    if (!sessionId.empty()) msg["sessionId"] = sessionId;
    std::string text = msg.dump();
    text.push_back('\0');
    for (size_t done = 0; done < text.size();) {
      ssize_t n = ::write(write_, text.data() + done, text.size() - done);
      if (n <= 0) throw std::runtime_error("DevTools pipe: write failed (browser gone?)" + logTail());
      done += size_t(n);
    }
    nlohmann::json reply =
        waitFor([&](const nlohmann::json& m) { return m.value("id", -1) == id; }, timeoutSeconds, method);
    if (reply.contains("error")) throw std::runtime_error(method + ": " + reply["error"].dump());
    return reply.value("result", nlohmann::json::object());
  }

  // The first kept event or newly read message that satisfies `match` (returned, not kept).
  nlohmann::json waitFor(const std::function<bool(const nlohmann::json&)>& match, double timeoutSeconds,
                         const std::string& what) {
    for (size_t k = 0; k < events_.size(); ++k)
      if (match(events_[k])) {
        nlohmann::json m = events_[k];
        events_.erase(events_.begin() + long(k));
        return m;
      }
    const auto until = Clock::now() + std::chrono::duration<double>(timeoutSeconds);
    for (;;) {
      size_t nul;
      while ((nul = buffer_.find('\0')) != std::string::npos) {
        nlohmann::json m = nlohmann::json::parse(buffer_.substr(0, nul));
        buffer_.erase(0, nul + 1);
        if (match(m)) return m;
        if (m.contains("method")) events_.push_back(std::move(m));
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now()).count();
      if (left <= 0) throw std::runtime_error("DevTools pipe: no " + what + " within the timeout" + logTail());
      pollfd p{read_, POLLIN, 0};
      if (::poll(&p, 1, int(std::min<long long>(left, 1000))) < 0) throw std::runtime_error("poll failed");
      if (p.revents & (POLLIN | POLLHUP)) {
        char chunk[65536];
        ssize_t n = ::read(read_, chunk, sizeof chunk);
        if (n <= 0) throw std::runtime_error("DevTools pipe: browser closed it" + logTail());
        buffer_.append(chunk, size_t(n));
      }
    }
  }

  // Events received and not consumed by waitFor, in order.
  const std::vector<nlohmann::json>& events() const { return events_; }
  void clearEvents() { events_.clear(); }

 private:
  bool running() const { return ::waitpid(pid_, nullptr, WNOHANG) == 0; }
  std::string logTail() const {
    std::FILE* f = std::fopen(log_.c_str(), "rb");
    if (!f) return "";
    std::string s;
    char buf[4096];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
    std::fclose(f);
    return "; chromium log: " + (s.size() > 2000 ? s.substr(s.size() - 2000) : s);
  }

  std::filesystem::path log_;
  pid_t pid_ = -1;
  int write_ = -1, read_ = -1;
  int lastId_ = 0;
  std::string buffer_;
  std::vector<nlohmann::json> events_;
};

}  // namespace mb::webgl
