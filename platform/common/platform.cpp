// platform/common/platform.cpp: the memory block, the clock, logging to stdout,
// /proc/cpuinfo, the default content folder. PNG writing is in png_writer.cpp.
#include "platform/common/platform.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/stat.h>

#include "engine/core/log.h"
#include "engine/host/cmdline.h"
#include "memory/memory_system.h"

#ifndef STARBOW_DEFAULT_BASEDIR
#define STARBOW_DEFAULT_BASEDIR "."
#endif

namespace sb::platform {

bool PlatformBlock::allocate(size_t mib, char* error, size_t error_size) {
  release();
  size_t size = mib * mem::kMiB;
  // The one big allocation of the process; everything else is carved from it.
  data_ = std::aligned_alloc(64, size);
  if (!data_) {
    std::snprintf(error, error_size, "cannot allocate the %zu MiB memory block (try a smaller -mem)", mib);
    return false;
  }
  size_ = size;
  return true;
}

void PlatformBlock::release() {
  std::free(data_);
  data_ = nullptr;
  size_ = 0;
}

size_t requested_block_mib(int argc, const char* const* argv) {
  host::CommandLine cl;
  if (host::parse_command_line(argc, argv, &cl).is_ok() && cl.mem_mib > 0) return size_t(cl.mem_mib);
  return mem::kDefaultBlockMiB;
}

double now_seconds() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

namespace {

bool png_service(void*, const char* path, const uint8_t* pixels, int width, int height, int stride,
                 const uint8_t* palette, char* error, size_t error_size) {
  return write_png_rgb(path, pixels, width, height, stride, palette, error, error_size);
}
double seconds_service(void*) { return now_seconds(); }

void stdout_sink(void*, LogLevel level, const char* line) {
  if (level == LogLevel::Info) {
    std::fprintf(stdout, "%s\n", line);
    std::fflush(stdout);
    return;
  }
  std::fflush(stdout);
  std::fprintf(stderr, "%s%s\n", level == LogLevel::Error ? "error: " : "warning: ", line);
  std::fflush(stderr);
}

}  // namespace

HostServices make_host_services() {
  HostServices s;
  s.write_png = png_service;
  s.seconds = seconds_service;
  return s;
}

void install_stdout_log() { set_log_sink(stdout_sink, nullptr); }

double cpu_mhz() {
  std::FILE* f = std::fopen("/proc/cpuinfo", "r");
  if (!f) return 0.0;
  char line[256];
  double mhz = 0.0;
  while (std::fgets(line, sizeof line, f)) {
    if (std::strncmp(line, "cpu MHz", 7) != 0) continue;
    const char* colon = std::strchr(line, ':');
    if (colon) mhz = std::strtod(colon + 1, nullptr);
    break;
  }
  std::fclose(f);
  return mhz > 0.0 ? mhz : 0.0;
}

namespace {
bool have_starbow_content() {
#ifdef STARBOW_CONTENT_BASEDIR
  struct stat st;
  return stat(STARBOW_CONTENT_BASEDIR "/starbow/gfx/palette.lmp", &st) == 0;
#else
  return false;
#endif
}
}  // namespace

const char* default_basedir() {
#ifdef STARBOW_CONTENT_BASEDIR
  if (have_starbow_content()) return STARBOW_CONTENT_BASEDIR;
#endif
  struct stat st;
  if (stat(STARBOW_DEFAULT_BASEDIR, &st) == 0 && S_ISDIR(st.st_mode)) return STARBOW_DEFAULT_BASEDIR;
  return ".";
}

const char* default_game() { return have_starbow_content() ? "starbow" : host::kDefaultGame; }

}  // namespace sb::platform
