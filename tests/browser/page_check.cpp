// page_check: opens an HTML page in headless Chromium (support/headless_browser.h), waits for
// a ready expression, optionally saves a screenshot, and prints one JSON object with what the
// page did. Used to make the screenshots in the docs and to look at a page by hand.
// Exit code: 0 when the ready expression held, 1 when it timed out, 2 on a usage error or
// when the browser failed.
#include <iostream>
#include <opencv2/imgcodecs.hpp>

#include "support/headless_browser.h"

namespace {

using nlohmann::json;
using slamkit::test::HeadlessBrowser;

constexpr const char* kUsage =
    "usage: page_check PAGE.html --ready EXPR [--screenshot OUT.png] [--width W] [--height H]\n"
    "                  [--timeout SECONDS] [--eval EXPR]...\n";

struct Options {
  std::string page;
  std::string ready;
  std::string screenshot;
  int width = 1280;
  int height = 800;
  double timeout_s = 60;
  std::vector<std::string> evals;
};

// Throws std::invalid_argument on bad usage.
Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument.rfind("--", 0) != 0) {
      if (!options.page.empty()) throw std::invalid_argument("more than one page");
      options.page = argument;
      continue;
    }
    if (i + 1 == argc) throw std::invalid_argument(argument + " needs a value");
    const std::string value = argv[++i];
    if (argument == "--ready") {
      options.ready = value;
    } else if (argument == "--screenshot") {
      options.screenshot = value;
    } else if (argument == "--width") {
      options.width = std::stoi(value);
    } else if (argument == "--height") {
      options.height = std::stoi(value);
    } else if (argument == "--timeout") {
      options.timeout_s = std::stod(value);
    } else if (argument == "--eval") {
      options.evals.push_back(value);
    } else {
      throw std::invalid_argument("unknown option " + argument);
    }
  }
  if (options.page.empty() || options.ready.empty()) {
    throw std::invalid_argument("a page and --ready are required");
  }
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  try {
    options = parse(argc, argv);
  } catch (const std::exception& error) {  // std::stoi's errors included
    std::cerr << "page_check: " << error.what() << "\n" << kUsage;
    return 2;
  }
  try {
    HeadlessBrowser browser(options.width, options.height);
    const slamkit::test::PageVisit visit =
        browser.open(options.page, options.ready, options.timeout_s);
    json report = {{"page", options.page},
                   {"ready", visit.condition_met},
                   {"seconds_to_ready", visit.seconds_to_condition}};
    json evals = json::array();
    for (const std::string& expression : options.evals) {
      try {
        evals.push_back({{"expression", expression}, {"value", browser.evaluate(expression)}});
      } catch (const std::runtime_error& error) {
        evals.push_back({{"expression", expression}, {"error", error.what()}});
      }
    }
    report["evals"] = evals;
    if (!options.screenshot.empty()) {
      if (!cv::imwrite(options.screenshot, browser.screenshot())) {
        throw std::runtime_error("cannot write " + options.screenshot);
      }
      report["screenshot"] = options.screenshot;
    }
    // Everything up to now: errors the evaluations or the screenshot caused included.
    report["console_errors"] = browser.visit().console_errors;
    report["network_requests"] = browser.visit().network_requests();
    std::cout << report.dump(2) << "\n";
    return visit.condition_met ? 0 : 1;
  } catch (const std::exception& error) {
    std::cerr << "page_check: " << error.what() << "\n";
    return 2;
  }
}
