#include "engine/host/cmdline.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace sb::host {
namespace {

bool is_option(const char* s) {
  return s[0] == '-' && ((s[1] >= 'a' && s[1] <= 'z') || (s[1] >= 'A' && s[1] <= 'Z'));
}
bool is_command_start(const char* s) { return s[0] == '+' && s[1] != '\0'; }

bool parse_int(const char* s, int* out) {
  char* end = nullptr;
  long v = std::strtol(s, &end, 10);
  if (end == s || *end != '\0' || v < -1000000000L || v > 1000000000L) return false;
  *out = int(v);
  return true;
}

bool parse_float(const char* s, float* out) {
  char* end = nullptr;
  float v = std::strtof(s, &end);
  if (end == s || *end != '\0') return false;
  *out = v;
  return true;
}

bool copy(char* dst, size_t dst_size, const char* src) {
  size_t n = std::strlen(src);
  if (n >= dst_size) return false;
  std::memcpy(dst, src, n + 1);
  return true;
}

// Appends s to a space- or line-separated list held in dst.
bool append(char* dst, size_t dst_size, const char* s, char separator) {
  size_t used = std::strlen(dst);
  size_t n = std::strlen(s);
  size_t sep = used > 0 && separator ? 1 : 0;
  if (used + sep + n >= dst_size) return false;
  if (sep) dst[used++] = separator;
  std::memcpy(dst + used, s, n + 1);
  return true;
}

}  // namespace

Status parse_command_line(int argc, const char* const* argv, CommandLine* out) {
  *out = CommandLine{};
  auto value = [&](int& i) -> const char* {
    if (i + 1 >= argc || is_command_start(argv[i + 1]) || is_option(argv[i + 1])) return nullptr;
    return argv[++i];
  };
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (is_command_start(a)) {
      // "+name arg arg ..." -> one line; quote arguments that hold blanks.
      char line[256] = {};
      if (!append(line, sizeof line, a + 1, 0)) return make_error("command line: '%.40s' is too long", a);
      if (std::strcmp(a + 1, "map") == 0 || std::strcmp(a + 1, "viewmap") == 0) out->has_map_command = true;
      while (i + 1 < argc && !is_command_start(argv[i + 1]) && !is_option(argv[i + 1])) {
        const char* arg = argv[++i];
        bool blank = std::strpbrk(arg, " \t;") != nullptr;
        char quoted[200];
        if (blank) {
          if (std::snprintf(quoted, sizeof quoted, "\"%s\"", arg) >= int(sizeof quoted))
            return make_error("command line: argument '%.40s' of '%s' is too long", arg, a);
          arg = quoted;
        }
        if (!append(line, sizeof line, arg, ' ')) return make_error("command line: '%s ...' is too long", a);
      }
      if (!append(out->commands, sizeof out->commands, line, out->commands[0] ? '\n' : 0))
        return make_error("command line: the + commands exceed %zu characters", sizeof out->commands);
      ++out->num_commands;
      continue;
    }
    if (!is_option(a)) continue;  // a stray word: Quake ignores these too
    const char* v = nullptr;
    if (std::strcmp(a, "-basedir") == 0 || std::strcmp(a, "-game") == 0) {
      bool base = a[1] == 'b';
      if (!(v = value(i))) return make_error("command line: %s needs a directory", a);
      if (!copy(base ? out->basedir : out->game, base ? sizeof out->basedir : sizeof out->game, v))
        return make_error("command line: %s '%.40s...' is too long", a, v);
    } else if (std::strcmp(a, "-mem") == 0) {
      if (!(v = value(i)) || !parse_int(v, &out->mem_mib) || out->mem_mib <= 0)
        return make_error("command line: -mem needs a size in MiB (e.g. -mem 128)");
    } else if (std::strcmp(a, "-memstats") == 0) {
      out->memstats = true;
    } else if (std::strcmp(a, "-width") == 0 || std::strcmp(a, "-height") == 0) {
      int* dst = a[1] == 'w' ? &out->width : &out->height;
      if (!(v = value(i)) || !parse_int(v, dst) || *dst <= 0)
        return make_error("command line: %s needs a size in pixels", a);
    } else if (std::strcmp(a, "-res") == 0) {
      int w = 0, h = 0;
      char tail = 0;
      if (!(v = value(i)) || std::sscanf(v, "%dx%d%c", &w, &h, &tail) != 2 || w <= 0 || h <= 0)
        return make_error("command line: -res needs WIDTHxHEIGHT (e.g. -res 640x480)");
      out->width = w;
      out->height = h;
    } else if (std::strcmp(a, "-fov") == 0) {
      if (!(v = value(i)) || !parse_float(v, &out->fov) || out->fov < 10.0f || out->fov > 170.0f)
        return make_error("command line: -fov needs degrees between 10 and 170");
    } else if (std::strcmp(a, "-frames") == 0) {
      if (!(v = value(i)) || !parse_int(v, &out->frames) || out->frames < 0)
        return make_error("command line: -frames needs a count");
    } else {
      append(out->ignored, sizeof out->ignored, a, ' ');
    }
  }
  return Status::ok();
}

}  // namespace sb::host
