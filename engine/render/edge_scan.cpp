// engine/render/edge_scan.cpp: the active edge list, scanline by scanline.
//
// Per scanline y:
//   1. edges whose first scanline is y (the bucket row_heads[y]) are sorted by x and
//      merged into the active edge list (AET), which is kept sorted by x;
//   2. the AET is walked left to right. Each edge moves its surface's winding count up
//      (leading) or down (trailing); a surface is "in" while its count is positive. The
//      "in" surfaces sit in a list sorted by key, ending in the background (key max), so
//      the list head is always the nearest surface at the current x. Whenever the head
//      changes at pixel position px, the old head gets the span [span_start, px);
//   3. at the end of the row the head (the background, for well-formed input) gets the
//      rest of the row; every pixel therefore lands in exactly one span;
//   4. edges that end are dropped, the rest step by dx and are re-sorted (insertion sort:
//      the list is nearly sorted, only crossing edges move).
// A winding count rather than an on/off flag keeps the state right when a surface's own
// edges meet at one x in any order, and for slightly non-convex projected polygons.
//
// Span budget: a span is only added while room remains for one span per remaining row
// plus one to close the current row. When the budget runs out, the rest of the current
// row and every later row go to the background (and *overflowed is set).
#include <algorithm>

#include "engine/render/front_local.h"

namespace sb::render::front {
namespace {

struct Scan {
  EdgeTable& t;
  TmpSpan* out;
  uint32_t max_spans;
  uint32_t num = 0;
  int y = 0;
  uint32_t top = kBackgroundSurface;  // head of the active-surface list
  int span_start = 0;
  bool overflow = false;

  // Adds [x0, x1) on row y to surface s. False when the budget is exhausted.
  bool emit(uint32_t s, int x0, int x1) {
    if (x1 <= x0) return true;
    if (num > 0) {
      TmpSpan& last = out[num - 1];
      if (last.surf == s && last.y == y && last.x + last.count == x0) {
        last.count = int16_t(last.count + (x1 - x0));
        return true;
      }
    }
    // Keep one span per later row plus one to close this row.
    if (num + 1 + uint32_t(t.height - y) > max_spans) return false;
    out[num++] = TmpSpan{int16_t(x0), int16_t(y), int16_t(x1 - x0), 0, s};
    ++t.surfs[s].num_spans;
    return true;
  }

  // The head changes at px: the old head owns [span_start, px).
  bool head_changes(int px) {
    if (!emit(top, span_start, px)) return false;  // span_start stays: the caller closes the row from it
    span_start = px;
    return true;
  }

  bool enter(uint32_t s, int px) {
    FrontSurface* sf = t.surfs;
    const uint32_t key = sf[s].key;
    if (key < sf[top].key) {
      if (!head_changes(px)) return false;
      sf[s].prev = kNone;
      sf[s].next = top;
      sf[top].prev = s;
      top = s;
      return true;
    }
    uint32_t p = top;  // the background (key max) ends the list, so this stops
    while (sf[sf[p].next].key < key) p = sf[p].next;
    uint32_t nx = sf[p].next;
    sf[s].prev = p;
    sf[s].next = nx;
    sf[p].next = s;
    sf[nx].prev = s;
    return true;
  }

