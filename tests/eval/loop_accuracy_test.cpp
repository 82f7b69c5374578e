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
                         "keyframe,candidate,keyframe_stamp,candidate_stamp,score,accepted,reason\n"
                         "40,0,120.000001,100,0.3,1,\"\"\n"
                         "40,20,120.000001,110,0.2,0,\"kappa: 4 m, above 1 m\"\n"
                         "41,1,119.5,101,0.2,1,\"\"\n");
  const std::vector<AcceptedLoop> loops = read_accepted_loops(csv);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_DOUBLE_EQ(loops[0].stamp, 120.000001);
  EXPECT_DOUBLE_EQ(loops[0].loop_stamp, 100);
  EXPECT_DOUBLE_EQ(loops[1].stamp, 119.5);
}

TEST(LoopAccuracy, AFileWithoutTheStampColumnsNamesFileAndLine) {
  const auto dir = test::temp_dir("loop_accuracy_header");
  const auto csv = write(dir / "loops.csv", "keyframe,candidate,accepted\n1,0,1\n");
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
  const std::vector<AcceptedLoop> loops = {
      {120, 100},  // back at the start: true
      {120, 110},  // the far side, 4 m away: false
      {119, 100},  // 0.63 m and 18 degrees from the start: false at 0.5 m
      {150, 100},  // no groundtruth at 150: unjudged
  };
  const std::vector<RevisitEpisode> episodes = {{119, 120}, {105, 106}};
  const LoopAccuracy a = judge_loops(loops, circle(), episodes);
  EXPECT_EQ(a.accepted, 4);
  EXPECT_EQ(a.true_loops, 1);
  EXPECT_EQ(a.unjudged, 1);
  EXPECT_EQ(a.false_loops(), 2);
  EXPECT_DOUBLE_EQ(*a.precision(), 1.0 / 3);
  EXPECT_EQ(*a.episodes, 2);
  EXPECT_EQ(a.episodes_found, 1);
  EXPECT_DOUBLE_EQ(*a.recall(), 0.5);

  LoopCriteria wide;
  wide.max_distance_m = 0.7;
  EXPECT_EQ(judge_loops(loops, circle(), std::nullopt, wide).true_loops, 2);
  EXPECT_FALSE(judge_loops(loops, circle(), std::nullopt).recall());
}

TEST(LoopAccuracy, NoLoopAcceptedIsNoFalseLoop) {
  const LoopAccuracy a = judge_loops({}, circle(), std::vector<RevisitEpisode>{{119, 120}});
  EXPECT_EQ(a.false_loops(), 0);
  EXPECT_DOUBLE_EQ(*a.precision(), 1.0);
  EXPECT_DOUBLE_EQ(*a.recall(), 0.0);
}

}  // namespace
}  // namespace slamkit::eval
