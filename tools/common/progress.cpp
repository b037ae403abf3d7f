// tools/common/progress.cpp: see progress.h.
#include "tools/common/progress.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace sb::tools {
namespace {

int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

constexpr int kBarWidth = 40;

}  // namespace

bool Progress::stderr_is_terminal() { return isatty(STDERR_FILENO) == 1; }

Progress::Progress(const char* stage, int64_t total, Mode mode)
    : stage_(stage), total_(total > 0 ? total : 0), mode_(mode), start_ns_(now_ns()) {
  if (mode_ == Mode::Auto) mode_ = stderr_is_terminal() ? Mode::Bar : Mode::Lines;
  if (mode_ == Mode::Lines) {
    std::fprintf(stderr, "%s: 0%% (0/%lld)\n", stage_, static_cast<long long>(total_));
    next_report_.store(total_ / 4 > 0 ? total_ / 4 : 1, std::memory_order_relaxed);
  } else if (mode_ == Mode::Bar) {
    report(0, false);
  }
}

Progress::~Progress() {
  if (!finished_.load()) finish();
}

void Progress::advance(int64_t n) {
  const int64_t done = done_.fetch_add(n, std::memory_order_relaxed) + n;
  if (mode_ == Mode::Quiet) return;
  int64_t threshold = next_report_.load(std::memory_order_relaxed);
  if (mode_ == Mode::Lines) {
    if (done < threshold || done >= total_) return;  // 100% is finish()'s line
    // Next quarter past `done`; one thread wins the right to print this one.
    const int64_t quarter = total_ / 4 > 0 ? total_ / 4 : 1;
    const int64_t next = (done / quarter + 1) * quarter;
    if (!next_report_.compare_exchange_strong(threshold, next)) return;
    // Two workers can win consecutive quarters and reach the printer in either order: the
    // first to get there prints every quarter not yet printed, up to its own, naming the
    // quarter (not the racing count), so a log reads 0, 25, 50, 75, 100 in order.
    std::lock_guard<std::mutex> lock(print_mutex_);
    if (finished_.load()) return;
    const int64_t q = std::min<int64_t>(done / quarter, 3);
    for (int64_t k = std::max<int64_t>(printed_ + 1, 1); k <= q; ++k) report(k * quarter, false);
    if (q > printed_) printed_ = q;
  } else {
    const int64_t ms = (now_ns() - start_ns_) / 1000000;
    if (ms < threshold) return;
    if (next_report_.compare_exchange_strong(threshold, ms + 100)) report(done, false);
  }
}

void Progress::report(int64_t done, bool final) {
  const double frac = total_ > 0 ? static_cast<double>(done) / static_cast<double>(total_) : 1.0;
  const double secs = static_cast<double>(now_ns() - start_ns_) * 1e-9;
  if (mode_ == Mode::Lines) {
    if (final) {
      std::fprintf(stderr, "%s: 100%% (%lld/%lld) %.2f s\n", stage_, static_cast<long long>(done),
                   static_cast<long long>(total_), secs);
    } else {
      std::fprintf(stderr, "%s: %d%% (%lld/%lld)\n", stage_, static_cast<int>(frac * 100.0 + 0.5),
                   static_cast<long long>(done), static_cast<long long>(total_));
    }
    return;
  }
  char bar[kBarWidth + 1];
  const int fill = static_cast<int>(frac * kBarWidth + 0.5);
  for (int i = 0; i < kBarWidth; ++i) bar[i] = i < fill ? '#' : '.';
  bar[kBarWidth] = 0;
  std::fprintf(stderr, "\r%-8s [%s] %3d%% %6.1f s%s", stage_, bar, static_cast<int>(frac * 100.0), secs,
               final ? "\n" : "");
  std::fflush(stderr);
}

double Progress::finish() {
  bool expected = false;
  const double secs = static_cast<double>(now_ns() - start_ns_) * 1e-9;
  if (!finished_.compare_exchange_strong(expected, true)) return secs;
  if (mode_ != Mode::Quiet) {
    std::lock_guard<std::mutex> lock(print_mutex_);
    report(done_.load() < total_ ? total_ : done_.load(), true);
  }
  return secs;
}

}  // namespace sb::tools
