// engine/host/host.cpp: engine_init / engine_frame / engine_shutdown.
//
// Sections: 1. state  2. framebuffer  3. init  4. frame (camera, render)  5. shutdown
#include "engine/host/host.h"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "engine/core/log.h"
#include "engine/host/host_local.h"
#include "engine/host/lightstyles.h"

namespace sb::host {

// ---- 1. state ---------------------------------------------------------------

namespace {
HostState g_host;  // static storage, not heap; reset by engine_init
}  // namespace

HostState& host_state() { return g_host; }

double host_seconds(const HostState& h) {
  return h.config.services.seconds ? h.config.services.seconds(h.config.services.user) : 0.0;
}

// ---- 2. framebuffer -----------------------------------------------------------

namespace {

int clamp_int(int v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : v; }

// Pushes pixels + zbuffer for w x h on the permanent arena. False when it does not fit
// (the arena is left as it was).
bool allocate_framebuffer(HostState& h, int w, int h_px) {
  mem::Arena& perm = h.memory.permanent;
  size_t mark = perm.mark();
  size_t count = size_t(w) * size_t(h_px);
  auto* pixels = perm.push_array<uint8_t>(count, "framebuffer");
  auto* z = pixels ? perm.push_array<uint16_t>(count, "zbuffer") : nullptr;
  if (!pixels || !z) {
    perm.pop_to(mark);
    return false;
  }
  h.pixels = pixels;
  h.zbuffer = z;
  h.fb_max_width = w;
  h.fb_max_height = h_px;
  return true;
}

}  // namespace

// Resizes within the allocation made at init: a request wider or taller than it is
// clamped to it (the platform scales at present), logged once.
Status set_framebuffer_size(HostState& h, int width, int height) {
  width = clamp_int(width, kMinWidth, kMaxWidth);
  height = clamp_int(height, kMinHeight, kMaxHeight);
  if (width > h.fb_max_width || height > h.fb_max_height) {
    if (!h.warned_resize)
      log_warning("framebuffer: %dx%d is larger than the %dx%d reserved at startup; rendering at most that "
                  "(start with a larger -res or -mem)",
                  width, height, h.fb_max_width, h.fb_max_height);
    h.warned_resize = true;
    width = width > h.fb_max_width ? h.fb_max_width : width;
    height = height > h.fb_max_height ? h.fb_max_height : height;
  }
  h.fb.pixels = h.pixels;
  h.fb.zbuffer = h.zbuffer;
  h.fb.width = width;
  h.fb.height = height;
  h.fb.stride = width;
  h.fb.coverage = nullptr;
  return Status::ok();
}

// ---- 3. init ----------------------------------------------------------------

namespace {

void missing_content_message(const HostState& h, const char* basedir, const char* game) {
  if (h.have_content)
    log_warning("no map to show: %s/%s has no maps/start.bsp (use +viewmap <name>).", basedir, game);
  else
    log_warning("no game content found: %s/%s is not a readable game folder.", basedir, game);
  log_info("  Point Starbow at a Quake-format game folder with -basedir <dir> -game <folder>, e.g.");
  log_info("    starbow -basedir /path/to/quake -game lq1 +viewmap start");
  log_info("  (LibreQuake's lq1 folder works; beside the source tree it is ../shared/quake).");
}

// Search path, palette and colormap. Missing content is reported, not fatal.
void init_content(HostState& h) {
  const char* basedir = h.cmdline.basedir[0] ? h.cmdline.basedir : h.config.default_basedir;
  if (!basedir || !*basedir) basedir = ".";
  // -game wins; with -basedir alone the game is lq1 (LibreQuake's folder); with neither,
  // the platform's default content (Starbow's own game folder when it has been built).
  const char* base_game = h.cmdline.basedir[0] || !h.config.default_game || !*h.config.default_game
                              ? kDefaultGame
                              : h.config.default_game;
  const char* game = h.cmdline.game[0] ? h.cmdline.game : base_game;
  Status s = open_search_path(h.files, basedir, game, base_game, h.memory.permanent);
  h.have_content = s.is_ok();
  if (!s) log_error("search path: %s", s.message());
  Status p = h.have_content ? load_palette_and_colormap(h.files, h.memory.scratch, h.palette, h.colormap)
                            : Status(make_error("no search path"));
  if (!p) {
    fallback_palette_and_colormap(h.palette, h.colormap);
    if (h.have_content) log_warning("%s (drawing with a grey palette)", p.message());
  }
}

// Default startup: the + commands decide; without a map among them, view Starbow's own
// sample map, or LibreQuake's start.
Status queue_startup_commands(HostState& h) {
  if (!h.cmdline.has_map_command) {
    if (h.have_content && h.files.exists("maps/sample.bsp")) {
      SB_TRY(h.console.append("viewmap sample"));
    } else if (h.have_content && h.files.exists("maps/start.bsp")) {
      SB_TRY(h.console.append("viewmap start"));
    } else {
      const char* basedir = h.cmdline.basedir[0] ? h.cmdline.basedir : h.config.default_basedir;
      missing_content_message(h, basedir ? basedir : ".", h.cmdline.game[0] ? h.cmdline.game : kDefaultGame);
    }
  }
  if (h.cmdline.commands[0]) SB_TRY(h.console.append(h.cmdline.commands));
  return Status::ok();
}

}  // namespace
}  // namespace sb::host

