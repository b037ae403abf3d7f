// tests/host/host_test_util.h: running the engine inside a test, capturing its log
// without touching the heap, running the built executables, reading PNGs.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/host/host.h"

namespace sb::test {

// Log lines go into a fixed buffer (no heap: the zero-allocation test uses it too).
void capture_log_begin();
std::string captured_log();  // copies the buffer (call outside counted regions)
void capture_log_end();      // back to the default stderr sink

// One engine in this process: block from aligned_alloc, argv kept alive, services
// from platform/common. Destructor shuts the engine down and frees the block.
class EngineSession {
 public:
  explicit EngineSession(std::vector<std::string> args, size_t mem_mib = 96, int max_w = 0, int max_h = 0);
  ~EngineSession();
  EngineSession(const EngineSession&) = delete;
  EngineSession& operator=(const EngineSession&) = delete;

  const Status& init_status() const { return status_; }
  HostFrame frame(const char* commands = nullptr, double dt = 1.0 / 60.0);
  HostFrame frame(const HostInput& input, double dt);

 private:
  std::vector<std::string> args_;
  std::vector<const char*> argv_;
  void* block_ = nullptr;
  Status status_;
  bool running_ = false;
};

// Runs a shell command; returns its exit status and fills *output with stdout+stderr.
int run_command(const std::string& command, std::string* output);

// Reads any PNG as RGB (libpng's simplified API). False with a message.
bool read_png_rgb(const std::string& path, int* width, int* height, std::vector<uint8_t>* rgb, std::string* error);

// Number of distinct RGB colours in an image (capped at 4096 for speed).
int distinct_colours(const std::vector<uint8_t>& rgb);

// A fresh empty directory under the system temp dir.
std::string make_temp_dir(const char* tag);

bool file_exists(const std::string& path);
bool program_on_path(const char* name);

}  // namespace sb::test
