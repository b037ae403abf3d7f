// tools/common/progress.h: progress reporting for long compile stages (sbbsp, sbvis, sblight).
//
// On a terminal (stderr is a tty) a one-line bar is redrawn in place at most ~10 times a
// second; in logs (stderr redirected) plain lines are printed at 0%, 25%, 50%, 75% and 100%,
// so a CI log shows a handful of lines and never carriage returns. quiet=true prints nothing.
//
// Thread-safe: any worker may call advance(); counting is one relaxed atomic add and
// printing is rate limited and serialised by a compare-exchange on the next threshold.
// finish() prints the final 100% line with the elapsed time and returns it in seconds.
#pragma once
#include <atomic>
#include <cstdint>
#include <mutex>

namespace sb::tools {

class Progress {
 public:
  enum class Mode { Auto, Bar, Lines, Quiet };
  Progress(const char* stage, int64_t total, Mode mode = Mode::Auto);
  ~Progress();  // finishes if finish() was not called
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(int64_t n = 1);
  double finish();  // seconds since construction

  // True when stderr is a terminal (Mode::Auto picks Bar then, Lines otherwise).
  static bool stderr_is_terminal();

 private:
  void report(int64_t done, bool final);
  const char* stage_;
  int64_t total_;
  Mode mode_;
  std::atomic<int64_t> done_{0};
  std::atomic<int64_t> next_report_{0};  // done count (Lines) or time in ms (Bar) of next print
  std::atomic<bool> finished_{false};
  std::mutex print_mutex_;  // printing only: lines come out in order, never interleaved
  int64_t printed_ = -1;    // last quarter printed (Lines), under print_mutex_
  int64_t start_ns_;
};

}  // namespace sb::tools
