// tools/vis/flow.cpp: portal visibility on the portal graph (fast flood and full clipped
// flow), see vis.h.
//
// The graph's nodes are PRT1 leaves or PRT2 clusters. Every PRT portal becomes two directed
// portals: 2i leads from node[0] into node[1], 2i + 1 back. A directed portal's plane normal
// points into the node it leads to, so the node it leaves is behind it. Visibility is found
// per directed portal (a bitset of the directed portals seen through it), then gathered per
// node (vis.cpp expands nodes to leaves).
//
// Full flow from a source portal s (its winding W, its plane facing forward):
//   step(node, S, P, PP, via): we entered `node` through portal `via`, whose usable part is
//   P; PP is the usable part of the portal before it; S is the part of W from which a
//   straight line can still get here. For each portal q leading out of `node`:
//     T  = q's winding clipped to the front of s's plane (cached per source),
//     S' = S clipped to the back of q's plane,
//     T is clipped by every plane that has S wholly behind it and P wholly in front (a line
//       from S through P continues in front of such a plane: the "separators" of (S, P),
//       found once per step and shared by all its targets),
//     then step(q's far node, S', T, P, q).
//   With chop_source (the default) a step first narrows S by the separators of (P, PP)
//   taken the other way round (a line from S that reaches P through PP started on PP's side
//   of them); `via` is marked seen once that narrowed S is not empty. The narrowing is lazy:
//   skipped when `via` is already marked and no target of the step passes the cheap tests.
// Pruning (none of it loosens the result):
//   - might: a target must be in the bitset carried down, the intersection of the might
//     sets of the portals on the chain (a finished portal's final result stands in for its
//     flood), less the unmarked portals wholly behind a separator of (S, P) or P's plane;
//   - a target that is already marked and whose might set holds nothing unmarked is skipped
//     (all the recursion could add is there already);
//   - a passage into q whose S', T and might set lie inside those of q's first passage in
//     this source's flow is skipped (the clipped regions only shrink with their inputs;
//     with the narrowing on, the first passage must also have come through the same, no
//     smaller, pass);
//   - symmetry: a line through s ... q, read backwards, passes q^1 ... s^1 (the reversed
//     portals). A source drops from its might set every t whose reverse has finished
//     without seeing the source's reverse; and at the end a pair is kept only when both
//     directions saw it (each direction is conservative on its own).
// Order and threads: sources run in order of fewest might-see portals first, in batches of
// kBatch; a source of batch b reads the results of batches <= b - 2 only and waits for them,
// so what each flow reads is fixed by the order: identical output for any thread count.
// Windings are fixed-size arrays on per-depth frames that are allocated once per thread and
// reused: the recursion does no heap allocation once the frames and caches have grown.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <deque>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>

#include "tools/common/progress.h"
#include "tools/vis/vis.h"
#include "tools/vis/vis_graph.h"

