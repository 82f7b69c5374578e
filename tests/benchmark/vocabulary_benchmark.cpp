// Vocabulary benchmark (a target, not a test): on a sequence's frames (argument 1, e.g. one
// rendered by `slamkit synth --preset loop --frames 600`), ORB features of every 5th frame;
// training time and peak memory for k = 10, L = 5 (a generic vocabulary) and k = 10, L = 3
// (one trained on a sequence's own features); transform time per descriptor; query time per
// keyframe with every 3rd frame in the database.
//   build/tests/benchmark/slamkit_vocabulary_benchmark SEQUENCE_DIR [FRAME_STEP]
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "core/stopwatch.h"
#include "loop/keyframe_database.h"
#include "loop/training_descriptors.h"
#include "loop/vocabulary_training.h"

using namespace slamkit;

namespace {

// Peak resident memory (VmHWM) in MB; writing 5 to clear_refs restarts the peak from now.
double peak_rss_mb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kb;
      status >> kb;
      return kb / 1024;
    }
    status.ignore(256, '\n');
  }
  return 0;
}
void reset_peak_rss() { std::ofstream("/proc/self/clear_refs") << "5"; }

void report(const char* name, const std::vector<cv::Mat>& training,
            const std::vector<cv::Mat>& all_frames, int branching, int depth) {
  VocabularySettings settings;
  settings.branching = branching;
  settings.depth = depth;
  reset_peak_rss();
  const double before = peak_rss_mb();
  Stopwatch watch;
  const Vocabulary vocabulary = train_vocabulary(training, settings);
  const double train_ms = watch.lap();
  const double peak = peak_rss_mb();
  std::printf("\n%s: k %d, L %d -> %zu nodes, %zu words\n", name, branching, depth,
              vocabulary.nodes().size(), vocabulary.word_count());
  std::printf("  training %.2f s, peak memory %.1f MB (%.1f MB above the features)\n",
              train_ms / 1000, peak, peak - before);

  size_t descriptors = 0;
  std::vector<ImageBow> images;
  watch.lap();
  for (const cv::Mat& d : all_frames) {
    images.push_back(vocabulary.transform(d, settings.depth >= 2 ? 2 : 1));
    descriptors += size_t(d.rows);
  }
  const double transform_ms = watch.lap();
  std::printf("  transform %.2f us per descriptor (%zu descriptors, with the direct index)\n",
              1000 * transform_ms / double(descriptors), descriptors);

  KeyframeDatabase db;
  for (size_t i = 0; i < images.size(); i += 3) db.add(int(i), images[i].words);
  size_t queries = 0;
  watch.lap();
  for (size_t i = 1; i < images.size(); i += 3, ++queries) db.query(images[i].words);
  std::printf("  query %.3f ms per keyframe with %zu keyframes in the database\n",
              watch.lap() / double(queries), db.size());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SEQUENCE_DIR [FRAME_STEP]\n", argv[0]);
    return 2;
  }
  const int step = argc > 2 ? std::atoi(argv[2]) : 5;
  const TumSequence sequence = TumSequence::open(argv[1]);
  Stopwatch watch;
  const std::vector<cv::Mat> frames = sequence_descriptors(sequence, OrbSettings{}, 1);
  std::printf("%s: %zu frames, ORB features of all of them in %.1f s\n", argv[1], frames.size(),
              watch.lap() / 1000);
  std::vector<cv::Mat> training;
  for (size_t i = 0; i < frames.size(); i += size_t(step)) training.push_back(frames[i]);
  report("generic", training, frames, 10, 5);
  report("sequence's own", training, frames, 10, 3);
  return 0;
}
