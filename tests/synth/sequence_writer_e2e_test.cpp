#include "datasets/synth/sequence_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "datasets/synth/renderer.h"
#include "io/camera_yaml.h"
#include "io/png_file.h"
#include "io/trajectory_io.h"
#include "io/tum_sequence.h"
#include "support/test_data.h"
#include "synth/shared_room.h"

namespace slamkit::synth {
namespace {

namespace fs = std::filesystem;

fs::path render(const std::string& tag, Preset preset, int frames, uint64_t seed = 1,
                int threads = 0) {
  SequenceSpec spec;
  spec.preset = preset;
  spec.frames = frames;
  spec.seed = seed;
  spec.threads = threads;
  spec.out = slamkit::test::temp_dir(tag);
  write_sequence(test::shared_scene(preset), spec);
  return spec.out;
}

// The reader needs the calibration for a folder not named after a Freiburg camera.
TumSequence open_sequence(const fs::path& folder) {
  SequenceOptions options;
  options.calibration_file = folder / "calibration.yaml";
  return TumSequence::open(folder, options);
}

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every file of folder `a` has a byte-identical twin in `b`.
void expect_identical_folders(const fs::path& a, const fs::path& b) {
  size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(a)) {
    if (!entry.is_regular_file()) continue;
    const fs::path twin = b / fs::relative(entry.path(), a);
    ASSERT_TRUE(fs::exists(twin)) << twin;
    EXPECT_TRUE(file_bytes(entry.path()) == file_bytes(twin)) << twin;
    ++files;
  }
  EXPECT_GT(files, 6u);
}

// The key property: depth back-projected with the groundtruth pose lands on the scene's
// surfaces, within the sensor's noise, for every preset, read through the project's reader.
TEST(SynthSequence, BackProjectedDepthLiesOnTheSurfacesForEveryPreset) {
  for (const std::string& name : preset_names()) {
    const Preset preset = parse_preset(name);
    const fs::path folder = render("surfaces_" + name, preset, 8);
    const TumSequence seq = open_sequence(folder);
    ASSERT_EQ(seq.size(), 8u) << name;
    ASSERT_TRUE(seq.groundtruth()) << name;
    const Camera& camera = seq.camera();
    std::vector<double> normalised;  // distance / sigma_z
    size_t outliers = 0, sampled = 0;
    for (size_t i = 0; i < seq.size(); ++i) {
      const RgbdFrame frame = seq.load(i);
      const auto pose = seq.groundtruth()->nearest(frame.stamp, 0.0);
      ASSERT_TRUE(pose) << name << " frame " << i << ": no pose at exactly the RGB stamp";
      const Eigen::Isometry3d& T_w_c = (*seq.groundtruth())[*pose].T_w_c;
      // Looking through long's doorway, the far room's end wall is beyond the sensor's 6 m.
      const double min_valid = preset == Preset::kLong ? 0.8 : 0.9;
      EXPECT_GT(cv::countNonZero(frame.depth) / double(frame.depth.total()), min_valid) << name;
      for (int v = 1; v < camera.height; v += 5)
        for (int u = 2; u < camera.width; u += 5) {
          const double z = frame.depth.at<float>(v, u);
          if (z == 0) continue;
          const Eigen::Vector3d p_w = T_w_c * camera.back_project(Eigen::Vector2d(u, v), z);
          const double distance = test::shared_scene(preset).distance_to_surface(p_w);
          const double sigma = SensorModel::depth_sigma(z);
          if (distance > 4 * sigma + 1 / camera.depth_scale) ++outliers;
          normalised.push_back(distance / sigma);
          ++sampled;
        }
    }
    EXPECT_LT(outliers, sampled / 100) << name << ": " << outliers << " of " << sampled;
    std::nth_element(normalised.begin(), normalised.begin() + normalised.size() / 2,
                     normalised.end());
    const double median = normalised[normalised.size() / 2];
    EXPECT_LT(median, 0.9) << name;  // |N(0,1)| has median 0.67
    EXPECT_GT(median, 0.2) << name;  // ... and the noise is really there
  }
}

TEST(SynthSequence, SameSeedGivesIdenticalFilesWhateverTheThreadCount) {
  const fs::path one = render("one_thread", Preset::kDesk, 4, 7, 1);
  const fs::path two = render("two_threads", Preset::kDesk, 4, 7, 2);
  expect_identical_folders(one, two);
  expect_identical_folders(two, one);
}

TEST(SynthSequence, OtherSeedGivesOtherNoiseAndShake) {
  const Camera camera = synthetic_camera();
  const auto poses = make_trajectory(Preset::kLoop, 10, 1);
  const SensorModel sensor;
  const RenderedFrame a = render_frame(test::shared_room(), camera, poses[3], sensor, 1, 3);
  const RenderedFrame b = render_frame(test::shared_room(), camera, poses[3], sensor, 2, 3);
  cv::Mat colour_diff, depth_diff;
  cv::absdiff(a.bgr, b.bgr, colour_diff);
  cv::absdiff(a.depth, b.depth, depth_diff);
  // Same view, other noise: most pixels differ, by a few grey levels or millimetres.
  EXPECT_GT(cv::countNonZero(colour_diff.reshape(1)), int(a.bgr.total()));
  EXPECT_LT(cv::mean(colour_diff)[0], 5.0);
  EXPECT_GT(cv::countNonZero(depth_diff), int(a.depth.total() / 2));
  // The next frame's noise is not this frame's either.
  const RenderedFrame c = render_frame(test::shared_room(), camera, poses[3], sensor, 1, 4);
  cv::absdiff(a.depth, c.depth, depth_diff);
  EXPECT_GT(cv::countNonZero(depth_diff), int(a.depth.total() / 2));
  // The hand shake depends on the seed too.
  EXPECT_FALSE(make_trajectory(Preset::kLoop, 10, 2)[3].isApprox(poses[3], 1e-9));
}

TEST(SynthSequence, LowTextureHasARunOfFeaturelessFramesWithValidDepth) {
  const int frames = 20;
  const auto poses = make_trajectory(Preset::kLowTexture, frames, 1);
  std::vector<size_t> corners;
  std::vector<double> valid;
  for (int i = 0; i < frames; ++i) {
    const RenderedFrame f =
        render_frame(test::shared_room(), synthetic_camera(), poses[i], SensorModel{}, 1, i);
    cv::Mat grey;
    cv::cvtColor(f.bgr, grey, cv::COLOR_BGR2GRAY);
    std::vector<cv::KeyPoint> keypoints;
    cv::FAST(grey, keypoints, 20);
    corners.push_back(keypoints.size());
    valid.push_back(cv::countNonZero(f.depth) / double(f.depth.total()));
  }
  EXPECT_GT(corners.front(), 1000u);  // textured before...
  EXPECT_GT(corners.back(), 1000u);   // ...and after
  int longest = 0;
  for (int i = 0, run = 0; i < frames; ++i) {
    run = corners[i] < corners.front() / 50 && valid[i] > 0.9 ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  EXPECT_GE(longest, frames / 3) << "frames with few corners and valid depth in a row";
}

TEST(SynthSequence, FilesRoundTripThroughTheProjectsReaders) {
  const int frames = 5;
  const fs::path folder = render("round_trip", Preset::kJerk, frames, 3);
  const auto poses = make_trajectory(Preset::kJerk, frames, 3);

  const TrajectoryFile gt = read_tum_trajectory(folder / "groundtruth.txt");
  EXPECT_TRUE(gt.warnings.empty());
  ASSERT_EQ(gt.trajectory.size(), size_t(frames));
  const std::vector<StampedFile> rgb = read_file_list(folder / "rgb.txt");
  const std::vector<StampedFile> depth = read_file_list(folder / "depth.txt");
  ASSERT_EQ(rgb.size(), size_t(frames));
  for (int i = 0; i < frames; ++i) {
    EXPECT_EQ(rgb[i].stamp, frame_stamp(i));
    EXPECT_EQ(depth[i].stamp, frame_stamp(i));
    EXPECT_EQ(gt.trajectory[i].stamp, frame_stamp(i));
    EXPECT_EQ(rgb[i].file, "rgb/" + frame_stamp_text(i) + ".png");
    EXPECT_EQ(gt.trajectory[i].T_w_c.translation(), poses[i].translation());  // exact
    EXPECT_TRUE(gt.trajectory[i].T_w_c.linear().isApprox(poses[i].linear(), 1e-14));
  }
  EXPECT_EQ(frame_stamp_text(0), "1600000000.000000");
  EXPECT_EQ(frame_stamp_text(1), "1600000000.033333");
  EXPECT_EQ(frame_stamp_text(30), "1600000001.000000");

  // associate.txt gives the same pairs as associating the lists.
  SequenceOptions options;
  options.calibration_file = folder / "calibration.yaml";
  options.association_file = folder / "associate.txt";
  const TumSequence listed = TumSequence::open(folder, options);
  const TumSequence associated = open_sequence(folder);
  ASSERT_EQ(listed.size(), associated.size());
  for (size_t i = 0; i < listed.size(); ++i) {
    EXPECT_EQ(listed.files(i).rgb.file, associated.files(i).rgb.file);
    EXPECT_EQ(listed.files(i).depth.file, associated.files(i).depth.file);
  }

  const Camera camera = read_camera_yaml(folder / "calibration.yaml");
  EXPECT_EQ(camera.fx, 525.0);
  EXPECT_EQ(camera.fy, 525.0);
  EXPECT_EQ(camera.cx, 319.5);
  EXPECT_EQ(camera.cy, 239.5);
  EXPECT_TRUE(camera.distortion.is_zero());
  EXPECT_EQ(camera.depth_scale, 5000.0);
}

TEST(SynthSequence, FramesDecodeAsLibpngDoes) {
  const fs::path folder = render("decode", Preset::kDesk, 4);
  size_t frames = 0;
  for (const char* kind : {"rgb", "depth"})
    for (const auto& entry : fs::directory_iterator(folder / kind)) {
      const cv::Mat ours = read_png(entry.path());
      const cv::Mat libpng = read_png_with_libpng(entry.path());
      ASSERT_EQ(ours.type(), libpng.type()) << entry.path();
      EXPECT_EQ(cv::norm(ours, libpng, cv::NORM_INF), 0) << entry.path();
      ++frames;
    }
  EXPECT_EQ(frames, 8u);
}

TEST(SynthSequence, RevisitsListTheFramesThatReturnToAPlace) {
  // Eight frames once round the loop: only the last, back on the first pose, revisits.
  const fs::path folder = render("revisits", Preset::kLoop, 8);
  std::ifstream in(folder / "revisits.txt");
  std::string line, last;
  int ranges = 0;
  while (std::getline(in, line))
    if (line[0] != '#') ++ranges, last = line;
  EXPECT_EQ(ranges, 1);
  EXPECT_EQ(last, "7 0 0 " + frame_stamp_text(7) + " " + frame_stamp_text(0) + " " +
                      frame_stamp_text(0));
}

// Lines of a list or trajectory file that are not comments.
std::vector<std::string> data_lines(const fs::path& file) {
  std::vector<std::string> lines;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  return lines;
}

// The first frames of a sequence are those of the whole one, image for image, for both sensors:
// the motion is the whole sequence's, only the rest is not rendered.
TEST(SynthSequence, TheFirstFramesAloneAreTheWholeSequencesFirstFrames) {
  for (const bool kinect : {false, true}) {
    SCOPED_TRACE(kinect ? "kinect" : "ideal");
    SequenceSpec spec;
    spec.preset = Preset::kLoop;
    spec.frames = 10;
    if (kinect) spec.kinect = KinectSettings{};
    spec.out = slamkit::test::temp_dir(kinect ? "first_whole_kinect" : "first_whole");
    write_sequence(test::shared_scene(spec.preset), spec);
    const fs::path whole = spec.out;
    spec.first_frames = 4;
    spec.out = slamkit::test::temp_dir(kinect ? "first_part_kinect" : "first_part");
    write_sequence(test::shared_scene(spec.preset), spec);
    const fs::path part = spec.out;

    const std::vector<std::string> rgb = data_lines(part / "rgb.txt");
    ASSERT_EQ(rgb.size(), 4u);
    const std::vector<std::string> all_rgb = data_lines(whole / "rgb.txt");
    EXPECT_TRUE(std::equal(rgb.begin(), rgb.end(), all_rgb.begin()));
    for (const char* list : {"depth.txt", "associate.txt", "groundtruth.txt"}) {
      const std::vector<std::string> some = data_lines(part / list), all = data_lines(whole / list);
      ASSERT_FALSE(some.empty()) << list;
      ASSERT_LT(some.size(), all.size()) << list;
      EXPECT_TRUE(std::equal(some.begin(), some.end(), all.begin())) << list;
    }
    EXPECT_EQ(data_lines(part / "associate.txt").size(), 4u);
    size_t images = 0;
    for (const char* folder : {"rgb", "depth"})
      for (const auto& entry : fs::directory_iterator(part / folder)) {
        EXPECT_TRUE(file_bytes(entry.path()) ==
                    file_bytes(whole / folder / entry.path().filename()))
            << entry.path();
        ++images;
      }
    EXPECT_EQ(images, 4 + data_lines(part / "depth.txt").size());
    // The sequence can be read and its groundtruth covers its frames.
    const TumSequence sequence = open_sequence(part);
    EXPECT_EQ(sequence.size(), 4u);
  }
}

TEST(SynthSequence, ASceneOtherThanThePresetsIsRefused) {
  SequenceSpec spec;
  spec.preset = Preset::kLong;
  spec.frames = 2;
  spec.out = slamkit::test::temp_dir("wrong_scene");
  EXPECT_THROW(write_sequence(test::shared_room(), spec), std::invalid_argument);
}

TEST(SynthSequence, BadSpecsAreInputErrorsNamingTheProblem) {
  SequenceSpec spec;
  spec.frames = 1;
  spec.out = slamkit::test::temp_dir("bad_frames");
  EXPECT_THROW(write_sequence(test::shared_room(), spec), InputError);

  // A folder cannot be created under a regular file (a permission test would not hold as root).
  const fs::path blocker = slamkit::test::temp_dir("bad_out") / "blocker";
  std::ofstream(blocker) << "not a folder";
  spec.frames = 2;
  spec.first_frames = 3;  // more than the sequence has
  spec.out = slamkit::test::temp_dir("bad_first_frames");
  try {
    write_sequence(test::shared_room(), spec);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("first frames: need 2..2"), std::string::npos)
        << e.what();
  }
  spec.first_frames = 0;
  spec.out = blocker / "sequence";
  try {
    write_sequence(test::shared_room(), spec);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(spec.out.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slamkit::synth
