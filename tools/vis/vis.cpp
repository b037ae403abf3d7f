// tools/vis/vis.cpp: the portal graph, node rows to leaf rows (clusters), the PHS, row
// compression, storing the PVS in a BSP, and the whole sbvis stage.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <map>
#include <atomic>
#include <thread>

#include "tools/vis/vis.h"
#include "tools/vis/vis_graph.h"

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

Status build_graph(const PortalFile& prt, Graph* g) {
  g->nodes = prt.num_clusters;
  g->portals.resize(prt.portals.size() * 2);
  g->node_portals.assign(size_t(g->nodes), {});
  g->words = (g->portals.size() + 63) / 64;
  for (size_t i = 0; i < prt.portals.size(); ++i) {
    const PrtPortal& pp = prt.portals[i];
    int n = int(pp.points.size() / 3);
    if (n > kMaxPts) return make_error("portal %zu: %d points (at most %d)", i, n, kMaxPts);
    if (pp.leaf[0] < 0 || pp.leaf[1] < 0 || pp.leaf[0] >= g->nodes || pp.leaf[1] >= g->nodes)
      return make_error("portal %zu: node out of range", i);
    Wind w;
    w.n = n;
    V c{0, 0, 0}, newell{0, 0, 0};
    for (int k = 0; k < n; ++k) w.p[k] = {pp.points[size_t(k * 3)], pp.points[size_t(k * 3 + 1)], pp.points[size_t(k * 3 + 2)]};
    for (int k = 0; k < n; ++k) {
      V a = w.p[k], b = w.p[(k + 1) % n];
      newell.x += (a.y - b.y) * (a.z + b.z);
      newell.y += (a.z - b.z) * (a.x + b.x);
      newell.z += (a.x - b.x) * (a.y + b.y);
      c = c + a;
    }
    c = c * (1.0 / n);
    double len = std::sqrt(dot(newell, newell));
    if (len < 1e-9) return make_error("portal %zu: degenerate winding", i);
    // Clockwise seen from the front: the front normal is minus the right-hand one.
    V front = newell * (-1.0 / len);
    Plane to_a{front, dot(front, c)};  // points into node[0]
    double r2 = 0;
    for (int k = 0; k < n; ++k) r2 = std::max(r2, dot(w.p[k] - c, w.p[k] - c));
    DPortal& ab = g->portals[i * 2];
    ab.pl = flip(to_a);
    ab.from = pp.leaf[0];
    ab.to = pp.leaf[1];
    ab.w = w;
    ab.center = c;
    ab.radius = std::sqrt(r2);
    DPortal& ba = g->portals[i * 2 + 1];
    ba.pl = to_a;
    ba.from = pp.leaf[1];
    ba.to = pp.leaf[0];
    ba.w = w;
    ba.center = c;
    ba.radius = ab.radius;
    g->node_portals[size_t(pp.leaf[0])].push_back(int(i * 2));
    g->node_portals[size_t(pp.leaf[1])].push_back(int(i * 2 + 1));
  }
  return Status::ok();
}

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Node rows (nodes x words64 of node bits) from per-portal bits: a node sees itself, the
// nodes its portals lead to, and the far nodes of every portal seen through them.
void gather_nodes(const Graph& g, const std::vector<uint64_t>& bits, size_t nwords, std::vector<uint64_t>* rows) {
  rows->assign(size_t(g.nodes) * nwords, 0);
  for (int n = 0; n < g.nodes; ++n) {
    uint64_t* row = &(*rows)[size_t(n) * nwords];
    row[size_t(n) >> 6] |= uint64_t(1) << (n & 63);
    for (int p : g.node_portals[size_t(n)]) {
      int to = g.portals[size_t(p)].to;
      row[size_t(to) >> 6] |= uint64_t(1) << (to & 63);
      const uint64_t* b = &bits[size_t(p) * g.words];
      for (size_t w = 0; w < g.words; ++w) {
        uint64_t x = b[w];
        while (x) {
          int q = int(w * 64) + __builtin_ctzll(x);
          x &= x - 1;
          int lt = g.portals[size_t(q)].to;
          row[size_t(lt) >> 6] |= uint64_t(1) << (lt & 63);
        }
      }
    }
  }
}

void symmetrise(int nodes, size_t nwords, std::vector<uint64_t>* rows) {
  for (int a = 0; a < nodes; ++a)
    for (int b = 0; b < nodes; ++b)
      if (((*rows)[size_t(a) * nwords + size_t(b >> 6)] >> (b & 63)) & 1)
        (*rows)[size_t(b) * nwords + size_t(a >> 6)] |= uint64_t(1) << (a & 63);
}

