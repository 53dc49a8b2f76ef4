// Progress on stderr: a bar redrawn in place on a terminal, a plain line per 10 % otherwise
// (logs, CI), silent when quiet.
#pragma once

#include <chrono>
#include <string>

namespace obscura::app {

class ProgressBar {
 public:
  ProgressBar(std::string label, bool quiet);
  // Thread-compatible: the render loop calls it serially.
  void update(int done, int total);
  void finish();

 private:
  std::string label_;
  bool quiet_, terminal_;
  int last_decile_ = 0;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
};

std::string format_seconds(double seconds);

}  // namespace obscura::app
