#include "support/headless_browser.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace slamkit::test {

namespace {

using nlohmann::json;

// Long enough for Chromium's first reply on a loaded 2-core machine.
constexpr std::chrono::seconds kReplyTimeout(30);
// How often open() evaluates the ready expression.
constexpr std::chrono::milliseconds kPollInterval(20);
// How long a closed Chromium gets to exit before its process group is killed.
constexpr std::chrono::seconds kExitGrace(5);

std::string file_url(const std::filesystem::path& file) {
  static const char* hex = "0123456789ABCDEF";
  std::string url = "file://";
  for (const unsigned char c : std::filesystem::absolute(file).lexically_normal().string()) {
    if (std::isalnum(c) || std::strchr("-._~/", c)) {
      url += static_cast<char>(c);
    } else {
      url += '%';
      url += hex[c >> 4];
      url += hex[c & 15];
    }
  }
  return url;
}

// A CDP RemoteObject as a console would print it.
std::string remote_object_text(const json& object) {
  if (object.contains("value")) {
    const json& value = object["value"];
    return value.is_string() ? value.get<std::string>() : value.dump();
  }
  return object.value("description", object.value("type", ""));
}

// "Uncaught Error: message" from Runtime.ExceptionDetails, without the stack.
std::string exception_text(const json& details) {
  std::string text = details.value("text", "");
  if (details.contains("exception")) {
    const std::string thrown = remote_object_text(details["exception"]);
    text += " " + thrown.substr(0, thrown.find('\n'));
  }
  return text;
}

// "kind: text (url:line)"; CDP's line numbers count from 0.
std::string describe_error(const std::string& kind, const std::string& text, const std::string& url,
                           int line) {
  std::string described = kind + ": " + text;
  if (!url.empty()) {
    described += " (" + url + (line >= 0 ? ":" + std::to_string(line + 1) : "") + ")";
  }
  return described;
}

// Writes all of `bytes`; false when the reader is gone. A write to a Chromium that died must
// throw rather than end the test process by SIGPIPE, so SIGPIPE is blocked during the write
// and a pending one consumed.
bool write_all(int fd, const std::string& bytes) {
  sigset_t pipe_signal, old_mask;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_signal, &old_mask);
  size_t written = 0;
  int error = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n >= 0) {
      written += static_cast<size_t>(n);
    } else if (errno != EINTR) {
      error = errno;
      break;
    }
  }
  if (error == EPIPE) {
    const timespec no_wait{0, 0};
    sigtimedwait(&pipe_signal, nullptr, &no_wait);
  }
  pthread_sigmask(SIG_SETMASK, &old_mask, nullptr);
  return error == 0;
}

std::string exit_status_text(int status) {
  if (WIFEXITED(status)) return "exited with code " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  return "stopped";
}

}  // namespace

