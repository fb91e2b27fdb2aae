// A real HTTP cache server for the remote-cache tests: Debian's nginx with WebDAV PUT
// (installed by scripts/install-deps.sh), started on 127.0.0.1 at a free port in a scratch
// directory, in the foreground as one process, and stopped when the object goes. Its access
// log gives exact request counts. Two locations share one blob root:
//   /       GET, PUT (create_full_put_path), as bazel-remote or ccache expect
//   /ro/    GET only (PUT answers 405), a read-only cache
#pragma once
#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

extern char** environ;

namespace mb::test {

// The tests talk to 127.0.0.1 directly, whatever proxy the environment names (libcurl
// honours http_proxy unless no_proxy excludes the host); children inherit it.
inline void bypassProxyForLocalhost() {
  static const bool done = [] {
    std::string hosts = "127.0.0.1,localhost";
    for (const char* name : {"no_proxy", "NO_PROXY"})
      if (const char* v = std::getenv(name); v && *v) hosts += std::string(",") + v;
    ::setenv("no_proxy", hosts.c_str(), 1);
    ::setenv("NO_PROXY", hosts.c_str(), 1);
    return true;
  }();
  (void)done;
}

// A TCP socket bound to 127.0.0.1 at a port the kernel picks, listening if asked; `port` is set.
inline int loopbackSocket(bool listening, int& port) {
  int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t len = sizeof a;
  if (fd < 0 || ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 || (listening && ::listen(fd, 64) != 0) ||
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) != 0)
    throw std::runtime_error("cannot bind a socket on 127.0.0.1");
  port = ntohs(a.sin_port);
  return fd;
}

// A port on 127.0.0.1 nothing listens on right now (the kernel's pick, then released).
inline int unusedLocalPort() {
  int port = 0;
  ::close(loopbackSocket(false, port));
  return port;
}

inline bool acceptsConnections(int port) {
  int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const bool ok = ::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
  ::close(fd);
  return ok;
}

// A listening socket that never accepts and never answers: connections complete in the
// kernel's backlog, then every request waits until the client's timeout.
class SilentServer {
 public:
  SilentServer() {
    bypassProxyForLocalhost();
    fd_ = loopbackSocket(true, port_);
  }
  ~SilentServer() { ::close(fd_); }
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_) + "/cache"; }

 private:
  int fd_ = -1;
  int port_ = 0;
};

// A cache server that answers every request correctly, but only after `delay` (changeable
// between builds): GET of a stored path is 200 with its body, else 404; PUT stores the body
// (201). One connection at a time, each closed after its answer. It counts what it answered.
class SlowServer {
 public:
  explicit SlowServer(std::chrono::milliseconds delay) : delayMs_(delay.count()) {
    bypassProxyForLocalhost();
    fd_ = loopbackSocket(true, port_);
    thread_ = std::thread([this] { serve(); });
  }
  ~SlowServer() {
    stop_ = true;
    ::shutdown(fd_, SHUT_RDWR);  // wakes the accept()
    thread_.join();
    ::close(fd_);
  }
  SlowServer(const SlowServer&) = delete;
  SlowServer& operator=(const SlowServer&) = delete;

  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_) + "/cache"; }
  void setDelay(std::chrono::milliseconds delay) { delayMs_ = delay.count(); }
  // Requests answered so far by "<METHOD> <status>", as DavServer::requests.
  std::map<std::string, int> requests() const {
    std::lock_guard lock(mutex_);
    return counts_;
  }
  int total() const {
    int n = 0;
    for (const auto& [what, count] : requests()) n += count;
    return n;
  }

 private:
  void serve() {
    while (!stop_) {
      const int c = ::accept(fd_, nullptr, nullptr);
      if (c < 0) continue;
      answer(c);
      ::close(c);
    }
  }
  static bool readSome(int c, std::string& in) {
    char buf[65536];
    const ssize_t n = ::recv(c, buf, sizeof buf, 0);
    if (n <= 0) return false;
    in.append(buf, static_cast<size_t>(n));
    return true;
  }
  void answer(int c) {
    std::string in;
    size_t end;
    while ((end = in.find("\r\n\r\n")) == std::string::npos)
      if (!readSome(c, in)) return;
    std::istringstream head(in.substr(0, end));
    std::string method, path, line;
    head >> method >> path;
    size_t length = 0;
    while (std::getline(head, line))
      if (line.rfind("Content-Length:", 0) == 0 || line.rfind("content-length:", 0) == 0)
        length = std::stoul(line.substr(15));
    std::string body = in.substr(end + 4);
    while (body.size() < length) {
      std::string more;
      if (!readSome(c, more)) return;
      body += more;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(delayMs_.load()));
    std::string status = "404 Not Found", reply;
    {
      std::lock_guard lock(mutex_);
      if (method == "PUT") {
        blobs_[path] = body;
        status = "201 Created";
      } else if (auto it = blobs_.find(path); it != blobs_.end()) {
        status = "200 OK";
        reply = it->second;
      }
      ++counts_[method + " " + status.substr(0, 3)];
    }
    const std::string out = "HTTP/1.1 " + status + "\r\nContent-Length: " + std::to_string(reply.size()) +
                            "\r\nConnection: close\r\n\r\n" + reply;
    for (size_t sent = 0; sent < out.size();) {
      const ssize_t n = ::send(c, out.data() + sent, out.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) return;
      sent += static_cast<size_t>(n);
    }
  }

  std::atomic<long> delayMs_;
  std::atomic<bool> stop_{false};
  int fd_ = -1;
  int port_ = 0;
  std::thread thread_;
  mutable std::mutex mutex_;
  std::map<std::string, std::string> blobs_;
  std::map<std::string, int> counts_;
};

