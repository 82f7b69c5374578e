#pragma once
// Runs a program as a child process and measures it: wall time, CPU time (user + system, all
// threads, wait4's rusage) and peak resident memory (its VmHWM, read every 20 ms; a peak in
// its last 20 ms could be missed). The benchmark measures slamkit and ORB-SLAM2 this same way,
// each in a fresh process.
#include <filesystem>
#include <string>
#include <vector>

namespace slamkit::bench {

struct ChildUsage {
  int exit_code = -1;
  double wall_s = 0;
  double cpu_s = 0;
  double peak_rss_mb = 0;  // MB
};

// argv[0] is the program's path. Standard output and error go to `log`; the child starts in
// `working_dir` with `extra_env` ("NAME=value") added to this process's environment. Throws
// std::runtime_error when the program cannot be started.
ChildUsage run_child(const std::vector<std::string>& argv, const std::filesystem::path& log,
                     const std::filesystem::path& working_dir,
                     const std::vector<std::string>& extra_env = {});

}  // namespace slamkit::bench
