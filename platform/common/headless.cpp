// platform/common/headless.cpp: the window-less main loop (see platform.h).
#include <cstdio>

#include "engine/host/cmdline.h"
#include "platform/common/platform.h"

namespace sb::platform {

int run_headless(const char* program, int argc, const char* const* argv) {
  host::CommandLine cl;
  Status parsed = host::parse_command_line(argc, argv, &cl);
  if (!parsed) {
    std::fprintf(stderr, "%s: %s\n", program, parsed.message());
    return 1;
  }
  PlatformBlock block;
  char error[256];
  if (!block.allocate(requested_block_mib(argc, argv), error, sizeof error)) {
    std::fprintf(stderr, "%s: %s\n", program, error);
    return 1;
  }
  HostConfig config;
  config.memory = block.data();
  config.memory_size = block.size();
  config.argc = argc;
  config.argv = argv;
  config.default_basedir = default_basedir();
  config.default_game = default_game();
  config.services = make_host_services();
  Status s = engine_init(config);
  if (!s) {
    std::fprintf(stderr, "%s: %s\n", program, s.message());
    return 1;
  }
  // Never wait for input: after the + commands comes 'quit'; without any, the
  // default map gets a screenshot and a timed flythrough.
  HostInput input;
  input.commands = cl.num_commands > 0 ? "quit" : "screenshot starbow_start.png\nflythrough 300\nquit";
  const double kStep = 1.0 / 60.0;
  for (long frame = 0;; ++frame) {
    HostFrame f = engine_frame(input, kStep);
    input.commands = nullptr;
    if (f.quit || (cl.frames > 0 && frame + 1 >= cl.frames)) break;
  }
  engine_shutdown();
  return 0;
}

}  // namespace sb::platform
