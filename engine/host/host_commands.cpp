// engine/host/host_commands.cpp: the console commands and cvars of the host.
//
//   map / viewmap <name>       load maps/<name>.bsp (level arena), view it from the player start
//   viewpos x y z [yaw [pitch]] place the camera
//   fov <deg> (cvar)           horizontal field of view, 10..170
//   r_singlepass 0|1 (cvar)    world surfaces from the surface cache (0) or single pass (1)
//   screenshot <file.png>      render now and write the frame through the platform's PNG writer
//   flythrough [frames]        fly the camera path; prints frames, seconds, ms/frame median, worst
//   memstats                   the memory report
//   quit, wait, echo, help
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "engine/core/log.h"
#include "engine/host/host_local.h"

namespace sb::host {
namespace {

HostState& H(void* user) { return *static_cast<HostState*>(user); }

bool parse_float(const char* s, float* out) {
  char* end = nullptr;
  float v = std::strtof(s, &end);
  if (end == s || *end != '\0' || !std::isfinite(v)) return false;
  *out = v;
  return true;
}

void cmd_map(void* user, const CommandArgs& args) {
  HostState& h = H(user);
  if (args.argc != 2) {
    log_error("usage: %s <name>   (loads maps/<name>.bsp)", args.argv[0]);
    return;
  }
  if (!h.have_content) {
    log_error("%s %s: no search path (start with -basedir <dir> -game <folder>)", args.argv[0], args.argv[1]);
    return;
  }
  double t0 = host_seconds(h);
  h.world = nullptr;
  h.map_name[0] = '\0';
  h.path = CameraPath{};
  h.render_error_logged = false;
  Result<BspWorld*> world = load_world(h.files, args.argv[1], h.memory);
  if (!world) {
    log_error("%s %s: %s", args.argv[0], args.argv[1], world.message());
    return;
  }
  Result<CameraPath> path = build_camera_path(*world.value(), h.memory.level);
  if (!path) {
    log_error("%s %s: %s", args.argv[0], args.argv[1], path.message());
    h.memory.cache.flush();
    h.memory.level.reset();
    return;
  }
  h.world = world.value();
  h.path = path.value();
  std::snprintf(h.map_name, sizeof h.map_name, "%s", args.argv[1]);
  h.view = h.path.points[0];
  h.time = 0.0;
  log_info("%s %s: %u faces, %u leaves, %u camera points, %.1f ms, level arena %zu KiB", args.argv[0],
           args.argv[1], h.world->num_faces, h.world->num_leaves, unsigned(h.path.count),
           (host_seconds(h) - t0) * 1000.0, h.memory.level.used() / 1024);
}

void cmd_viewpos(void* user, const CommandArgs& args) {
  HostState& h = H(user);
  float v[5] = {0, 0, 0, h.view.yaw, h.view.pitch};
  bool ok = args.argc >= 4 && args.argc <= 6;
  for (int i = 1; ok && i < args.argc; ++i) ok = parse_float(args.argv[i], &v[i - 1]);
  if (!ok) {
    log_error("usage: viewpos x y z [yaw [pitch]]   (now %.0f %.0f %.0f %.0f %.0f)", double(h.view.origin.x),
              double(h.view.origin.y), double(h.view.origin.z), double(h.view.yaw), double(h.view.pitch));
    return;
  }
  h.view.origin = glm::vec3(v[0], v[1], v[2]);
  h.view.yaw = v[3];
  h.view.pitch = v[4] > 89.0f ? 89.0f : v[4] < -89.0f ? -89.0f : v[4];
}

void cmd_screenshot(void* user, const CommandArgs& args) {
  HostState& h = H(user);
  if (args.argc != 2) {
    log_error("usage: screenshot <file.png>");
    return;
  }
  if (!h.config.services.write_png) {
    log_error("screenshot: this platform cannot write PNG files");
    return;
  }
  if (!h.world) log_warning("screenshot: no map loaded; the picture is blank");
  render_frame(h);
  char error[256] = {};
  if (!h.config.services.write_png(h.config.services.user, args.argv[1], h.fb.pixels, h.fb.width, h.fb.height,
                                   h.fb.stride, h.palette, error, sizeof error)) {
    log_error("screenshot: %s", error[0] ? error : args.argv[1]);
    return;
  }
  log_info("screenshot: wrote %s (%dx%d)", args.argv[1], h.fb.width, h.fb.height);
}

void cmd_flythrough(void* user, const CommandArgs& args) {
  HostState& h = H(user);
  int frames = kDefaultFlythroughFrames;
  if (args.argc > 2 || (args.argc == 2 && ((frames = std::atoi(args.argv[1])) < 1 || frames > kMaxFlythroughFrames))) {
    log_error("usage: flythrough [frames]   (1..%d, default %d)", kMaxFlythroughFrames, kDefaultFlythroughFrames);
    return;
  }
  if (!h.world) {
    log_error("flythrough: no map loaded (viewmap <name> first)");
    return;
  }
  Flythrough& f = h.fly;
  f.level_mark = h.memory.level.mark();
  f.times_ms = h.memory.level.push_array<float>(size_t(frames), "flythrough frame times");
  if (!f.times_ms) {
    char msg[256];
    h.memory.level.failure_message(msg, sizeof msg);
    log_error("flythrough: %s", msg);
    return;
  }
  f.active = true;
  f.frame = 0;
  f.total = frames;
  f.saved_view = h.view;
  f.saved_time = h.time;
  f.start_seconds = host_seconds(h);
  h.console.wait();  // the rest of the buffer runs when the flight is over
}

void cmd_memstats(void* user, const CommandArgs&) { log_memory_report(H(user)); }

void cmd_quit(void* user, const CommandArgs&) {
  HostState& h = H(user);
  h.quit = true;
  h.console.wait();
}

void cmd_wait(void* user, const CommandArgs&) { H(user).console.wait(); }

void cmd_echo(void*, const CommandArgs& args) {
  char line[kMaxLineChars + 1] = {};
  size_t used = 0;
  for (int i = 1; i < args.argc; ++i) {
    int n = std::snprintf(line + used, sizeof line - used, "%s%s", i > 1 ? " " : "", args.argv[i]);
    if (n < 0 || size_t(n) >= sizeof line - used) break;
    used += size_t(n);
  }
  log_info("%s", line);
}

void print_line(void*, const char* text) { log_info("%s", text); }

void cmd_help(void* user, const CommandArgs&) {
  log_info("commands and cvars:");
  H(user).console.list(print_line, nullptr);
}

void fov_changed(void* user, const Cvar& cvar) {
  HostState& h = H(user);
  float v = cvar.value;
  if (!(v >= 10.0f && v <= 170.0f)) {
    log_warning("fov: %s is outside 10..170; using 90", cvar.string);
    h.console.set_cvar(*h.fov, "90");
  }
}

void report_line(void*, const char* line) { log_info("%s", line); }

}  // namespace

void log_memory_report(const HostState& h) { h.memory.report(report_line, nullptr); }

void flythrough_step(HostState& h) {
  Flythrough& f = h.fly;
  float fov = h.fov ? h.fov->value : 90.0f;
  h.view = camera_path_view(h.path, f.frame, f.total, fov);
  h.time = f.saved_time + f.frame * kFlythroughStep;
  double t0 = host_seconds(h);
  render_frame(h);
  f.times_ms[f.frame] = float((host_seconds(h) - t0) * 1000.0);
  if (++f.frame < f.total) return;

  double seconds = host_seconds(h) - f.start_seconds;
  float worst = *std::max_element(f.times_ms, f.times_ms + f.total);
  std::sort(f.times_ms, f.times_ms + f.total);  // in place: no heap
  float median = f.total % 2 ? f.times_ms[f.total / 2]
                             : 0.5f * (f.times_ms[f.total / 2 - 1] + f.times_ms[f.total / 2]);
  double px = double(h.fb.width) * double(h.fb.height);
  log_info("flythrough %s %dx%d: %d frames, %.3f seconds, %.3f ms/frame median, %.3f ms worst, %.2f ns/pixel",
           h.map_name, h.fb.width, h.fb.height, f.total, seconds, double(median), double(worst),
           double(median) * 1e6 / px);
  h.memory.level.pop_to(f.level_mark);
  f = Flythrough{.saved_view = f.saved_view, .saved_time = f.saved_time};
  h.view = f.saved_view;
  h.time = f.saved_time;
}

Status register_commands(HostState& h) {
  Console& c = h.console;
  SB_TRY(c.add_command("map", cmd_map, &h, "map <name>: load maps/<name>.bsp and view it"));
  SB_TRY(c.add_command("viewmap", cmd_map, &h, "viewmap <name>: load maps/<name>.bsp and view it"));
  SB_TRY(c.add_command("viewpos", cmd_viewpos, &h, "viewpos x y z [yaw [pitch]]: place the camera"));
  SB_TRY(c.add_command("screenshot", cmd_screenshot, &h, "screenshot <file.png>: write the frame as a PNG"));
  SB_TRY(c.add_command("flythrough", cmd_flythrough, &h, "flythrough [frames]: timed flight along the map's viewpoints"));
  SB_TRY(c.add_command("memstats", cmd_memstats, &h, "print the memory regions and largest allocations"));
  SB_TRY(c.add_command("quit", cmd_quit, &h, "leave the engine"));
  SB_TRY(c.add_command("wait", cmd_wait, &h, "run the rest of the command buffer next frame"));
  SB_TRY(c.add_command("echo", cmd_echo, &h, "echo <text>: print text"));
  SB_TRY(c.add_command("help", cmd_help, &h, "list commands and cvars"));
  h.fov = c.add_cvar("fov", "90", "horizontal field of view in degrees (10..170)", fov_changed, &h);
  h.speed = c.add_cvar("cl_speed", "320", "free-fly speed in units per second (shift: 3x)");
  h.animate_styles = c.add_cvar("r_lightstyles", "1", "1 = animate light styles, 0 = all normal, 2 = every style changes every frame (benchmark)");
  h.single_pass = c.add_cvar("r_singlepass", "0",
                             "1 = world surfaces drawn single pass (texture x light per pixel, no surface cache)");
  if (!h.fov || !h.speed || !h.animate_styles || !h.single_pass) return make_error("console: cvar table is full");
  return Status::ok();
}

}  // namespace sb::host
