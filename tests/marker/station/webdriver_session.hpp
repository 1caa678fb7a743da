#pragma once
// A real browser for the operator page's test: Debian's chromedriver (W3C WebDriver over HTTP on
// a loopback port it picks itself) driving headless Debian chromium. The test speaks WebDriver's
// JSON with httplib and nlohmann, so no Selenium or other download is needed.
//
// chromedriver runs in its own process group: the destructor ends the session (which closes the
// browser) and then kills the group, so no chromium process outlives the test, failed or not.
//
// Include it last: <httplib.h> brings <resolv.h>, whose `_res` macro breaks Eigen's headers.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <httplib.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

extern char** environ;

namespace mark::test {

inline bool browser_installed() {
  return std::filesystem::exists("/usr/bin/chromium") && std::filesystem::exists("/usr/bin/chromedriver");
}

// Standard base64 (RFC 4648) as WebDriver returns screenshots; throws on a character outside it.
inline std::string base64_decode(const std::string& text) {
  std::string out;
  unsigned bits = 0;
  int count = 0;
  for (const char c : text) {
    int v;
    if (c >= 'A' && c <= 'Z') v = c - 'A';
    else if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
    else if (c >= '0' && c <= '9') v = c - '0' + 52;
    else if (c == '+') v = 62;
    else if (c == '/') v = 63;
    else if (c == '=' || c == '\n' || c == '\r') continue;
    else throw std::runtime_error("base64: unexpected character");
    bits = (bits << 6) | static_cast<unsigned>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<char>((bits >> count) & 0xFF));
    }
  }
  return out;
}

class WebDriverSession {
 public:
  using json = nlohmann::json;

  // Starts chromedriver and a headless chromium of `width` × `height` CSS pixels; `log` gets
  // chromedriver's output (read it when a step fails).
  WebDriverSession(const std::filesystem::path& log, int width, int height) : log_(log) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attr, 0);
    char arg0[] = "chromedriver", arg1[] = "--port=0";
    char* argv[] = {arg0, arg1, nullptr};
    const int rc = ::posix_spawn(&pid_, "/usr/bin/chromedriver", &actions, &attr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    if (rc != 0) throw std::runtime_error("cannot start /usr/bin/chromedriver");
    // "ChromeDriver was started successfully on port 44997."
    const std::regex started("started successfully on port ([0-9]+)");
    for (int i = 0; i < 200 && port_ == 0; ++i) {
      std::smatch m;
      const std::string text = log_text();
      if (std::regex_search(text, m, started)) port_ = std::stoi(m[1]);
      else std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    if (port_ == 0) throw std::runtime_error("chromedriver did not start: " + log_text());
    client_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
    client_->set_read_timeout(std::chrono::seconds(60));
    const json caps = {{"capabilities",
                        {{"alwaysMatch",
                          {{"browserName", "chrome"},
                           {"goog:chromeOptions",
                            {{"binary", "/usr/bin/chromium"},
                             {"args",
                              {"--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                               "--window-size=" + std::to_string(width) + "," + std::to_string(height)}}}}}}}}};
    session_ = call("POST", "/session", caps).at("sessionId").get<std::string>();
  }

  ~WebDriverSession() {
    if (!session_.empty()) {
      try {
        client_->Delete("/session/" + session_);
      } catch (...) {
      }
    }
    if (pid_ > 0) {
      ::kill(-pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  WebDriverSession(const WebDriverSession&) = delete;
  WebDriverSession& operator=(const WebDriverSession&) = delete;

  void navigate(const std::string& url) { command("POST", "/url", {{"url", url}}); }
  // Runs `script` (a function body: `return ...;`) in the page and gives its value.
  json run(const std::string& script) { return command("POST", "/execute/sync", {{"script", script}, {"args", json::array()}}); }
  // Clicks the element the CSS selector finds, as a user would (WebDriver moves the pointer there).
  void click(const std::string& css) { command("POST", "/element/" + element(css) + "/click", json::object()); }
  // Types `text` into the element the CSS selector finds, as key strokes.
  void type(const std::string& css, const std::string& text) {
    command("POST", "/element/" + element(css) + "/value", {{"text", text}});
  }
  // The viewport as PNG bytes.
  std::string screenshot() { return base64_decode(command("GET", "/screenshot", nullptr).get<std::string>()); }
  // Polls `script` (a boolean expression) every 50 ms until it is true or `timeout` has passed.
  bool wait_for(const std::string& expression, std::chrono::seconds timeout) {
    const auto until = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < until) {
      if (run("return !!(" + expression + ");").get<bool>()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
  }
  std::string log_text() const {
    std::ifstream in(log_);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

 private:
  // The WebDriver id of the element the CSS selector finds (the value of its one key).
  std::string element(const std::string& css) {
    return command("POST", "/element", {{"using", "css selector"}, {"value", css}}).begin().value().get<std::string>();
  }
  json command(const std::string& method, const std::string& path, const json& body) {
    return call(method, "/session/" + session_ + path, body);
  }
  // One WebDriver request; its "value", or an exception with WebDriver's error and message.
  json call(const std::string& method, const std::string& path, const json& body) {
    httplib::Result r = method == "GET" ? client_->Get(path)
                                        : client_->Post(path, body.is_null() ? "{}" : body.dump(), "application/json");
    if (!r) throw std::runtime_error(method + " " + path + ": no answer from chromedriver");
    const json reply = json::parse(r->body, nullptr, false);
    if (reply.is_discarded() || !reply.contains("value"))
      throw std::runtime_error(method + " " + path + ": " + r->body.substr(0, 300));
    if (r->status != 200)
      throw std::runtime_error(method + " " + path + ": " + reply["value"].value("error", "") + ": " +
                               reply["value"].value("message", "").substr(0, 300));
    return reply["value"];
  }

  std::filesystem::path log_;
  pid_t pid_ = -1;
  int port_ = 0;
  std::unique_ptr<httplib::Client> client_;
  std::string session_;
};

}  // namespace mark::test