std::vector<std::string> PageVisit::network_requests() const {
  std::vector<std::string> network;
  for (const std::string& url : requested_urls) {
    std::string scheme = url.substr(0, url.find(':'));
    std::transform(scheme.begin(), scheme.end(), scheme.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (scheme != "file" && scheme != "data" && scheme != "blob" && scheme != "about") {
      network.push_back(url);
    }
  }
  return network;
}

std::filesystem::path HeadlessBrowser::executable() {
  const char* chosen = std::getenv("SLAMKIT_CHROMIUM");
  return chosen && *chosen ? chosen : "/usr/bin/chromium";
}

bool HeadlessBrowser::available() { return ::access(executable().c_str(), X_OK) == 0; }

HeadlessBrowser::HeadlessBrowser(int width, int height) {
  if (!available()) {
    throw std::runtime_error("Chromium not found at " + executable().string() +
                             ": install it with scripts/setup.sh --browser");
  }
  std::string work_dir =
      (std::filesystem::temp_directory_path() / "slamkit-chromium-XXXXXX").string();
  if (!::mkdtemp(work_dir.data())) {
    throw std::runtime_error("cannot create a Chromium profile folder: " +
                             std::string(std::strerror(errno)));
  }
  work_dir_ = work_dir;
  try {
    start(width, height);
    // A page of our own, attached in flattened mode: its commands and events carry its
    // sessionId on the same pipe.
    const json target = command("Target.createTarget", {{"url", "about:blank"}}, true);
    session_id_ = command("Target.attachToTarget",
                          {{"targetId", target.at("targetId")}, {"flatten", true}}, true)
                      .at("sessionId")
                      .get<std::string>();
    // In the new headless mode the window size includes room for a toolbar that is not drawn;
    // the viewport (and so the screenshot) gets exactly the size asked for.
    command("Emulation.setDeviceMetricsOverride",
            {{"width", width}, {"height", height}, {"deviceScaleFactor", 1}, {"mobile", false}});
    // Before any navigation, so that nothing the page does is missed.
    for (const char* domain : {"Runtime", "Log", "Network", "Page"}) {
      command(std::string(domain) + ".enable");
    }
  } catch (...) {
    shut_down();
    throw;
  }
}

HeadlessBrowser::~HeadlessBrowser() { shut_down(); }

void HeadlessBrowser::start(int width, int height) {
  int to_browser[2], from_browser[2];
  if (::pipe2(to_browser, O_CLOEXEC) != 0 || ::pipe2(from_browser, O_CLOEXEC) != 0) {
    throw std::runtime_error("cannot create pipes for Chromium: " +
                             std::string(std::strerror(errno)));
  }
  to_browser_ = to_browser[1];
  from_browser_ = from_browser[0];
  // Chromium's ends become its fds 3 and 4; they are first moved above 4 so that neither
  // dup2 overwrites the other end.
  const int browser_in = ::fcntl(to_browser[0], F_DUPFD_CLOEXEC, 10);
  const int browser_out = ::fcntl(from_browser[1], F_DUPFD_CLOEXEC, 10);
  ::close(to_browser[0]);
  ::close(from_browser[1]);

  const std::string log = (work_dir_ / "chromium.log").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawn_file_actions_adddup2(&actions, browser_in, 3);
  posix_spawn_file_actions_adddup2(&actions, browser_out, 4);
  // Its own process group, so that the renderer and GPU processes are killed with it.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);

  const std::vector<std::string> arguments = {
      executable().string(),
      "--headless=new",
      "--remote-debugging-pipe",
      "--no-sandbox",  // the tests may run as root, where Chromium's sandbox refuses to start
      // WebGL without a GPU: ANGLE on SwiftShader. Without these two flags Chromium still falls
      // back to it, but logs that this automatic fallback is deprecated.
      "--use-angle=swiftshader",
      "--enable-unsafe-swiftshader",
      "--window-size=" + std::to_string(width) + "," + std::to_string(height),
      "--hide-scrollbars",
      "--user-data-dir=" + (work_dir_ / "profile").string(),
      "--no-first-run",
      "--no-default-browser-check",
      "--disable-background-networking",
      "--disable-component-update",
      "--disable-sync",
      "--disable-extensions",
      "about:blank",
  };
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  const int error = posix_spawn(&pid_, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(browser_in);
  ::close(browser_out);
  if (error != 0) {
    pid_ = -1;
    throw std::runtime_error("cannot start " + arguments[0] + ": " + std::strerror(error));
  }
}

void HeadlessBrowser::shut_down() {
  if (pid_ > 0) {
    // Asked to close, Chromium ends its own processes; whatever is left after the grace
    // period (all of it, when Chromium hangs) is killed.
    write_all(to_browser_, json{{"id", ++last_id_}, {"method", "Browser.close"}}.dump() + '\0');
    const auto give_up = Clock::now() + kExitGrace;
    while (::waitpid(pid_, nullptr, WNOHANG) == 0 && Clock::now() < give_up) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ::kill(-pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);  // ECHILD when reaped above
    pid_ = -1;
  }
  for (int* fd : {&to_browser_, &from_browser_}) {
    if (*fd >= 0) ::close(*fd);
    *fd = -1;
  }
  std::error_code ignored;
  std::filesystem::remove_all(work_dir_, ignored);
}

PageVisit HeadlessBrowser::open(const std::filesystem::path& html_file,
                                const std::string& ready_expression, double timeout_s) {
  const std::string url = file_url(html_file);
  visit_ = PageVisit{};
  const auto start = Clock::now();
  const json navigation = command("Page.navigate", {{"url", url}});
  if (!navigation.value("errorText", "").empty()) {
    throw std::runtime_error("cannot open " + url + ": " + navigation.value("errorText", ""));
  }
  // Until the new document has replaced the old one, the expression would be evaluated in
  // the old. A navigation within the same document has no loader.
  const std::string loader = navigation.value("loaderId", "");
  // On lines of its own, so that a trailing // comment cannot swallow the parenthesis.
  const json truthy = {{"expression", "!!(\n" + ready_expression + "\n)"}, {"returnByValue", true}};
  const json::json_pointer value("/result/result/value");
  const auto deadline =
      start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s));
  for (;;) {
    // An evaluation that throws (say, before the page defined its variables) is "not yet".
    if ((loader.empty() || main_frame_loader_ == loader) &&
        send_command("Runtime.evaluate", truthy).value(value, json()) == true) {
      visit_.condition_met = true;
      break;
    }
    const auto now = Clock::now();
    if (now >= deadline) break;
    read_until(0, std::min(now + kPollInterval, deadline));
  }
  visit_.seconds_to_condition = std::chrono::duration<double>(Clock::now() - start).count();
  return visit_;
}

