// The report page in a real browser: `slamkit run` writes it, headless Chromium opens it from
// disk, and the 3D view must show the map, the page must log no error, request nothing beyond
// the file, and answer a click. Also the `report` command's comparison page and its bad input.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "datasets/synth/room_layout.h"
#include "support/headless_browser.h"
#include "support/synthetic_sequence.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

const cv::Vec3b kViewBackground(0x1e, 0x18, 0x15);  // #15181e, the page's clear colour, as BGR
constexpr double kInteractiveSeconds = 3.0;         // the page is to be usable within this

struct ViewShare {
  double drawn = 0;       // pixels of the 3D view that are not its background
  double background = 0;  // pixels of the clear colour: WebGL did render
};

ViewShare view_share(test::HeadlessBrowser& browser) {
  const nlohmann::json rect = browser.evaluate(
      "(() => { const r = document.getElementById('view3d').getBoundingClientRect();"
      " return [r.x, r.y, r.width, r.height]; })()");
  const cv::Rect region(int(rect[0].get<double>()), int(rect[1].get<double>()),
                        int(rect[2].get<double>()), int(rect[3].get<double>()));
  const cv::Mat shot = browser.screenshot();
  const double drawn = test::non_background_share(shot, region, kViewBackground, 6);
  return {drawn, 1 - test::non_background_share(shot, region, kViewBackground, 2)};
}

// Opens a page and checks what every report page must do; returns the browser for more.
void expect_a_working_page(test::HeadlessBrowser& browser, const fs::path& page) {
  const char* ready = "window.slamkitReport && window.slamkitReport.ready";
  // Opened twice: the first visit also pays for Chromium's own first navigation (its renderer
  // and software GPU process starting), which a user's running browser has behind it.
  const test::PageVisit visit = browser.open(page, ready, 20);
  ASSERT_TRUE(visit.condition_met) << "the page never became ready";
  const double warm = browser.open(page, ready, 20).seconds_to_condition;
  std::printf("interactive %s: %.2f s, %.2f s in a browser already running\n",
              page.filename().c_str(), visit.seconds_to_condition, warm);
  EXPECT_LE(warm, kInteractiveSeconds) << "slow to become interactive";
  EXPECT_TRUE(visit.console_errors.empty())
      << visit.console_errors.size() << " errors, first: " << visit.console_errors.front();
  EXPECT_TRUE(visit.network_requests().empty())
      << "the page requested " << visit.network_requests().front();
  const ViewShare share = view_share(browser);
  EXPECT_GT(share.background, 0.05) << "the 3D view was not rendered";
  EXPECT_GT(share.drawn, 0.05) << "the 3D view is blank";
}

TEST(ReportBrowser, TheRunsPageShowsTheMapLoopsAndPlotsAndAnswersALayerToggle) {
  SLAMKIT_REQUIRE_BROWSER();
  const fs::path sequence = test::synthetic_sequence(synth::Preset::kLoop, 200);
  const fs::path run = test::temp_dir("report_browser_loop") / "run";
  std::string output;
  ASSERT_EQ(test::run_slamkit("run " + sequence.string() + " --out " + run.string(), &output), 0)
      << output;
  EXPECT_NE(output.find("report      " + (run / "report.html").string()), std::string::npos);

  test::HeadlessBrowser browser(1280, 900);
  expect_a_working_page(browser, run / "report.html");
  // What the page drew from the run: loops judged true, the evaluator's SVG plots inline.
  EXPECT_GT(browser.evaluate("document.querySelectorAll('#figures svg').length").get<int>(), 1);
  const std::string layers = browser.evaluate("document.getElementById('layers').textContent");
  EXPECT_NE(layers.find(" true)"), std::string::npos) << layers;
  EXPECT_EQ(layers.find(" false"), std::string::npos) << layers;
  EXPECT_NE(layers.find("coloured by ATE"), std::string::npos);

  // Hiding the map leaves far fewer drawn pixels: the page responds.
  const double with_map = view_share(browser).drawn;
  browser.evaluate(
      "new Promise((done) => { document.querySelector('#layer-list input').click();"
      " requestAnimationFrame(() => requestAnimationFrame(done)); })");
  EXPECT_LT(view_share(browser).drawn, 0.5 * with_map);
}

TEST(ReportBrowser, ARealSequencesPageAndAComparisonPageWork) {
  SLAMKIT_REQUIRE_BROWSER();
  SLAMKIT_REQUIRE_DATA(sequence, "rgbd_dataset_freiburg2_desk_first50");
  const fs::path dir = test::temp_dir("report_browser_fr2");
  for (const char* name : {"a", "b"}) {
    const std::string extra = name[0] == 'a' ? "" : " --no-loops";
    ASSERT_EQ(test::run_slamkit("run " + sequence.string() + " --no-plot --out " +
                                (dir / name).string() + extra),
              0);
  }
  test::HeadlessBrowser browser;
  expect_a_working_page(browser, dir / "a" / "report.html");

  std::string output;
  ASSERT_EQ(test::run_slamkit("report " + (dir / "a").string() + " " + (dir / "b").string() +
                                  " --out " + (dir / "compare.html").string(),
                              &output),
            0)
      << output;
  expect_a_working_page(browser, dir / "compare.html");
  EXPECT_EQ(browser.evaluate("document.querySelectorAll('#metrics th').length").get<int>(), 3);
}

TEST(ReportCommand, RefusesWhatItCannotShowAndShowsWhatAnUnfinishedRunHas) {
  const fs::path dir = test::temp_dir("report_command");
  test::SlamkitResult missing = test::run_slamkit_apart("report " + (dir / "nothing").string() +
                                                        " --out " + (dir / "page.html").string());
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find((dir / "nothing").string() + ": no run folder here"),
            std::string::npos)
      << missing.err;

  fs::create_directories(dir / "run");
  test::SlamkitResult not_run = test::run_slamkit_apart("report " + (dir / "run").string() +
                                                        " --out " + (dir / "page.html").string());
  EXPECT_EQ(not_run.code, 2);
  EXPECT_NE(not_run.err.find("not a run folder"), std::string::npos) << not_run.err;

  // An interrupted run: the page holds what is there, stderr says what is not.
  std::ofstream(dir / "run" / "run.json") << R"({"status": "interrupted"})";
  std::ofstream(dir / "run" / "trajectory.txt") << "1 0 0 0 0 0 0 1\n2 0.1 0 0 0 0 0 1\n";
  test::SlamkitResult partial = test::run_slamkit_apart("report " + (dir / "run").string() +
                                                        " --out " + (dir / "page.html").string());
  EXPECT_EQ(partial.code, 0) << partial.err;
  EXPECT_NE(partial.err.find("the run is not complete (run.json says 'interrupted'"),
            std::string::npos)
      << partial.err;
  EXPECT_NE(partial.err.find("no map.ply"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "page.html"));

  test::SlamkitResult into_folder =
      test::run_slamkit_apart("report " + (dir / "run").string() + " --out " + dir.string());
  EXPECT_EQ(into_folder.code, 2);
  EXPECT_NE(into_folder.err.find("--out"), std::string::npos) << into_folder.err;
}

}  // namespace
}  // namespace slamkit
