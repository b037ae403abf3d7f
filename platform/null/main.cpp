// platform/null/main.cpp: `starbow`, the headless platform (tests, CI, benchmarks).
//
//   starbow -basedir ../shared/quake -game lq1 +viewmap start +viewpos 480 -352 88 90 0
//           +screenshot out.png +quit                       (one command line)
//   starbow ... +viewmap lq_e0m1 +flythrough 300 +quit
//
// No window, no input: frames run back to back with a fixed 1/60 s step. It never
// waits for input, so it always ends:
//   - with + commands: they run, then a 'quit' appended after them;
//   - without any: the default map (start) is shown, a screenshot written to
//     starbow_start.png and a 300-frame flythrough timed, then quit;
//   - -frames N stops after N frames in any case.
// Exit code: 0 after quit, 1 when the engine could not start.
#include "platform/common/platform.h"

int main(int argc, char** argv) {
  sb::platform::install_stdout_log();
  return sb::platform::run_headless("starbow", argc, argv);
}
