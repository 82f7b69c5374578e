#pragma once
// ORB-SLAM2's RGB-D example (`rgbd_tum`, built outside the project: see docs/performance.md) on
// the same frames as slamkit, for the benchmark's ratios. Its settings file is written from the
// sequence's camera in the layout of ORB-SLAM2's TUM1.yaml, with its TUM defaults (1000
// features, 8 levels of 1.2, FAST 20/7, bf 40 at fx 517.3 and ThDepth 40: the close/far split at
// 3.1 m), and the association from slamkit's own, so both see the same frame pairs.
#include <filesystem>
#include <string>

#include "child_process.h"
#include "io/tum_sequence.h"

namespace slamkit::bench {

struct OrbSlam2 {
  std::filesystem::path rgbd_tum;    // the example's binary
  std::filesystem::path vocabulary;  // ORBvoc.txt or a stand-in
};

struct PeerRun {
  ChildUsage usage;
  size_t poses = 0;  // frames it tracked (lost frames are left out of its trajectory)
};

// Runs it once in `work_dir` (created; settings.yaml, associate.txt, its trajectories and
// log.txt go there) with the real-time pacing off (ORBSLAM2_NO_PACING, as the peers' build
// patches it).
PeerRun run_orbslam2(const OrbSlam2& peer, const TumSequence& sequence,
                     const std::filesystem::path& work_dir);

}  // namespace slamkit::bench
