#include <gtest/gtest.h>
#include <omp.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>

#include "core/error.h"
#include "datasets/synth/map_quality.h"
#include "datasets/synth/sequence_writer.h"
#include "fusion/map_fusion.h"
#include "fusion/ply_cloud.h"
#include "ply_reader.h"
#include "support/test_data.h"
#include "synth/shared_room.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;
using test::file_bytes;
using test::parse_ply;
using test::PlyFile;

// One short synthetic sequence per test process (rendering costs ~50 ms a frame a core).
constexpr int kFrames = 24;
constexpr uint64_t kSeed = 3;

// Rendered on first use, removed when the process ends (each is about 20 MB). One folder
// per process: ctest runs each test in its own process, maybe in parallel.
class RenderedSequence {
 public:
  RenderedSequence()
      : folder_(fs::temp_directory_path() / "slamkit_tests" /
                ("fusion_sequence_" + std::to_string(getpid()))) {
    synth::SequenceSpec spec;
    spec.preset = synth::Preset::kDesk;
    spec.frames = kFrames;
    spec.seed = kSeed;
    spec.out = folder_;
    fs::remove_all(folder_);
    synth::write_sequence(synth::test::shared_room(), spec);
  }
  ~RenderedSequence() {
    std::error_code ignored;
    fs::remove_all(folder_, ignored);
  }
  const fs::path& folder() const { return folder_; }

 private:
  fs::path folder_;
};

const fs::path& rendered_sequence() {
  static const RenderedSequence sequence;
  return sequence.folder();
}

const TumSequence& sequence() {
  static const TumSequence seq = TumSequence::open(rendered_sequence());
  return seq;
}

// Every `step`-th frame with its exact groundtruth pose.
std::vector<FusionFrame> groundtruth_frames(const TumSequence& seq, size_t step = 1) {
  std::vector<FusionFrame> frames;
  for (size_t i = 0; i < seq.size(); i += step) {
    const auto k = seq.groundtruth()->nearest(seq.stamp(i), 0.0);
    EXPECT_TRUE(k) << "frame " << i;
    frames.push_back({i, (*seq.groundtruth())[*k].T_w_c, nullptr});
  }
  return frames;
}

std::vector<Eigen::Isometry3d> poses_of(const std::vector<FusionFrame>& frames) {
  std::vector<Eigen::Isometry3d> poses;
  for (const FusionFrame& f : frames) poses.push_back(f.T_w_c);
  return poses;
}

TEST(MapFusion, MapPlyHasTheLayoutViewersExpectInBinaryAndAscii) {
  const fs::path dir = test::temp_dir("layout");
  FusionSettings settings;
  settings.method = MapMethod::kCentroids;
  settings.pixel_stride = 4;
  const std::vector<FusionFrame> frames = groundtruth_frames(sequence(), 4);
  const FusionReport report = fuse_map(sequence(), frames, settings, dir / "map.ply");
  settings.binary_ply = false;
  const FusionReport ascii_report = fuse_map(sequence(), frames, settings, dir / "ascii.ply");
  EXPECT_EQ(ascii_report.points, report.points);

  const PlyFile binary = parse_ply(dir / "map.ply");
  EXPECT_EQ(binary.format, "binary_little_endian");
  EXPECT_EQ(binary.vertices, report.points);
  const PlyCloud pcl_read = read_ply_cloud(dir / "map.ply");
  ASSERT_EQ(pcl_read.points.size(), binary.cloud.points.size());
  EXPECT_EQ(pcl_read.points, binary.cloud.points);
  EXPECT_EQ(pcl_read.colours, binary.cloud.colours);

  const PlyFile ascii = parse_ply(dir / "ascii.ply");
  EXPECT_EQ(ascii.format, "ascii");
  ASSERT_EQ(ascii.vertices, binary.vertices);
  for (size_t i = 0; i < ascii.vertices; ++i) {
    EXPECT_LT((ascii.cloud.points[i] - binary.cloud.points[i]).cwiseAbs().maxCoeff(), 1e-5f);
    EXPECT_EQ(ascii.cloud.colours[i], binary.cloud.colours[i]);
  }
  EXPECT_EQ(report.frames, frames.size());
  EXPECT_GT(report.raw_points, report.after_voxel_grid);
  EXPECT_GE(report.after_voxel_grid, report.points);
  EXPECT_GT(report.points, report.after_voxel_grid * 9 / 10);
}

