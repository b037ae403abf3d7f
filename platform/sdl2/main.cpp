// platform/sdl2/main.cpp: `starbow_sdl`, the engine in a resizable SDL2 window.
//
//   keys: W/S forward/back, A/D strafe, space/C up/down, shift faster, Esc quits;
//   mouse looks around (relative mouse mode).
//   -scale K (1..8, default 1): the window opens at K x the render size (-res, default
//   640x480), and the render size follows the window's drawable size / K (clamped to
//   320x200..1920x1080). Each frame the 8-bit picture is expanded through the palette AND
//   scaled by K in one pass on the CPU (asm/ expand_palette, the tuned variant: each pixel
//   becomes a K x K square) into a streaming ARGB texture of K x the render size, which is
//   copied 1:1, centred. Only when the window cannot hold that (it is smaller than K x the
//   minimum render size) does SDL shrink it to fit, keeping the aspect.
//   (There is no console-variable system yet: the scale is a command-line choice.)
//   -frames N quits after N frames (tests); + commands work as in `starbow`, and
//   console lines typed into the terminal run as they arrive.
//
// No display: when SDL cannot start video, or it picked the offscreen / dummy
// driver by itself (no DISPLAY: SDL 2.26 falls back to offscreen), we say so and
// run headless exactly like `starbow` (exit code 0). Naming a driver explicitly
// (SDL_VIDEODRIVER=dummy or offscreen) keeps the SDL path, e.g. for tests.
#include <SDL.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "asm/kernels.h"
#include "engine/host/cmdline.h"
#include "engine/host/host.h"
#include "platform/common/platform.h"

namespace {

using namespace sb;

constexpr float kMouseDegreesPerPixel = 0.15f;

// True when SDL video started on a driver that shows something, or on one the
// user named. On false, *why says what happened (SDL is shut down again).
bool start_video(char* why, size_t why_size) {
  const char* requested = std::getenv("SDL_VIDEODRIVER");
  bool named = requested && *requested;
  if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_EVENTS) != 0) {
    std::snprintf(why, why_size, "SDL could not start video (%s)", SDL_GetError());
    return false;
  }
  const char* driver = SDL_GetCurrentVideoDriver();
  if (!named && driver && (std::strcmp(driver, "offscreen") == 0 || std::strcmp(driver, "dummy") == 0)) {
    std::snprintf(why, why_size, "no display (SDL chose its '%s' video driver)", driver);
    SDL_Quit();
    return false;
  }
  return true;
}

constexpr int kMaxScale = 8;

struct Presenter {
  SDL_Window* window = nullptr;
  SDL_Renderer* renderer = nullptr;
  SDL_Texture* texture = nullptr;
  int tex_w = 0, tex_h = 0;
  int scale = 1;  // -scale: each frame pixel becomes a scale x scale square on the CPU
  uint32_t argb[256] = {};
  const uint8_t* palette_seen = nullptr;

  bool present(const HostFrame& f) {
    if (!f.pixels || f.width <= 0 || f.height <= 0) return true;
    const int k = scale, w = f.width * k, h = f.height * k;
    if (!texture || tex_w != w || tex_h != h) {
      if (texture) SDL_DestroyTexture(texture);
      texture = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_ARGB8888, SDL_TEXTUREACCESS_STREAMING, w, h);
      if (!texture) return false;
      tex_w = w;
      tex_h = h;
    }
    for (int i = 0; i < 256; ++i) {  // cheap enough per frame; palettes may change later (flashes)
      const uint8_t* c = f.palette + i * 3;
      argb[i] = 0xff000000u | uint32_t(c[0]) << 16 | uint32_t(c[1]) << 8 | c[2];
    }
    void* dst = nullptr;
    int pitch = 0;
    if (SDL_LockTexture(texture, nullptr, &dst, &pitch) != 0) return false;
    // Palette and integer scale in one pass (asm/palette_expand.h); SDL's pitch is in bytes
    // and a multiple of 4 for a 32-bit format.
    simd::active().expand_palette(f.pixels, f.stride, f.width, f.height, argb, static_cast<uint32_t*>(dst),
                                  pitch / 4, k);
    SDL_UnlockTexture(texture);
    int ow = 0, oh = 0;
    SDL_GetRendererOutputSize(renderer, &ow, &oh);
    SDL_Rect dst_rect{0, 0, w, h};
    if (w > ow || h > oh) {  // the window is smaller than the scaled frame: fit, keep aspect
      double s = double(ow) / w < double(oh) / h ? double(ow) / w : double(oh) / h;
      dst_rect.w = int(w * s);
      dst_rect.h = int(h * s);
    }
    dst_rect.x = (ow - dst_rect.w) / 2;
    dst_rect.y = (oh - dst_rect.h) / 2;
    SDL_SetRenderDrawColor(renderer, 0, 0, 0, 255);
    SDL_RenderClear(renderer);
    SDL_RenderCopy(renderer, texture, nullptr, &dst_rect);
    SDL_RenderPresent(renderer);
    return true;
  }

  void destroy() {
    if (texture) SDL_DestroyTexture(texture);
    if (renderer) SDL_DestroyRenderer(renderer);
    if (window) SDL_DestroyWindow(window);
    texture = nullptr;
    renderer = nullptr;
    window = nullptr;
  }
};

int clamp_int(int v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : v; }

// -scale K from the command line (a platform option: host::parse_command_line ignores it).
// 1 when absent; clamped to 1..kMaxScale.
int requested_scale(int argc, char** argv) {
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "-scale") == 0) return clamp_int(std::atoi(argv[i + 1]), 1, kMaxScale);
  return 1;
}

