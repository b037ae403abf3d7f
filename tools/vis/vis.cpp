// tools/vis/vis.cpp: row compression, storing the PVS in a BSP, and the whole sbvis stage.
#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <map>

#include "tools/vis/vis.h"

namespace sb::tools::vis {

void compress_row(const uint8_t* row, size_t bytes, std::vector<uint8_t>* out) {
  out->clear();
  size_t i = 0;
  while (i < bytes) {
    if (row[i]) {
      out->push_back(row[i++]);
      continue;
    }
    size_t run = 0;
    while (i < bytes && row[i] == 0 && run < 255) {
      ++run;
      ++i;
    }
    out->push_back(0);
    out->push_back(uint8_t(run));
  }
}

Status store_pvs(BspData* bsp, int num_leaves, const std::vector<uint8_t>& rows, VisStats* stats) {
  if (bsp->models.empty()) return make_error("bsp: no models");
  if (bsp->models[0].visleafs != num_leaves)
    return make_error("bsp: models[0].visleafs is %d but the portal file has %d leaves (stale .prt?)",
                      bsp->models[0].visleafs, num_leaves);
  if (size_t(num_leaves) + 1 > bsp->leaves.size())
    return make_error("bsp: %zu leaves, fewer than the %d + 1 the portal file needs", bsp->leaves.size(), num_leaves);
  const size_t row_bytes = (size_t(num_leaves) + 7) / 8;
  if (rows.size() != size_t(num_leaves) * row_bytes) return make_error("vis: row buffer of the wrong size");
  bsp->visdata.clear();
  std::map<std::vector<uint8_t>, int32_t> shared;
  std::vector<uint8_t> packed;
  for (DLeaf& l : bsp->leaves) l.visofs = -1;
  for (int i = 0; i < num_leaves; ++i) {
    compress_row(&rows[size_t(i) * row_bytes], row_bytes, &packed);
    auto it = shared.find(packed);
    int32_t ofs;
    if (it != shared.end()) {
      ofs = it->second;
    } else {
      ofs = int32_t(bsp->visdata.size());
      bsp->visdata.insert(bsp->visdata.end(), packed.begin(), packed.end());
      shared.emplace(packed, ofs);
    }
    bsp->leaves[size_t(i) + 1].visofs = ofs;
  }
  if (stats) {
    stats->visdata_bytes = bsp->visdata.size();
    stats->unique_rows = shared.size();
  }
  return Status::ok();
}

namespace {

std::string prt_path_for(const std::string& bsp) {
  size_t slash = bsp.find_last_of('/');
  size_t dot = bsp.find_last_of('.');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) return bsp.substr(0, dot) + ".prt";
  return bsp + ".prt";
}

void say(void (*log)(void*, const char*), void* user, const char* fmt, ...) __attribute__((format(printf, 3, 4)));
void say(void (*log)(void*, const char*), void* user, const char* fmt, ...) {
  if (!log) return;
  char buf[512];
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  log(user, buf);
}

struct ProgressCtx {
  void (*log)(void*, const char*);
  void* user;
};

}  // namespace

Status run_vis(const std::string& bsp_path, const VisOptions& opt, VisStats* stats,
               void (*log)(void*, const char*), void* user) {
  auto t0 = std::chrono::steady_clock::now();
  *stats = VisStats();
  BspData bsp;
  SB_TRY(read_bsp(bsp_path.c_str(), &bsp));
  std::string prt_path = prt_path_for(bsp_path);
  PortalFile prt;
  SB_TRY(read_prt(prt_path.c_str(), &prt));
  if (!opt.quiet)
    say(log, user, "portals: %s: %d leaves, %zu portals", prt_path.c_str(), prt.num_leaves, prt.portals.size());
  if (bsp.models.empty() || bsp.models[0].visleafs != prt.num_leaves)
    return make_error("%s: %d leaves, but %s has %d visleafs (stale .prt?)", prt_path.c_str(), prt.num_leaves,
                      bsp_path.c_str(), bsp.models.empty() ? 0 : bsp.models[0].visleafs);
  std::vector<uint8_t> rows;
  ProgressCtx pc{log, user};
  auto progress = [](void* u, int done, int total) {
    auto* c = static_cast<ProgressCtx*>(u);
    say(c->log, c->user, "vis: %d/%d portals (%d%%)", done, total, int(int64_t(done) * 100 / total));
  };
  SB_TRY(compute_pvs(prt, opt, &rows, stats, opt.quiet ? nullptr : +progress, &pc));
  SB_TRY(store_pvs(&bsp, prt.num_leaves, rows, stats));
  BspFormat used;
  BspFormat keep = bsp.format;
  SB_TRY(write_bsp(bsp_path.c_str(), bsp, keep, &used));
  stats->seconds_total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  say(log, user,
      "vis (%s, %d threads): %d leaves, %d portals; visible leaves per leaf %.1f (fast flood %.1f); "
      "visdata %zu bytes (%zu unique rows of %zu); flood %.2f s, full %.2f s, total %.2f s",
      stats->full ? "full" : "fast", opt.threads, stats->leaves, stats->portals, stats->mean_visible,
      stats->mean_might, stats->visdata_bytes, stats->unique_rows, size_t(stats->leaves), stats->seconds_fast,
      stats->seconds_full, stats->seconds_total);
  return Status::ok();
}

}  // namespace sb::tools::vis