TEST(MapFusion, SameBytesAtOneAndTwoThreads) {
  for (const MapMethod method : {MapMethod::kTsdf, MapMethod::kCentroids}) {
    const fs::path dir = test::temp_dir(method == MapMethod::kTsdf ? "threads_tsdf" : "threads");
    FusionSettings settings;
    settings.method = method;
    settings.mesh = true;  // TSDF only
    settings.batch_frames = 3;  // several batches
    settings.pixel_stride = 3;
    const std::vector<FusionFrame> frames = groundtruth_frames(sequence());
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const FusionReport one =
        fuse_map(sequence(), frames, settings, dir / "one.ply", dir / "one_mesh.ply");
    omp_set_num_threads(2);
    const FusionReport two =
        fuse_map(sequence(), frames, settings, dir / "two.ply", dir / "two_mesh.ply");
    omp_set_num_threads(threads);
    EXPECT_EQ(one.points, two.points);
    EXPECT_TRUE(file_bytes(dir / "one.ply") == file_bytes(dir / "two.ply"));
    if (method == MapMethod::kTsdf) {
      EXPECT_GT(one.triangles, one.points / 2);
      EXPECT_TRUE(file_bytes(dir / "one_mesh.ply") == file_bytes(dir / "two_mesh.ply"));
      const PlyCloud mesh = read_ply_cloud(dir / "one_mesh.ply");
      EXPECT_EQ(mesh.triangles.size(), one.triangles);
    } else {
      EXPECT_EQ(one.triangles, 0u);
      EXPECT_FALSE(fs::exists(dir / "one_mesh.ply"));
    }
  }
}

TEST(MapFusion, KeptSamplesGiveTheSameBytesAsLoadingAgain) {
  const fs::path dir = test::temp_dir("samples");
  FusionSettings settings;
  settings.pixel_stride = 3;
  std::vector<FusionFrame> frames = groundtruth_frames(sequence());
  fuse_map(sequence(), frames, settings, dir / "loaded.ply");
  for (size_t i = 0; i < frames.size(); i += 2) {  // half of them from samples, as tracking keeps
    const RgbdFrame frame = sequence().load(frames[i].index);
    frames[i].samples = std::make_shared<const FusionSamples>(
        sample_for_fusion(frame.rgb, frame.depth, settings.pixel_stride));
    EXPECT_EQ(frames[i].samples->depth.size(), size_t((640 + 2) / 3 * ((480 + 2) / 3)));
  }
  fuse_map(sequence(), frames, settings, dir / "sampled.ply");
  EXPECT_TRUE(file_bytes(dir / "loaded.ply") == file_bytes(dir / "sampled.ply"));
}

TEST(MapFusion, GroundtruthPosesGiveAnAccurateAndCompleteMap) {
  const fs::path dir = test::temp_dir("geometry");
  const FusionSettings settings;  // the defaults: stride 2, 1 cm voxels, 3 m
  const std::vector<FusionFrame> frames = groundtruth_frames(sequence());
  const FusionReport report = fuse_map(sequence(), frames, settings, dir / "map.ply");
  synth::MapQualitySettings quality_settings;
  quality_settings.frame_step = 4;
  quality_settings.max_depth = settings.max_depth;
  const synth::MapQuality q =
      synth::evaluate_map_quality(read_ply_points(dir / "map.ply"), synth::test::shared_room(),
                                  poses_of(frames), sequence().camera(), quality_settings);
  std::printf(
      "fused %zu frames in %.2f s: %zu raw points, %zu after voxel grid, %zu after "
      "outliers\naccuracy mean %.4f median %.4f p95 %.4f max %.4f m; "
      "completeness %.3f of %zu samples\n",
      report.frames, report.seconds, report.raw_points, report.after_voxel_grid,
      report.points, q.accuracy_mean, q.accuracy_median, q.accuracy_p95,
      q.accuracy_max, q.completeness, q.surface_samples);
  EXPECT_EQ(q.map_points, report.points);
  EXPECT_LT(q.accuracy_median, 0.01);
  // Most points lie far off, where single-frame depth noise is 8-14 mm (2.5-3 m).
  EXPECT_LT(q.accuracy_p95, 0.03);
  EXPECT_GT(q.completeness, 0.95);

  // Near the camera the sensor is millimetre-exact (sigma 1.2-2.4 mm up to 1.5 m): so is the
  // map, which shows that fusion adds no error of its own (pixel centres, undistortion, pose).
  FusionSettings near = settings;
  near.max_depth = quality_settings.max_depth = 1.5;
  fuse_map(sequence(), frames, near, dir / "near.ply");
  const synth::MapQuality nq =
      synth::evaluate_map_quality(read_ply_points(dir / "near.ply"), synth::test::shared_room(),
                                  poses_of(frames), sequence().camera(), quality_settings);
  EXPECT_LT(nq.accuracy_median, 0.002);
  EXPECT_LT(nq.accuracy_p95, 0.004);
  EXPECT_GT(nq.completeness, 0.95);
}

