// The headless-browser client itself (support/headless_browser.h), on tiny pages: WebGL
// renders into screenshots, errors and network requests are caught, the ready expression is
// timed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "support/headless_browser.h"

namespace slamkit::test {
namespace {

namespace fs = std::filesystem;

fs::path write_page(const std::string& name, const std::string& body) {
  const fs::path file = temp_dir(name) / name;
  std::ofstream(file) << "<!DOCTYPE html><html><head><meta charset=\"utf-8\"></head>"
                      << "<body style=\"margin:0;background:#ffffff\">" << body
                      << "</body></html>\n";
  return file;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

// Share of the pixels in `region` within `tolerance` of `colour`.
double colour_share(const cv::Mat& image, const cv::Rect& region, cv::Vec3b colour) {
  return 1.0 - non_background_share(image, region, colour, 40);
}

// A 200x150 canvas at the top left, cleared to blue, with a red triangle over its centre.
const char* const kWebGlPage = R"(
<canvas id="view" width="200" height="150" style="display:block"></canvas>
<script>
  const gl = document.getElementById('view').getContext('webgl');
  if (!gl) {
    window.failure = 'no WebGL context';
  } else {
    const compile = (type, source) => {
      const shader = gl.createShader(type);
      gl.shaderSource(shader, source);
      gl.compileShader(shader);
      return shader;
    };
    const program = gl.createProgram();
    gl.attachShader(program, compile(gl.VERTEX_SHADER,
        'attribute vec2 p; void main() { gl_Position = vec4(p, 0.0, 1.0); }'));
    gl.attachShader(program, compile(gl.FRAGMENT_SHADER,
        'precision mediump float; void main() { gl_FragColor = vec4(1.0, 0.0, 0.0, 1.0); }'));
    gl.linkProgram(program);
    gl.useProgram(program);
    gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer());
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-0.6, -0.6, 0.6, -0.6, 0.0, 0.7]),
                  gl.STATIC_DRAW);
    const p = gl.getAttribLocation(program, 'p');
    gl.enableVertexAttribArray(p);
    gl.vertexAttribPointer(p, 2, gl.FLOAT, false, 0, 0);
    gl.clearColor(0.0, 0.0, 1.0, 1.0);
    gl.clear(gl.COLOR_BUFFER_BIT);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    window.renderer = gl.getParameter(gl.RENDERER);
    window.ready = true;
  }
</script>)";

TEST(HeadlessBrowser, WebGlCanvasShowsInTheScreenshot) {
  SLAMKIT_REQUIRE_BROWSER();
  HeadlessBrowser browser(640, 480);
  const PageVisit visit = browser.open(write_page("webgl.html", kWebGlPage),
                                       "window.ready === true || window.failure", 30);
  ASSERT_TRUE(visit.condition_met);
  ASSERT_TRUE(browser.evaluate("window.failure || ''").get<std::string>().empty())
      << browser.evaluate("window.failure");
  EXPECT_TRUE(visit.console_errors.empty()) << joined(visit.console_errors);

  const cv::Mat shot = browser.screenshot();
  ASSERT_EQ(shot.cols, 640);
  ASSERT_EQ(shot.rows, 480);
  const cv::Rect canvas(0, 0, 200, 150);
  const cv::Vec3b white(255, 255, 255), blue(255, 0, 0), red(0, 0, 255);
  SCOPED_TRACE("renderer: " + browser.evaluate("window.renderer").dump());
  EXPECT_GT(non_background_share(shot, canvas, white, 30), 0.95);
  EXPECT_GT(colour_share(shot, canvas, blue), 0.5);
  EXPECT_GT(colour_share(shot, canvas, red), 0.1);
  // The triangle's centre is red, the canvas corners are blue, the page beside it is white.
  EXPECT_GT(colour_share(shot, cv::Rect(95, 70, 10, 10), red), 0.99);
  EXPECT_GT(colour_share(shot, cv::Rect(0, 0, 10, 10), blue), 0.99);
  EXPECT_EQ(non_background_share(shot, cv::Rect(300, 0, 340, 480), white, 0), 0.0);
}