// Union of the rows named by each row (PHS of PVS rows), in 64-bit words.
void union_of_rows(int nodes, size_t nwords, const std::vector<uint64_t>& rows, std::vector<uint64_t>* out) {
  out->assign(rows.size(), 0);
  for (int a = 0; a < nodes; ++a) {
    uint64_t* o = &(*out)[size_t(a) * nwords];
    const uint64_t* r = &rows[size_t(a) * nwords];
    for (size_t w = 0; w < nwords; ++w) {
      uint64_t x = r[w];
      while (x) {
        int b = int(w * 64) + __builtin_ctzll(x);
        x &= x - 1;
        const uint64_t* rb = &rows[size_t(b) * nwords];
        for (size_t k = 0; k < nwords; ++k) o[k] |= rb[k];
      }
    }
  }
}

// Leaves counted over all leaves: sum over leaves of |leaves of the nodes in its node row|.
int64_t leaf_total(int nodes, size_t nwords, const std::vector<uint64_t>& rows, const std::vector<int64_t>& node_size) {
  int64_t sum = 0;
  for (int a = 0; a < nodes; ++a) {
    int64_t row = 0;
    for (size_t w = 0; w < nwords; ++w) {
      uint64_t x = rows[size_t(a) * nwords + w];
      while (x) {
        row += node_size[w * 64 + size_t(__builtin_ctzll(x))];
        x &= x - 1;
      }
    }
    sum += row * node_size[size_t(a)];
  }
  return sum;
}

// Leaf byte rows from node rows: a leaf's row holds the leaves of every node its node sees.
void expand_rows(const PortalFile& prt, int nodes, size_t nwords, const std::vector<uint64_t>& node_rows,
                 std::vector<uint8_t>* rows) {
  const size_t row_bytes = (size_t(prt.num_leaves) + 7) / 8;
  rows->assign(size_t(prt.num_leaves) * row_bytes, 0);
  if (!prt.clustered()) {
    for (int l = 0; l < prt.num_leaves; ++l)
      for (size_t i = 0; i < row_bytes; ++i)
        (*rows)[size_t(l) * row_bytes + i] = uint8_t(node_rows[size_t(l) * nwords + (i >> 3)] >> ((i & 7) * 8));
    return;
  }
  std::vector<std::vector<int>> members(static_cast<size_t>(nodes));
  for (int l = 0; l < prt.num_leaves; ++l) members[size_t(prt.leaf_cluster[size_t(l)])].push_back(l);
  std::vector<uint8_t> row(row_bytes);
  for (int c = 0; c < nodes; ++c) {
    std::fill(row.begin(), row.end(), 0);
    for (size_t w = 0; w < nwords; ++w) {
      uint64_t x = node_rows[size_t(c) * nwords + w];
      while (x) {
        int v = int(w * 64) + __builtin_ctzll(x);
        x &= x - 1;
        for (int l : members[size_t(v)]) row[size_t(l) >> 3] |= uint8_t(1u << (l & 7));
      }
    }
    for (int l : members[size_t(c)]) std::copy(row.begin(), row.end(), rows->begin() + ptrdiff_t(size_t(l) * row_bytes));
  }
}


