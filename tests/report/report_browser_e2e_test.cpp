// The report page in a real browser: `slamkit run` writes it, headless Chromium opens it from
// disk, and the 3D view must show the map, the page must log no error, request nothing beyond
// the file, and answer a click. Also a page with a mesh, the `report` command's comparison page
// and its bad input.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "datasets/synth/room_layout.h"
#include "report/mesh_fixtures.h"
#include "support/headless_browser.h"
#include "support/synthetic_sequence.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

const cv::Vec3b kViewBackground(0x1e, 0x18, 0x15);  // #15181e, the page's clear colour, as BGR

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
  // Reported, not asserted: a duration depends on the machine's load (docs/performance.md
  // gives the figures).
  std::printf("interactive %s: %.2f s, %.2f s in a browser already running\n",
              page.filename().c_str(), visit.seconds_to_condition, warm);
  EXPECT_TRUE(visit.console_errors.empty())
      << visit.console_errors.size() << " errors, first: " << visit.console_errors.front();
  EXPECT_TRUE(visit.network_requests().empty())
      << "the page requested " << visit.network_requests().front();
  const ViewShare share = view_share(browser);
  EXPECT_GT(share.background, 0.05) << "the 3D view was not rendered";
  EXPECT_GT(share.drawn, 0.05) << "the 3D view is blank";
}

// The toggles of the layers whose names start with `name` ("map (", "mesh ("), as a JavaScript
// array.
std::string toggles(const std::string& name) {
  return "[...document.querySelectorAll('#layer-list label')].filter((label) => "
         "label.textContent.startsWith('" +
         name + "')).map((label) => label.querySelector('input'))";
}

// Sets those toggles and waits for the frame drawn after.
void show_layers(test::HeadlessBrowser& browser, const std::string& name, bool shown) {
  const std::string checked = shown ? "true" : "false";
  browser.evaluate("new Promise((done) => { for (const box of " + toggles(name) +
                   ") if (box.checked !== " + checked +
                   ") box.click(); requestAnimationFrame(() => requestAnimationFrame(done)); })");
}

bool layer_shown(test::HeadlessBrowser& browser, const std::string& name) {
  return browser.evaluate(toggles(name) + ".some((box) => box.checked)").get<bool>();
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

  // Hiding the map (and the mesh, when the run made one) leaves far fewer drawn pixels: the
  // page responds.
  const double with_map = view_share(browser).drawn;
  show_layers(browser, "map (", false);
  show_layers(browser, "mesh (", false);
  EXPECT_LT(view_share(browser).drawn, 0.5 * with_map);
}

// The groundtruth's frame (the scene's) into the run's own: the inverse of metrics.json's ATE
// alignment.
Eigen::Affine3d scene_to_run(const fs::path& run) {
  const nlohmann::json alignment =
      nlohmann::json::parse(test::read_text(run / "metrics.json"))["ate"]["alignment"];
  Eigen::Affine3d run_to_scene = Eigen::Affine3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      run_to_scene.linear()(r, c) =
          alignment.value("scale", 1.0) * alignment["rotation"][r][c].get<double>();
    run_to_scene.translation()[r] = alignment["translation"][r].get<double>();
  }
  return run_to_scene.inverse();
}