class DavServer {
 public:
  explicit DavServer(const std::filesystem::path& dir) : dir_(dir) {
    bypassProxyForLocalhost();
    std::filesystem::create_directories(dir_ / "root");
    std::filesystem::create_directories(dir_ / "tmp");
    for (int attempt = 0; attempt < 5 && pid_ <= 0; ++attempt) start(unusedLocalPort());
    if (pid_ <= 0) throw std::runtime_error("nginx did not start; see " + (dir_ / "error.log").string());
  }
  ~DavServer() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  DavServer(const DavServer&) = delete;
  DavServer& operator=(const DavServer&) = delete;

  std::string url(const std::string& location = "") const {
    return "http://127.0.0.1:" + std::to_string(port_) + "/" + location;
  }
  const std::filesystem::path root() const { return dir_ / "root"; }

  // Requests so far by "<METHOD> <status>", e.g. {"GET 404", 3}, {"PUT 201", 3}.
  std::map<std::string, int> requests() const {
    std::map<std::string, int> counts;
    std::ifstream log(dir_ / "access.log");
    for (std::string line; std::getline(log, line);) {
      std::istringstream in(line);
      std::string method, path, status;
      in >> method >> path >> status;
      ++counts[method + " " + status];
    }
    return counts;
  }
  int total() const {
    int n = 0;
    for (const auto& [what, count] : requests()) n += count;
    return n;
  }
  // requests() once the log holds `made` lines, the requests the clients made so far (for up to
  // 5 s). nginx writes a request's log line after sending its answer, so a client that has its
  // answer can be ahead of the log (seen under load).
  std::map<std::string, int> requestsOnceLogged(int made) const {
    for (int i = 0; i < 500 && total() < made; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return requests();
  }

 private:
  void start(int port) {
    port_ = port;
    const std::string d = dir_.string();
    std::ofstream conf(dir_ / "nginx.conf");
    conf << "daemon off;\nmaster_process off;\nworker_processes 1;\n"
         << "pid " << d << "/nginx.pid;\nerror_log " << d << "/error.log;\n"
         << "events { worker_connections 256; }\n"
         << "http {\n"
         << "  log_format counts '$request_method $uri $status';\n"
         << "  access_log " << d << "/access.log counts;\n"
         << "  client_body_temp_path " << d << "/tmp/body;\n  proxy_temp_path " << d << "/tmp/proxy;\n"
         << "  fastcgi_temp_path " << d << "/tmp/fastcgi;\n  uwsgi_temp_path " << d << "/tmp/uwsgi;\n"
         << "  scgi_temp_path " << d << "/tmp/scgi;\n"
         << "  client_max_body_size 64m;\n"
         << "  server {\n    listen 127.0.0.1:" << port << ";\n    root " << d << "/root;\n"
         << "    location /ro/ { alias " << d << "/root/; }\n"
         << "    location / { dav_methods PUT; create_full_put_path on; dav_access user:rw group:r all:r; }\n"
         << "  }\n}\n";
    conf.close();
    const std::string confPath = (dir_ / "nginx.conf").string(), errPath = (dir_ / "error.log").string();
    std::vector<std::string> args{"nginx", "-p", d, "-c", confPath, "-e", errPath};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (::posix_spawnp(&pid, "nginx", nullptr, nullptr, argv.data(), environ) != 0) return;
    for (int i = 0; i < 200; ++i) {  // up to 10 s on a loaded machine
      if (acceptsConnections(port)) {
        pid_ = pid;
        return;
      }
      int status = 0;
      if (::waitpid(pid, &status, WNOHANG) == pid) return;  // exited: port taken meanwhile, retry
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ::kill(pid, SIGTERM);
    ::waitpid(pid, nullptr, 0);
  }

  std::filesystem::path dir_;
  int port_ = 0;
  pid_t pid_ = -1;
};

}  // namespace mb::test
