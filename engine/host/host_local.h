// engine/host/host_local.h: the host's insides, shared by host.cpp (init, frame,
// rendering) and host_commands.cpp (console commands). Not for use outside host/.
//
// Memory: HostState itself is one static object (no heap); everything it points
// at lives in the block: console tables, colormap and framebuffer in the permanent
// arena; the world, its camera path and flythrough timings in the level arena.
#pragma once
#include <cstdint>

#include "engine/formats/bsp.h"
#include "engine/fs/file_system.h"
#include "engine/host/camera_path.h"
#include "engine/host/cmdline.h"
#include "engine/host/console.h"
#include "engine/host/content.h"
#include "engine/host/host.h"
#include "engine/render/render.h"
#include "memory/memory_system.h"

namespace sb::host {

constexpr int kDefaultFlythroughFrames = 300;
constexpr int kMaxFlythroughFrames = 1000000;
constexpr double kFlythroughStep = 1.0 / 30.0;  // simulated seconds per flythrough frame

struct Flythrough {
  bool active = false;
  int frame = 0, total = 0;
  float* times_ms = nullptr;   // total entries, level arena (popped when the flight ends)
  size_t level_mark = 0;
  double start_seconds = 0.0;
  ViewParams saved_view;       // restored when the flight ends
  double saved_time = 0.0;
};

struct HostState {
  bool initialized = false;
  HostConfig config;
  CommandLine cmdline;
  mem::MemorySystem memory;
  fs::FileSystem files;
  bool have_content = false;   // the search path opened
  Console console;
  Cvar* fov = nullptr;
  Cvar* speed = nullptr;
  Cvar* animate_styles = nullptr;
  Cvar* single_pass = nullptr;  // r_singlepass

  uint8_t palette[kPaletteBytes] = {};
  uint8_t* colormap = nullptr;  // kColormapBytes, permanent

  // Framebuffer: pixels and zbuffer hold fb_capacity entries (permanent); the
  // current size is fb.width x fb.height with stride == width.
  uint8_t* pixels = nullptr;
  uint16_t* zbuffer = nullptr;
  int fb_max_width = 0, fb_max_height = 0;
  Framebuffer fb;
  bool warned_resize = false;

  // The level.
  BspWorld* world = nullptr;
  char map_name[64] = {};
  CameraPath path;
  ViewParams view;
  double time = 0.0;            // seconds of game time (light styles, animation)
  int styles[kMaxLightStyleSlots] = {};
  unsigned rendered_frames = 0;  // render_frame calls (r_lightstyles 2 steps every style per frame)
  RenderStats stats;
  bool render_error_logged = false;

  Flythrough fly;
  bool quit = false;
};

HostState& host_state();

// host.cpp
void render_frame(HostState& h);  // begin_frame + render_world (or clear when no world)
Status set_framebuffer_size(HostState& h, int width, int height);
double host_seconds(const HostState& h);

// host_commands.cpp
Status register_commands(HostState& h);
void flythrough_step(HostState& h);  // renders one flythrough frame, finishes the flight
void log_memory_report(const HostState& h);

}  // namespace sb::host