  bool leave(uint32_t s, int px) {
    FrontSurface* sf = t.surfs;
    if (s == top) {
      if (!head_changes(px)) return false;
      top = sf[s].next;
      sf[top].prev = kNone;
    } else {
      sf[sf[s].prev].next = sf[s].next;
      sf[sf[s].next].prev = sf[s].prev;
    }
    sf[s].prev = sf[s].next = kNone;
    return true;
  }
};

inline bool x_less(const FrontEdge* e, uint32_t a, uint32_t b) { return e[a].x < e[b].x; }

void insertion_sort(const FrontEdge* edges, uint32_t* a, uint32_t n) {
  for (uint32_t i = 1; i < n; ++i) {
    uint32_t v = a[i];
    int32_t x = edges[v].x;
    uint32_t j = i;
    while (j > 0 && edges[a[j - 1]].x > x) {
      a[j] = a[j - 1];
      --j;
    }
    a[j] = v;
  }
}

}  // namespace

uint32_t scan_edges(EdgeTable& table, uint32_t* aet_a, uint32_t* aet_b, uint32_t* incoming, TmpSpan* out,
                    uint32_t max_spans, bool* overflowed) {
  Scan sc{table, out, max_spans};
  FrontEdge* edges = table.edges;
  FrontSurface* sf = table.surfs;
  const int width = table.width;
  uint32_t* aet = aet_a;
  uint32_t* spare = aet_b;
  uint32_t num_active = 0;

  sf[kBackgroundSurface].key = 0xffffffffu;
  sf[kBackgroundSurface].prev = sf[kBackgroundSurface].next = kNone;
  for (uint32_t s = 0; s < table.num_surfs; ++s) sf[s].winding = 0;

  for (int y = 0; y < table.height; ++y) {
    sc.y = y;
    if (sc.overflow) {  // budget gone: the background owns whole rows (room was kept for them)
      out[sc.num++] = TmpSpan{0, int16_t(y), int16_t(width), 0, kBackgroundSurface};
      ++sf[kBackgroundSurface].num_spans;
      continue;
    }

    // 1. Merge the edges starting on this row.
    uint32_t k = 0;
    for (uint32_t e = table.row_heads[y]; e != kNone; e = edges[e].next) incoming[k++] = e;
    if (k > 0) {
      if (k < 16) insertion_sort(edges, incoming, k);
      else std::sort(incoming, incoming + k, [edges](uint32_t a, uint32_t b) { return x_less(edges, a, b); });
      uint32_t i = 0, j = 0, m = 0;
      while (i < num_active && j < k) spare[m++] = x_less(edges, incoming[j], aet[i]) ? incoming[j++] : aet[i++];
      while (i < num_active) spare[m++] = aet[i++];
      while (j < k) spare[m++] = incoming[j++];
      uint32_t* t = aet; aet = spare; spare = t;
      num_active = m;
    }

    // 2. Walk the row.
    sc.top = kBackgroundSurface;
    sc.span_start = 0;
    bool ok = true;
    for (uint32_t i = 0; i < num_active && ok; ++i) {
      const FrontEdge& e = edges[aet[i]];
      int32_t px = int32_t((int64_t(e.x) + 0xffff) >> 16);  // first pixel whose centre is at or right of the edge
      if (px < 0) px = 0;
      if (px > width) px = width;
      uint32_t s = e.surf & ~kTrailingBit;
      FrontSurface& f = sf[s];
      if (e.surf & kTrailingBit) {
        if (f.winding-- == 1) ok = sc.leave(s, px);
      } else {
        if (++f.winding == 1) ok = sc.enter(s, px);
      }
    }

    // 3. Close the row.
    if (ok) ok = sc.emit(sc.top, sc.span_start, width);
    if (!ok) {
      // Out of span room: the reserve always holds this one.
      sc.overflow = true;
      if (sc.span_start < width) {
        out[sc.num++] = TmpSpan{int16_t(sc.span_start), int16_t(y), int16_t(width - sc.span_start), 0,
                                kBackgroundSurface};
        ++sf[kBackgroundSurface].num_spans;
      }
    }
    // 4. Reset the surfaces (well-formed input leaves every count at zero; reset whatever
    // did not), drop finished edges, step the rest, and re-sort only if some pair crossed.
    uint32_t m = 0;
    bool sorted = true;
    int32_t last_x = INT32_MIN;
    for (uint32_t i = 0; i < num_active; ++i) {
      FrontEdge& e = edges[aet[i]];
      FrontSurface& f = sf[e.surf & ~kTrailingBit];
      f.winding = 0;
      f.prev = f.next = kNone;
      if (e.ybottom <= y + 1) continue;
      e.x += e.dx;
      sorted &= e.x >= last_x;
      last_x = e.x;
      aet[m++] = aet[i];
    }
    sf[kBackgroundSurface].prev = sf[kBackgroundSurface].next = kNone;
    num_active = m;
    if (!sorted) insertion_sort(edges, aet, num_active);
  }
  *overflowed = sc.overflow;
  return sc.num;
}

}  // namespace sb::render::front
