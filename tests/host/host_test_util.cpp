#include "tests/host/host_test_util.h"

#ifndef STARBOW_NO_PNG  // STARBOW_PNG=OFF (cross builds): read_png_rgb reports "compiled out"
#include <png.h>
#endif

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <set>
#include <unistd.h>

#include "engine/core/log.h"
#include "platform/common/platform.h"

namespace sb::test {
namespace {

char g_log[1 << 16];
size_t g_log_used = 0;

void capture_sink(void*, LogLevel level, const char* line) {
  const char* tag = level == LogLevel::Error ? "error: " : level == LogLevel::Warning ? "warning: " : "";
  int n = std::snprintf(g_log + g_log_used, sizeof g_log - g_log_used, "%s%s\n", tag, line);
  if (n > 0) g_log_used += std::min(size_t(n), sizeof g_log - 1 - g_log_used);
  std::fprintf(stderr, "%s%s\n", tag, line);  // unbuffered: no heap
}

}  // namespace

void capture_log_begin() {
  g_log_used = 0;
  g_log[0] = '\0';
  set_log_sink(capture_sink, nullptr);
}
std::string captured_log() { return std::string(g_log, g_log_used); }
void capture_log_end() { set_log_sink(nullptr, nullptr); }

EngineSession::EngineSession(std::vector<std::string> args, size_t mem_mib, int max_w, int max_h)
    : args_(std::move(args)) {
  args_.insert(args_.begin(), "host_test");
  for (const std::string& a : args_) argv_.push_back(a.c_str());
  size_t size = mem_mib * 1024 * 1024;
  block_ = std::aligned_alloc(64, size);
  HostConfig config;
  config.memory = block_;
  config.memory_size = size;
  config.argc = int(argv_.size());
  config.argv = argv_.data();
  config.default_basedir = ".";
  config.max_width = max_w;
  config.max_height = max_h;
  config.services = platform::make_host_services();
  status_ = engine_init(config);
  running_ = status_.is_ok();
}

EngineSession::~EngineSession() {
  if (running_) engine_shutdown();
  std::free(block_);
}

HostFrame EngineSession::frame(const char* commands, double dt) {
  HostInput in;
  in.commands = commands;
  return engine_frame(in, dt);
}

HostFrame EngineSession::frame(const HostInput& input, double dt) { return engine_frame(input, dt); }

int run_command(const std::string& command, std::string* output) {
  output->clear();
  std::FILE* p = popen((command + " 2>&1").c_str(), "r");
  if (!p) return -1;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) output->append(buf, n);
  int status = pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool read_png_rgb(const std::string& path, int* width, int* height, std::vector<uint8_t>* rgb, std::string* error) {
#ifdef STARBOW_NO_PNG
  (void)width;
  (void)height;
  (void)rgb;
  *error = path + ": PNG support compiled out (STARBOW_PNG=OFF)";
  return false;
#else
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) {
    *error = path + ": " + image.message;
    return false;
  }
  image.format = PNG_FORMAT_RGB;
  rgb->resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, rgb->data(), 0, nullptr)) {
    *error = path + ": " + image.message;
    png_image_free(&image);
    return false;
  }
  *width = int(image.width);
  *height = int(image.height);
  return true;
#endif
}

int distinct_colours(const std::vector<uint8_t>& rgb) {
  std::set<uint32_t> seen;
  for (size_t i = 0; i + 2 < rgb.size() && seen.size() < 4096; i += 3)
    seen.insert(uint32_t(rgb[i]) << 16 | uint32_t(rgb[i + 1]) << 8 | rgb[i + 2]);
  return int(seen.size());
}

std::string make_temp_dir(const char* tag) {
  std::string pattern = (std::filesystem::temp_directory_path() / (std::string("starbow_") + tag + "_XXXXXX")).string();
  std::vector<char> buf(pattern.begin(), pattern.end());
  buf.push_back('\0');
  const char* dir = mkdtemp(buf.data());
  return dir ? std::string(dir) : std::string();
}

bool file_exists(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

bool program_on_path(const char* name) {
  std::string out;
  return run_command(std::string("command -v ") + name, &out) == 0 && !out.empty();
}

}  // namespace sb::test
