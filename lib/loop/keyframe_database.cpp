#include "loop/keyframe_database.h"

#include <algorithm>

namespace slamkit {

void KeyframeDatabase::add(int keyframe, const BowVector& words) {
  erase(keyframe);
  vectors_[keyframe] = words;
  for (const BowEntry& e : words) {
    if (e.word >= postings_.size()) postings_.resize(e.word + 1);
    postings_[e.word].push_back({keyframe, e.weight});
  }
}

void KeyframeDatabase::erase(int keyframe) {
  const auto found = vectors_.find(keyframe);
  if (found == vectors_.end()) return;
  for (const BowEntry& e : found->second) {
    auto& list = postings_[e.word];
    list.erase(std::remove_if(list.begin(), list.end(),
                              [&](const Posting& p) { return p.keyframe == keyframe; }),
               list.end());
  }
  vectors_.erase(found);
}

std::vector<BowCandidate> KeyframeDatabase::query(const BowVector& words,
                                                  const BowQuery& options) const {
  // For L1-normalised vectors of positive weights, 1 - 0.5 |a - b|_1 equals the sum over the
  // shared words of min(a_w, b_w): the words only one side has add nothing, so the postings of
  // the query's words are all the score needs.
  std::unordered_map<int, BowCandidate> scored;
  for (const BowEntry& q : words) {
    if (q.word >= postings_.size()) continue;
    for (const Posting& p : postings_[q.word]) {
      if (options.exclude.count(p.keyframe)) continue;
      BowCandidate& c = scored.try_emplace(p.keyframe, BowCandidate{p.keyframe, 0, 0}).first->second;
      c.score += std::min(q.weight, p.weight);
      ++c.shared_words;
    }
  }
  std::vector<BowCandidate> candidates;
  for (const auto& [keyframe, c] : scored)
    if (c.score >= options.min_score) candidates.push_back(c);
  std::sort(candidates.begin(), candidates.end(), [](const BowCandidate& a, const BowCandidate& b) {
    return a.score != b.score ? a.score > b.score : a.keyframe < b.keyframe;
  });
  if (options.max_results > 0 && candidates.size() > options.max_results)
    candidates.resize(options.max_results);
  return candidates;
}

}  // namespace slamkit