TEST(HeadlessBrowser, ConsoleErrorsAndUncaughtExceptionsAreCaught) {
  SLAMKIT_REQUIRE_BROWSER();
  HeadlessBrowser browser;
  const PageVisit logged = browser.open(
      write_page("console.html", "<script>console.error('boom'); console.log('fine');</script>"),
      "document.readyState === 'complete'", 30);
  ASSERT_TRUE(logged.condition_met);
  ASSERT_EQ(logged.console_errors.size(), 1u) << joined(logged.console_errors);
  EXPECT_NE(logged.console_errors[0].find("boom"), std::string::npos) << logged.console_errors[0];

  const PageVisit thrown =
      browser.open(write_page("throws.html", "<script>throw new Error('kaboom');</script>"),
                   "document.readyState === 'complete'", 30);
  ASSERT_TRUE(thrown.condition_met);
  ASSERT_EQ(thrown.console_errors.size(), 1u) << joined(thrown.console_errors);
  EXPECT_NE(thrown.console_errors[0].find("kaboom"), std::string::npos) << thrown.console_errors[0];
  EXPECT_NE(thrown.console_errors[0].find("throws.html:1"), std::string::npos)
      << thrown.console_errors[0];
}

TEST(HeadlessBrowser, NetworkRequestsAreSeenAndDataUrlsAreNot) {
  SLAMKIT_REQUIRE_BROWSER();
  HeadlessBrowser browser;
  // Nothing listens on port 9 (discard): the load fails at once, but it was requested.
  const PageVisit remote =
      browser.open(write_page("remote.html",
                              "<img src=\"http://127.0.0.1:9/x.png\" "
                              "onerror=\"window.ready = true\" onload=\"window.ready = true\">"),
                   "window.ready === true", 30);
  ASSERT_TRUE(remote.condition_met);
  EXPECT_EQ(remote.network_requests(), std::vector<std::string>{"http://127.0.0.1:9/x.png"})
      << joined(remote.requested_urls);

  // A 1x1 PNG.
  const PageVisit local = browser.open(
      write_page("local.html",
                 "<img src=\"data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAA"
                 "DUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg==\" "
                 "onerror=\"window.ready = 'failed'\" onload=\"window.ready = true\">"),
      "window.ready", 30);
  ASSERT_TRUE(local.condition_met);
  EXPECT_EQ(browser.evaluate("window.ready"), true);
  EXPECT_TRUE(local.network_requests().empty()) << joined(local.network_requests());
  EXPECT_TRUE(local.console_errors.empty()) << joined(local.console_errors);
}

TEST(HeadlessBrowser, ReadyExpressionIsTimedFromTheNavigation) {
  SLAMKIT_REQUIRE_BROWSER();
  HeadlessBrowser browser;
  const fs::path page =
      write_page("late.html", "<script>setTimeout(() => { window.ready = true; }, 300);</script>");
  const PageVisit ready = browser.open(page, "window.ready === true", 30);
  ASSERT_TRUE(ready.condition_met);
  // Not before the page's own 300 ms (a lower bound holds on any machine, however loaded; no
  // upper bound is asserted).
  EXPECT_GE(ready.seconds_to_condition, 0.25);
  EXPECT_TRUE(ready.console_errors.empty()) << joined(ready.console_errors);

  // An expression that never holds times out rather than hanging.
  const PageVisit never = browser.open(page, "window.never === true", 0.5);
  EXPECT_FALSE(never.condition_met);
  EXPECT_GE(never.seconds_to_condition, 0.5);
}

TEST(HeadlessBrowser, EvaluateReturnsValuesAndReportsExceptions) {
  SLAMKIT_REQUIRE_BROWSER();
  HeadlessBrowser browser;
  ASSERT_TRUE(browser.open(write_page("empty.html", ""), "true", 30).condition_met);
  EXPECT_EQ(browser.evaluate("({a: [1, 2], b: 'x'})"), (nlohmann::json{{"a", {1, 2}}, {"b", "x"}}));
  EXPECT_EQ(browser.evaluate("Promise.resolve(42)"), 42);
  EXPECT_THROW(browser.evaluate("undefinedVariable.field"), std::runtime_error);
}

TEST(HeadlessBrowser, FailuresThrowRatherThanHang) {
  SLAMKIT_REQUIRE_BROWSER();
  {
    HeadlessBrowser browser;
    EXPECT_THROW(browser.open(temp_dir("missing") / "missing.html", "true", 30),
                 std::runtime_error);
  }
  // A "browser" that exits at once: its closed pipe is reported with its exit status.
  const std::string chosen = HeadlessBrowser::executable();
  ::setenv("SLAMKIT_CHROMIUM", "/bin/false", 1);
  try {
    HeadlessBrowser browser;
    ADD_FAILURE() << "/bin/false was taken for a browser";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("exited with code 1"), std::string::npos)
        << error.what();
  }
  ::setenv("SLAMKIT_CHROMIUM", chosen.c_str(), 1);
}

}  // namespace
}  // namespace slamkit::test
