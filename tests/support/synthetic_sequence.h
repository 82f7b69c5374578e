#pragma once
// Synthetic sequences for tests (the suite links slamkit_synth), rendered once per build and
// shared by every test process: ctest runs each test as its own process, two at a time, and
// a dozen of them need the same sequence (rendering loop 200 takes 15 s of CPU, desk 600 40 s).
// A sequence is rendered into a temporary folder and renamed into place when complete, under a
// lock that makes the other processes wait instead of rendering it too; nothing is removed at
// exit, so no reader loses its folder. The folders sit under the build folder, in a folder
// named after the renderer's build (the modification times of the libraries that draw and
// write the images), so a rebuilt renderer renders afresh and the older folders are removed.
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "datasets/synth/room_layout.h"
#include "datasets/synth/sequence_writer.h"

namespace slamkit::test {

// The renderer's build: "<seconds>.<nanoseconds>" of each library in SLAMKIT_RENDERER_LIBRARIES
// (paths separated by '|').
inline std::string renderer_build_key() {
  std::stringstream libraries(SLAMKIT_RENDERER_LIBRARIES), key;
  for (std::string library; std::getline(libraries, library, '|');) {
    struct stat info {};
    if (stat(library.c_str(), &info) != 0)
      throw std::runtime_error("synthetic_sequence: no renderer library " + library);
    key << (key.tellp() > 0 ? "-" : "") << info.st_mtim.tv_sec << "." << info.st_mtim.tv_nsec;
  }
  return key.str();
}

// Through the ideal sensor or the kinect one with its default settings; with first_frames only
// the start of the `frames`-long motion (SequenceSpec::first_frames).
inline std::filesystem::path synthetic_sequence(synth::Preset preset, int frames,
                                                bool kinect = false, uint64_t seed = 1,
                                                int first_frames = 0) {
  namespace fs = std::filesystem;
  const fs::path base = SLAMKIT_TEST_SEQUENCES;
  const fs::path root = base / renderer_build_key();
  const fs::path dir = root / (synth::preset_name(preset) + std::to_string(frames) +
                               (kinect ? "_kinect" : "") +
                               (seed == 1 ? "" : "_seed" + std::to_string(seed)) +
                               (first_frames ? "_first" + std::to_string(first_frames) : ""));
  if (fs::exists(dir)) return dir;

  std::error_code ignored;
  if (fs::create_directories(root))  // a new renderer: the older builds' sequences go
    for (const auto& entry : fs::directory_iterator(base, ignored))
      if (entry.path() != root) fs::remove_all(entry.path(), ignored);
  const std::string lock_file = dir.string() + ".lock";
  const int lock = open(lock_file.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
  if (lock < 0 || flock(lock, LOCK_EX) != 0)
    throw std::runtime_error("synthetic_sequence: cannot lock " + lock_file);
  if (!fs::exists(dir)) {  // nobody rendered it while this process waited
    const fs::path partial = dir.string() + ".partial";
    fs::remove_all(partial);  // left by a process killed mid-render
    synth::SequenceSpec spec;
    spec.preset = preset;
    spec.frames = frames;
    spec.out = partial;
    spec.seed = seed;
    spec.first_frames = first_frames;
    if (kinect) spec.kinect = synth::KinectSettings{};
    synth::write_sequence(synth::make_named_scene(synth::preset_scene(preset)), spec);
    fs::rename(partial, dir);
  }
  close(lock);  // releases the lock
  return dir;
}

}  // namespace slamkit::test
