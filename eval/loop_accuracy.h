#pragma once
// How right a run's loops were, judged from files: loops.csv (the run's decisions), the
// groundtruth, and, for synthetic sequences, revisits.txt (the frames that truly return to a
// place, written by `slamkit synth`). A loop is true when the relative pose it measured agrees
// with the groundtruth's: a false one bends the whole map, so precision is the number users
// check first; recall says whether the drift got a chance to be corrected.
#include <filesystem>
#include <optional>
#include <vector>

#include "core/trajectory.h"

namespace slamkit::eval {

struct AcceptedLoop {
  double stamp = 0;                                            // the keyframe that found the loop
  double loop_stamp = 0;                                       // the earlier keyframe it closed on
  Eigen::Isometry3d measured = Eigen::Isometry3d::Identity();  // loop keyframe in keyframe's
};

// The accepted rows of loops.csv. InputError naming the file (and line) for a file without
// the columns keyframe_stamp, candidate_stamp, tx..qw and accepted, or with a malformed row.
std::vector<AcceptedLoop> read_accepted_loops(const std::filesystem::path& loops_csv);

// A run of consecutive frames of revisits.txt: the camera back at an earlier place.
struct RevisitEpisode {
  double first_stamp = 0, last_stamp = 0;  // of the revisiting (later) frames
};

// Episodes of revisits.txt (columns later first last later_stamp first_stamp last_stamp).
std::vector<RevisitEpisode> read_revisit_episodes(const std::filesystem::path& revisits_txt);

struct LoopCriteria {
  // A loop is true when its measured relative pose is this close to the groundtruth's (a
  // look-alike place measures metres off; a true loop's error is the map's, centimetres).
  double max_error_m = 0.1;
  double max_error_deg = 5.0;
  // The same place, as revisits.txt counts it.
  double max_distance_m = 0.5;
  double max_angle_deg = 30.0;
};

// One accepted loop judged: how far its measured relative pose is from the groundtruth's.
enum class LoopVerdict { kTrue, kFalse, kUnjudged };
struct JudgedLoop {
  double stamp = 0, loop_stamp = 0;
  LoopVerdict verdict = LoopVerdict::kUnjudged;
  double error_m = 0, error_deg = 0;  // of the measured pose; 0 when unjudged
};
const char* to_string(LoopVerdict verdict);

struct LoopAccuracy {
  std::vector<JudgedLoop> loops;  // in the order of loops.csv
  int accepted = 0;
  int true_loops = 0;
  int same_place = 0;           // keyframes within max_distance_m and max_angle_deg of each other
  int unjudged = 0;             // a keyframe without a groundtruth pose within 20 ms
  std::optional<int> episodes;  // with revisits.txt only
  int episodes_found = 0;       // episodes holding a true loop's keyframe

  int false_loops() const { return accepted - true_loops - unjudged; }
  // 1 when nothing was accepted (no false loop); nullopt when nothing could be judged.
  std::optional<double> precision() const;
  std::optional<double> recall() const;
};

LoopAccuracy judge_loops(const std::vector<AcceptedLoop>& loops, const Trajectory& groundtruth,
                         const std::optional<std::vector<RevisitEpisode>>& episodes,
                         const LoopCriteria& criteria = {});

// loop_check.csv: one row per accepted loop (keyframe_stamp,loop_stamp,verdict,error_m,
// error_deg), for readers that have no groundtruth at hand (`slamkit report`).
void write_loop_check_csv(const std::filesystem::path& path, const LoopAccuracy& accuracy);

}  // namespace slamkit::eval
