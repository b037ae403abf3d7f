// engine/core/log.h: one sink for every line the engine prints.
// The platform installs a sink (stdout, a console buffer); the default writes to stderr.
// Lines are formatted into a stack buffer (512 bytes): no heap.
#pragma once

namespace sb {

enum class LogLevel { Info, Warning, Error };
using LogSink = void (*)(void* user, LogLevel level, const char* line);

void set_log_sink(LogSink sink, void* user);
void log_info(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
void log_warning(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
void log_error(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

}  // namespace sb
