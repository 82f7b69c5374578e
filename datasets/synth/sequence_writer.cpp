#include "datasets/synth/sequence_writer.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "core/error.h"
#include "core/trajectory.h"
#include "datasets/synth/kinect_renderer.h"
#include "datasets/synth/map_quality.h"
#include "datasets/synth/renderer.h"
#include "datasets/synth/revisits.h"
#include "datasets/synth/sensor_streams.h"
#include "io/camera_yaml.h"
#include "io/png_file.h"
#include "io/trajectory_io.h"

namespace fs = std::filesystem;

namespace slamkit::synth {
namespace {

constexpr int64_t kFirstStampMicroseconds = 1600000000LL * 1000000LL;

int64_t stamp_microseconds(int i) {
  return kFirstStampMicroseconds + std::llround(i * 1e6 / kFrameRate);
}

std::string describe(const SequenceSpec& spec) {
  return "slamkit synth --preset " + preset_name(spec.preset) + " --frames " +
         std::to_string(spec.frames) + " --seed " + std::to_string(spec.seed) +
         (spec.kinect ? " --sensor kinect (settings in synthetic.yaml)" : "") +
         (spec.first_frames > 0 ? ", its first " + std::to_string(spec.first_frames) + " frames"
                                : "");
}

// How many of the frames are written (SequenceSpec::first_frames).
int written_frames(const SequenceSpec& spec) {
  return spec.first_frames > 0 ? spec.first_frames : spec.frames;
}

// The streams up to colour frame k - 1: the depth frames paired with those, and groundtruth up
// to the last of either (its first stamp at or past it included).
void keep_first_frames(StreamStamps& s, int k) {
  if (k >= int(s.colour.size())) return;
  s.colour.resize(size_t(k));
  size_t depth_end = 0;
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [c, d] : s.pairs)
    if (c < k) {
      pairs.emplace_back(c, d);
      depth_end = std::max(depth_end, size_t(d) + 1);
    }
  s.pairs = pairs;
  s.depth.resize(std::min(depth_end, s.depth.size()));
  const int64_t end = std::max(s.colour.back(), s.depth.empty() ? s.colour.back() : s.depth.back());
  const auto past = std::lower_bound(s.groundtruth.begin(), s.groundtruth.end(), end);
  s.groundtruth.erase(past == s.groundtruth.end() ? past : past + 1, s.groundtruth.end());
}

void create_folder(const fs::path& folder) {
  std::error_code error;
  fs::create_directories(folder, error);
  if (error || !fs::is_directory(folder))
    throw_input_error(folder.string(),
                      "cannot create output folder: " + (error ? error.message() : "not a folder"));
}

std::ofstream open_for_writing(const fs::path& path) {
  std::ofstream out(path);
  if (!out) throw_input_error(path.string(), "cannot write file");
  return out;
}

void close_written(std::ofstream& out, const fs::path& path) {
  if (!out.flush()) throw_input_error(path.string(), "write failed");
}

// rgb.txt and depth.txt, headed as TUM's, and associate.txt: open, closed by close().
struct ListFiles {
  explicit ListFiles(const SequenceSpec& spec)
      : folder(spec.out),
        rgb(open_for_writing(folder / "rgb.txt")),
        depth(open_for_writing(folder / "depth.txt")),
        assoc(open_for_writing(folder / "associate.txt")) {
    rgb << "# color images\n# file: '" << describe(spec) << "'\n# timestamp filename\n";
    depth << "# depth maps\n# file: '" << describe(spec) << "'\n# timestamp filename\n";
  }
  void close() {
    close_written(rgb, folder / "rgb.txt");
    close_written(depth, folder / "depth.txt");
    close_written(assoc, folder / "associate.txt");
  }
  fs::path folder;
  std::ofstream rgb, depth, assoc;
};

void write_lists(const SequenceSpec& spec) {
  ListFiles lists(spec);
  for (int i = 0; i < written_frames(spec); ++i) {
    // Depth shares the colour stamp: the images are rendered from the same pose.
    const std::string stamp = frame_stamp_text(i);
    lists.rgb << stamp << " rgb/" << stamp << ".png\n";
    lists.depth << stamp << " depth/" << stamp << ".png\n";
    lists.assoc << stamp << " rgb/" << stamp << ".png " << stamp << " depth/" << stamp << ".png\n";
  }
  lists.close();
}

void write_revisits(const fs::path& path, const std::vector<Eigen::Isometry3d>& poses) {
  const RevisitCriteria criteria;
  std::ofstream out = open_for_writing(path);
  out << "# true revisits (groundtruth): frame `later` is within " << criteria.max_distance_m
      << " m and " << criteria.max_angle_deg << " deg of each of frames first..last, having been\n"
      << "# more than " << criteria.min_excursion_m << " m from it in between\n"
      << "# later first last later_stamp first_stamp last_stamp\n";
  for (const RevisitRange& r : true_revisits(poses, criteria))
    out << r.later << ' ' << r.first << ' ' << r.last << ' ' << frame_stamp_text(r.later) << ' '
        << frame_stamp_text(r.first) << ' ' << frame_stamp_text(r.last) << '\n';
  close_written(out, path);
}

// The kinect sensor's lists: rgb.txt and depth.txt with their own stamps, associate.txt as
// associate.py would pair them.
void write_stream_lists(const SequenceSpec& spec, const StreamStamps& stamps) {
  ListFiles lists(spec);
  for (int64_t us : stamps.colour)
    lists.rgb << stamp_text(us) << " rgb/" << stamp_text(us) << ".png\n";
  for (int64_t us : stamps.depth)
    lists.depth << stamp_text(us) << " depth/" << stamp_text(us) << ".png\n";
  for (const auto& [c, d] : stamps.pairs) {
    const std::string rgb_stamp = stamp_text(stamps.colour[c]);
    const std::string depth_stamp = stamp_text(stamps.depth[d]);
    lists.assoc << rgb_stamp << " rgb/" << rgb_stamp << ".png " << depth_stamp << " depth/"
                << depth_stamp << ".png\n";
  }
  lists.close();
}

// Renders colour and depth frames (colour first, then depth, as one parallel loop); returns
// the first file that could not be written, or "".
std::string render_kinect_frames(const SyntheticScene& scene, const SequenceSpec& spec,
                                 const ContinuousTrajectory& trajectory, const StreamStamps& stamps,
                                 const std::function<void(size_t)>& on_progress) {
  const KinectSettings& settings = *spec.kinect;
  const Camera camera = synthetic_camera();
  const std::vector<Eigen::Vector3d> rays = colour_pixel_rays(camera, settings);
  const PoseAt pose_at = [&trajectory](double t) { return trajectory.pose(t); };
  const int colour_frames = int(stamps.colour.size());
  const int jobs = colour_frames + int(stamps.depth.size());
  std::atomic<size_t> done{0};
  std::string failed;
  const int threads = spec.threads > 0 ? spec.threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int job = 0; job < jobs; ++job) {
    const bool colour = job < colour_frames;
    const int i = colour ? job : job - colour_frames;
    const int64_t us = colour ? stamps.colour[i] : stamps.depth[i];
    const double t = us / 1e6;
    const fs::path path = spec.out / (colour ? "rgb" : "depth") / (stamp_text(us) + ".png");
    try {  // exceptions must not escape an OpenMP region
      if (colour) {
        write_png(path, render_kinect_colour(scene, camera, rays, pose_at, settings, spec.seed,
                                             uint64_t(i), t));
      } else {
        const Eigen::Isometry3d T_w_d = depth_camera_pose(trajectory.pose(t), settings);
        write_png(path,
                  render_kinect_depth(scene, camera, T_w_d, settings, spec.seed, uint64_t(i)));
      }
    } catch (const InputError& e) {
#pragma omp critical(synth_failed)
      if (failed.empty()) failed = e.what();
    }
    // Progress counts colour frames' worth of work: a depth frame is about half one.
    ++done;
    if (on_progress && omp_get_thread_num() == 0)
      on_progress(size_t(done) * size_t(spec.frames) / size_t(jobs));
  }
  if (on_progress) on_progress(size_t(spec.frames));
  return failed;
}

