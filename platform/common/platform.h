// platform/common/platform.h: what every Starbow platform shares.
//
//   main(argc, argv)
//     -> PlatformBlock::allocate(-mem MiB)       the one big allocation of the process
//     -> make_host_services()                    PNG writer + monotonic clock for the host
//     -> sb::engine_init / engine_frame / engine_shutdown
//
// This layer may use the C library, libpng and the OS freely; the engine never does.
#pragma once
#include <cstddef>
#include <cstdint>

#include "engine/host/host.h"

namespace sb::platform {

// The one memory block. Size from -mem <MiB> (default mem::kDefaultBlockMiB).
// 64-byte aligned; freed by release() or the destructor.
class PlatformBlock {
 public:
  PlatformBlock() = default;
  ~PlatformBlock() { release(); }
  PlatformBlock(const PlatformBlock&) = delete;
  PlatformBlock& operator=(const PlatformBlock&) = delete;

  // False (message in error) when the allocation fails.
  bool allocate(size_t mib, char* error, size_t error_size);
  void release();
  void* data() const { return data_; }
  size_t size() const { return size_; }

 private:
  void* data_ = nullptr;
  size_t size_ = 0;
};

// The block size asked for on the command line (-mem), else the default. MiB.
size_t requested_block_mib(int argc, const char* const* argv);

// Seconds from a monotonic clock (arbitrary origin).
double now_seconds();

// Writes an 8-bit image + 768-byte RGB palette as an RGB PNG (libpng; without libpng,
// STARBOW_PNG=OFF, an uncompressed PNG from builtin_png/png_writer_stored.cpp).
// False with a message naming the file on failure.
bool write_png_rgb(const char* path, const uint8_t* pixels, int width, int height, int stride,
                   const uint8_t* palette, char* error, size_t error_size);

// Services the host uses: write_png -> write_png_rgb, seconds -> now_seconds.
HostServices make_host_services();

// Prints engine log lines to stdout (info) / stderr (warnings, errors), flushed.
void install_stdout_log();

// The CPU clock in MHz from /proc/cpuinfo ("cpu MHz"), or 0 when unknown.
double cpu_mhz();

// The source tree's default content folder (../shared/quake next to the project)
// when it exists, else "." (the current directory).
const char* default_basedir();
// The game folder that goes with default_basedir(): "starbow" for Starbow's own content
// (built into <build>/content/starbow), else "lq1".
const char* default_game();

}  // namespace sb::platform

namespace sb::platform {

// The headless main loop shared by `starbow` and by `starbow_sdl` when there is
// no display: allocates the block, runs the engine with a fixed 1/60 s step and
// never waits for input (see platform/null/main.cpp for what runs). `program`
// prefixes error messages. Returns the process exit code.
int run_headless(const char* program, int argc, const char* const* argv);

}  // namespace sb::platform

namespace sb::platform {

// Console lines typed into the terminal, read without blocking (poll + read on
// stdin). next() returns the complete lines that arrived since the last call,
// '\n'-separated, or nullptr; the text stays valid until the next call. Stops at
// end of input. Used by the windowed platform: type "viewmap lq_e1m1" + Enter.
class StdinLines {
 public:
  const char* next();

 private:
  char pending_[1024] = {};
  size_t used_ = 0;
  char ready_[1025] = {};
  bool closed_ = false;
};

}  // namespace sb::platform