namespace sb::tools::vis {

namespace {

inline bool test_bit(const uint64_t* b, int i) { return (b[i >> 6] >> (i & 63)) & 1; }
inline void set_bit(uint64_t* b, int i) { b[i >> 6] |= uint64_t(1) << (i & 63); }
inline void clear_bit(uint64_t* b, int i) { b[i >> 6] &= ~(uint64_t(1) << (i & 63)); }

// Keeps the part of `in` on the front of `pl` (points within kEps count as on the plane and
// are kept). Returns 0 when nothing remains, 1 when `in` is wholly kept (*out untouched),
// 2 when the clipped winding is in *out. `out` may not alias `in`. A clip that would
// overflow kMaxPts keeps `in` whole (conservative).
int clip_front(const Wind& in, const Plane& pl, Wind* out) {
  double d[kMaxPts];
  int front = 0, back = 0;
  for (int i = 0; i < in.n; ++i) {
    d[i] = pl.dist(in.p[i]);
    if (d[i] > kEps) ++front;
    else if (d[i] < -kEps) ++back;
  }
  if (back == 0) return 1;
  if (front == 0) return 0;
  if (in.n + 1 > kMaxPts) return 1;
  int m = 0;
  for (int i = 0; i < in.n; ++i) {
    int j = i + 1 == in.n ? 0 : i + 1;
    bool ib = d[i] < -kEps, jb = d[j] < -kEps;
    if (!ib) out->p[m++] = in.p[i];
    if ((ib && d[j] > kEps) || (!ib && d[i] > kEps && jb)) {
      double t = d[i] / (d[i] - d[j]);
      out->p[m++] = in.p[i] + (in.p[j] - in.p[i]) * t;
    }
  }
  out->n = m;
  return m >= 3 ? 2 : 0;
}

// Clips *cur (which points at `a` or at a buffer) by `pl`, ping-ponging between buffers a/b.
// Returns false when nothing remains.
inline bool clip_in_place(const Wind** cur, const Plane& pl, Wind* a, Wind* b) {
  Wind* out = *cur == a ? b : a;
  int r = clip_front(**cur, pl, out);
  if (r == 0) return false;
  if (r == 2) *cur = out;
  return true;
}

// Tests the plane through the edge e0 -> e0 + edge of winding e (centre ce) and the vertex q
// of the other winding v. The plane has all of e on one side (convex, planar, the plane holds
// one of its edges): it qualifies when e's centre lies off it (more than kEps) and v lies
// wholly on the other side (some point more than kEps off, none more than kEps on e's side).
// It is oriented with `back` behind and `front` in front (e_is_back: e is `back`). Distances
// are compared unnormalised (d^2 against kEps^2 |n|^2) so rejected candidates cost no
// square root.
inline bool try_separator(V e0, V edge, V q, V ce, bool e_is_back, const Wind& v, Plane* out) {
  V n = cross(edge, q - e0);
  double len2 = dot(n, n);
  if (len2 < 1e-8) return false;
  const double e2 = kEps * kEps * len2;
  const double base = dot(n, e0);
  const double dc = dot(n, ce) - base;
  if (dc * dc <= e2) return false;  // e (nearly) in the plane
  const double side = dc > 0 ? -1.0 : 1.0;  // v must lie where side * d > 0
  bool off = false;
  for (int i = 0; i < v.n; ++i) {
    double d = (dot(n, v.p[i]) - base) * side;
    if (d * d > e2) {
      if (d < 0) return false;
      off = true;
    }
  }
  if (!off) return false;
  // back behind: with e = back its centre side is negative; with e = front v (back) is.
  const double sign = e_is_back ? (dc > 0 ? -1.0 : 1.0) : (dc > 0 ? 1.0 : -1.0);
  double inv = sign / std::sqrt(len2);
  out->n = n * inv;
  out->d = base * inv;
  return true;
}

// The separators of (back, front): planes through an edge of one and a vertex of the other
// with `back` behind and `front` in front. Any line from a point of `back` through a point
// of `front` continues in front of each of them. For an edge, only the planes through the
// two angular extremes of the other winding's vertices (turning about the edge) can have
// all of that winding on one side, so only those two are tested.
// Separators for an edge of one winding are at most 2 * its points; both windings: at most
// 4 * kMaxPts planes.
}  // namespace

int find_separators(const Wind& back, const Wind& front, Plane* out) {
  int count = 0;
  Plane pl;
  for (int pass = 0; pass < 2; ++pass) {
    const Wind& e = pass == 0 ? back : front;
    const Wind& v = pass == 0 ? front : back;
    V ce{0, 0, 0};  // e's centre: e lies on its side of any plane through one of its edges
    for (int i = 0; i < e.n; ++i) ce = ce + e.p[i];
    ce = ce * (1.0 / e.n);
    for (int i = 0; i < e.n; ++i) {
      const V e0 = e.p[i];
      const V edge = e.p[i + 1 == e.n ? 0 : i + 1] - e0;
      // The first vertex off the edge's line starts both; later ones replace lo (hi) when
      // they lie behind (in front of) its plane. Vertices on the line lie on every plane.
      int k0 = 0;
      V n0{0, 0, 0};
      for (; k0 < v.n; ++k0) {
        n0 = cross(edge, v.p[k0] - e0);
        if (dot(n0, n0) >= 1e-8) break;
      }
      if (k0 == v.n) continue;
      int lo = k0, hi = k0;
      V nlo = n0, nhi = n0;
      for (int k = k0 + 1; k < v.n; ++k) {
        const V w = v.p[k] - e0;
        if (dot(nlo, w) < 0) {
          lo = k;
          nlo = cross(edge, w);
        }
        if (dot(nhi, w) > 0) {
          hi = k;
          nhi = cross(edge, w);
        }
      }
      if (lo < 0) continue;
      // v lies on the positive side of nlo and the negative side of nhi: a plane can only
      // separate when e is on the other side.
      const V c = ce - e0;
      if (dot(nlo, c) < 0 && try_separator(e0, edge, v.p[lo], ce, pass == 0, v, &pl)) out[count++] = pl;
      if (hi != lo && dot(nhi, c) > 0 && try_separator(e0, edge, v.p[hi], ce, pass == 0, v, &pl)) out[count++] = pl;
    }
  }
  return count;
}

namespace {

// Runs fn(index, worker) for index in [0, count) on `threads` threads.
template <class Fn>
void parallel_for(int count, int threads, Fn fn) {
  std::atomic<int> next{0};
  auto body = [&](int worker) {
    for (;;) {
      int i = next.fetch_add(1, std::memory_order_relaxed);
      if (i >= count) break;
      fn(i, worker);
    }
  };
  if (threads <= 1 || count < 2) {
    body(0);
    return;
  }
  std::vector<std::thread> pool;
  int n = std::min(threads, count);
  for (int t = 1; t < n; ++t) pool.emplace_back(body, t);
  body(0);
  for (std::thread& t : pool) t.join();
}

// Fast flood from portal p: portals q reachable through nodes, each at least partly in
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
    for (int q : g.node_portals[size_t(leaf)]) {
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

// True when every point of `a` lies inside the convex winding `b` (both in a plane with
// normal n), allowing 1e-4 units (far below kEps).
bool inside(const Wind& a, const Wind& b, V n) {
  V c{0, 0, 0};
  for (int i = 0; i < b.n; ++i) c = c + b.p[i];
  c = c * (1.0 / b.n);
  for (int i = 0; i < b.n; ++i) {
    V e = b.p[i + 1 == b.n ? 0 : i + 1] - b.p[i];
    V en = cross(e, n);
    double len = std::sqrt(dot(en, en));
    if (len < 1e-9) continue;
    double side = dot(en, c - b.p[i]);
    for (int k = 0; k < a.n; ++k) {
      double d = dot(en, a.p[k] - b.p[i]);
      if (side > 0 ? d < -1e-4 * len : d > 1e-4 * len) return false;
    }
  }
  return true;
}

// Per-thread state of the full flow.
struct Flow {
  const Graph& g;
  const std::vector<uint64_t>& might_all;  // portals x words: the floods (not changed by the flow)
  const std::vector<uint64_t>& vis_all;    // finished portals' results (read when done(q))
  const std::vector<int>& batch_of;        // the batch each portal is run in
  int limit = -1;                          // batches <= limit are finished (see graph_flow)
  const bool chop;                         // narrow the source on entry (VisOptions::chop_source)
  uint64_t* vis = nullptr;                 // this source's result row
  const DPortal* src = nullptr;
  std::vector<char> in_chain;              // nodes on the current path
  std::vector<uint32_t> active;            // words of the source's might set that are not zero
  std::vector<uint32_t> prev_active;       // the previous source's (to re-zero the frames)
  // Targets clipped to the front of the source plane, per target: -1 not yet, -2 empty,
  // -3 whole, else index into front_w. Reset per source through `touched`.
  std::vector<int> front_state;
  std::vector<int> touched;
  std::deque<Wind> front_w;  // a deque: pointers into it stay valid while it grows
  size_t front_used = 0;
  std::vector<uint64_t> root_might;
  int64_t n_steps = 0;
  // The first passage into each target portal in this source's flow (reset per source): a
  // later passage whose source part, target part and might set lie inside it can reach
  // nothing more (the clipped regions only shrink with their inputs), so it is skipped.
  struct Seen {
    Wind s, t, p;  // source part, target part, pass (p with chop only)
    int via = -1;  // the pass portal
    std::vector<uint64_t> might;
  };
  std::deque<Seen> seen;
  size_t seen_used = 0;
  std::vector<int> seen_of;
  struct Frame {
    Wind src;          // the entry source after the lazy narrowing
    Wind ta, tb;       // target clipping buffers
    Wind sb;           // source clipped behind the target (handed to the next step)
    int nseps = 0;
    Plane seps[kMaxSeps];
    std::vector<uint64_t> might;
  };
  std::vector<std::unique_ptr<Frame>> frames;

  Flow(const Graph& graph, const std::vector<uint64_t>& m, const std::vector<uint64_t>& v, const std::vector<int>& b,
       bool chop_source)
      : g(graph), might_all(m), vis_all(v), batch_of(b), chop(chop_source), in_chain(size_t(graph.nodes), 0),
        front_state(graph.portals.size(), -1), root_might(graph.words, 0), seen_of(graph.portals.size(), -1) {}

  bool done(int q) const { return batch_of[size_t(q)] <= limit; }

  Frame& frame(size_t depth) {
    while (frames.size() <= depth) {
      frames.push_back(std::make_unique<Frame>());
      frames.back()->might.assign(g.words, 0);
    }
    return *frames[depth];
  }

  const Wind* front_of_source(int q) {
    int s = front_state[size_t(q)];
    if (s == -1) {
      touched.push_back(q);
      if (front_used == front_w.size()) front_w.emplace_back();
      int r = clip_front(g.portals[size_t(q)].w, src->pl, &front_w[front_used]);
      s = r == 0 ? -2 : r == 1 ? -3 : int(front_used++);
      front_state[size_t(q)] = s;
    }
    if (s == -2) return nullptr;
    return s == -3 ? &g.portals[size_t(q)].w : &front_w[size_t(s)];
  }

  // The flow from directed portal p; vis row already holds what is known in advance.
  void run(int p, int finished_limit, uint64_t* vis_row) {
    limit = finished_limit;
    vis = vis_row;
    src = &g.portals[size_t(p)];
    const int rp = p ^ 1;
    // Root might set: the flood, without the portals whose reverse has finished and does not
    // see this portal's reverse (symmetry).
    const uint64_t* m = &might_all[size_t(p) * g.words];
    for (uint32_t w : prev_active)
      for (auto& f : frames) f->might[w] = 0;
    active.clear();
    for (size_t w = 0; w < g.words; ++w) {
      uint64_t x = m[w];
      uint64_t keep = x;
      while (x) {
        int t = int(w * 64) + __builtin_ctzll(x);
        x &= x - 1;
        int rt = t ^ 1;
        if (done(rt) && !test_bit(&vis_all[size_t(rt) * g.words], rp)) keep &= ~(uint64_t(1) << (t & 63));
      }
      root_might[w] = keep;
      if (keep) active.push_back(uint32_t(w));
    }
    prev_active = active;
    in_chain[size_t(src->from)] = 1;
    step(src->to, src->w, nullptr, nullptr, -1, root_might.data(), 0);
    in_chain[size_t(src->from)] = 0;
    for (int q : touched) front_state[size_t(q)] = -1, seen_of[size_t(q)] = -1;
    seen_used = 0;
    touched.clear();
    front_used = 0;
  }

  void step(int node, const Wind& src_in, const Wind* pass, const Wind* prev_pass, int via, const uint64_t* might,
            size_t depth) {
    Frame& f = frame(depth);
    ++n_steps;
    const Wind* s = &src_in;
    bool narrowed = prev_pass == nullptr || !chop;
    auto narrow = [&]() -> bool {
      if (narrowed) return true;
      narrowed = true;
      f.nseps = find_separators(*pass, *prev_pass, f.seps);
      const Wind* cur = &src_in;
      for (int k = 0; k < f.nseps; ++k)
        if (!clip_in_place(&cur, f.seps[k], &f.ta, &f.tb)) return false;
      if (cur != &src_in) {
        f.src = *cur;
        s = &f.src;
      }
      return true;
    };
    if (via >= 0 && !test_bit(vis, via)) {
      if (!narrow()) return;
      set_bit(vis, via);
    }
    in_chain[size_t(node)] = 1;
    // Every line from the source through the pass continues in front of the pass's plane and
    // of each separator of (source, pass): a portal wholly behind one of them cannot be seen
    // from here on (a bounding-sphere test first, then the points).
    const Plane* pass_plane = pass ? &g.portals[size_t(via)].pl : nullptr;
    auto hidden = [&](int r) {
      const DPortal& pr = g.portals[size_t(r)];
      for (int k = 0; k <= f.nseps; ++k) {
        const Plane& pl = k < f.nseps ? f.seps[k] : *pass_plane;
        const double dc = pl.dist(pr.center);
        if (dc < -pr.radius - kEps) return true;
        if (dc < pr.radius) {
          bool behind = true;
          for (int i = 0; i < pr.w.n && behind; ++i) behind = pl.dist(pr.w.p[i]) < -kEps;
          if (behind) return true;
        }
      }
      return false;
    };
    if (pass) {
      bool any = false;
      for (int q : g.node_portals[size_t(node)])
        if (test_bit(might, q) && !in_chain[size_t(g.portals[size_t(q)].to)]) any = true;
      if (!any || !narrow()) {
        in_chain[size_t(node)] = 0;
        return;
      }
      f.nseps = find_separators(*s, *pass, f.seps);
    }
    for (int q : g.node_portals[size_t(node)]) {
      if (!test_bit(might, q)) continue;
      const DPortal& t = g.portals[size_t(q)];
      if (in_chain[size_t(t.to)]) continue;  // a line crosses a convex node once
      if (pass && hidden(q)) continue;
      // What q can see at most: its finished result when there is one, else its might set;
      // less the portals not yet seen that the separators hide (those already seen stay:
      // the recursion may pass through them, and tests them itself).
      const uint64_t* qm = done(q) ? &vis_all[size_t(q) * g.words] : &might_all[size_t(q) * g.words];
      uint64_t more = 0;
      for (uint32_t w : active) {
        uint64_t x = might[w] & qm[w];
        uint64_t fresh = x & ~vis[w];
        if (pass) {
          uint64_t y = fresh;
          while (y) {
            const int r = int(w * 64) + __builtin_ctzll(y);
            y &= y - 1;
            if (hidden(r)) {
              x &= ~(uint64_t(1) << (r & 63));
              fresh &= ~(uint64_t(1) << (r & 63));
            }
          }
        }
        f.might[w] = x;
        more |= fresh;
      }
      if (!more && test_bit(vis, q)) continue;  // nothing new can be reached through q
      const Wind* target = front_of_source(q);  // in front of the source portal...
      if (!target) continue;
      if (!narrow()) break;  // the source is empty: nothing here is visible
      // ...and the source behind the target.
      const Wind* sq = s;
      int r = clip_front(*s, flip(t.pl), &f.sb);
      if (r == 0) continue;
      if (r == 2) sq = &f.sb;
      if (pass) {  // (the separators were found above)
        bool empty = false;
        for (int k = 0; k < f.nseps; ++k)
          if (!clip_in_place(&target, f.seps[k], &f.ta, &f.tb)) {
            empty = true;
            break;
          }
        if (empty) continue;
      }
      if (pass) {
        int e = seen_of[size_t(q)];
        if (e >= 0) {
          Seen& o = seen[size_t(e)];
          bool sub = true;
          for (uint32_t w : active)
            if (f.might[w] & ~o.might[w]) {
              sub = false;
              break;
            }
          // With the source narrowing on, the next step also narrows by (target, pass): the
          // earlier passage must then have come through the same pass, no smaller.
          if (sub && chop) sub = o.via == via && inside(*pass, o.p, g.portals[size_t(via)].pl.n);
          if (sub && inside(*target, o.t, t.pl.n) && inside(*sq, o.s, src->pl.n)) continue;
        } else {
          if (seen_used == seen.size()) seen.emplace_back();
          Seen& o = seen[seen_used];
          seen_of[size_t(q)] = int(seen_used++);
          o.s = *sq;
          o.t = *target;
          o.via = via;
          if (chop) o.p = *pass;
          o.might.resize(g.words);
          for (uint32_t w : active) o.might[w] = f.might[w];
        }
      }
      step(t.to, *sq, target, pass, q, f.might.data(), depth + 1);
    }
    in_chain[size_t(node)] = 0;
  }
};

}  // namespace

// See vis_graph.h.
void graph_flow(const Graph& g, const VisOptions& opt, std::vector<uint64_t>* might_out, std::vector<uint64_t>* vis_out,
                double* seconds_fast, double* seconds_full, int64_t* flow_steps) {
  using Clock = std::chrono::steady_clock;
  auto secs = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const int np = int(g.portals.size());
  const int threads = opt.threads < 1 ? 1 : opt.threads;
  const Progress::Mode mode = opt.quiet ? Progress::Mode::Quiet : Progress::Mode::Auto;
  auto t0 = Clock::now();
  std::vector<uint64_t>& might = *might_out;
  might.assign(size_t(np) * g.words, 0);
  {
    Progress prog("vis flood", np, mode);
    std::vector<std::vector<int>> stacks(static_cast<size_t>(threads));
    std::vector<std::vector<char>> seen(size_t(threads), std::vector<char>(size_t(g.nodes)));
    parallel_for(np, threads, [&](int p, int w) {
      flood_might(g, p, &might[size_t(p) * g.words], &stacks[size_t(w)], &seen[size_t(w)]);
      prog.advance();
    });
    prog.finish();
  }
  *seconds_fast = secs(t0);
  *seconds_full = 0;
  *flow_steps = 0;
  if (!vis_out) return;

  auto t1 = Clock::now();
  std::vector<uint64_t>& vis = *vis_out;
  vis.assign(size_t(np) * g.words, 0);
  // Portals that might see little first: they finish quickly and their results then bound
  // the flow through them. A portal of batch b (kBatch portals in this order) reads the
  // results of batches <= b - 2 only, and waits until those are complete: what every flow
  // reads is fixed by the order, so the output does not depend on the thread count or
  // timing, while a thread may run one batch ahead of a slow one.
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
  constexpr int kBatch = 16;
  const int nbatches = (np + kBatch - 1) / kBatch;
  std::vector<int> batch_of(static_cast<size_t>(np));
  std::vector<int> left(static_cast<size_t>(nbatches), 0);
  for (int i = 0; i < np; ++i) {
    batch_of[size_t(order[size_t(i)])] = i / kBatch;
    ++left[size_t(i / kBatch)];
  }
  std::vector<std::unique_ptr<Flow>> flows;
  for (int t = 0; t < threads; ++t) flows.push_back(std::make_unique<Flow>(g, might, vis, batch_of, opt.chop_source));
  Progress prog("vis flow", np, mode);
  std::mutex mu;
  std::condition_variable cv;
  int complete = -1;  // batches <= complete are finished (guarded by mu)
  std::atomic<int> next{0};
  auto worker = [&](int w) {
    for (;;) {
      const int i = next.fetch_add(1, std::memory_order_relaxed);
      if (i >= np) break;
      const int b = i / kBatch;
      {
        std::unique_lock<std::mutex> lock(mu);
        cv.wait(lock, [&] { return complete >= b - 2; });
      }
      const int p = order[size_t(i)];
      flows[size_t(w)]->run(p, b - 2, &vis[size_t(p) * g.words]);
      prog.advance();
      std::lock_guard<std::mutex> lock(mu);
      if (--left[size_t(b)] == 0) {
        while (complete + 1 < nbatches && left[size_t(complete + 1)] == 0) ++complete;
        cv.notify_all();
      }
    }
  };
  {
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker, t);
    worker(0);
    for (std::thread& t : pool) t.join();
  }
  // Both directions of a line are computed (s sees q, q^1 sees s^1); each is conservative,
  // so a pair is kept only when both agree.
  for (int p = 0; p < np; ++p) {
    uint64_t* vp = &vis[size_t(p) * g.words];
    for (size_t w = 0; w < g.words; ++w) {
      uint64_t x = vp[w];
      while (x) {
        int q = int(w * 64) + __builtin_ctzll(x);
        x &= x - 1;
        if (!test_bit(&vis[size_t(q ^ 1) * g.words], p ^ 1)) clear_bit(vp, q);
      }
    }
  }
  int64_t steps = 0;
  for (auto& f : flows) steps += f->n_steps;
  *flow_steps = steps;
  *seconds_full = secs(t1);
  prog.finish();
}

}  // namespace sb::tools::vis
