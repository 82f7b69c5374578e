#include "loop/loop_pass.h"

#include <algorithm>
#include <unordered_set>

#include "core/stopwatch.h"
#include "loop/bow_matching.h"
#include "loop/keyframe_database.h"
#include "loop/loop_fusion.h"
#include "loop/vocabulary_training.h"

namespace slamkit {
namespace {

// The keyframe's features that can pair in 3D: with depth (as the query) or with a good map
// point (as the candidate).
FeatureVector usable_features(const Map& map, const Keyframe& k, const FeatureVector& nodes,
                              bool as_query) {
  std::vector<bool> keep(k.keypoints.size());
  for (size_t i = 0; i < keep.size(); ++i)
    keep[i] = as_query ? k.depths[i] > 0 : k.point_ids[i] >= 0 && !map.point(k.point_ids[i]).bad;
  return keep_features(nodes, keep);
}

class LoopDetector {
 public:
  LoopDetector(const Map& map, const Camera& camera, const Settings& settings,
               const Vocabulary& vocabulary)
      : map_(map), camera_(camera), settings_(settings), bows_(map.keyframes().size()) {
    // Every keyframe in words, once (independent: parallel, same result at any thread count).
#pragma omp parallel for schedule(dynamic, 4)
    for (long k = 0; k < long(bows_.size()); ++k)
      if (!map.keyframe(int(k)).culled)
        bows_[size_t(k)] = vocabulary.transform(map.keyframe(int(k)).descriptors,
                                                settings.vocabulary.direct_index_level);
  }

  // The decisions on keyframe k's candidates among the keyframes indexed so far; then k is
  // indexed. Returns the accepted loop, if any.
  std::optional<LoopConstraint> detect(int k, std::vector<LoopDecision>& decisions) {
    std::optional<LoopConstraint> loop;
    const LoopSettings& s = settings_.loop;
    const Keyframe& keyframe = map_.keyframe(k);
    if (k >= s.recent_keyframes && !keyframe.covisible.empty()) {
      BowQuery query;
      query.min_score = 1;
      for (int neighbour : keyframe.covisible) {
        query.exclude.insert(neighbour);
        query.min_score = std::min(
            query.min_score, l1_score(bows_[size_t(k)].words, bows_[size_t(neighbour)].words));
      }
      for (int recent = std::max(0, k - s.recent_keyframes); recent < k; ++recent)
        query.exclude.insert(recent);
      loop = judge(k, database_.query(bows_[size_t(k)].words, query), query.min_score, decisions);
    }
    database_.add(k, bows_[size_t(k)].words);
    return loop;
  }

 private:
  std::optional<LoopConstraint> judge(int k, const std::vector<BowCandidate>& candidates,
                                      double min_score, std::vector<LoopDecision>& decisions) {
    const LoopSettings& s = settings_.loop;
    std::unordered_set<int> candidate_set;
    for (const BowCandidate& c : candidates) candidate_set.insert(c.keyframe);
    int verified = 0;
    std::optional<LoopConstraint> loop;
    for (const BowCandidate& c : candidates) {  // best score first
      LoopDecision d;
      d.keyframe = k;
      d.candidate = c.keyframe;
      d.score = c.score;
      d.min_score = min_score;
      for (int neighbour : map_.best_covisible(c.keyframe, s.consistency_neighbours))
        d.consistent += int(candidate_set.count(neighbour));
      if (d.consistent < s.min_consistent_neighbours) {
        d.check.reason = "consistency: " + std::to_string(d.consistent) +
                         " neighbours, fewer than " + std::to_string(s.min_consistent_neighbours);
      } else if (loop || verified >= s.max_verified) {
        d.check.reason = loop ? "a loop was accepted already" : "not among the best verified";
      } else {
        ++verified;
        d.verified = true;
        d.check = verify_loop(map_, k, c.keyframe, matches(k, c.keyframe), camera_,
                              settings_.tracking.ransac, settings_.tracking.motion_ba, s);
        if (d.check.accepted) loop = LoopConstraint{k, c.keyframe, d.check.T_keyframe_candidate};
      }
      decisions.push_back(d);
    }
    return loop;
  }

  // Guided by the vocabulary's direct index: only features under the same node are compared.
  std::vector<KeypointPair> matches(int k, int candidate) const {
    const Keyframe& a = map_.keyframe(k);
    const Keyframe& b = map_.keyframe(candidate);
    std::vector<KeypointPair> pairs;
    for (const FeaturePair& p : match_by_nodes(
             usable_features(map_, a, bows_[size_t(k)].nodes, true), a.descriptors,
             usable_features(map_, b, bows_[size_t(candidate)].nodes, false), b.descriptors))
      pairs.push_back({p.a, p.b});
    return pairs;
  }

  const Map& map_;
  const Camera& camera_;
  const Settings& settings_;
  std::vector<ImageBow> bows_;
  KeyframeDatabase database_;
};

}  // namespace

LoopPassReport close_loops(Map& map, const Camera& camera, const Settings& settings,
                           const Vocabulary* vocabulary) {
  LoopPassReport report;
  const LoopSettings& s = settings.loop;
  report.keyframes = int(map.keyframes().size());
  if (!s.enabled || (!vocabulary && !s.train_on_sequence) || report.keyframes <= s.recent_keyframes)
    return report;
  report.ran = true;
  Stopwatch watch;
  Vocabulary trained;
  if (!vocabulary) {
    std::vector<cv::Mat> images;
    int active = 0;
    for (const Keyframe& k : map.keyframes())
      if (!k.culled && active++ % s.training_keyframe_step == 0)
        images.push_back(k.descriptors);
    trained = train_vocabulary(images, settings.vocabulary);
    vocabulary = &trained;
  }
  report.vocabulary_words = vocabulary->word_count();
  report.vocabulary_seconds = watch.lap() / 1000.0;

  LoopDetector detector(map, camera, settings, *vocabulary);
  for (int k = 0; k < report.keyframes; ++k) {
    if (map.keyframe(k).culled) continue;  // redundant: its neighbours stand for it
    if (const auto loop = detector.detect(k, report.decisions)) report.loops.push_back(*loop);
  }
  report.detection_seconds = watch.lap() / 1000.0;

  double largest_gap = 0;
  for (const LoopDecision& d : report.decisions)
    if (d.check.accepted) largest_gap = std::max(largest_gap, d.check.pose_error);
  if (!report.loops.empty() && largest_gap >= s.min_correction) {
    report.correction =
        correct_loops(map, report.loops, {s.essential_min_weight, s.correction_iterations});
    if (s.fuse_points) report.fused_points = fuse_loop_points(map, report.loops, camera, settings);
  }
  report.correction_seconds = watch.lap() / 1000.0;
  return report;
}

}  // namespace slamkit
