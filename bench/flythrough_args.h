// bench/flythrough_args.h: the command line and log sink the flythrough tools share
// (bench/kernel_ratio_bench.cpp, bench/span_hist.cpp): --markdown=FILE, --frames=N,
// --maps=a,b and --res=WxH,... over the defaults the caller puts in FlythroughArgs.
#pragma once
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/log.h"

namespace sb::bench {

struct FlythroughArgs {
  std::string markdown;  // empty: no file
  int frames = 300;
  std::vector<std::string> maps = {"start", "lq_e0m1", "lq_e1m1"};
  std::vector<std::pair<int, int>> res;
};

// "a,b,,c" -> {"a", "b", "c"}.
inline std::vector<std::string> split_commas(const char* s) {
  std::vector<std::string> out;
  std::string cur;
  for (; *s; ++s) {
    if (*s == ',') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += *s;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

// Parses argv[1 ..] into a; false (with the usage on stderr) on an argument it does not know.
inline bool parse_flythrough_args(int argc, char** argv, FlythroughArgs& a) {
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--markdown=", 11) == 0) {
      a.markdown = argv[i] + 11;
    } else if (std::strncmp(argv[i], "--frames=", 9) == 0) {
      a.frames = std::max(1, std::atoi(argv[i] + 9));
    } else if (std::strncmp(argv[i], "--maps=", 7) == 0) {
      a.maps = split_commas(argv[i] + 7);
    } else if (std::strncmp(argv[i], "--res=", 6) == 0) {
      a.res.clear();
      for (const std::string& r : split_commas(argv[i] + 6)) {
        int w = 0, h = 0;
        if (std::sscanf(r.c_str(), "%dx%d", &w, &h) == 2 && w > 0 && h > 0) a.res.push_back({w, h});
      }
    } else {
      std::fprintf(stderr, "usage: %s [--markdown=FILE] [--frames=N] [--maps=a,b] [--res=WxH,...]\n", argv[0]);
      return false;
    }
  }
  return true;
}

// A log sink that prints warnings and errors only (map loading logs every lump at Info).
inline void quiet_sink(void*, LogLevel level, const char* line) {
  if (level != LogLevel::Info) std::fprintf(stderr, "%s\n", line);
}

}  // namespace sb::bench