json HeadlessBrowser::evaluate(const std::string& expression) {
  const json result =
      command("Runtime.evaluate",
              {{"expression", expression}, {"returnByValue", true}, {"awaitPromise", true}});
  if (result.contains("exceptionDetails")) {
    throw std::runtime_error("`" + expression +
                             "` threw: " + exception_text(result["exceptionDetails"]));
  }
  return result.at("result").value("value", json());
}

cv::Mat HeadlessBrowser::screenshot() {
  const json result = command("Page.captureScreenshot", {{"format", "png"}});
  const std::string png = base64_decode(result.at("data").get<std::string>());
  const cv::Mat encoded(1, static_cast<int>(png.size()), CV_8U, const_cast<char*>(png.data()));
  cv::Mat image = cv::imdecode(encoded, cv::IMREAD_COLOR);
  if (image.empty()) throw std::runtime_error("Chromium's screenshot is not a readable PNG");
  return image;
}

json HeadlessBrowser::send_command(const std::string& method, const json& params, bool to_browser) {
  json message = {{"id", ++last_id_},
                  {"method", method},
                  {"params", params.is_null() ? json::object() : params}};
  if (!to_browser) message["sessionId"] = session_id_;
  if (!write_all(to_browser_, message.dump() + '\0')) fail("cannot send " + method);
  std::optional<json> reply = read_until(last_id_, Clock::now() + kReplyTimeout);
  if (!reply) {
    fail("no reply to " + method + " within " + std::to_string(kReplyTimeout.count()) + " s");
  }
  return *reply;
}

json HeadlessBrowser::command(const std::string& method, const json& params, bool to_browser) {
  const json reply = send_command(method, params, to_browser);
  if (reply.contains("error")) {
    throw std::runtime_error("headless Chromium: " + method +
                             " failed: " + reply["error"].value("message", reply["error"].dump()));
  }
  return reply.value("result", json::object());
}

