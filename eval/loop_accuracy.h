#pragma once
// How right a run's loops were, judged from files: loops.csv (the run's decisions), the
// groundtruth, and, for synthetic sequences, revisits.txt (the frames that truly return to a
// place, written by `slamkit synth`). A false loop bends the whole map, so precision is the
// number users check first; recall says whether the drift got a chance to be corrected.
#include <filesystem>
#include <optional>
#include <vector>

#include "core/trajectory.h"

namespace slamkit::eval {

struct AcceptedLoop {
  double stamp = 0;       // the keyframe that found the loop
  double loop_stamp = 0;  // the earlier keyframe it closed on
};

// The accepted rows of loops.csv. InputError naming the file (and line) for a file without
// the columns keyframe_stamp, candidate_stamp and accepted, or with a malformed row.
std::vector<AcceptedLoop> read_accepted_loops(const std::filesystem::path& loops_csv);

// A run of consecutive frames of revisits.txt: the camera back at an earlier place.
struct RevisitEpisode {
  double first_stamp = 0, last_stamp = 0;  // of the revisiting (later) frames
};

// Episodes of revisits.txt (columns later first last later_stamp first_stamp last_stamp).
std::vector<RevisitEpisode> read_revisit_episodes(const std::filesystem::path& revisits_txt);

// A loop is true when its two keyframes' groundtruth poses are within the revisit criteria of
// revisits.txt (0.5 m and 30 degrees).
struct LoopCriteria {
  double max_distance_m = 0.5;
  double max_angle_deg = 30.0;
};

struct LoopAccuracy {
  int accepted = 0;
  int true_loops = 0;
  int unjudged = 0;  // a keyframe without a groundtruth pose within 20 ms
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

}  // namespace slamkit::eval
