#pragma once
// A real headless Chromium for tests of the HTML pages slamkit writes. It speaks the Chrome
// DevTools Protocol over --remote-debugging-pipe (JSON messages ended by '\0'; Chromium reads
// fd 3 and writes fd 4), so no WebSocket client is needed. WebGL renders in software
// (SwiftShader), so a page's 3D view shows up in screenshots without a GPU.
#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "support/test_data.h"

namespace slamkit::test {

// What one page did between its navigation and the moment it was looked at.
struct PageVisit {
  // console.error / console.assert, uncaught exceptions and error log entries (such as failed
  // loads), each as "kind: text (url:line)".
  std::vector<std::string> console_errors;
  // Every URL the page requested, its own file:// URL included.
  std::vector<std::string> requested_urls;
  bool condition_met = false;
  // From the navigation to the ready expression turning truthy, or to giving up.
  double seconds_to_condition = 0;

  // The requested URLs that leave the machine: any scheme but file:, data:, blob:, about:.
  std::vector<std::string> network_requests() const;
};

class HeadlessBrowser {
 public:
  // $SLAMKIT_CHROMIUM, else /usr/bin/chromium.
  static std::filesystem::path executable();
  static bool available();

  // Starts Chromium with a fresh profile and a window of the given size in CSS pixels.
  explicit HeadlessBrowser(int width = 1280, int height = 800);
  // Closes Chromium, kills what is left of its process group and removes the profile.
  ~HeadlessBrowser();
  HeadlessBrowser(const HeadlessBrowser&) = delete;
  HeadlessBrowser& operator=(const HeadlessBrowser&) = delete;

  // Navigates to the file and evaluates `ready_expression` in the page every few
  // milliseconds until it is truthy or `timeout_s` has passed.
  PageVisit open(const std::filesystem::path& html_file, const std::string& ready_expression,
                 double timeout_s);
  // The current page's visit so far: also what arrived after open() returned.
  const PageVisit& visit() const { return visit_; }

  // The value of a JavaScript expression in the page (promises are awaited). Throws when it
  // throws.
  nlohmann::json evaluate(const std::string& expression);

  // The viewport as an 8-bit BGR image.
  cv::Mat screenshot();

 private:
  using Clock = std::chrono::steady_clock;

  void start(int width, int height);
  void shut_down();

  // Sends a command and waits for its reply (the whole message, "error" included); events
  // that arrive meanwhile are recorded. In the page's session unless `to_browser`.
  nlohmann::json send_command(const std::string& method, const nlohmann::json& params,
                              bool to_browser = false);
  // Its "result"; throws on an "error" reply.
  nlohmann::json command(const std::string& method, const nlohmann::json& params = {},
                         bool to_browser = false);
  void write_message(const nlohmann::json& message);
  // Reads and records events until the reply `id` arrives (returned) or the deadline passes.
  std::optional<nlohmann::json> read_until(int id, Clock::time_point deadline);
  void record_event(const nlohmann::json& message);
  // Throws, with Chromium's exit status and the end of its log when it died.
  [[noreturn]] void fail(const std::string& what);

  pid_t pid_ = -1;
  int to_browser_ = -1;
  int from_browser_ = -1;
  std::filesystem::path work_dir_;  // profile and log
  std::string session_id_;
  std::string unread_;  // bytes after the last whole message
  int last_id_ = 0;
  PageVisit visit_;
  std::string main_frame_loader_;  // of the main frame's last committed navigation
};

// Share of the pixels in `region` (clipped to the image) whose colour differs from
// `background` by more than `tolerance` in any channel.
double non_background_share(const cv::Mat& image, const cv::Rect& region, cv::Vec3b background,
                            int tolerance);

}  // namespace slamkit::test

// Fails (CI) or skips (elsewhere) the test when Chromium is missing.
#define SLAMKIT_REQUIRE_BROWSER()                                                       \
  do {                                                                                  \
    if (!::slamkit::test::HeadlessBrowser::available()) {                               \
      const std::string why = "Chromium not found at " +                                \
                              ::slamkit::test::HeadlessBrowser::executable().string() + \
                              ": install it with scripts/setup.sh --browser (or set "   \
                              "SLAMKIT_CHROMIUM)";                                      \
      if (::slamkit::test::running_under_ci()) FAIL() << why;                           \
      GTEST_SKIP() << why;                                                              \
    }                                                                                   \
  } while (false)
