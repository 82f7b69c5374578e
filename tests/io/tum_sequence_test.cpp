#include "io/tum_sequence.h"

#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "core/error.h"
#include "io/text_table.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

TEST(TumSequence, AssociationEqualsTheBenchmarksAssociateFile) {
  for (const char* name :
       {"rgbd_dataset_freiburg2_desk_first50", "rgbd_dataset_freiburg1_desk_9frames"}) {
    SLAMKIT_REQUIRE_DATA(folder, name);
    const TumSequence seq = TumSequence::open(folder);
    const auto expected = read_table(folder / "associate.txt");
    ASSERT_EQ(seq.size(), expected.size()) << name;
    for (size_t i = 0; i < seq.size(); ++i) {
      EXPECT_EQ(seq.files(i).rgb.file, expected[i].fields[1]) << name << " line " << i;
      EXPECT_EQ(seq.files(i).depth.file, expected[i].fields[3]) << name << " line " << i;
      EXPECT_EQ(seq.stamp(i), std::stod(expected[i].fields[0]));
    }
  }
}

TEST(TumSequence, RealSequencesHaveTheirCameraFramesAndGroundtruth) {
  SLAMKIT_REQUIRE_DATA(fr2, "rgbd_dataset_freiburg2_desk_first50");
  const TumSequence seq = TumSequence::open(fr2);
  EXPECT_EQ(seq.size(), 50u);
  EXPECT_EQ(seq.camera().name, "freiburg2");
  ASSERT_TRUE(seq.groundtruth().has_value());
  EXPECT_EQ(seq.groundtruth()->size(), 20956u);  // 20,957 lines, one stamp repeated

  const RgbdFrame frame = seq.load(0);
  EXPECT_EQ(frame.rgb.type(), CV_8UC3);
  EXPECT_EQ(frame.depth.type(), CV_32FC1);
  EXPECT_EQ(frame.rgb.size(), cv::Size(640, 480));
  // Depth is metres: the raw value over 5000, and 0 where the file has 0.
  const cv::Mat raw = cv::imread((fr2 / seq.files(0).depth.file).string(), cv::IMREAD_UNCHANGED);
  int checked = 0;
  for (int v = 0; v < raw.rows; v += 17)
    for (int u = 0; u < raw.cols; u += 13) {
      const double expected = raw.at<uint16_t>(v, u) / 5000.0;
      const double got = frame.depth.at<float>(v, u);
      if (expected == 0 || expected > 8.0) {
        EXPECT_EQ(got, 0.0f);
      } else {
        EXPECT_NEAR(got, expected, 1e-6);
        ++checked;
      }
    }
  EXPECT_GT(checked, 500);

  SLAMKIT_REQUIRE_DATA(fr1, "rgbd_dataset_freiburg1_desk_9frames");
  const TumSequence fr1_seq = TumSequence::open(fr1);
  EXPECT_EQ(fr1_seq.size(), 9u);
  EXPECT_EQ(fr1_seq.camera().name, "freiburg1");
}

TEST(TumSequence, DepthScaleOverrideForFreiburg2) {
  SLAMKIT_REQUIRE_DATA(fr2, "rgbd_dataset_freiburg2_desk_first50");
  SequenceOptions options;
  options.depth_scale = 5208.0;
  const TumSequence seq = TumSequence::open(fr2, options);
  EXPECT_EQ(seq.camera().depth_scale, 5208.0);
}

