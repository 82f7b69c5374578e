#include "fuzz_parsers.h"

#include <unistd.h>

#include <fstream>
#include <stdexcept>

#include "core/error.h"
#include "core/settings/settings.h"
#include "eval/regression/suite.h"
#include "eval/sweep/sweep_file.h"
#include "io/camera_yaml.h"
#include "io/euroc_csv.h"
#include "io/kitti_poses.h"
#include "io/png_file.h"
#include "settings/settings_yaml.h"
#include "io/trajectory_format.h"
#include "io/trajectory_io.h"
#include "io/tum_sequence.h"

namespace slamkit::fuzz {
namespace {

namespace fs = std::filesystem;

void write_bytes(const fs::path& file, const uint8_t* data, size_t size) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  if (!out) throw std::runtime_error("fuzz: cannot write " + file.string());
}

// Through streams, which retry a read or write that a signal interrupts: fs::copy_file does not,
// and libFuzzer's timeout alarm (every few seconds) interrupts it now and then.
void copy_bytes(const fs::path& from, const fs::path& to) {
  std::ifstream in(from, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream out(to, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  if (!out) throw std::runtime_error("fuzz: cannot copy " + from.string() + " to " + to.string());
}

// A sequence folder whose name gives the Freiburg 1 camera, so no calibration file is needed.
fs::path sequence_folder(const fs::path& scratch) {
  const fs::path folder = scratch / "rgbd_dataset_freiburg1_fuzz";
  fs::create_directories(folder);
  return folder;
}

// rgb.txt and depth.txt: the input serves as both lists, which exercises the association too.
void parse_tum_list(const fs::path& input, const fs::path& scratch) {
  const fs::path folder = sequence_folder(scratch);
  copy_bytes(input, folder / "rgb.txt");
  copy_bytes(input, folder / "depth.txt");
  TumSequence::open(folder);
}

void parse_association(const fs::path& input, const fs::path& scratch) {
  SequenceOptions options;
  options.association_file = input;
  TumSequence::open(sequence_folder(scratch), options);
}

// As `eval` reads them: the benchmark's defaults, and evo's with nanosecond stamps.
void parse_trajectory(const fs::path& input, const fs::path&) {
  read_tum_trajectory(input);
  read_tum_trajectory(input, {TimeUnit::kNanoseconds, DuplicateStamps::kKeepFirst});
}

// The input as a pose file, and as the times.txt of a fixed three-pose file.
void parse_kitti(const fs::path& input, const fs::path& scratch) {
  try {
    read_kitti_poses(input, std::nullopt);
  } catch (const InputError&) {  // refused as poses: go on to read it as times
  }
  const fs::path poses = scratch / "kitti_poses.txt";
  if (!fs::exists(poses)) {
    std::ofstream out(poses);
    for (int k = 0; k < 3; ++k) out << "1 0 0 " << k << " 0 1 0 0 0 0 1 0\n";
  }
  read_kitti_poses(poses, input);
}

void parse_euroc(const fs::path& input, const fs::path&) {
  read_euroc_csv(input);
  read_euroc_csv(input, {TimeUnit::kSeconds, DuplicateStamps::kKeepFirst});
}

// As `eval` reads a file given without --format: detected, then read.
void parse_detected(const fs::path& input, const fs::path&) {
  read_trajectory(input, std::nullopt, {}, std::nullopt);
}

void parse_settings(const fs::path& input, const fs::path&) {
  Settings settings;
  read_settings_yaml(input, settings);
}

void parse_calibration(const fs::path& input, const fs::path&) { read_camera_yaml(input); }

void parse_png(const fs::path& input, const fs::path&) { read_png(input); }

// What `slamkit regress` and `slamkit sweep` pass, with the preset and TUM names fixed here (the
// synthetic generator and the download script are not needed to parse) and downloads off.
regress::SuiteContext suite_context(const fs::path& scratch) {
  regress::SuiteContext context;
  context.data_dir = scratch;
  context.presets = {"desk", "loop", "lowtexture", "jerk", "long", "lookalike"};
  context.tum_names = [] { return std::vector<std::string>{"freiburg1_desk", "freiburg2_desk"}; };
  context.download = false;
  return context;
}

void parse_suite(const fs::path& input, const fs::path& scratch) {
  regress::load_suite(input, suite_context(scratch));
}

void parse_sweep(const fs::path& input, const fs::path& scratch) {
  sweep::load_sweep(input, suite_context(scratch));
}

fs::path process_scratch() {
  static const fs::path scratch = [] {
    const fs::path dir = fs::temp_directory_path() / ("slamkit_fuzz_" + std::to_string(getpid()));
    fs::create_directories(dir);
    return dir;
  }();
  return scratch;
}

}  // namespace

const std::vector<FuzzTarget>& fuzz_targets() {
  static const std::vector<FuzzTarget> targets = {
      {"tum_list", parse_tum_list},
      {"association", parse_association},
      {"trajectory", parse_trajectory},
      {"kitti", parse_kitti},
      {"euroc", parse_euroc},
      {"trajectory_format", parse_detected},
      {"settings", parse_settings},
      {"calibration", parse_calibration},
      {"png", parse_png},
      {"suite", parse_suite},
      {"sweep", parse_sweep},
  };
  return targets;
}

const FuzzTarget& fuzz_target(const std::string& name) {
  for (const FuzzTarget& target : fuzz_targets())
    if (target.name == name) return target;
  throw std::invalid_argument("no fuzz target '" + name + "'");
}

void parse_bytes(const FuzzTarget& target, const uint8_t* data, size_t size) {
  const fs::path scratch = process_scratch();
  const fs::path input = scratch / ("input_" + target.name);
  write_bytes(input, data, size);
  try {
    target.parse(input, scratch);
  } catch (const InputError&) {
    // The clean refusal: one line naming the file, exit code 2 at the command line.
  }
}

}  // namespace slamkit::fuzz