namespace sb {

using namespace sb::host;

Status engine_init(const HostConfig& config) {
  HostState& h = g_host;
  if (h.initialized) return make_error("engine_init: the engine is already running (call engine_shutdown first)");
  h = HostState{};
  h.config = config;
  SB_TRY(parse_command_line(config.argc, config.argv, &h.cmdline));
  if (h.cmdline.ignored[0]) log_info("command line: ignoring unknown options: %s", h.cmdline.ignored);

  char error[256];
  if (!config.memory || !h.memory.init(config.memory, config.memory_size, error, sizeof error))
    return make_error("memory: %s", config.memory ? error : "no memory block given");

  SB_TRY(h.console.init(h.memory.permanent, 64, 64, 16 * 1024));
  h.colormap = h.memory.permanent.push_array<uint8_t>(kColormapBytes, "colormap");
  if (!h.colormap) return make_error("memory: permanent region cannot fit the colormap");
  SB_TRY(register_commands(h));
  if (h.cmdline.fov > 0.0f) {
    char fov[32];
    std::snprintf(fov, sizeof fov, "%g", double(h.cmdline.fov));
    h.console.set_cvar(*h.fov, fov);
  }

  init_content(h);  // before the framebuffer: pak directories must find room in permanent

  // Framebuffer: reserve the largest size the platform may ask for, else the initial one.
  int w = clamp_int(h.cmdline.width ? h.cmdline.width : kDefaultWidth, kMinWidth, kMaxWidth);
  int ht = clamp_int(h.cmdline.height ? h.cmdline.height : kDefaultHeight, kMinHeight, kMaxHeight);
  if (h.cmdline.width && !h.cmdline.height) ht = clamp_int(w * 3 / 4, kMinHeight, kMaxHeight);
  if (h.cmdline.height && !h.cmdline.width) w = clamp_int(ht * 4 / 3, kMinWidth, kMaxWidth);
  int max_w = clamp_int(config.max_width > w ? config.max_width : w, kMinWidth, kMaxWidth);
  int max_h = clamp_int(config.max_height > ht ? config.max_height : ht, kMinHeight, kMaxHeight);
  if (!allocate_framebuffer(h, max_w, max_h)) {
    if ((max_w != w || max_h != ht) && allocate_framebuffer(h, w, ht)) {
      log_warning("framebuffer: %dx%d does not fit the permanent region; window sizes above %dx%d are "
                  "rendered at %dx%d (raise -mem)", max_w, max_h, w, ht, w, ht);
    } else {
      return make_error("memory: the permanent region (%zu KiB free) cannot fit a %dx%d framebuffer and "
                        "zbuffer (%zu KiB); raise -mem",
                        h.memory.permanent.remaining() / 1024, w, ht, size_t(w) * size_t(ht) * 3 / 1024);
    }
  }
  SB_TRY(set_framebuffer_size(h, w, ht));
  std::memset(h.pixels, 0, size_t(h.fb_max_width) * size_t(h.fb_max_height));

  SB_TRY(queue_startup_commands(h));
  h.initialized = true;
  return Status::ok();
}

}  // namespace sb

