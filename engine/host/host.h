// engine/host/host.h: the only doors a platform uses.
//
//   platform main()                         engine/host
//   ---------------                         -----------
//   allocate the one block (-mem)  ------>  engine_init(config)
//                                             carve memory regions, search path (-basedir/-game),
//                                             palette + colormap, console, framebuffer for the
//                                             largest size the platform may ask for, queue the
//                                             + commands (or the default map)
//   loop:  input, dt  ------------------->  engine_frame(input, dt) -> HostFrame
//            present frame.pixels              run console text (stops while a flythrough runs),
//            with frame.palette                move the camera, animate light styles,
//            until frame.quit                  memory.begin_frame(), render_world
//                                           engine_shutdown()
//
// The platform supplies services (function pointers) for what the engine may not
// do itself: write a PNG, read a clock. The engine never includes an OS header.
// Memory: after engine_init, engine_frame never touches the heap (a test counts);
// maps load into the level arena (reset on every map change).
// One engine per process: init / frame / shutdown, then init may run again.
#pragma once
#include <cstddef>
#include <cstdint>

#include "engine/core/error.h"

namespace sb {

struct HostServices {
  void* user = nullptr;
  // Writes pixels (8-bit, width x height, stride bytes per row) through palette
  // (768 bytes RGB) as an RGB PNG. False with a message naming the file on failure.
  bool (*write_png)(void* user, const char* path, const uint8_t* pixels, int width, int height, int stride,
                    const uint8_t* palette, char* error, size_t error_size) = nullptr;
  // Seconds from a monotonic clock; only differences are used (flythrough figures).
  double (*seconds)(void* user) = nullptr;
};

struct HostConfig {
  void* memory = nullptr;  // the one block, memory_size bytes (the engine never frees it)
  size_t memory_size = 0;
  int argc = 0;            // the process command line (see cmdline.h)
  const char* const* argv = nullptr;
  const char* default_basedir = ".";  // used when -basedir is absent
  const char* default_game = "lq1";    // game folder used when neither -basedir nor -game is given
  // The largest framebuffer engine_frame may be asked for (a resizable window says
  // 1920x1080). 0 = the initial size. When it does not fit the permanent region the
  // host keeps the initial size and renders resizes at that size (logged once).
  int max_width = 0, max_height = 0;
  HostServices services;
};

struct HostInput {
  float forward = 0.0f, right = 0.0f, up = 0.0f;  // free-fly movement intents, -1..1
  float yaw_delta = 0.0f, pitch_delta = 0.0f;     // degrees to turn this frame (+yaw = left, +pitch = down)
  bool fast = false;                              // move faster (shift)
  int width = 0, height = 0;                      // new framebuffer size, 0 = keep (clamped to limits)
  const char* commands = nullptr;                 // console text to run this frame (appended)
};

// The frame to present; valid until the next engine_frame or engine_shutdown.
struct HostFrame {
  const uint8_t* pixels = nullptr;  // 8-bit palette indices
  int width = 0, height = 0, stride = 0;
  const uint8_t* palette = nullptr;  // 768 bytes RGB
  bool quit = false;                 // the console ran 'quit': call engine_shutdown
};

// Fails (message) on a bad command line, a block too small for the regions, a
// missing -basedir, or a framebuffer that does not fit. A missing map or missing
// content is not an init failure: the console says what to do.
Status engine_init(const HostConfig& config);
HostFrame engine_frame(const HostInput& input, double dt_seconds);
void engine_shutdown();

}  // namespace sb
