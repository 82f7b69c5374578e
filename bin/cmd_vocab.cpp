// slamkit vocab train SEQ... --out FILE: a bag-of-words vocabulary from the ORB features of
// sequences' frames (docs/method.md#loop-closing); slamkit vocab info FILE: what a vocabulary
// file holds.
#include <omp.h>

#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>

#include "bin/command.h"
#include "bin/output_folder.h"
#include "bin/sequence_options.h"
#include "core/stopwatch.h"
#include "settings/settings_yaml.h"
#include "loop/training_descriptors.h"
#include "loop/vocabulary_file.h"
#include "loop/vocabulary_training.h"

namespace slamkit::cli {
namespace {

struct TrainArgs {
  std::vector<std::string> folders;
  std::string out;
  std::string settings_file;
  std::optional<int> branching, depth, frame_step;
  int threads = -1;
  bool allow_out_in_sequence = false;
  SequenceOptions sequence;
};

void print_vocabulary(const Vocabulary& v) {
  int deepest = 0;
  for (size_t n = 0; n < v.nodes().size(); ++n) deepest = std::max(deepest, v.level(NodeId(n)));
  size_t zero_weight = 0;
  for (WordId w = 0; w < v.word_count(); ++w) zero_weight += v.weight(w) == 0;
  std::printf("tree        k %d, L %d (deepest leaf at level %d)\n", v.branching(), v.depth(),
              deepest);
  std::printf("nodes       %zu, of which %zu words (%zu with weight 0: in every training image)\n",
              v.nodes().size(), v.word_count(), zero_weight);
}

void train(const TrainArgs& args) {
  check_output_file("--out", args.out);
  check_output_outside_sequences("--out", args.out, args.folders, args.allow_out_in_sequence);
  Settings settings;
  if (!args.settings_file.empty()) read_settings_yaml(args.settings_file, settings);
  VocabularySettings& vs = settings.vocabulary;
  if (args.branching) vs.branching = *args.branching;
  if (args.depth) vs.depth = *args.depth;
  if (args.frame_step) vs.frame_step = *args.frame_step;
  if (args.threads >= 0) settings.pipeline.threads = args.threads;
  if (settings.pipeline.threads > 0) omp_set_num_threads(settings.pipeline.threads);

  Stopwatch watch;
  std::vector<cv::Mat> images;
  size_t descriptors = 0;
  for (const std::string& folder : args.folders) {
    const TumSequence seq = TumSequence::open(folder, args.sequence);
    for (cv::Mat& d : sequence_descriptors(seq, settings.orb, vs.frame_step)) {
      descriptors += size_t(d.rows);
      images.push_back(std::move(d));
    }
  }
  const double extract_ms = watch.lap();
  const Vocabulary vocabulary = train_vocabulary(images, vs);
  const double train_ms = watch.lap();
  save_vocabulary(args.out, vocabulary);
  std::printf("training    %zu images (every %d-th frame of %zu sequences), %zu descriptors\n",
              images.size(), vs.frame_step, args.folders.size(), descriptors);
  print_vocabulary(vocabulary);
  std::printf("time        %.2f s extraction, %.2f s training\n", extract_ms / 1000,
              train_ms / 1000);
  std::printf("output      %s (%ju bytes)\n", args.out.c_str(),
              std::uintmax_t(std::filesystem::file_size(args.out)));
}

void info(const std::string& file) {
  Stopwatch watch;
  const Vocabulary vocabulary = load_vocabulary(file);
  std::printf("vocabulary  %s (loaded in %.2f s)\n", file.c_str(), watch.lap() / 1000);
  print_vocabulary(vocabulary);
}

const bool kRegistered = register_command([](CLI::App& root) {
  CLI::App* vocab = root.add_subcommand("vocab", "Bag-of-words vocabularies for loop closing");
  vocab->require_subcommand(1);

  auto args = std::make_shared<TrainArgs>();
  CLI::App* train_cmd = vocab->add_subcommand(
      "train", "Train a vocabulary on the ORB features of sequences' frames");
  train_cmd->add_option("sequences", args->folders, "Sequence folders (TUM layout)")->required();
  train_cmd->add_option("--out", args->out, "Vocabulary file to write (binary)")->required();
  train_cmd->add_option("--settings", args->settings_file,
                        "Settings YAML (orb and vocabulary sections, over the built-in defaults)");
  // The ranges are those of the vocabulary settings (io/settings_fields.h).
  train_cmd->add_option("-k,--branching", args->branching, "Children per node (default 10)")
      ->check(CLI::Range(2, 255));
  train_cmd->add_option("-L,--depth", args->depth, "Levels below the root (default 5)")
      ->check(CLI::Range(1, 10));
  train_cmd->add_option("--frame-step", args->frame_step, "Use every n-th frame (default 5)")
      ->check(CLI::Range(1, 100000));
  train_cmd->add_option("--threads", args->threads, "Threads (0 = all cores)")
      ->check(CLI::Range(0, std::numeric_limits<int>::max()));
  add_sequence_options(train_cmd, args->sequence);
  add_allow_out_in_sequence_flag(train_cmd, args->allow_out_in_sequence);
  train_cmd->callback([args] { train(*args); });

  auto file = std::make_shared<std::string>();
  CLI::App* info_cmd = vocab->add_subcommand(
      "info", "Summarise a vocabulary file (ours, or ORB-SLAM2's ORBvoc.txt)");
  info_cmd->add_option("file", *file, "Vocabulary file")->required();
  info_cmd->callback([file] { info(*file); });
});

}  // namespace
}  // namespace slamkit::cli