void write_kinect_sequence(const SyntheticScene& scene, const SequenceSpec& spec,
                           const std::function<void(size_t)>& on_progress) {
  const KinectSettings& settings = *spec.kinect;
  const ContinuousTrajectory trajectory(spec.preset, spec.frames, spec.seed);
  StreamStamps stamps = make_stream_stamps(settings, spec.frames, spec.seed);
  keep_first_frames(stamps, written_frames(spec));
  const std::string failed = render_kinect_frames(scene, spec, trajectory, stamps, on_progress);
  if (!failed.empty()) throw InputError(failed);

  write_stream_lists(spec, stamps);
  Trajectory groundtruth;
  for (int64_t us : stamps.groundtruth)
    groundtruth.push_back(stamp_seconds(us), trajectory.pose(us / 1e6));
  write_tum_trajectory(spec.out / "groundtruth.txt", groundtruth,
                       "ground truth trajectory (exact, T_w_c of the colour camera)\n# file: '" +
                           describe(spec) + "'");
  std::vector<Eigen::Isometry3d> frame_poses;
  for (int64_t us : stamps.colour) frame_poses.push_back(trajectory.pose(us / 1e6));
  write_revisits(spec.out / "revisits.txt", frame_poses);
  write_camera_yaml(spec.out / "calibration.yaml",
                    kinect_colour_camera(synthetic_camera(), settings));
  write_synthetic_info(spec.out, spec);
}

}  // namespace