int run_window(int argc, char** argv, const host::CommandLine& cl) {
  platform::PlatformBlock block;
  char error[256];
  if (!block.allocate(platform::requested_block_mib(argc, argv), error, sizeof error)) {
    std::fprintf(stderr, "starbow_sdl: %s\n", error);
    return 1;
  }
  int w = clamp_int(cl.width ? cl.width : host::kDefaultWidth, host::kMinWidth, host::kMaxWidth);
  int h = clamp_int(cl.height ? cl.height : host::kDefaultHeight, host::kMinHeight, host::kMaxHeight);
  Presenter p;
  p.scale = requested_scale(argc, argv);
  p.window = SDL_CreateWindow("Starbow", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, w * p.scale, h * p.scale,
                              SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
  if (p.window) {
    SDL_SetWindowMinimumSize(p.window, host::kMinWidth * p.scale, host::kMinHeight * p.scale);
    p.renderer = SDL_CreateRenderer(p.window, -1, SDL_RENDERER_PRESENTVSYNC);
    if (!p.renderer) p.renderer = SDL_CreateRenderer(p.window, -1, SDL_RENDERER_SOFTWARE);
  }
  if (!p.window || !p.renderer) {
    std::fprintf(stderr, "starbow_sdl: cannot open a window (%s)\n", SDL_GetError());
    p.destroy();
    return 1;
  }

  HostConfig config;
  config.memory = block.data();
  config.memory_size = block.size();
  config.argc = argc;
  config.argv = argv;
  config.default_basedir = platform::default_basedir();
  config.default_game = platform::default_game();
  config.max_width = host::kMaxWidth;  // the window may grow to this
  config.max_height = host::kMaxHeight;
  config.services = platform::make_host_services();
  Status s = engine_init(config);
  if (!s) {
    std::fprintf(stderr, "starbow_sdl: %s\n", s.message());
    p.destroy();
    return 1;
  }
  bool mouse_look = SDL_SetRelativeMouseMode(SDL_TRUE) == 0;
  if (!mouse_look) std::printf("starbow_sdl: relative mouse mode unavailable (%s); mouse look off\n", SDL_GetError());

  std::printf("starbow_sdl: type console commands here (e.g. 'viewmap lq_e1m1', 'help'); Esc in the window quits\n");
  std::fflush(stdout);
  platform::StdinLines typed;
  double last = platform::now_seconds();
  double title_at = last, render_ms_sum = 0.0;
  int title_frames = 0;
  bool quit = false;
  for (long frame = 0; !quit; ++frame) {
    HostInput in;
    SDL_Event e;
    while (SDL_PollEvent(&e)) {
      if (e.type == SDL_QUIT) quit = true;
      if (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_ESCAPE) quit = true;
      if (e.type == SDL_MOUSEMOTION && mouse_look) {
        in.yaw_delta -= float(e.motion.xrel) * kMouseDegreesPerPixel;
        in.pitch_delta += float(e.motion.yrel) * kMouseDegreesPerPixel;
      }
    }
    const Uint8* keys = SDL_GetKeyboardState(nullptr);
    in.forward = float(keys[SDL_SCANCODE_W]) - float(keys[SDL_SCANCODE_S]);
    in.right = float(keys[SDL_SCANCODE_D]) - float(keys[SDL_SCANCODE_A]);
    in.up = float(keys[SDL_SCANCODE_SPACE]) - float(keys[SDL_SCANCODE_C]);
    in.fast = keys[SDL_SCANCODE_LSHIFT] || keys[SDL_SCANCODE_RSHIFT];
    int dw = 0, dh = 0;
    SDL_GetRendererOutputSize(p.renderer, &dw, &dh);  // resize: render at the drawable size / scale
    in.width = clamp_int(dw / p.scale, host::kMinWidth, host::kMaxWidth);
    in.height = clamp_int(dh / p.scale, host::kMinHeight, host::kMaxHeight);
    in.commands = typed.next();

    double now = platform::now_seconds();
    double t0 = now;
    HostFrame f = engine_frame(in, now - last);
    render_ms_sum += (platform::now_seconds() - t0) * 1000.0;
    last = now;
    if (f.quit) quit = true;
    if (!p.present(f)) {
      std::fprintf(stderr, "starbow_sdl: present failed (%s)\n", SDL_GetError());
      quit = true;
    }
    if (cl.frames > 0 && frame + 1 >= cl.frames) quit = true;
    ++title_frames;
    if (now - title_at >= 1.0) {
      char title[128];
      std::snprintf(title, sizeof title, "Starbow  %dx%d x%d  %.2f ms/frame  %.0f fps", f.width, f.height, p.scale,
                    render_ms_sum / title_frames, title_frames / (now - title_at));
      SDL_SetWindowTitle(p.window, title);
      title_at = now;
      title_frames = 0;
      render_ms_sum = 0.0;
    }
  }
  engine_shutdown();
  p.destroy();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  sb::platform::install_stdout_log();
  sb::host::CommandLine cl;
  sb::Status parsed = sb::host::parse_command_line(argc, argv, &cl);
  if (!parsed) {
    std::fprintf(stderr, "starbow_sdl: %s\n", parsed.message());
    return 1;
  }
  char why[256];
  if (!start_video(why, sizeof why)) {
    std::printf("starbow_sdl: %s; running headless like 'starbow' instead.\n", why);
    std::printf("starbow_sdl: (to force SDL without a screen, set SDL_VIDEODRIVER=dummy)\n");
    std::fflush(stdout);
    return sb::platform::run_headless("starbow_sdl", argc, argv);
  }
  int rc = run_window(argc, argv, cl);
  SDL_Quit();
  return rc;
}
