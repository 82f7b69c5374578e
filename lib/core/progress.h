#pragma once
// A one-line progress bar on stderr for long work; silent when stderr is not a terminal
// (logs and CI stay clean).
#include <chrono>
#include <string>

namespace slamkit {

class Progress {
 public:
  Progress(std::string label, size_t total);
  ~Progress();
  void update(size_t done);  // thread-safe enough: only the caller's thread should call it

 private:
  std::string label_;
  size_t total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace slamkit
