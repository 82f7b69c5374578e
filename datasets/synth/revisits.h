#pragma once
// Which frames truly revisit a place, from groundtruth alone: the yardstick for loop
// detection's precision and recall. Frame j revisits frame i (i < j) when the camera is back
// within max_distance_m and max_angle_deg of pose i after having been farther than
// min_excursion_m from it in between (so hovering in one place is not a revisit).
#include <Eigen/Geometry>
#include <vector>

namespace slamkit::synth {

struct RevisitCriteria {
  double max_distance_m = 0.5;
  double max_angle_deg = 30.0;
  double min_excursion_m = 1.0;
};

// Frame `later` revisits frames first..last (inclusive, first <= last < later), all of them.
struct RevisitRange {
  int later = 0, first = 0, last = 0;
  bool operator==(const RevisitRange& o) const {
    return later == o.later && first == o.first && last == o.last;
  }
};

// Every revisit, as ranges of earlier frames per later frame, ordered by (later, first).
// O(frames^2) distance tests: about 0.05 s for 2,000 poses.
std::vector<RevisitRange> true_revisits(const std::vector<Eigen::Isometry3d>& T_w_c,
                                        const RevisitCriteria& criteria = {});

}  // namespace slamkit::synth