Camera synthetic_camera() {
  Camera camera;
  camera.name = "slamkit_synth";
  camera.fx = camera.fy = 525.0;
  camera.cx = 319.5;
  camera.cy = 239.5;
  camera.width = 640;
  camera.height = 480;
  camera.depth_scale = 5000.0;
  return camera;
}

std::string frame_stamp_text(int i) {
  const int64_t us = stamp_microseconds(i);
  char text[32];
  std::snprintf(text, sizeof text, "%" PRId64 ".%06" PRId64, us / 1000000, us % 1000000);
  return text;
}

// Integer microseconds divided once: the correctly rounded quotient is the double nearest to
// the decimal text, which is what strtod gives when the lists are read back.
double frame_stamp(int i) { return double(stamp_microseconds(i)) / 1e6; }

void check_spec(const SequenceSpec& spec) {
  if (spec.frames < 2)
    throw InputError("--frames: need at least 2 frames, got " + std::to_string(spec.frames));
  if (spec.threads < 0)
    throw InputError("--threads: must be 0 (default) or positive, got " +
                     std::to_string(spec.threads));
  if (spec.first_frames != 0 && (spec.first_frames < 2 || spec.first_frames > spec.frames))
    throw InputError("first frames: need 2.." + std::to_string(spec.frames) + " (or 0: all), got " +
                     std::to_string(spec.first_frames));
  if (spec.kinect) check_kinect_settings(*spec.kinect);
}

void write_sequence(const SyntheticScene& scene, const SequenceSpec& spec,
                    const std::function<void(size_t)>& on_progress) {
  check_spec(spec);
  if (scene.description().name != preset_scene(spec.preset))
    throw std::invalid_argument("write_sequence: preset " + preset_name(spec.preset) + " films " +
                                preset_scene(spec.preset) + ", not " + scene.description().name);
  create_folder(spec.out / "rgb");
  create_folder(spec.out / "depth");
  if (spec.kinect) return write_kinect_sequence(scene, spec, on_progress);
  std::vector<Eigen::Isometry3d> poses = make_trajectory(spec.preset, spec.frames, spec.seed);
  poses.resize(size_t(written_frames(spec)));
  const Camera camera = synthetic_camera();

  std::atomic<size_t> done{0};
  std::string failed;  // the first file that could not be written
  const int threads = spec.threads > 0 ? spec.threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int i = 0; i < int(poses.size()); ++i) {
    const RenderedFrame frame = render_frame(scene, camera, poses[i], spec.sensor, spec.seed, i);
    const std::string name = frame_stamp_text(i) + ".png";
    const fs::path rgb = spec.out / "rgb" / name, depth = spec.out / "depth" / name;
    // Fast PNG compression (write_png's level 1, run-length): at the default level writing
    // costs more than rendering, and sensor noise leaves deflate few long matches anyway.
    try {  // exceptions must not escape an OpenMP region
      write_png(rgb, frame.bgr);
      write_png(depth, frame.depth);
    } catch (const InputError& e) {
#pragma omp critical(synth_failed)
      if (failed.empty()) failed = e.what();
    }
    ++done;
    if (on_progress && omp_get_thread_num() == 0) on_progress(done);
  }
  if (!failed.empty()) throw InputError(failed);
  if (on_progress) on_progress(done);

  write_lists(spec);
  Trajectory groundtruth;
  for (int i = 0; i < int(poses.size()); ++i) groundtruth.push_back(frame_stamp(i), poses[i]);
  write_tum_trajectory(spec.out / "groundtruth.txt", groundtruth,
                       "ground truth trajectory (exact, T_w_c)\n# file: '" + describe(spec) + "'");
  write_revisits(spec.out / "revisits.txt", poses);
  write_camera_yaml(spec.out / "calibration.yaml", camera);
  write_synthetic_info(spec.out, spec);  // lets tools (map-eval) rebuild the scene
}

}  // namespace slamkit::synth
