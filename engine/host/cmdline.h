// engine/host/cmdline.h: the Quake-style command line, parsed into plain values.
//
//   starbow -basedir ../shared/quake -game lq1 -mem 128 -res 640x480 -fov 100 -memstats
//           +viewmap start +viewpos 480 -352 88 90 0 +screenshot out.png +quit
//
// Options ("-name [value]"):
//   -basedir <dir>   root of the content (holds the game folders)
//   -game <dir>      game folder under basedir (default "lq1")
//   -mem <MiB>       size of the one memory block (the platform allocates it)
//   -memstats        print the memory report at shutdown
//   -width <px> -height <px>, or -res <W>x<H>   framebuffer size (320x200..1920x1080 by default)
//   -fov <deg>       horizontal field of view (10..170)
//   -frames <n>      platforms that run a loop stop after n frames (0 = run until quit)
// Unknown options are ignored (a platform may define its own) but listed in `ignored`.
// "+name args..." starts a console command; its arguments run until the next token that
// starts with '+' or with '-' followed by a letter (so "-352" stays an argument).
// Pure function over argv: no heap, no OS; the platform may call it before the engine
// exists (to size the memory block) and engine_init calls it again.
#pragma once
#include <cstddef>

#include "engine/core/error.h"

namespace sb::host {

constexpr int kMinWidth = 320, kMinHeight = 200;
constexpr int kMaxWidth = 1920, kMaxHeight = 1080;
constexpr int kDefaultWidth = 640, kDefaultHeight = 480;
constexpr const char* kDefaultGame = "lq1";

struct CommandLine {
  char basedir[256] = {};      // empty when -basedir was not given
  char game[64] = {};          // empty when -game was not given
  int mem_mib = 0;             // 0 when -mem was not given
  bool memstats = false;
  int width = 0, height = 0;   // 0 when not given
  float fov = 0.0f;            // 0 when not given
  int frames = 0;              // -frames value, 0 when not given
  char commands[2048] = {};    // the + commands, one per line
  int num_commands = 0;
  bool has_map_command = false;  // a +map or +viewmap is among the commands
  char ignored[256] = {};      // unknown options, space separated (for a warning)
};

// Fails with a message naming the option when a value is missing or malformed,
// or when the + commands do not fit.
Status parse_command_line(int argc, const char* const* argv, CommandLine* out);

}  // namespace sb::host
