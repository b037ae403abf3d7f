// platform/common/stdin_lines.cpp: non-blocking console lines from the terminal.
#include <poll.h>
#include <unistd.h>

#include <cstring>

#include "platform/common/platform.h"

namespace sb::platform {

const char* StdinLines::next() {
  if (closed_) return nullptr;
  pollfd p{STDIN_FILENO, POLLIN, 0};
  while (poll(&p, 1, 0) > 0 && (p.revents & (POLLIN | POLLHUP))) {
    if (used_ == sizeof pending_) used_ = 0;  // an over-long line is dropped
    ssize_t n = read(STDIN_FILENO, pending_ + used_, sizeof pending_ - used_);
    if (n <= 0) {
      closed_ = true;
      break;
    }
    used_ += size_t(n);
  }
  // Hand out everything up to the last complete line.
  size_t end = used_;
  while (end > 0 && pending_[end - 1] != '\n') --end;
  if (end == 0) return nullptr;
  std::memcpy(ready_, pending_, end);
  ready_[end] = '\0';  // ready_ is one byte longer than pending_
  std::memmove(pending_, pending_ + end, used_ - end);
  used_ -= end;
  return ready_;
}

}  // namespace sb::platform
