#pragma once
// Pairs estimated poses with groundtruth poses by timestamp.
//   tum: the benchmark's associate.py (core/association.h): candidates with
//        |t_gt - (t_est + offset)| < max_diff, taken greedily by smallest difference, each
//        pose used at most once.
//   evo: evo's sync.associate_trajectories: each pose of the trajectory with fewer poses (the
//        estimate when both have as many) takes the nearest pose of the other (the earlier on
//        a tie) if |difference| <= max_diff; a pose of the longer one may serve twice.
#include <string>
#include <vector>

#include "core/association.h"
#include "core/trajectory.h"

namespace slamkit::eval {

enum class AssociationMethod { kTum, kEvo };

// The default tolerances: associate.py's --max_difference and evo's --t_max_diff.
constexpr double kTumMaxDiff = 0.02;
constexpr double kEvoMaxDiff = 0.01;

struct AssociationOptions {
  AssociationMethod method = AssociationMethod::kTum;
  double max_diff = kTumMaxDiff;  // seconds
  double offset = 0.0;            // added to estimate stamps (the benchmark's --offset)
};

// IndexPair::first indexes `gt`, ::second indexes `est`; sorted by estimate index (then by
// groundtruth index).
std::vector<IndexPair> associate(const Trajectory& gt, const Trajectory& est,
                                 const AssociationOptions& options);

// Throws InputError naming the estimate when the stamps crowd together so that the benchmark's
// association would take quadratic time and memory (core/association.h: too_crowded_to_associate).
void require_associable(const Trajectory& gt, const Trajectory& est, const std::string& gt_name,
                        const std::string& est_name, const AssociationOptions& options);

// Throws InputError when fewer than 2 pairs matched, saying how many poses each file has,
// their time ranges and the tolerance used.
void require_enough_pairs(size_t pair_count, const Trajectory& gt, const Trajectory& est,
                          const std::string& gt_name, const std::string& est_name,
                          const AssociationOptions& options);

std::string to_string(AssociationMethod method);
AssociationMethod parse_association_method(const std::string& text);  // "tum" or "evo"

}  // namespace slamkit::eval