std::optional<json> HeadlessBrowser::read_until(int id, Clock::time_point deadline) {
  size_t searched = 0;  // bytes of unread_ known to hold no message end
  for (;;) {
    const size_t end = unread_.find('\0', searched);
    if (end != std::string::npos) {
      json message;
      try {
        message = json::parse(unread_.begin(), unread_.begin() + static_cast<long>(end));
      } catch (const json::exception& error) {
        fail(std::string("unreadable message: ") + error.what());
      }
      unread_.erase(0, end + 1);
      searched = 0;
      if (!message.contains("id")) {
        record_event(message);
      } else if (message["id"] == id) {
        return message;
      }  // else the late reply to a command given up on
      continue;
    }
    searched = unread_.size();
    const auto left = deadline - Clock::now();
    if (left <= Clock::duration::zero()) return std::nullopt;
    pollfd readable{from_browser_, POLLIN, 0};
    const auto wait_ms = std::chrono::ceil<std::chrono::milliseconds>(left).count();
    const int ready = ::poll(&readable, 1, static_cast<int>(wait_ms));
    if (ready < 0 && errno != EINTR) fail(std::string("poll: ") + std::strerror(errno));
    if (ready <= 0) continue;
    char buffer[1 << 16];
    const ssize_t n = ::read(from_browser_, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("Chromium closed the DevTools pipe");
    unread_.append(buffer, static_cast<size_t>(n));
  }
}

void HeadlessBrowser::record_event(const json& message) {
  if (message.value("sessionId", "") != session_id_) return;
  const std::string method = message.value("method", "");
  const json params = message.value("params", json::object());
  if (method == "Runtime.consoleAPICalled") {
    const std::string type = params.value("type", "");
    if (type != "error" && type != "assert") return;
    std::string text;
    for (const json& argument : params.value("args", json::array())) {
      text += (text.empty() ? "" : " ") + remote_object_text(argument);
    }
    const json frames = params.value(json::json_pointer("/stackTrace/callFrames"), json::array());
    const json top = frames.empty() ? json::object() : frames[0];
    visit_.console_errors.push_back(
        describe_error("console." + type, text, top.value("url", ""), top.value("lineNumber", -1)));
  } else if (method == "Runtime.exceptionThrown") {
    const json details = params.value("exceptionDetails", json::object());
    visit_.console_errors.push_back(describe_error("exception", exception_text(details),
                                                   details.value("url", ""),
                                                   details.value("lineNumber", -1)));
  } else if (method == "Log.entryAdded") {
    const json entry = params.value("entry", json::object());
    if (entry.value("level", "") != "error") return;
    visit_.console_errors.push_back(describe_error("log " + entry.value("source", ""),
                                                   entry.value("text", ""), entry.value("url", ""),
                                                   entry.value("lineNumber", -1)));
  } else if (method == "Network.requestWillBeSent") {
    visit_.requested_urls.push_back(params.value(json::json_pointer("/request/url"), ""));
  } else if (method == "Page.frameNavigated") {
    const json frame = params.value("frame", json::object());
    if (!frame.contains("parentId")) main_frame_loader_ = frame.value("loaderId", "");
  }
}

void HeadlessBrowser::fail(const std::string& what) {
  std::string message = "headless Chromium: " + what;
  // After its pipe closed, Chromium's exit status may take a moment to arrive.
  const auto give_up = Clock::now() + std::chrono::seconds(1);
  int status = 0;
  pid_t exited = 0;
  while (pid_ > 0 && (exited = ::waitpid(pid_, &status, WNOHANG)) == 0 && Clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (exited == pid_) message += "; Chromium " + exit_status_text(status);
  std::ifstream log_file(work_dir_ / "chromium.log");
  const std::string log((std::istreambuf_iterator<char>(log_file)),
                        std::istreambuf_iterator<char>());
  constexpr size_t kLogTail = 2000;
  if (!log.empty()) {
    message += "; the end of its log:\n" + log.substr(log.size() - std::min(log.size(), kLogTail));
  }
  throw std::runtime_error(message);
}

double non_background_share(const cv::Mat& image, const cv::Rect& region, cv::Vec3b background,
                            int tolerance) {
  CV_Assert(image.type() == CV_8UC3);
  const cv::Rect inside = region & cv::Rect(0, 0, image.cols, image.rows);
  if (inside.empty()) return 0;
  int differing = 0;
  for (int y = inside.y; y < inside.br().y; ++y) {
    for (int x = inside.x; x < inside.br().x; ++x) {
      const cv::Vec3b& pixel = image.at<cv::Vec3b>(y, x);
      for (int c = 0; c < 3; ++c) {
        if (std::abs(pixel[c] - background[c]) > tolerance) {
          ++differing;
          break;
        }
      }
    }
  }
  return static_cast<double>(differing) / inside.area();
}

}  // namespace slamkit::test
