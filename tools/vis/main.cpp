// tools/vis/main.cpp: sbvis, the VIS stage of the map compiler.
//
//   sbvis [-fast] [-nochop] [-threads N] [-transsky] [-sym] [-q] file.bsp
//     -fast         the portal flood only (quick, looser)
//     -nochop       full flow without the source narrowing (faster, a little looser)
//     -threads N    worker threads (default 2)
//     -transsky     see through sky (by default sky is opaque: no portals into sky leaves)
//     -sym          make the PVS symmetric (a sees b => b sees a)
//     -q            quiet: the summary only
// Reads file.prt (PRT1, or PRT2 with detail clusters; written by sbbsp next to the BSP),
// prints progress on stderr and a summary line on stdout, and writes the visdata lump and every
// leaf's visofs back into file.bsp, in the format it was read in.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "tools/vis/vis.h"

namespace {

void usage() { std::fprintf(stderr, "usage: sbvis [-fast] [-nochop] [-threads N] [-transsky] [-sym] [-q] file.bsp\n"); }

void print_line(void*, const char* line) {
  std::printf("%s\n", line);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  sb::tools::vis::VisOptions opt;
  const char* path = nullptr;
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (!std::strcmp(a, "-fast")) {
      opt.fast = true;
    } else if (!std::strcmp(a, "-nochop")) {
      opt.chop_source = false;
    } else if (!std::strcmp(a, "-transsky")) {
      opt.trans_sky = true;
    } else if (!std::strcmp(a, "-sym")) {
      opt.symmetric = true;
    } else if (!std::strcmp(a, "-q")) {
      opt.quiet = true;
    } else if (!std::strcmp(a, "-threads") && i + 1 < argc) {
      char* end = nullptr;
      long v = std::strtol(argv[++i], &end, 10);
      if (*end || v < 1 || v > 256) {
        std::fprintf(stderr, "sbvis: -threads wants 1..256\n");
        return 2;
      }
      opt.threads = int(v);
    } else if (a[0] == '-') {
      std::fprintf(stderr, "sbvis: unknown option %s\n", a);
      usage();
      return 2;
    } else if (!path) {
      path = a;
    } else {
      usage();
      return 2;
    }
  }
  if (!path) {
    usage();
    return 2;
  }
  sb::tools::vis::VisStats stats;
  sb::Status st = sb::tools::vis::run_vis(path, opt, &stats, print_line, nullptr);
  if (!st) {
    std::fprintf(stderr, "sbvis: %s\n", st.message());
    return 1;
  }
  return 0;
}
