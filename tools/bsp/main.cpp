// tools/bsp/main.cpp: sbbsp, the BSP stage of Starbow's map compiler.
//   sbbsp [options] file.map [file.bsp]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "tools/bsp/compile.h"

namespace {

void usage() {
  std::fprintf(stderr,
               "usage: sbbsp [options] file.map [file.bsp]\n"
               "  -wad <path>       WAD file or folder to search for textures (repeatable)\n"
               "  -subdivide <n>    largest face extent in texels before subdivision (default 240, 0: off)\n"
               "  -nofill           keep the outside (no outside removal, no .prt)\n"
               "  -noclip           no clipping hulls 1 and 2\n"
               "  -notjunc          do not fix T-junctions (vertices inside other faces' edges)\n"
               "  -prt1             write PRT1 leaf portals even when the map has func_detail (default PRT2)\n"
               "  -clusterleaves <n>  PRT2: split a detail cluster of more than n leaves (default 0: never)...\n"
               "  -clusterextent <u>  ...when its leaves also span more than u units (default 512)\n"
               "  -noprogress       no progress bar / progress lines on stderr\n"
               "  -threads <n>      worker threads (default 2; 1 = everything on one thread)\n"
               "  -bsp2             write BSP2 even when BSP29 would do\n"
               "  -2psb             write 2PSB (RMQ's BSP2 variant with 16-bit bounds)\n"
               "  -bsp29            write BSP29 or fail, naming the BSP29 limit the map exceeds\n"
               "                    (default: BSP29 when it fits, else BSP2)\n"
               "  -verbose          more progress lines\n"
               "  -q                quiet: errors only\n");
}

void print_line(void*, const char* line) { std::printf("%s\n", line); std::fflush(stdout); }

bool number_arg(int argc, char** argv, int* i, double* out) {
  if (*i + 1 >= argc) return false;
  char* end = nullptr;
  double v = std::strtod(argv[*i + 1], &end);
  if (!end || *end) return false;
  *out = v;
  ++*i;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  sb::tools::bsp::BspOptions opt;
  std::string files[2];
  int nfiles = 0;
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    double v = 0;
    if (a[0] == '-' && a[1] == '-') ++a;
    if (!std::strcmp(a, "-wad")) {
      if (i + 1 >= argc) { usage(); return 2; }
      opt.wads.push_back(argv[++i]);
    } else if (!std::strcmp(a, "-subdivide")) {
      if (!number_arg(argc, argv, &i, &v) || v < 0) { std::fprintf(stderr, "sbbsp: -subdivide needs a number >= 0\n"); return 2; }
      opt.subdivide = v;
    } else if (!std::strcmp(a, "-threads")) {
      if (!number_arg(argc, argv, &i, &v) || v < 1) { std::fprintf(stderr, "sbbsp: -threads needs a number >= 1\n"); return 2; }
      opt.threads = int(v);
    } else if (!std::strcmp(a, "-bsp2")) {
      opt.format = sb::tools::BspFormat::Bsp2;
    } else if (!std::strcmp(a, "-2psb")) {
      opt.format = sb::tools::BspFormat::Bsp2rmq;
    } else if (!std::strcmp(a, "-bsp29")) {
      opt.format = sb::tools::BspFormat::Bsp29;
    } else if (!std::strcmp(a, "-nofill")) {
      opt.fill = false;
    } else if (!std::strcmp(a, "-noclip")) {
      opt.clip_hulls = false;
    } else if (!std::strcmp(a, "-notjunc")) {
      opt.tjunc = false;
    } else if (!std::strcmp(a, "-prt1")) {
      opt.prt1_only = true;
    } else if (!std::strcmp(a, "-clusterleaves")) {
      if (!number_arg(argc, argv, &i, &v) || v < 0) { std::fprintf(stderr, "sbbsp: -clusterleaves needs a number >= 0\n"); return 2; }
      opt.cluster_leaves = int(v);
    } else if (!std::strcmp(a, "-clusterextent")) {
      if (!number_arg(argc, argv, &i, &v) || v < 0) { std::fprintf(stderr, "sbbsp: -clusterextent needs a number >= 0\n"); return 2; }
      opt.cluster_extent = v;
    } else if (!std::strcmp(a, "-noprogress")) {
      opt.progress = false;
    } else if (!std::strcmp(a, "-verbose") || !std::strcmp(a, "-v")) {
      opt.verbose = true;
    } else if (!std::strcmp(a, "-q") || !std::strcmp(a, "-quiet")) {
      opt.quiet = true;
    } else if (!std::strcmp(a, "-h") || !std::strcmp(a, "-help")) {
      usage();
      return 0;
    } else if (a[0] == '-') {
      std::fprintf(stderr, "sbbsp: unknown option '%s'\n", argv[i]);
      usage();
      return 2;
    } else if (nfiles < 2) {
      files[nfiles++] = argv[i];
    } else {
      usage();
      return 2;
    }
  }
  if (nfiles == 0) { usage(); return 2; }
  opt.map_path = files[0];
  if (nfiles > 1) opt.bsp_path = files[1];
  sb::tools::bsp::CompileReport rep;
  sb::Status s = sb::tools::bsp::compile_map(opt, &rep, print_line, nullptr);
  if (!s) {
    std::fprintf(stderr, "sbbsp: error: %s\n", s.message());
    return 1;
  }
  return 0;
}
