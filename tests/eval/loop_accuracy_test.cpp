#include "eval/loop_accuracy.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "support/test_data.h"

namespace slamkit::eval {
namespace {

// Once round a circle of radius 2 m at 1 Hz, looking along the path: pose 20 is pose 0 again,
// pose 10 is 4 m away on the far side.
Trajectory circle() {
  Trajectory t;
  for (int k = 0; k <= 20; ++k) {
    const double a = 2 * M_PI * k / 20;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T.translation() = Eigen::Vector3d(2 * std::cos(a), 2 * std::sin(a), 0);
    t.push_back(100.0 + k, T);
  }
  return t;
}

std::filesystem::path write(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file) << text;
  return file;
}

TEST(LoopAccuracy, ReadsTheAcceptedRowsOfLoopsCsv) {
  const auto dir = test::temp_dir("loop_accuracy_read");
  const auto csv = write(dir / "loops.csv",
                         "keyframe,candidate,keyframe_stamp,candidate_stamp,score,tx,ty,tz,qx,qy,"
                         "qz,qw,accepted,reason\n"
                         "40,0,120.000001,100,0.3,0.5,0,0,0,0,0.6,0.8,1,\"\"\n"
                         "40,20,120.000001,110,0.2,0,0,0,0,0,0,1,0,\"kappa: 4 m, above 1 m\"\n"
                         "41,1,119.5,101,0.2,0,0,0,0,0,0,1,1,\"\"\n");
  const std::vector<AcceptedLoop> loops = read_accepted_loops(csv);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_DOUBLE_EQ(loops[0].stamp, 120.000001);
  EXPECT_DOUBLE_EQ(loops[0].loop_stamp, 100);
  EXPECT_TRUE(loops[0].measured.translation().isApprox(Eigen::Vector3d(0.5, 0, 0)));
  EXPECT_NEAR(Eigen::AngleAxisd(loops[0].measured.linear()).angle(), 2 * std::asin(0.6), 1e-12);
  EXPECT_DOUBLE_EQ(loops[1].stamp, 119.5);
}

TEST(LoopAccuracy, AFileWithoutTheStampColumnsNamesFileAndLine) {
  const auto dir = test::temp_dir("loop_accuracy_header");
  const auto csv = write(dir / "loops.csv", "keyframe,candidate,accepted,reason\n1,0,1,\"\"\n");
  try {
    read_accepted_loops(csv);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(csv.string() + ":1: no column 'keyframe_stamp'"),
              std::string::npos)
        << e.what();
  }
}

TEST(LoopAccuracy, ConsecutiveRevisitingFramesAreOneEpisode) {
  const auto dir = test::temp_dir("loop_accuracy_revisits");
  const auto txt = write(dir / "revisits.txt",
                         "# later first last later_stamp first_stamp last_stamp\n"
                         "19 0 0 119.0 100.0 100.0\n"
                         "20 0 1 120.0 100.0 101.0\n"
                         "30 5 6 130.0 105.0 106.0\n");
  const std::vector<RevisitEpisode> episodes = read_revisit_episodes(txt);
  ASSERT_EQ(episodes.size(), 2u);
  EXPECT_DOUBLE_EQ(episodes[0].first_stamp, 119.0);
  EXPECT_DOUBLE_EQ(episodes[0].last_stamp, 120.0);
  EXPECT_DOUBLE_EQ(episodes[1].first_stamp, 130.0);
}

TEST(LoopAccuracy, TrueFalseAndUnjudgedLoopsAndTheRevisitsFound) {
  const Trajectory gt = circle();
  const auto relative = [&](int a, int b) { return gt.pose(a).inverse() * gt.pose(b); };
  Eigen::Isometry3d off_by_30cm = relative(20, 0);
  off_by_30cm.translation().x() += 0.3;
  const std::vector<AcceptedLoop> loops = {
      {120, 100, relative(20, 0)},  // back at the start, measured right: true
      {120, 110, relative(20, 0)},  // a look-alike: the far side (4 m) measured as here
      {119, 100, relative(19, 0)},  // 0.63 m and 18 degrees apart, measured right: true
      {150, 100, relative(20, 0)},  // no groundtruth at 150: unjudged
      {120, 100, off_by_30cm},      // the right place measured 30 cm off: false
  };
  const std::vector<RevisitEpisode> episodes = {{119, 120}, {105, 106}};
  const LoopAccuracy a = judge_loops(loops, gt, episodes);
  EXPECT_EQ(a.accepted, 5);
  EXPECT_EQ(a.true_loops, 2);
  EXPECT_EQ(a.same_place, 2);  // the first and the last (0.63 m is beyond 0.5 m)
  EXPECT_EQ(a.unjudged, 1);
  EXPECT_EQ(a.false_loops(), 2);
  EXPECT_DOUBLE_EQ(*a.precision(), 0.5);
  EXPECT_EQ(*a.episodes, 2);
  EXPECT_EQ(a.episodes_found, 1);
  EXPECT_DOUBLE_EQ(*a.recall(), 0.5);

  LoopCriteria lenient;
  lenient.max_error_m = 0.5;
  EXPECT_EQ(judge_loops(loops, gt, std::nullopt, lenient).true_loops, 3);
  EXPECT_FALSE(judge_loops(loops, gt, std::nullopt).recall());
}

TEST(LoopAccuracy, NoLoopAcceptedIsNoFalseLoop) {
  const LoopAccuracy a = judge_loops({}, circle(), std::vector<RevisitEpisode>{{119, 120}});
  EXPECT_EQ(a.false_loops(), 0);
  EXPECT_DOUBLE_EQ(*a.precision(), 1.0);
  EXPECT_DOUBLE_EQ(*a.recall(), 0.0);
}

}  // namespace
}  // namespace slamkit::eval