// ---- 4. frame -----------------------------------------------------------------

namespace sb::host {
namespace {

constexpr float kDegToRad = 0.017453292519943295f;

// Free-fly camera: no collision; yaw/pitch in degrees (pitch clamped to +-89).
void move_camera(HostState& h, const HostInput& in, double dt) {
  ViewParams& v = h.view;
  v.yaw = std::fmod(v.yaw + in.yaw_delta, 360.0f);
  v.pitch = v.pitch + in.pitch_delta;
  if (v.pitch > 89.0f) v.pitch = 89.0f;
  if (v.pitch < -89.0f) v.pitch = -89.0f;
  float yaw = v.yaw * kDegToRad, pitch = v.pitch * kDegToRad;
  glm::vec3 forward(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), -std::sin(pitch));
  glm::vec3 right(std::sin(yaw), -std::cos(yaw), 0.0f);
  glm::vec3 up(0.0f, 0.0f, 1.0f);
  float speed = (h.speed ? h.speed->value : 320.0f) * (in.fast ? 3.0f : 1.0f);
  v.origin += (forward * in.forward + right * in.right + up * in.up) * (speed * float(dt));
}

}  // namespace

void render_frame(HostState& h) {
  const float style_mode = h.animate_styles ? h.animate_styles->value : 1.0f;
  light_styles_at(h.time, style_mode != 0.0f, h.styles);
  // r_lightstyles 2: every style new every frame (bench/singlepass_arm.py's "dynamic").
  if (style_mode == 2.0f) light_styles_every_frame(h.rendered_frames, h.styles);
  ++h.rendered_frames;
  h.memory.begin_frame();
  if (!h.world) {
    for (int y = 0; y < h.fb.height; ++y) std::memset(h.fb.pixels + size_t(y) * size_t(h.fb.stride), 0, size_t(h.fb.width));
    return;
  }
  RenderInputs in;
  in.world = h.world;
  in.view = h.view;
  in.view.fov_x = h.fov ? h.fov->value : 90.0f;
  in.time = h.time;
  in.lightstyles = h.styles;
  in.colormap = h.colormap;
  in.single_pass = h.single_pass && h.single_pass->value != 0.0f;
  h.stats = RenderStats{};
  Status s = render_world(in, h.fb, h.memory, &h.stats);
  if (!s && !h.render_error_logged) {
    log_error("render: %s", s.message());
    h.render_error_logged = true;
  }
}

}  // namespace sb::host

namespace sb {

HostFrame engine_frame(const HostInput& input, double dt) {
  HostState& h = g_host;
  HostFrame out;
  if (!h.initialized) {
    out.quit = true;
    return out;
  }
  if (!(dt >= 0.0)) dt = 0.0;
  if (dt > 0.25) dt = 0.25;  // a stall (debugger, window drag) must not fling the camera

  if (input.commands && *input.commands) {
    Status s = h.console.append(input.commands);
    if (!s) log_error("%s", s.message());
  }
  if (input.width > 0 && input.height > 0 && (input.width != h.fb.width || input.height != h.fb.height))
    (void)set_framebuffer_size(h, input.width, input.height);

  if (!h.fly.active) h.console.execute();  // a running flythrough holds the rest of the buffer

  if (!h.quit) {
    if (h.fly.active) {
      flythrough_step(h);
    } else {
      move_camera(h, input, dt);
      h.time += dt;
      render_frame(h);
    }
  }
  out.pixels = h.fb.pixels;
  out.width = h.fb.width;
  out.height = h.fb.height;
  out.stride = h.fb.stride;
  out.palette = h.palette;
  out.quit = h.quit;
  return out;
}

// ---- 5. shutdown ------------------------------------------------------------

void engine_shutdown() {
  HostState& h = g_host;
  if (!h.initialized) return;
  if (h.cmdline.memstats) {
    log_info("memory report at exit:");
    log_memory_report(h);
  }
  h.memory.cache.flush();
  h.initialized = false;
  h.world = nullptr;
}

}  // namespace sb
