#pragma once
#include <chrono>
#include <ctime>

namespace slamkit {

// Milliseconds since construction or the last lap().
class Stopwatch {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - start_).count();
    start_ = now;
    return ms;
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// CPU milliseconds of the whole process (every thread) since construction or the last lap():
// beside a Stopwatch's wall time, it tells how busy the cores were.
class CpuStopwatch {
 public:
  double lap() {
    const double now = process_cpu_ms();
    const double ms = now - start_;
    start_ = now;
    return ms;
  }

 private:
  static double process_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
  }
  double start_ = process_cpu_ms();
};

}  // namespace slamkit
