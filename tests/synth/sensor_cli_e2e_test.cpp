// `slamkit synth --sensor`: the ideal sensor's output is pinned, the kinect one's sequence is
// readable as TUM data with its own depth stamps, 100 Hz groundtruth and recorded settings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <vector>

#include "datasets/synth/map_quality.h"
#include "io/camera_yaml.h"
#include "io/png_file.h"
#include "io/tum_sequence.h"
#include "support/test_data.h"

namespace slamkit::synth {
namespace {

namespace fs = std::filesystem;

// FNV-1a over bytes (written here: a fingerprint needs no library).
uint64_t fnv1a(uint64_t h, const void* data, size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 0x100000001B3ull;
  return h;
}

// Every file of the folder in name order: its name, then its bytes, or for a PNG its decoded
// pixels (so that a new zlib compressing the same pixels differently does not count, while any
// changed pixel, stamp, pose or list line does).
uint64_t folder_fingerprint(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) files.push_back(fs::relative(entry.path(), folder));
  std::sort(files.begin(), files.end());
  uint64_t h = 0xCBF29CE484222325ull;
  for (const fs::path& file : files) {
    const std::string name = file.generic_string();
    h = fnv1a(h, name.data(), name.size());
    if (file.extension() == ".png") {
      const cv::Mat image = read_png(folder / file);
      for (int v = 0; v < image.rows; ++v)
        h = fnv1a(h, image.ptr(v), image.cols * image.elemSize());
    } else {
      const std::string bytes = test::read_text(folder / file);
      h = fnv1a(h, bytes.data(), bytes.size());
    }
  }
  return h;
}

fs::path synth(const std::string& tag, const std::string& arguments) {
  const fs::path out = test::temp_dir(tag);
  std::string output;
  EXPECT_EQ(test::run_slamkit("synth " + arguments + " --out " + out.string(), &output), 0)
      << output;
  return out;
}

TEST(SensorCli, IdealOutputIsTheSameAsBeforeTheKinectSensorExisted) {
  // Fingerprints of the folders that slamkit rendered before `--sensor` was added (checked
  // against sha256 sums of every file of the same renderings by the binary of commit e0fae1e).
  // A change here changes every ideal synthetic sequence and every baseline made from one.
  // The default sensor is the ideal one: desk runs without --sensor, jerk with it.
  const std::map<std::string, uint64_t> expected = {
      {"--preset desk --frames 20 --seed 1", 0x791b4243caae6d8eull},
      {"--preset jerk --frames 20 --sensor ideal", 0xb8ccb29248f8b6d2ull},
  };
  for (const auto& [arguments, fingerprint] : expected) {
    const fs::path out = synth("ideal", arguments + " --threads 2");
    EXPECT_EQ(folder_fingerprint(out), fingerprint)
        << std::hex << folder_fingerprint(out) << " for " << arguments;
  }
}

std::vector<double> stamps_of(const fs::path& list) {
  std::vector<double> stamps;
  for (const StampedFile& f : read_file_list(list)) stamps.push_back(f.stamp);
  return stamps;
}

TEST(SensorCli, KinectSequenceHasItsOwnDepthStampsAndIsTheSameForAnyThreadCount) {
  const std::string arguments = "--preset jerk --frames 12 --seed 2 --sensor kinect";
  const fs::path a = synth("kinect1", arguments + " --threads 1");
  const fs::path b = synth("kinect2", arguments + " --threads 2");
  EXPECT_EQ(folder_fingerprint(a), folder_fingerprint(b));

  const std::vector<double> rgb = stamps_of(a / "rgb.txt"), depth = stamps_of(a / "depth.txt");
  ASSERT_EQ(rgb.size(), 12u);
  ASSERT_GE(depth.size(), 11u);
  // fr1-like: depth 14 ms ahead at the start, never on a colour stamp.
  EXPECT_NEAR(depth[0] - rgb[0], -0.014, 0.01);
  for (double d : depth) EXPECT_EQ(std::count(rgb.begin(), rgb.end(), d), 0);

  SequenceOptions options;
  options.calibration_file = a / "calibration.yaml";
  const TumSequence sequence = TumSequence::open(a, options);
  EXPECT_GE(sequence.size(), 11u);
  // The calibration tells the tracker the exposure timing (docs/method.md#exposure-timing).
  EXPECT_DOUBLE_EQ(sequence.camera().readout_time, KinectSettings().readout_s);
  EXPECT_TRUE(sequence.camera().exact_depth_stamps);
  EXPECT_EQ(sequence.depth_stamp(0), sequence.files(0).depth.stamp);
  for (size_t i = 0; i < sequence.size(); ++i)
    EXPECT_LT(std::abs(sequence.files(i).depth.stamp - sequence.stamp(i)), 0.02);
  const Trajectory& gt = *sequence.groundtruth();
  ASSERT_GT(gt.size(), 36u);  // 100 Hz over 0.37 s and more
  for (size_t k = 1; k < gt.size(); ++k) EXPECT_NEAR(gt[k].stamp - gt[k - 1].stamp, 0.01, 2e-6);

  // synthetic.yaml names the sensor and its settings; tools read it back.
  const std::optional<SyntheticInfo> info = read_synthetic_info(a);
  ASSERT_TRUE(info);
  ASSERT_TRUE(info->kinect);
  EXPECT_EQ(info->kinect->on, KinectSettings().on);
  EXPECT_DOUBLE_EQ(info->kinect->exposure_s, KinectSettings().exposure_s);
}

TEST(SensorCli, EffectsSwitchOnTheCommandLineAndLensDistortionReachesTheCalibration) {
  const fs::path out = synth("kinect_switches",
                             "--preset desk --frames 2 --sensor kinect --sensor-off "
                             "motion_blur,stream_timing --sensor-on lens_distortion");
  const std::optional<SyntheticInfo> info = read_synthetic_info(out);
  ASSERT_TRUE(info && info->kinect);
  EXPECT_FALSE(info->kinect->has(KinectEffect::kMotionBlur));
  EXPECT_TRUE(info->kinect->has(KinectEffect::kLensDistortion));
  // stream_timing off: depth shares the colour stamps.
  EXPECT_EQ(stamps_of(out / "rgb.txt"), stamps_of(out / "depth.txt"));
  const Camera camera = read_camera_yaml(out / "calibration.yaml");
  EXPECT_DOUBLE_EQ(camera.distortion.k1, KinectSettings().k1);
  EXPECT_FALSE(camera.exact_depth_stamps);  // stream_timing off
  EXPECT_GT(camera.readout_time, 0);

  std::string output;
  EXPECT_EQ(test::run_slamkit("synth --frames 2 --sensor kinect --sensor-off blur --out " +
                                  test::temp_dir("bad_effect").string(),
                              &output),
            2);
  EXPECT_NE(output.find("unknown sensor effect 'blur'"), std::string::npos) << output;
  EXPECT_EQ(test::run_slamkit("synth --frames 2 --sensor-off motion_blur --out " +
                                  test::temp_dir("ideal_switch").string(),
                              &output),
            2);
  // A settings file: unknown keys and values out of range are bad input naming the problem.
  const fs::path dir = test::temp_dir("sensor_settings");
  for (const auto& [text, message] :
       std::map<std::string, std::string>{{"exposure: 0.01\n", "unknown setting 'exposure'"},
                                          {"groundtruth_rate_hz: 0\n", "groundtruth_rate_hz"},
                                          {"effects: {blur: false}\n", "unknown sensor effect"}}) {
    std::ofstream(dir / "kinect.yaml") << text;
    EXPECT_EQ(
        test::run_slamkit("synth --frames 2 --sensor kinect --sensor-settings " +
                              (dir / "kinect.yaml").string() + " --out " + (dir / "out").string(),
                          &output),
        2)
        << text;
    EXPECT_NE(output.find(message), std::string::npos) << output;
  }
}

}  // namespace
}  // namespace slamkit::synth
