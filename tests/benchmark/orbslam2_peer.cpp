#include "orbslam2_peer.h"

#include <fstream>
#include <iomanip>
#include <string>

namespace fs = std::filesystem;

namespace slamkit::bench {
namespace {

void write_settings(const TumSequence& sequence, const fs::path& path) {
  const Camera& c = sequence.camera();
  const double fps = sequence.size() > 1 && sequence.duration() > 0
                         ? (sequence.size() - 1) / sequence.duration()
                         : 30.0;
  std::ofstream out(path);
  out << std::setprecision(17) << "%YAML:1.0\n"
      << "Camera.fx: " << c.fx << "\nCamera.fy: " << c.fy << "\nCamera.cx: " << c.cx
      << "\nCamera.cy: " << c.cy << "\nCamera.k1: " << c.distortion.k1
      << "\nCamera.k2: " << c.distortion.k2 << "\nCamera.p1: " << c.distortion.p1
      << "\nCamera.p2: " << c.distortion.p2 << "\nCamera.k3: " << c.distortion.k3
      << "\nCamera.width: " << c.width << "\nCamera.height: " << c.height << "\nCamera.fps: " << fps
      << "\nCamera.bf: " << c.fx * 40.0 / 517.306408
      << "\nCamera.RGB: 1\nThDepth: 40.0\nDepthMapFactor: " << c.depth_scale
      << "\nORBextractor.nFeatures: 1000\nORBextractor.scaleFactor: 1.2\n"
         "ORBextractor.nLevels: 8\nORBextractor.iniThFAST: 20\nORBextractor.minThFAST: 7\n";
  // The viewer is off in the peers' build, but the example still reads its keys.
  out << "Viewer.KeyFrameSize: 0.05\nViewer.KeyFrameLineWidth: 1\nViewer.GraphLineWidth: 0.9\n"
         "Viewer.PointSize: 2\nViewer.CameraSize: 0.08\nViewer.CameraLineWidth: 3\n"
         "Viewer.ViewpointX: 0\nViewer.ViewpointY: -0.7\nViewer.ViewpointZ: -1.8\n"
         "Viewer.ViewpointF: 500\n";
}

void write_association(const TumSequence& sequence, const fs::path& path) {
  std::ofstream out(path);
  out << std::fixed << std::setprecision(6);
  for (size_t i = 0; i < sequence.size(); ++i) {
    const FrameFiles& f = sequence.files(i);
    out << f.rgb.stamp << ' ' << f.rgb.file << ' ' << f.depth.stamp << ' ' << f.depth.file << '\n';
  }
}

size_t count_poses(const fs::path& trajectory) {
  std::ifstream in(trajectory);
  size_t poses = 0;
  for (std::string line; std::getline(in, line);) poses += !line.empty() && line[0] != '#';
  return poses;
}

}  // namespace

PeerRun run_orbslam2(const OrbSlam2& peer, const TumSequence& sequence, const fs::path& work_dir) {
  fs::create_directories(work_dir);
  fs::remove(work_dir / "CameraTrajectory.txt");
  write_settings(sequence, work_dir / "settings.yaml");
  write_association(sequence, work_dir / "associate.txt");
  PeerRun run;
  run.usage = run_child(
      {peer.rgbd_tum.string(), peer.vocabulary.string(), (work_dir / "settings.yaml").string(),
       sequence.folder().string(), (work_dir / "associate.txt").string()},
      work_dir / "log.txt", work_dir, {"ORBSLAM2_NO_PACING=1"});
  run.poses = count_poses(work_dir / "CameraTrajectory.txt");
  return run;
}

}  // namespace slamkit::bench
