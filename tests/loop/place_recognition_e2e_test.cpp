// Place recognition end to end: ORB features of real and synthetic frames, a vocabulary
// trained on them, a keyframe database; the image of the same place must score highest.
#include <gtest/gtest.h>

#include <cmath>

#include "io/tum_sequence.h"
#include "loop/keyframe_database.h"
#include "loop/training_descriptors.h"
#include "loop/vocabulary_training.h"
#include "support/synthetic_sequence.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

// A vocabulary small enough to train on one sequence's own features.
Vocabulary sequence_vocabulary(const std::vector<cv::Mat>& images) {
  VocabularySettings settings;
  settings.branching = 10;
  settings.depth = 3;
  return train_vocabulary(images, settings);
}

Eigen::Isometry3d true_pose(const TumSequence& seq, size_t frame) {
  const auto i = seq.groundtruth()->nearest(seq.stamp(frame), 0.02);
  EXPECT_TRUE(i.has_value());
  return seq.groundtruth()->pose(*i);
}

// Revisit as the loop check counts it: within 0.5 m and 30 degrees.
bool same_place(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::Isometry3d d = a.inverse() * b;
  return d.translation().norm() < 0.5 && Eigen::AngleAxisd(d.rotation()).angle() < M_PI / 6;
}

TEST(PlaceRecognition, SyntheticLoopEndFindsItsStart) {
  const int frames = 150;
  const TumSequence seq = TumSequence::open(test::synthetic_sequence(synth::Preset::kLoop, frames));
  const std::vector<cv::Mat> descriptors = sequence_descriptors(seq, OrbSettings{}, 1);
  std::vector<cv::Mat> every_fifth;
  for (int i = 0; i < frames; i += 5) every_fifth.push_back(descriptors[i]);
  const Vocabulary vocabulary = sequence_vocabulary(every_fifth);

  KeyframeDatabase db;
  for (int i = 0; i < frames; i += 5) db.add(i, vocabulary.transform(descriptors[i], 2).words);

  // Mid-sequence frames: the nearest keyframes in time are the same place.
  for (int query : {12, 53, 77, 101}) {
    const auto candidates = db.query(vocabulary.transform(descriptors[query], 2).words);
    ASSERT_FALSE(candidates.empty());
    EXPECT_TRUE(candidates[0].keyframe == query / 5 * 5 ||
                candidates[0].keyframe == query / 5 * 5 + 5)
        << "query " << query << " best " << candidates[0].keyframe;
  }
  // The loop: the last frames, with the recent keyframes excluded (as loop detection does),
  // find the keyframes at the start, where the camera was.
  BowQuery old_only;
  for (int i = 100; i < frames; i += 5) old_only.exclude.insert(i);
  // (The preset swings the yaw: 142 is still 32 degrees from the start, 146 and 149 within 15.)
  for (int query : {146, 149}) {
    const auto candidates = db.query(vocabulary.transform(descriptors[query], 2).words, old_only);
    ASSERT_FALSE(candidates.empty());
    EXPECT_TRUE(same_place(true_pose(seq, query), true_pose(seq, candidates[0].keyframe)))
        << "query " << query << " best " << candidates[0].keyframe << " score "
        << candidates[0].score;
  }
}

TEST(PlaceRecognition, RealFramesScoreTheirOwnPlaceHighest) {
  SLAMKIT_REQUIRE_DATA(fr2, "rgbd_dataset_freiburg2_desk_first50");
  SLAMKIT_REQUIRE_DATA(fr1, "rgbd_dataset_freiburg1_desk_9frames");
  const TumSequence seq2 = TumSequence::open(fr2);
  const TumSequence seq1 = TumSequence::open(fr1);
  const std::vector<cv::Mat> d2 = sequence_descriptors(seq2, OrbSettings{}, 1);
  const std::vector<cv::Mat> d1 = sequence_descriptors(seq1, OrbSettings{}, 1);
  std::vector<cv::Mat> training = d2;
  training.insert(training.end(), d1.begin(), d1.end());
  const Vocabulary vocabulary = sequence_vocabulary(training);

  // Keyframes: fr2 every 10th frame (ids 0..40), fr1 every 4th (ids 1000 + 0, 4, 8).
  KeyframeDatabase db;
  for (size_t i = 0; i < d2.size(); i += 10) db.add(int(i), vocabulary.transform(d2[i], 2).words);
  for (size_t i = 0; i < d1.size(); i += 4)
    db.add(1000 + int(i), vocabulary.transform(d1[i], 2).words);

  auto expect_bracketing = [&](const cv::Mat& frame, int id, int step) {
    const auto candidates = db.query(vocabulary.transform(frame, 2).words);
    ASSERT_FALSE(candidates.empty());
    const int best = candidates[0].keyframe;
    EXPECT_TRUE(best == id / step * step || best == id / step * step + step)
        << "frame " << id << " best " << best << " score " << candidates[0].score;
  };
  for (size_t i = 0; i < d2.size(); ++i)
    if (i % 10 != 0) expect_bracketing(d2[i], int(i), 10);
  for (size_t i = 0; i < d1.size(); ++i)
    if (i % 4 != 0) expect_bracketing(d1[i], 1000 + int(i), 4);
}

}  // namespace
}  // namespace slamkit
