// tools/vis/flow.cpp: portal visibility (fast flood and full clipped flow), see vis.h.
//
// Every PRT portal becomes two directed portals: 2i leads from leaf[0] into leaf[1], 2i + 1
// back. A directed portal's plane normal points into the leaf it leads to, so the leaf it
// leaves is behind it. Visibility is computed per directed portal (as a bitset of directed
// portals seen through it), then gathered per leaf.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <thread>

#include "tools/vis/vis.h"

namespace sb::tools::vis {

namespace {

constexpr double kEps = 0.01;  // units: a point within kEps of a plane counts as on it
constexpr int kMaxPts = 64;    // clipped windings; a clip that would overflow is skipped

struct V {
  double x, y, z;
};
inline V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V operator*(V a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V cross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

struct Plane {
  V n;
  double d;
  double dist(V p) const { return dot(n, p) - d; }
};

// Fixed-capacity convex polygon (no heap in the recursion).
struct Wind {
  int n = 0;
  V p[kMaxPts];
  Wind() = default;
  Wind(const Wind& o) : n(o.n) { std::copy(o.p, o.p + o.n, p); }
  Wind& operator=(const Wind& o) {  // copies the used points only
    if (this != &o) {
      n = o.n;
      std::copy(o.p, o.p + o.n, p);
    }
    return *this;
  }
};

struct DPortal {
  Plane pl;        // normal into `to`
  int from, to;    // PRT leaves
  Wind w;
};

struct Graph {
  int leaves = 0;
  std::vector<DPortal> portals;
  std::vector<std::vector<int>> leaf_portals;  // directed portals leading out of each leaf
  size_t words = 0;                            // 64-bit words per portal bitset
};

inline bool test_bit(const uint64_t* b, int i) { return (b[i >> 6] >> (i & 63)) & 1; }
inline void set_bit(uint64_t* b, int i) { b[i >> 6] |= uint64_t(1) << (i & 63); }

// Keeps the part of `in` on the front of `pl` (points within kEps count as on the plane and
// are kept). Returns false when nothing remains. `out` may not alias `in`.
bool clip_front(const Wind& in, const Plane& pl, Wind* out) {
  double d[kMaxPts + 1];
  int front = 0, back = 0;
  for (int i = 0; i < in.n; ++i) {
    d[i] = pl.dist(in.p[i]);
    if (d[i] > kEps) ++front;
    else if (d[i] < -kEps) ++back;
  }
  if (back == 0) {
    *out = in;
    return true;
  }
  if (front == 0) return false;
  // Each crossing adds at most one point; the result has at most in.n + 1 points.
  if (in.n + 1 > kMaxPts) {
    *out = in;  // conservative: keep it whole
    return true;
  }
  int m = 0;
  for (int i = 0; i < in.n; ++i) {
    int j = i + 1 == in.n ? 0 : i + 1;
    bool ib = d[i] < -kEps, jb = d[j] < -kEps;
    if (!ib) out->p[m++] = in.p[i];
    // A real crossing: one end strictly in front and the other strictly behind.
    if ((ib && d[j] > kEps) || (!ib && d[i] > kEps && jb)) {
      double t = d[i] / (d[i] - d[j]);
      out->p[m++] = in.p[i] + (in.p[j] - in.p[i]) * t;
    }
  }
  out->n = m;
  return m >= 3;
}

Plane flip(const Plane& p) { return {{-p.n.x, -p.n.y, -p.n.z}, -p.d}; }

// One candidate separating plane through the edge e0-e1 and point q. Oriented so that `a`
// is behind it and `b` in front; returns false when it does not separate them.
bool separator(V e0, V e1, V q, const Wind& a, const Wind& b, Plane* out) {
  V n = cross(e1 - e0, q - e0);
  double len2 = dot(n, n);
  if (len2 < 1e-8) return false;
  n = n * (1.0 / std::sqrt(len2));
  Plane pl{n, dot(n, e0)};
  bool pos = false, neg = false;
  for (int i = 0; i < a.n; ++i) {
    double d = pl.dist(a.p[i]);
    if (d > kEps) pos = true;
    else if (d < -kEps) neg = true;
  }
  if (pos == neg) return false;  // a straddles it or lies in it
  if (pos) pl = flip(pl);
  bool ahead = false;
  for (int i = 0; i < b.n; ++i) {
    double d = pl.dist(b.p[i]);
    if (d < -kEps) return false;
    if (d > kEps) ahead = true;
  }
  if (!ahead) return false;
  *out = pl;
  return true;
}

// Any straight line from a point of `a` through a point of `b` continues on b's side of
// every plane that has `a` wholly behind and `b` wholly in front. Clips *t (in place) to
// that side for all such planes through an edge of one winding and a vertex of the other.
void find_separators(const Wind& a, const Wind& b, std::vector<Plane>* out) {
  out->clear();
  Plane pl;
  for (int pass = 0; pass < 2; ++pass) {
    const Wind& e = pass == 0 ? a : b;
    const Wind& v = pass == 0 ? b : a;
    for (int i = 0; i < e.n; ++i) {
      V e0 = e.p[i], e1 = e.p[i + 1 == e.n ? 0 : i + 1];
      for (int j = 0; j < v.n; ++j)
        if (separator(e0, e1, v.p[j], a, b, &pl)) out->push_back(pl);
    }
  }
}

bool clip_separators(const Wind& a, const Wind& b, Wind* t, Wind* tmp) {
  Plane pl;
  for (int pass = 0; pass < 2; ++pass) {
    const Wind& e = pass == 0 ? a : b;  // edges from this one
    const Wind& v = pass == 0 ? b : a;  // vertices from the other
    for (int i = 0; i < e.n; ++i) {
      V e0 = e.p[i], e1 = e.p[i + 1 == e.n ? 0 : i + 1];
      for (int j = 0; j < v.n; ++j) {
        if (!separator(e0, e1, v.p[j], a, b, &pl)) continue;
        if (!clip_front(*t, pl, tmp)) return false;
        *t = *tmp;
      }
    }
  }
  return true;
}

Status build_graph(const PortalFile& prt, Graph* g) {
  g->leaves = prt.num_leaves;
  g->portals.resize(prt.portals.size() * 2);
  g->leaf_portals.assign(size_t(prt.num_leaves), {});
  g->words = (g->portals.size() + 63) / 64;
  for (size_t i = 0; i < prt.portals.size(); ++i) {
    const PrtPortal& pp = prt.portals[i];
    int n = int(pp.points.size() / 3);
    if (n > kMaxPts) return make_error("portal %zu: %d points (at most %d)", i, n, kMaxPts);
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
    Plane to_a{front, dot(front, c)};  // points into leaf[0]
    DPortal& ab = g->portals[i * 2];
    ab.pl = flip(to_a);
    ab.from = pp.leaf[0];
    ab.to = pp.leaf[1];
    ab.w = w;
    DPortal& ba = g->portals[i * 2 + 1];
    ba.pl = to_a;
    ba.from = pp.leaf[1];
    ba.to = pp.leaf[0];
    ba.w = w;
    g->leaf_portals[size_t(pp.leaf[0])].push_back(int(i * 2));
    g->leaf_portals[size_t(pp.leaf[1])].push_back(int(i * 2 + 1));
  }
  return Status::ok();
}

// Runs fn(portal_index, worker_index) over all portals on `threads` threads.
template <class Fn>
void parallel_portals(int count, int threads, Fn fn, void (*progress)(void*, int, int), void* user) {
  std::atomic<int> next{0};
  std::atomic<int> done{0};
  std::mutex mu;
  int last_tenth = 0;
  auto body = [&](int worker) {
    for (;;) {
      int i = next.fetch_add(1);
      if (i >= count) break;
      fn(i, worker);
      int d = done.fetch_add(1) + 1;
      if (progress) {
        std::lock_guard<std::mutex> lock(mu);
        int tenth = int(int64_t(d) * 10 / count);
        if (tenth > last_tenth) {
          last_tenth = tenth;
          progress(user, d, count);
        }
      }
    }
  };
  if (threads <= 1 || count < 2) {
    body(0);
    return;
  }
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(body, t);
  for (std::thread& t : pool) t.join();
}

// Fast flood from portal p: portals q reachable through leaves, each at least partly in
// front of p while p is at least partly behind q.
void flood_might(const Graph& g, int p, uint64_t* might, std::vector<int>* stack, std::vector<char>* seen) {
  const DPortal& src = g.portals[size_t(p)];
  std::fill(seen->begin(), seen->end(), 0);
  stack->clear();
  stack->push_back(src.to);
  (*seen)[size_t(src.to)] = 1;
  while (!stack->empty()) {
    int leaf = stack->back();
    stack->pop_back();
    for (int q : g.leaf_portals[size_t(leaf)]) {
      if ((q ^ 1) == p || test_bit(might, q)) continue;
      const DPortal& t = g.portals[size_t(q)];
      bool in_front = false;
      for (int k = 0; k < t.w.n && !in_front; ++k) in_front = src.pl.dist(t.w.p[k]) > kEps;
      if (!in_front) continue;
      bool behind = false;
      for (int k = 0; k < src.w.n && !behind; ++k) behind = t.pl.dist(src.w.p[k]) < -kEps;
      if (!behind) continue;
      set_bit(might, q);
      if (!(*seen)[size_t(t.to)]) {
        (*seen)[size_t(t.to)] = 1;
        stack->push_back(t.to);
      }
    }
  }
}

// Per-thread state of the full flow.
struct Flow {
  const Graph& g;
  const std::vector<uint64_t>& might_all;  // portals x words
  const std::vector<uint64_t>& vis_all;    // finished portals' results (read when done[q])
  const std::vector<char>& done;           // changes only between batches
  uint64_t* vis = nullptr;                 // this source's result row
  const DPortal* src = nullptr;
  std::vector<char> in_chain;              // leaves on the current path
  struct Frame {
    Wind source, target, tmp;
    std::vector<uint64_t> might;
    std::vector<Plane> seps;  // separators from this step's incoming source to its pass
  };
  std::vector<std::unique_ptr<Frame>> frames;

  Flow(const Graph& graph, const std::vector<uint64_t>& m, const std::vector<uint64_t>& v, const std::vector<char>& d)
      : g(graph), might_all(m), vis_all(v), done(d), in_chain(size_t(graph.leaves), 0) {}

  Frame& frame(size_t depth) {
    while (frames.size() <= depth) {
      frames.push_back(std::make_unique<Frame>());
      frames.back()->might.resize(g.words);
    }
    return *frames[depth];
  }

  // Into `leaf`, seen from `source` (the part of the source portal still useful) through
  // `pass` (the clipped last portal; null at the first leaf), limited to `might`.
  void step(int leaf, const Wind& source, const Wind* pass, const uint64_t* might, size_t depth) {
    in_chain[size_t(leaf)] = 1;
    Frame& f = frame(depth);
    bool have_seps = false;
    for (int q : g.leaf_portals[size_t(leaf)]) {
      if (!test_bit(might, q)) continue;
      const DPortal& t = g.portals[size_t(q)];
      if (in_chain[size_t(t.to)]) continue;  // a line crosses a convex leaf once
      // What q can see at most: its finished result when there is one, else its flood.
      const uint64_t* qm = done[size_t(q)] ? &vis_all[size_t(q) * g.words] : &might_all[size_t(q) * g.words];
      uint64_t more = 0;
      for (size_t w = 0; w < g.words; ++w) {
        f.might[w] = might[w] & qm[w];
        more |= f.might[w] & ~vis[w];
      }
      if (!more && test_bit(vis, q)) continue;  // nothing new can be reached
      // The target must lie in front of the source portal...
      if (!clip_front(t.w, src->pl, &f.target)) continue;
      // ...and the source behind the target.
      if (!clip_front(source, flip(t.pl), &f.source)) continue;
      if (pass) {
        // Planes separating the whole incoming source from the pass also separate any part
        // of it, so they are found once per step and shared by all targets.
        if (!have_seps) {
          find_separators(source, *pass, &f.seps);
          have_seps = true;
        }
        bool empty = false;
        for (const Plane& pl : f.seps) {
          if (!clip_front(f.target, pl, &f.tmp)) {
            empty = true;
            break;
          }
          f.target = f.tmp;
        }
        if (empty) continue;
        if (!clip_separators(f.target, *pass, &f.source, &f.tmp)) continue;
      }
      set_bit(vis, q);
      step(t.to, f.source, &f.target, f.might.data(), depth + 1);
    }
    in_chain[size_t(leaf)] = 0;
  }
};

}  // namespace

Status compute_pvs(const PortalFile& prt, const VisOptions& opt, std::vector<uint8_t>* rows, VisStats* stats,
                   void (*progress)(void*, int, int), void* user) {
  using Clock = std::chrono::steady_clock;
  auto secs = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  auto t0 = Clock::now();
  Graph g;
  SB_TRY(build_graph(prt, &g));
  const int np = int(g.portals.size());
  const int threads = opt.threads < 1 ? 1 : opt.threads;
  stats->leaves = g.leaves;
  stats->portals = int(prt.portals.size());
  stats->full = !opt.fast;

  // Fast flood for every directed portal.
  std::vector<uint64_t> might(size_t(np) * g.words, 0);
  {
    std::vector<std::vector<int>> stacks(static_cast<size_t>(threads));
    std::vector<std::vector<char>> seen(size_t(threads), std::vector<char>(size_t(g.leaves)));
    parallel_portals(
        np, threads,
        [&](int p, int w) { flood_might(g, p, &might[size_t(p) * g.words], &stacks[size_t(w)], &seen[size_t(w)]); },
        nullptr, nullptr);
  }
  stats->seconds_fast = secs(t0);

  std::vector<uint64_t> vis;
  if (!opt.fast) {
    auto t1 = Clock::now();
    vis.assign(size_t(np) * g.words, 0);
    std::vector<char> done(size_t(np), 0);
    // Portals that might see little first; they finish quickly and their results then bound
    // the flow through them. Results are published between fixed-size batches only, so the
    // output does not depend on the thread count or timing.
    std::vector<int> order(static_cast<size_t>(np));
    std::vector<int> count(static_cast<size_t>(np));
    for (int p = 0; p < np; ++p) {
      order[size_t(p)] = p;
      int c = 0;
      for (size_t w = 0; w < g.words; ++w) c += __builtin_popcountll(might[size_t(p) * g.words + w]);
      count[size_t(p)] = c;
    }
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      return count[size_t(a)] != count[size_t(b)] ? count[size_t(a)] < count[size_t(b)] : a < b;
    });
    std::vector<std::unique_ptr<Flow>> flows;
    for (int t = 0; t < threads; ++t) flows.push_back(std::make_unique<Flow>(g, might, vis, done));
    constexpr int kBatch = 32;
    int last_tenth = 0;
    for (int b0 = 0; b0 < np; b0 += kBatch) {
      int n = std::min(kBatch, np - b0);
      parallel_portals(
        n, threads,
        [&](int i, int w) {
          int p = order[size_t(b0 + i)];
          Flow& fl = *flows[size_t(w)];
          fl.vis = &vis[size_t(p) * g.words];
          fl.src = &g.portals[size_t(p)];
          fl.in_chain[size_t(fl.src->from)] = 1;
          fl.step(fl.src->to, fl.src->w, nullptr, &might[size_t(p) * g.words], 0);
          fl.in_chain[size_t(fl.src->from)] = 0;
        },
        nullptr, nullptr);
      for (int i = 0; i < n; ++i) done[size_t(order[size_t(b0 + i)])] = 1;
      int tenth = int(int64_t(b0 + n) * 10 / np);
      if (progress && tenth > last_tenth) {
        last_tenth = tenth;
        progress(user, b0 + n, np);
      }
    }
    stats->seconds_full = secs(t1);
  }