// A small synthetic sequence folder written by hand, to break in controlled ways.
class BrokenSequence : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::temp_dir("seq") / "rgbd_dataset_freiburg3_test";
    fs::create_directories(dir_ / "rgb");
    fs::create_directories(dir_ / "depth");
    write("rgb.txt", "# colour\n1.00 rgb/1.png\n1.10 rgb/2.png\n");
    write("depth.txt", "1.01 depth/1.png\n1.11 depth/2.png\n");
    for (const char* name : {"1", "2"}) {
      cv::imwrite((dir_ / "rgb" / (std::string(name) + ".png")).string(),
                  cv::Mat(480, 640, CV_8UC3, cv::Scalar(10, 20, 30)));
      cv::imwrite((dir_ / "depth" / (std::string(name) + ".png")).string(),
                  cv::Mat(480, 640, CV_16UC1, cv::Scalar(5000)));
    }
  }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  void expect_open_error(const std::string& fragment) {
    try {
      TumSequence::open(dir_);
      FAIL() << "no error, expected: " << fragment;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  }
  void expect_load_error(size_t i, const std::string& fragment) {
    const TumSequence seq = TumSequence::open(dir_);
    try {
      seq.load(i);
      FAIL() << "no error, expected: " << fragment;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  }
  fs::path dir_;
};

TEST_F(BrokenSequence, ValidFolderLoads) {
  const TumSequence seq = TumSequence::open(dir_);
  ASSERT_EQ(seq.size(), 2u);
  const RgbdFrame f = seq.load(1);
  EXPECT_FLOAT_EQ(f.depth.at<float>(10, 10), 1.0f);
}

TEST_F(BrokenSequence, MissingFolderOrList) {
  fs::remove(dir_ / "depth.txt");
  expect_open_error("depth.txt: file not found");
  try {
    TumSequence::open(dir_ / "nope");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sequence folder not found"), std::string::npos);
  }
}

TEST_F(BrokenSequence, LineWithTooFewFieldsOrANonNumber) {
  write("rgb.txt", "1.00 rgb/1.png\n1.10\n");
  expect_open_error("rgb.txt:2: expected 'timestamp filename', found 1 field(s)");
  write("rgb.txt", "1.00 rgb/1.png\nabc rgb/2.png\n");
  expect_open_error("rgb.txt:2: field 1 is not a number: 'abc'");
}

TEST_F(BrokenSequence, NoPairWithinTolerance) {
  write("depth.txt", "5.0 depth/1.png\n");
  expect_open_error("no RGB frame has a depth frame within 0.02");
}

TEST_F(BrokenSequence, GroundtruthWithoutOverlap) {
  write("groundtruth.txt", "100 0 0 0 0 0 0 1\n101 0 0 0 0 0 0 1\n");
  expect_open_error("groundtruth.txt: groundtruth covers 100.000..101.000 s");
}

TEST_F(BrokenSequence, DepthStampsCarryTheClockOffset) {
  SequenceOptions options;
  options.time_offset = -0.005;
  const TumSequence seq = TumSequence::open(dir_, options);
  ASSERT_EQ(seq.size(), 2u);
  EXPECT_DOUBLE_EQ(seq.stamp(1), 1.10);
  EXPECT_DOUBLE_EQ(seq.depth_stamp(1), 1.11 - 0.005);
}

TEST_F(BrokenSequence, CalibrationCarriesTheExposureTimingAndRejectsBadValues) {
  const std::string camera = "fx: 525\nfy: 525\ncx: 319.5\ncy: 239.5\n";
  write("calibration.yaml", camera + "readout_time: 0.03\nexact_depth_stamps: true\n");
  SequenceOptions options;
  options.calibration_file = dir_ / "calibration.yaml";
  const TumSequence seq = TumSequence::open(dir_, options);
  EXPECT_DOUBLE_EQ(seq.camera().readout_time, 0.03);
  EXPECT_TRUE(seq.camera().exact_depth_stamps);
  for (const auto& [line, message] :
       {std::pair<std::string, std::string>{
            "exact_depth_stamps: maybe\n",
            "calibration.yaml:5: 'exact_depth_stamps' is not true or false"},
        {"readout_time: 2\n", "calibration.yaml:5: readout_time: 2 is outside"}}) {
    write("calibration.yaml", camera + line);
    try {
      TumSequence::open(dir_, options);
      FAIL() << "no error, expected: " << message;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

TEST_F(BrokenSequence, ListedPngMissing) {
  fs::remove(dir_ / "rgb" / "2.png");
  expect_load_error(1, "rgb.txt:3: listed image does not exist");
}

TEST_F(BrokenSequence, DepthNot16Bit) {
  cv::imwrite((dir_ / "depth" / "1.png").string(), cv::Mat(480, 640, CV_8UC1, cv::Scalar(5)));
  expect_load_error(0, "depth image must be 16-bit single channel, found 8-bit 1-channel");
}

TEST_F(BrokenSequence, ImagesOfDifferentSizes) {
  cv::imwrite((dir_ / "depth" / "1.png").string(), cv::Mat(240, 320, CV_16UC1, cv::Scalar(5)));
  expect_load_error(0, "depth is 320x240 but colour is 640x480");
}

TEST_F(BrokenSequence, CameraNotKnown) {
  const fs::path renamed = dir_.parent_path() / "my_sequence";
  fs::rename(dir_, renamed);
  try {
    TumSequence::open(renamed);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot tell the camera"), std::string::npos);
  }
}

}  // namespace
}  // namespace slamkit
