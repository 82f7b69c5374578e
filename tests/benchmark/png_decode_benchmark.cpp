// The PNG decode benchmark (a target, not a test): every decoder of png_candidates.h on the
// real frames under $SLAMKIT_DATA (each sequence's rgb/ and depth/) and on a synthetic desk
// sequence rendered for the run. Prints ms per colour and per depth frame on one core (the
// median of 3 passes over the frames, files in the page cache) and whether the decoder gave
// libpng's pixels on every frame.
//   cmake --build build --target png_benchmark    (or: build/tests/benchmark/slamkit_png_benchmark)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
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

struct Measurement {
  double ms_per_frame = 0;
  bool identical = true;
};

Measurement measure(const bench::PngCandidate& candidate, const FrameSet& set) {
  Measurement m;
  for (size_t k = 0; k < set.files.size(); ++k)
    m.identical = same(candidate.decode(set.files[k]), set.reference[k]) && m.identical;
  std::vector<double> passes;
  for (int pass = 0; pass < 3; ++pass) {
    Stopwatch watch;
    for (const fs::path& file : set.files) candidate.decode(file);
    passes.push_back(watch.lap() / double(set.files.size()));
  }
  std::sort(passes.begin(), passes.end());
  m.ms_per_frame = passes[1];
  return m;
}

}  // namespace

int main() {
  std::vector<FrameSet> sets;
  if (const char* data = std::getenv("SLAMKIT_DATA")) {
    sets = frame_sets("real", data);
  } else {
    std::printf("SLAMKIT_DATA not set: synthetic frames only\n");
  }
  const fs::path synthetic = fs::temp_directory_path() / "slamkit_png_benchmark_desk";
  synth::SequenceSpec spec;
  spec.preset = synth::Preset::kDesk;
  spec.frames = 50;
  spec.out = synthetic;
  synth::write_sequence(synth::make_furnished_room(), spec);
  for (FrameSet& set : frame_sets("synthetic", synthetic)) sets.push_back(std::move(set));

  const std::vector<bench::PngCandidate> candidates = bench::png_candidates();
  for (FrameSet& set : sets)
    for (const fs::path& file : set.files) set.reference.push_back(candidates[0].decode(file));

  std::printf("\nPNG decode, ms per frame on one core (median of 3 passes)\n\n| decoder |");
  for (const FrameSet& set : sets) std::printf(" %s (%zu) |", set.name.c_str(), set.files.size());
  std::printf(" same pixels as libpng |\n|---|");
  for (size_t k = 0; k <= sets.size(); ++k) std::printf("---|");
  std::printf("\n");
  for (const bench::PngCandidate& candidate : candidates) {
    std::printf("| %s |", candidate.name.c_str());
    bool identical = true;
    try {
      for (const FrameSet& set : sets) {
        const Measurement m = measure(candidate, set);
        identical = identical && m.identical;
        std::printf(" %.2f |", m.ms_per_frame);
      }
      std::printf(" %s |\n", identical ? "yes, every frame" : "NO");
    } catch (const std::exception& e) {
      std::printf(" failed: %s |\n", e.what());
    }
  }
  fs::remove_all(synthetic);
  return 0;
}