  // Gather per leaf: itself, the leaves its portals lead to, and what they see.
  const size_t row_bytes = (size_t(g.leaves) + 7) / 8;
  stats->row_bytes = row_bytes;
  rows->assign(size_t(g.leaves) * row_bytes, 0);
  auto gather = [&](const std::vector<uint64_t>& bits, int64_t* total) {
    std::vector<uint8_t> row(row_bytes);
    int64_t sum = 0;
    for (int l = 0; l < g.leaves; ++l) {
      std::fill(row.begin(), row.end(), 0);
      row[size_t(l) >> 3] |= uint8_t(1u << (l & 7));
      for (int p : g.leaf_portals[size_t(l)]) {
        int to = g.portals[size_t(p)].to;
        row[size_t(to) >> 3] |= uint8_t(1u << (to & 7));
        const uint64_t* b = &bits[size_t(p) * g.words];
        for (size_t w = 0; w < g.words; ++w) {
          uint64_t x = b[w];
          while (x) {
            int q = int(w * 64) + __builtin_ctzll(x);
            x &= x - 1;
            int lt = g.portals[size_t(q)].to;
            row[size_t(lt) >> 3] |= uint8_t(1u << (lt & 7));
          }
        }
      }
      std::copy(row.begin(), row.end(), rows->begin() + ptrdiff_t(size_t(l) * row_bytes));
    }
    if (opt.symmetric) {
      for (int a = 0; a < g.leaves; ++a)
        for (int b = 0; b < g.leaves; ++b)
          if ((*rows)[size_t(a) * row_bytes + size_t(b >> 3)] & (1u << (b & 7)))
            (*rows)[size_t(b) * row_bytes + size_t(a >> 3)] |= uint8_t(1u << (a & 7));
    }
    for (uint8_t byte : *rows) sum += __builtin_popcount(byte);
    *total = sum;
  };
  int64_t might_total = 0;
  if (!opt.fast) {
    gather(might, &might_total);
    gather(vis, &stats->visible_total);
  } else {
    gather(might, &stats->visible_total);
    might_total = stats->visible_total;
  }
  stats->mean_visible = g.leaves ? double(stats->visible_total) / g.leaves : 0;
  stats->mean_might = g.leaves ? double(might_total) / g.leaves : 0;
  stats->seconds_total = secs(t0);
  return Status::ok();
}

}  // namespace sb::tools::vis