TEST(MapFusion, DepthBeyondMaxDepthIsCut) {
  const fs::path dir = test::temp_dir("max_depth");
  const std::vector<FusionFrame> frames = groundtruth_frames(sequence(), 6);
  const Camera& camera = sequence().camera();
  // The nearest depth of a world point over the fused cameras that image it (a few pixels of
  // margin: a voxel centroid may sit just outside the image of the frame it came from).
  const auto nearest_depth = [&](const Eigen::Vector3f& p) {
    double nearest = 1e9;
    for (const FusionFrame& f : frames) {
      const Eigen::Vector3d p_c = f.T_w_c.inverse() * p.cast<double>();
      const Eigen::Vector2d uv = camera.project(p_c);
      if (p_c.z() > 0 && uv.x() > -10 && uv.y() > -10 && uv.x() < camera.width + 10 &&
          uv.y() < camera.height + 10)
        nearest = std::min(nearest, p_c.z());
    }
    return nearest;
  };
  FusionSettings settings;
  settings.pixel_stride = 4;
  settings.max_depth = 8.0;
  fuse_map(sequence(), frames, settings, dir / "far.ply");
  size_t beyond = 0;
  for (const Eigen::Vector3f& p : read_ply_points(dir / "far.ply"))
    beyond += nearest_depth(p) > 1.7;
  EXPECT_GT(beyond, 1000u) << "the scene must reach beyond the cut for this test to mean much";

  settings.max_depth = 1.5;
  fuse_map(sequence(), frames, settings, dir / "near.ply");
  // A voxel centroid lies within a voxel diagonal of a point that was within the cut.
  const double limit = settings.max_depth + std::sqrt(3.0) * settings.voxel_size;
  for (const Eigen::Vector3f& p : read_ply_points(dir / "near.ply"))
    ASSERT_LE(nearest_depth(p), limit) << p.transpose();
}

TEST(MapFusion, EachVoxelIsTheMeanOfAllItsPointsWhateverTheBatches) {
  const fs::path dir = test::temp_dir("voxel_means");
  FusionSettings settings;
  settings.method = MapMethod::kCentroids;
  settings.batch_frames = 1;
  const std::vector<FusionFrame> once = groundtruth_frames(sequence());
  const FusionReport report = fuse_map(sequence(), once, settings, dir / "map.ply");
  // The same frames twice, in batches of another size: every sum doubles, so the same voxels
  // and the same means (to float rounding), which per-batch grids merged would not give.
  std::vector<FusionFrame> twice = once;
  twice.insert(twice.end(), once.begin(), once.end());
  settings.batch_frames = 5;
  const FusionReport doubled = fuse_map(sequence(), twice, settings, dir / "twice.ply");
  EXPECT_EQ(doubled.raw_points, 2 * report.raw_points);
  EXPECT_EQ(doubled.after_voxel_grid, report.after_voxel_grid);
  ASSERT_EQ(doubled.points, report.points);
  const PlyCloud a = read_ply_cloud(dir / "map.ply"), b = read_ply_cloud(dir / "twice.ply");
  for (size_t i = 0; i < a.points.size(); ++i) {
    ASSERT_LT((a.points[i] - b.points[i]).cwiseAbs().maxCoeff(), 1e-5f) << i;
    ASSERT_EQ(a.colours[i], b.colours[i]) << i;
  }
}

