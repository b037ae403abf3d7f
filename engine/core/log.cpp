#include "engine/core/log.h"

#include <cstdarg>
#include <cstdio>

namespace sb {
namespace {

void stderr_sink(void*, LogLevel level, const char* line) {
  const char* tag = level == LogLevel::Error ? "error: " : level == LogLevel::Warning ? "warning: " : "";
  std::fprintf(stderr, "%s%s\n", tag, line);
}

LogSink g_sink = stderr_sink;
void* g_user = nullptr;

void emit(LogLevel level, const char* fmt, va_list args) {
  char line[512];
  std::vsnprintf(line, sizeof line, fmt, args);
  g_sink(g_user, level, line);
}

}  // namespace

void set_log_sink(LogSink sink, void* user) {
  g_sink = sink ? sink : stderr_sink;
  g_user = user;
}

#define SB_LOG_FN(fn, level)        \
  void fn(const char* fmt, ...) {   \
    va_list args;                   \
    va_start(args, fmt);            \
    emit(level, fmt, args);         \
    va_end(args);                   \
  }
SB_LOG_FN(log_info, LogLevel::Info)
SB_LOG_FN(log_warning, LogLevel::Warning)
SB_LOG_FN(log_error, LogLevel::Error)

}  // namespace sb