// The synthetic room's surfaces as a TSDF of its sequence would mesh them, in the run's frame:
// each face of the room and of its furniture a grid of `step`-metre squares, two triangles each,
// counter-clockwise seen from the free side, each vertex in the scene's colour there.
PlyCloud room_mesh(const synth::SyntheticScene& scene, double step, const Eigen::Affine3d& to_run) {
  PlyCloud mesh;
  const auto byte = [](float c) { return uint8_t(std::clamp(c, 0.0f, 255.0f)); };
  const auto add_face = [&](const Eigen::AlignedBox3d& box, int axis, int side, bool inside) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;  // u x v is +axis
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // towards the free side
    normal[axis] = (side == 1) != inside ? 1 : -1;
    const Eigen::Vector3d size = box.sizes();
    const int nu = std::max(1, int(std::ceil(size[u] / step)));
    const int nv = std::max(1, int(std::ceil(size[v] / step)));
    const uint32_t first = uint32_t(mesh.points.size());
    for (int j = 0; j <= nv; ++j) {
      for (int i = 0; i <= nu; ++i) {
        Eigen::Vector3d p = box.min();
        p[axis] = side == 1 ? box.max()[axis] : box.min()[axis];
        p[u] += size[u] * i / nu;
        p[v] += size[v] * j / nv;
        const auto hit = scene.cast_ray(p + 0.01 * normal, -normal);
        const Eigen::Vector3f bgr = hit ? scene.colour(*hit, step) : Eigen::Vector3f(128, 128, 128);
        mesh.points.push_back((to_run * p).cast<float>());
        mesh.colours.push_back({byte(bgr[2]), byte(bgr[1]), byte(bgr[0])});
      }
    }
    const auto at = [&](int i, int j) { return first + uint32_t(j * (nu + 1) + i); };
    for (int j = 0; j < nv; ++j) {
      for (int i = 0; i < nu; ++i) {
        const uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
        if (normal[axis] > 0) {
          mesh.triangles.push_back({a, b, c});
          mesh.triangles.push_back({a, c, d});
        } else {
          mesh.triangles.push_back({a, c, b});
          mesh.triangles.push_back({a, d, c});
        }
      }
    }
  };
  const synth::SceneDescription& description = scene.description();
  for (int face = 0; face < 6; ++face) add_face(description.room, face / 2, face % 2, true);
  for (const synth::Furniture& piece : description.furniture)
    for (const synth::BoxPart& part : piece.parts)
      for (int face = 0; face < 6; ++face) add_face(part.bounds, face / 2, face % 2, false);
  return mesh;
}

TEST(ReportBrowser, AMeshOfARoomIsALayerOfItsOwnWithinItsBudgetAndAnswersItsToggle) {
  SLAMKIT_REQUIRE_BROWSER();
  const fs::path sequence = test::synthetic_sequence(synth::Preset::kLoop, 200);
  const fs::path run = test::temp_dir("report_browser_mesh") / "run";
  ASSERT_EQ(test::run_slamkit("run " + sequence.string() + " --no-plot --no-report --out " +
                              run.string()),
            0);
  // A room at 1.2 cm, about the triangles a TSDF at 1 cm makes of it.
  const PlyCloud room = room_mesh(synth::make_furnished_room(), 0.012, scene_to_run(run));
  ASSERT_GT(room.triangles.size(), 1'000'000u);
  write_ply_cloud(run / "mesh.ply", room);
  std::string output;
  ASSERT_EQ(test::run_slamkit("report " + run.string() + " --out " + (run / "report.html").string(),
                              &output),
            0)
      << output;
  EXPECT_NE(output.find(" of " + std::to_string(room.triangles.size()) + " mesh triangles"),
            std::string::npos)
      << output;
  const uintmax_t bytes = fs::file_size(run / "report.html");
  std::printf("a page with a mesh of %zu triangles at the default budget: %.1f MB\n",
              room.triangles.size(), double(bytes) / 1e6);
  EXPECT_LT(bytes, 15'000'000u);

  test::HeadlessBrowser browser(1280, 900);
  expect_a_working_page(browser, run / "report.html");
  const std::string layers = browser.evaluate("document.getElementById('layers').textContent");
  EXPECT_NE(layers.find("mesh triangles shown"), std::string::npos) << layers;
  // The mesh is drawn where the map is: the map's box lies within the room's, give or take the
  // map's noise.
  const nlohmann::json boxes = browser.evaluate(
      "[runs[0].map.min, runs[0].map.size, "
      "runs[0].mesh.min, runs[0].mesh.size]");
  for (int d = 0; d < 3; ++d) {
    const double map_min = boxes[0][d], map_size = boxes[1][d];
    const double mesh_min = boxes[2][d], mesh_size = boxes[3][d];
    EXPECT_GT(map_min, mesh_min - 0.1) << d;
    EXPECT_LT(map_min + map_size, mesh_min + mesh_size + 0.1) << d;
  }
  // The mesh shows, the map's points do not; each answers its toggle.
  EXPECT_TRUE(layer_shown(browser, "mesh ("));
  EXPECT_FALSE(layer_shown(browser, "map ("));
  const double with_mesh = view_share(browser).drawn;
  show_layers(browser, "mesh (", false);
  const double without = view_share(browser).drawn;
  EXPECT_LT(without, 0.5 * with_mesh);
  show_layers(browser, "map (", true);
  EXPECT_GT(view_share(browser).drawn, 2 * without);
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