TEST(FuseCommand, FusesTheFramesWithAPoseAsTheLibraryDoesAndRefusesATrajectoryWithoutOne) {
  const fs::path dir = test::temp_dir("fuse_command");
  const fs::path groundtruth = rendered_sequence() / "groundtruth.txt";
  std::string output;
  ASSERT_EQ(test::run_slamkit("fuse " + rendered_sequence().string() + " --trajectory " +
                                  groundtruth.string() + " --frame-step 2 --mesh --out " +
                                  (dir / "cli").string(),
                              &output),
            0)
      << output;
  EXPECT_NE(output.find("fused map   12 frames"), std::string::npos) << output;
  // The same frames (every 2nd, each with its exact pose) through the library.
  FusionSettings settings;
  settings.mesh = true;
  const FusionReport report = fuse_map(sequence(), groundtruth_frames(sequence(), 2), settings,
                                       dir / "map.ply", dir / "mesh.ply");
  EXPECT_GT(report.triangles, 0u);
  EXPECT_TRUE(file_bytes(dir / "cli" / "map.ply") == file_bytes(dir / "map.ply"));
  EXPECT_TRUE(file_bytes(dir / "cli" / "mesh.ply") == file_bytes(dir / "mesh.ply"));

  // A trajectory that has no pose near any frame: exit 2, naming it.
  const fs::path far = dir / "far.txt";
  std::ofstream(far) << "1 0 0 0 0 0 0 1\n";
  EXPECT_EQ(test::run_slamkit("fuse " + rendered_sequence().string() + " --trajectory " +
                                  far.string() + " --out " + (dir / "none").string(),
                              &output),
            2);
  EXPECT_NE(output.find(far.string()), std::string::npos) << output;
  EXPECT_NE(output.find("no pose within"), std::string::npos) << output;
}

TEST(MapFusion, BadInputIsAnInputErrorNamingTheFile) {
  const fs::path dir = test::temp_dir("bad_input");
  const FusionSettings settings;
  const auto error_of = [&](const TumSequence& seq, const std::vector<FusionFrame>& frames,
                            const fs::path& out) -> std::string {
    try {
      fuse_map(seq, frames, settings, out);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  // A frame index out of range names the sequence.
  std::string message = error_of(sequence(), {{size_t(kFrames), {}, nullptr}}, dir / "map.ply");
  EXPECT_NE(message.find(rendered_sequence().string()), std::string::npos) << message;
  EXPECT_NE(message.find("out of range"), std::string::npos) << message;

  // An unreadable image names the image, whichever batch it is in.
  const fs::path copy = dir / "copy";
  fs::copy(rendered_sequence(), copy, fs::copy_options::recursive);
  const TumSequence damaged = TumSequence::open(copy);
  const fs::path broken = copy / damaged.files(7).depth.file;
  std::ofstream(broken, std::ios::trunc) << "not a PNG";
  message = error_of(damaged, groundtruth_frames(damaged), dir / "map.ply");
  EXPECT_NE(message.find(broken.string()), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(dir / "map.ply"));

  // An output folder that cannot be created fails before any work.
  std::ofstream(dir / "blocker") << "a file, not a folder";
  const fs::path unwritable = dir / "blocker" / "run" / "map.ply";
  message = error_of(sequence(), groundtruth_frames(sequence(), 8), unwritable);
  EXPECT_NE(message.find(unwritable.string()), std::string::npos) << message;

  FusionSettings bad = settings;
  bad.voxel_size = 0;
  EXPECT_THROW(fuse_map(sequence(), {}, bad, dir / "map.ply"), InputError);
}

TEST(CameraPoses, PlyHoldsTheCentresFromBlueToRed) {
  const fs::path dir = test::temp_dir("poses");
  const std::vector<FusionFrame> frames = groundtruth_frames(sequence(), 5);
  write_camera_poses_ply(dir / "cameras.ply", frames);
  const PlyCloud cloud = read_ply_cloud(dir / "cameras.ply");
  ASSERT_EQ(cloud.points.size(), frames.size());
  for (size_t i = 0; i < frames.size(); ++i)
    EXPECT_EQ(cloud.points[i], frames[i].T_w_c.translation().cast<float>()) << i;
  EXPECT_EQ(cloud.colours.front(), (Rgb8{0, 0, 255}));
  EXPECT_EQ(cloud.colours.back(), (Rgb8{255, 0, 0}));
}

TEST(SyntheticInfo, WrittenWithTheSequenceSoToolsCanRebuildTheScene) {
  const std::optional<synth::SyntheticInfo> info = synth::read_synthetic_info(rendered_sequence());
  ASSERT_TRUE(info);
  EXPECT_EQ(info->scene, "furnished_room");
  EXPECT_EQ(info->preset, synth::Preset::kDesk);
  EXPECT_EQ(info->frames, kFrames);
  EXPECT_EQ(info->seed, kSeed);
}

}  // namespace
}  // namespace slamkit
