// The PNG decode benchmark (a target, not a test): every decoder of png_candidates.h on the
// real frames under $SLAMKIT_DATA (each sequence's rgb/ and depth/) and on a synthetic desk
// sequence rendered for the run. Prints ms per colour and per depth frame on one core (the
// median of 3 passes over the frames, files in the page cache) and whether the decoder gave
// libpng's pixels on every frame.
//   cmake --build build --target png_benchmark    (or: build/tests/benchmark/slamkit_png_benchmark)
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "core/stopwatch.h"
#include "datasets/synth/room_layout.h"
#include "datasets/synth/sequence_writer.h"
#include "png_candidates.h"

namespace fs = std::filesystem;
using namespace slamkit;

namespace {

struct FrameSet {
  std::string name;
  std::vector<fs::path> files;
  std::vector<cv::Mat> reference;  // libpng's pixels
};

void add_pngs(const fs::path& folder, std::vector<fs::path>& files) {
  if (!fs::is_directory(folder)) return;
  std::vector<fs::path> found;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.path().extension() == ".png") found.push_back(entry.path());
  std::sort(found.begin(), found.end());
  files.insert(files.end(), found.begin(), found.end());
}

// Colour and depth frames of every sequence folder under `root`.
std::vector<FrameSet> frame_sets(const std::string& name, const fs::path& root) {
  FrameSet colour{name + " colour", {}, {}}, depth{name + " depth", {}, {}};
  std::vector<fs::path> sequences = {root};
  for (const auto& entry : fs::directory_iterator(root))
    if (entry.is_directory()) sequences.push_back(entry.path());
  std::sort(sequences.begin(), sequences.end());
  for (const fs::path& sequence : sequences) {
    add_pngs(sequence / "rgb", colour.files);
    add_pngs(sequence / "depth", depth.files);
  }
  return {colour, depth};
}

bool same(const cv::Mat& a, const cv::Mat& b) {
  return a.type() == b.type() && a.size() == b.size() && cv::norm(a, b, cv::NORM_INF) == 0;
}

// Whether the candidate gives libpng's pixels on every frame of the set.
bool identical(const bench::PngCandidate& candidate, const FrameSet& set) {
  bool all = true;
  for (size_t k = 0; k < set.files.size(); ++k)
    all = same(candidate.decode(set.files[k]), set.reference[k]) && all;
  return all;
}

double ms_per_frame(const bench::PngCandidate& candidate, const FrameSet& set) {
  Stopwatch watch;
  for (const fs::path& file : set.files) candidate.decode(file);
  return watch.lap() / double(set.files.size());
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

int main() {
  std::vector<FrameSet> sets;
  if (const char* data = std::getenv("SLAMKIT_DATA")) {
    sets = frame_sets("real", data);
  } else {
    std::printf("SLAMKIT_DATA not set: synthetic frames only\n");
  }
  const fs::path synthetic =
      fs::temp_directory_path() / ("slamkit_png_benchmark_desk_" + std::to_string(getpid()));
  synth::SequenceSpec spec;
  spec.preset = synth::Preset::kDesk;
  spec.frames = 50;
  spec.out = synthetic;
  synth::write_sequence(synth::make_furnished_room(), spec);
  for (FrameSet& set : frame_sets("synthetic", synthetic)) sets.push_back(std::move(set));

  const std::vector<bench::PngCandidate> candidates = bench::png_candidates();
  for (FrameSet& set : sets)
    for (const fs::path& file : set.files) set.reference.push_back(candidates[0].decode(file));

  // Which candidates decode everything, and as libpng does.
  std::vector<std::string> verdicts;
  std::vector<bool> decodes;
  for (const bench::PngCandidate& candidate : candidates) {
    try {
      bool all = true;
      for (const FrameSet& set : sets) all = identical(candidate, set) && all;
      verdicts.push_back(all ? "yes, every frame" : "NO");
      decodes.push_back(true);
    } catch (const std::exception& e) {
      verdicts.push_back(std::string("failed: ") + e.what());
      decodes.push_back(false);
    }
  }
  // Passes interleave the candidates, so that a machine's changing load hits all alike.
  std::vector<std::vector<std::vector<double>>> times(
      candidates.size(), std::vector<std::vector<double>>(sets.size()));
  for (int pass = 0; pass < 3; ++pass)
    for (size_t c = 0; c < candidates.size(); ++c)
      if (decodes[c])
        for (size_t s = 0; s < sets.size(); ++s)
          times[c][s].push_back(ms_per_frame(candidates[c], sets[s]));

  std::printf("\nPNG decode, ms per frame on one core (median of 3 passes)\n\n| decoder |");
  for (const FrameSet& set : sets) std::printf(" %s (%zu) |", set.name.c_str(), set.files.size());
  std::printf(" same pixels as libpng |\n|---|");
  for (size_t k = 0; k <= sets.size(); ++k) std::printf("---|");
  std::printf("\n");
  for (size_t c = 0; c < candidates.size(); ++c) {
    std::printf("| %s |", candidates[c].name.c_str());
    for (size_t s = 0; s < sets.size(); ++s)
      times[c][s].empty() ? std::printf(" - |") : std::printf(" %.2f |", median(times[c][s]));
    std::printf(" %s |\n", verdicts[c].c_str());
  }
  fs::remove_all(synthetic);
  return 0;
}
