#pragma once
// The inverted index of keyframes by word (docs/method.md#loop-closing): which keyframes look
// like a query image, for loop detection and relocalisation.
//
// Detection on top of it (ORB-SLAM2's DetectLoopCandidates) queries with the current keyframe,
// excluding its covisible neighbours and recent keyframes, sets min_score to the lowest score
// of those neighbours, then judges the candidates' shared_words and their neighbours' scores.
#include <cstddef>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "loop/bow_vector.h"

namespace slamkit {

struct BowCandidate {
  int keyframe;
  double score;      // l1_score() with the query
  int shared_words;  // words the keyframe has in common with the query
};

struct BowQuery {
  std::unordered_set<int> exclude;  // keyframes never returned (e.g. covisible, recent)
  double min_score = 0;             // candidates scoring below are dropped
  size_t max_results = 0;           // the best ones only; 0 = all
};

class KeyframeDatabase {
 public:
  // Indexes the keyframe under each of its words; a keyframe added again replaces itself.
  void add(int keyframe, const BowVector& words);
  void erase(int keyframe);  // e.g. a culled keyframe; unknown ids are ignored
  bool contains(int keyframe) const { return vectors_.count(keyframe) > 0; }
  size_t size() const { return vectors_.size(); }

  // Every indexed keyframe sharing at least one word with `words` and not excluded, best score
  // first (ties by keyframe id, so results repeat exactly).
  std::vector<BowCandidate> query(const BowVector& words, const BowQuery& options = {}) const;

 private:
  struct Posting {
    int keyframe;
    double weight;
  };
  std::vector<std::vector<Posting>> postings_;  // indexed by word
  std::unordered_map<int, BowVector> vectors_;
};

}  // namespace slamkit