// PRT2, full mode, leaf boxes known: leaf byte rows. A leaf sees every leaf of its own
// cluster and of the clusters next to it. Further away, a line from leaf L (cluster C) to
// leaf M (cluster D) leaves C through a portal p, and enters D through a portal q that p
// sees; it runs from q through p on to L, and from p through q on to M. So L is kept for M
// only when, for some such (p, q), L's box is (at least partly) in front of every
// separator of (q, p) and M's box in front of every separator of (p, q).
void refine_leaf_rows(const PortalFile& prt, const Graph& g, const std::vector<uint64_t>& vis, int threads,
                      std::vector<uint8_t>* rows) {
  const int nl = prt.num_leaves;
  const size_t rb = (size_t(nl) + 7) / 8;
  rows->assign(size_t(nl) * rb, 0);
  std::vector<std::vector<int>> members(static_cast<size_t>(g.nodes));
  for (int l = 0; l < nl; ++l) members[size_t(prt.leaf_cluster[size_t(l)])].push_back(l);
  // Partly in front: the box corner farthest along the normal, the box grown by a unit
  // (BSP29 boxes are whole units), with 0.1 units to spare.
  auto in_front = [&](int l, const Plane* seps, int ns) {
    const float* b = &prt.leaf_boxes[size_t(l) * 6];
    for (int k = 0; k < ns; ++k) {
      const Plane& pl = seps[k];
      const double n[3] = {pl.n.x, pl.n.y, pl.n.z};
      double d = -pl.d;
      for (int j = 0; j < 3; ++j) d += n[j] * (n[j] > 0 ? double(b[3 + j]) + 1.0 : double(b[j]) - 1.0);
      if (d <= -0.1) return false;
    }
    return true;
  };
  std::atomic<int> next{0};
  auto work = [&]() {
    std::vector<Plane> src_seps(static_cast<size_t>(kMaxSeps)), dst_seps(static_cast<size_t>(kMaxSeps));
    std::vector<int> pass_l, pass_m;
    std::vector<uint64_t> whole;  // per member of C: clusters all of whose leaves are set
    const size_t nwords = (size_t(g.nodes) + 63) / 64;
    for (;;) {
      const int c = next.fetch_add(1);
      if (c >= g.nodes) break;
      const std::vector<int>& mem = members[size_t(c)];
      whole.assign(mem.size() * nwords, 0);
      auto set_all = [&](int d) {
        for (size_t i = 0; i < mem.size(); ++i) {
          uint64_t& w = whole[i * nwords + (size_t(d) >> 6)];
          if (w >> (d & 63) & 1) continue;
          w |= uint64_t(1) << (d & 63);
          uint8_t* row = &(*rows)[size_t(mem[i]) * rb];
          for (int m : members[size_t(d)]) row[size_t(m) >> 3] |= uint8_t(1u << (m & 7));
        }
      };
      set_all(c);
      for (int p : g.node_portals[size_t(c)]) set_all(g.portals[size_t(p)].to);
      for (int p : g.node_portals[size_t(c)]) {
        const uint64_t* b = &vis[size_t(p) * g.words];
        for (size_t w = 0; w < g.words; ++w) {
          uint64_t x = b[w];
          while (x) {
            const int q = int(w * 64) + __builtin_ctzll(x);
            x &= x - 1;
            const int d = g.portals[size_t(q)].to;
            pass_l.clear();
            for (size_t i = 0; i < mem.size(); ++i)
              if (!(whole[i * nwords + (size_t(d) >> 6)] >> (d & 63) & 1)) pass_l.push_back(int(i));
            if (pass_l.empty()) continue;
            if (mem.size() > 1) {
              const int ns = find_separators(g.portals[size_t(q)].w, g.portals[size_t(p)].w, src_seps.data());
              size_t k = 0;
              for (int i : pass_l)
                if (in_front(mem[size_t(i)], src_seps.data(), ns)) pass_l[k++] = i;
              pass_l.resize(k);
              if (pass_l.empty()) continue;
            }
            const std::vector<int>& dm = members[size_t(d)];
            pass_m.clear();
            if (dm.size() > 1) {
              const int ns = find_separators(g.portals[size_t(p)].w, g.portals[size_t(q)].w, dst_seps.data());
              for (int m : dm)
                if (in_front(m, dst_seps.data(), ns)) pass_m.push_back(m);
            } else {
              pass_m = dm;
            }
            if (pass_m.size() == dm.size()) {
              for (int i : pass_l) {
                whole[size_t(i) * nwords + (size_t(d) >> 6)] |= uint64_t(1) << (d & 63);
                uint8_t* row = &(*rows)[size_t(mem[size_t(i)]) * rb];
                for (int m : dm) row[size_t(m) >> 3] |= uint8_t(1u << (m & 7));
              }
            } else {
              for (int i : pass_l) {
                uint8_t* row = &(*rows)[size_t(mem[size_t(i)]) * rb];
                for (int m : pass_m) row[size_t(m) >> 3] |= uint8_t(1u << (m & 7));
              }
            }
          }
        }
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
}

}  // namespace

std::vector<int> prt_leaf_contents(const BspData& bsp, int num_leaves) {
  std::vector<int> c(size_t(num_leaves), -1);
  for (int i = 0; i < num_leaves && size_t(i) + 1 < bsp.leaves.size(); ++i) c[size_t(i)] = bsp.leaves[size_t(i) + 1].contents;
  return c;
}

int drop_sky_portals(PortalFile* prt, const std::vector<int>& leaf_contents) {
  constexpr int kSky = -6;  // CONTENTS_SKY
  std::vector<char> sky(size_t(prt->num_clusters), 1);
  for (int l = 0; l < prt->num_leaves; ++l) {
    int node = prt->clustered() ? prt->leaf_cluster[size_t(l)] : l;
    int c = size_t(l) < leaf_contents.size() ? leaf_contents[size_t(l)] : -1;
    if (node >= 0 && node < prt->num_clusters && c != kSky) sky[size_t(node)] = 0;
  }
  size_t kept = 0;
  for (size_t i = 0; i < prt->portals.size(); ++i) {
    const PrtPortal& p = prt->portals[i];
    if (sky[size_t(p.leaf[0])] || sky[size_t(p.leaf[1])]) continue;
    if (kept != i) prt->portals[kept] = std::move(prt->portals[i]);
    ++kept;
  }
  int dropped = int(prt->portals.size() - kept);
  prt->portals.resize(kept);
  return dropped;
}

int prepare_portals(PortalFile* prt, const BspData& bsp, const VisOptions& opt) {
  int dropped = opt.trans_sky ? 0 : drop_sky_portals(prt, prt_leaf_contents(bsp, prt->num_leaves));
  prt->leaf_boxes.clear();
  if (size_t(prt->num_leaves) + 1 <= bsp.leaves.size()) {
    prt->leaf_boxes.resize(size_t(prt->num_leaves) * 6);
    for (int l = 0; l < prt->num_leaves; ++l)
      for (int k = 0; k < 3; ++k) {
        prt->leaf_boxes[size_t(l) * 6 + size_t(k)] = bsp.leaves[size_t(l) + 1].mins[k];
        prt->leaf_boxes[size_t(l) * 6 + 3 + size_t(k)] = bsp.leaves[size_t(l) + 1].maxs[k];
      }
  }
  return dropped;
}

Status compute_pvs(const PortalFile& prt, const VisOptions& opt, std::vector<uint8_t>* rows, VisStats* stats,
                   std::vector<uint8_t>* phs) {
  Graph g;
  SB_TRY(build_graph(prt, &g));
  if (prt.clustered() && prt.leaf_cluster.size() != size_t(prt.num_leaves))
    return make_error("portal file: %zu leaf clusters for %d leaves", prt.leaf_cluster.size(), prt.num_leaves);
  stats->leaves = prt.num_leaves;
  stats->clusters = g.nodes;
  stats->portals = int(prt.portals.size());
  stats->full = !opt.fast;

  std::vector<uint64_t> might, vis;
  graph_flow(g, opt, &might, opt.fast ? nullptr : &vis, &stats->seconds_fast, &stats->seconds_full, &stats->flow_steps);

  auto t1 = Clock::now();
  const int nodes = g.nodes;
  const size_t nwords = (size_t(nodes) + 63) / 64;
  std::vector<int64_t> node_size(nwords * 64, 0);
  if (prt.clustered()) {
    for (int c : prt.leaf_cluster) ++node_size[size_t(c)];
  } else {
    for (int l = 0; l < nodes; ++l) node_size[size_t(l)] = 1;
  }
  std::vector<uint64_t> node_rows, might_rows;
  gather_nodes(g, might, nwords, &might_rows);
  if (opt.symmetric) symmetrise(nodes, nwords, &might_rows);
  int64_t might_total = leaf_total(nodes, nwords, might_rows, node_size);
  if (opt.fast) {
    node_rows = std::move(might_rows);
  } else {
    gather_nodes(g, vis, nwords, &node_rows);
    if (opt.symmetric) symmetrise(nodes, nwords, &node_rows);
  }
  stats->visible_total = leaf_total(nodes, nwords, node_rows, node_size);
  std::vector<uint64_t> hear;
  union_of_rows(nodes, nwords, node_rows, &hear);
  int64_t hear_total = leaf_total(nodes, nwords, hear, node_size);
  if (prt.clustered() && !opt.fast && !opt.symmetric && prt.leaf_boxes.size() == size_t(prt.num_leaves) * 6) {
    refine_leaf_rows(prt, g, vis, opt.threads, rows);
    int64_t total = 0;
    for (uint8_t byte : *rows) total += __builtin_popcount(byte);
    stats->visible_total = total;
  } else {
    expand_rows(prt, nodes, nwords, node_rows, rows);
  }
  if (phs) expand_rows(prt, nodes, nwords, hear, phs);
  stats->row_bytes = (size_t(prt.num_leaves) + 7) / 8;
  const double nl = prt.num_leaves ? double(prt.num_leaves) : 1.0;
  stats->mean_visible = double(stats->visible_total) / nl;
  stats->mean_might = double(might_total) / nl;
  stats->mean_hearable = double(hear_total) / nl;
  stats->seconds_rows = since(t1);
  return Status::ok();
}

int64_t compute_phs(const std::vector<uint8_t>& pvs, int num_leaves, std::vector<uint8_t>* phs) {
  const size_t rb = (size_t(num_leaves) + 7) / 8;
  phs->assign(pvs.size(), 0);
  int64_t total = 0;
  for (int a = 0; a < num_leaves; ++a) {
    uint8_t* o = &(*phs)[size_t(a) * rb];
    const uint8_t* r = &pvs[size_t(a) * rb];
    for (int b = 0; b < num_leaves; ++b)
      if (r[b >> 3] & (1u << (b & 7)))
        for (size_t k = 0; k < rb; ++k) o[k] |= pvs[size_t(b) * rb + k];
    for (size_t k = 0; k < rb; ++k) total += __builtin_popcount(o[k]);
  }
  return total;
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
  char buf[1024];
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  log(user, buf);
}

}  // namespace

Status run_vis(const std::string& bsp_path, const VisOptions& opt, VisStats* stats,
               void (*log)(void*, const char*), void* user) {
  auto t0 = Clock::now();
  *stats = VisStats();
  BspData bsp;
  SB_TRY(read_bsp(bsp_path.c_str(), &bsp));
  std::string prt_path = prt_path_for(bsp_path);
  PortalFile prt;
  SB_TRY(read_prt(prt_path.c_str(), &prt));
  if (!opt.quiet) {
    if (prt.clustered())
      say(log, user, "portals: %s: PRT2, %d leaves in %d clusters, %zu portals", prt_path.c_str(), prt.num_leaves,
          prt.num_clusters, prt.portals.size());
    else
      say(log, user, "portals: %s: %d leaves, %zu portals", prt_path.c_str(), prt.num_leaves, prt.portals.size());
  }
  if (bsp.models.empty() || bsp.models[0].visleafs != prt.num_leaves)
    return make_error("%s: %d leaves, but %s has %d visleafs (stale .prt?)", prt_path.c_str(), prt.num_leaves,
                      bsp_path.c_str(), bsp.models.empty() ? 0 : bsp.models[0].visleafs);
  {
    int dropped = prepare_portals(&prt, bsp, opt);
    if (!opt.quiet && dropped) say(log, user, "sky: %d portals into sky dropped (sky is opaque; -transsky keeps them)", dropped);
  }
  const double t_read = since(t0);
  std::vector<uint8_t> rows;
  SB_TRY(compute_pvs(prt, opt, &rows, stats));
  stats->seconds_read = t_read;
  auto t2 = Clock::now();
  // vis_faces: the marksurfaces of the leaves in each leaf's PVS, averaged over leaves.
  int64_t faces = 0;
  const size_t rb = stats->row_bytes;
  for (int l = 0; l < prt.num_leaves; ++l)
    for (size_t i = 0; i < rb; ++i) {
      unsigned x = rows[size_t(l) * rb + i];
      while (x) {
        size_t leaf = i * 8 + size_t(__builtin_ctz(x)) + 1;
        x &= x - 1;
        if (leaf < bsp.leaves.size()) faces += bsp.leaves[leaf].num_marksurfaces;
      }
    }
  stats->mean_faces = prt.num_leaves ? double(faces) / prt.num_leaves : 0;
  SB_TRY(store_pvs(&bsp, prt.num_leaves, rows, stats));
  BspFormat used;
  BspFormat keep = bsp.format;
  SB_TRY(write_bsp(bsp_path.c_str(), bsp, keep, &used));
  stats->seconds_write = since(t2);
  stats->seconds_total = since(t0);
  say(log, user,
      "vis (%s, %d threads): %d portals, %d leaves%s; visible leaves per leaf %.1f (flood %.1f), PHS leaves per "
      "leaf %.1f, vis_faces %.1f; visdata %zu bytes (%zu unique rows); read %.2f s, flood %.2f s, flow %.2f s, "
      "rows %.2f s, write %.2f s, total %.2f s; %lld flow steps",
      stats->full ? "full" : "fast", opt.threads, stats->portals, stats->leaves,
      prt.clustered() ? (" in " + std::to_string(stats->clusters) + " clusters").c_str() : "", stats->mean_visible,
      stats->mean_might, stats->mean_hearable, stats->mean_faces, stats->visdata_bytes, stats->unique_rows,
      stats->seconds_read, stats->seconds_fast, stats->seconds_full, stats->seconds_rows, stats->seconds_write,
      stats->seconds_total, static_cast<long long>(stats->flow_steps));
  return Status::ok();
}

}  // namespace sb::tools::vis
