// engine/render/front_end.cpp: build_spans, the front end's one door.
//
// Frame-arena layout while it runs (one push, named "render front end", carved by hand):
//
//   mark0
//   [ poly scratch | row heads | surfaces | edges | AET x3 | tmp spans | SurfaceDraw out | Span out ]
//     sized from the face list     ^ capped by need     ^ everything left goes to spans
//
// When it returns, the SurfaceDraw and Span arrays have been moved down to mark0 and the
// arena popped to just past them, so the back end gets all the rest of the frame arena.
// (The arena's named-allocation record keeps the block's peak size.)
//
// Overflow policy: when surfaces or edges run out the walk stops adding faces (the
// background shows where later, farther faces would have been); when spans run out the
// rest of the screen goes to the background. Either way every pixel is in exactly one
// span, the RenderStats flag is set, and a warning is logged once per level.
#include <cstring>

#include "engine/core/log.h"
#include "engine/render/front_local.h"

namespace sb::render {
namespace {

struct WarnState {
  const BspWorld* world = nullptr;
  uint32_t num_faces = 0;
  bool edges = false, surfaces = false, spans = false;
};
WarnState g_warned;  // per level: reset when a different world shows up

void warn_once(const BspWorld& world, bool WarnState::*flag, const char* what, uint32_t capacity) {
  if (g_warned.world != &world || g_warned.num_faces != world.num_faces) {
    g_warned = WarnState{};
    g_warned.world = &world;
    g_warned.num_faces = world.num_faces;
  }
  if (g_warned.*flag) return;
  g_warned.*flag = true;
  log_warning("render: %s: %s buffer full (%u entries from the frame arena); some surfaces are not drawn "
              "this frame (warned once per level)", world.name, what, capacity);
}

inline uint8_t* align16(uint8_t* p) {
  return reinterpret_cast<uint8_t*>((reinterpret_cast<uintptr_t>(p) + 15) & ~uintptr_t(15));
}

// Carves aligned arrays out of [at, end).
struct Carver {
  uint8_t* at;
  uint8_t* end;
  template <class T>
  T* take(size_t count) {
    uint8_t* p = align16(at);
    if (p > end || count > size_t(end - p) / sizeof(T)) return nullptr;
    at = p + count * sizeof(T);
    return reinterpret_cast<T*>(p);
  }
  size_t left() const {
    uint8_t* p = align16(at);
    return p < end ? size_t(end - p) : 0;
  }
};

}  // namespace

Status build_spans(BspWorld& world, const ViewState& view, mem::Arena& frame, FrameSpans* out,
                   RenderStats* stats) {
  using namespace front;
  RenderStats local;
  RenderStats& st = stats ? *stats : local;
  *out = FrameSpans{};
  st.visible_leaves = st.nodes_visited = st.faces_emitted = st.edges = st.surfaces = st.spans = 0;
  st.edges_overflowed = st.surfaces_overflowed = st.spans_overflowed = false;

  if (view.width < 1 || view.width > 32767 || view.height < 1 || view.height > 32767) {
    return make_error("build_spans: view size %dx%d outside 1..32767", view.width, view.height);
  }
  if (world.num_models == 0) return make_error("build_spans: world '%s' has no model 0", world.name);

  // Sizes that bound the working arrays.
  uint32_t max_face_edges = 3;
  uint64_t edge_bound = 0;
  for (uint32_t i = 0; i < world.num_faces; ++i) {
    uint32_t n = world.faces[i].num_edges;
    if (n > max_face_edges) max_face_edges = n;
    edge_bound += uint64_t(n) + 4;  // clipping adds at most one vertex per plane
  }

  const size_t mark0 = frame.mark();
  st.visible_leaves = mark_visible(world, view, frame);
  frame.pop_to(mark0);  // the PVS row is spent

  const size_t slack = 256;
  if (frame.remaining() < slack * 4) {
    return make_error("build_spans: frame arena '%s' has only %zu bytes left", frame.name(), frame.remaining());
  }
  const size_t block_size = frame.remaining() - slack;
  auto* block = static_cast<uint8_t*>(frame.push(block_size, "render front end"));
  if (!block) {
    char msg[200];
    frame.failure_message(msg, sizeof msg);
    return make_error("build_spans: %s", msg);
  }
  Carver c{block, block + block_size};

  EdgeTable t;
  t.width = view.width;
  t.height = view.height;
  t.poly_cap = 2 * max_face_edges + 8;
  t.poly_a = c.take<float>(3 * size_t(t.poly_cap));
  t.poly_b = c.take<float>(3 * size_t(t.poly_cap));
  t.proj = c.take<float>(2 * size_t(t.poly_cap));
  t.row_heads = c.take<uint32_t>(size_t(view.height));

  // Surfaces: up to 1/8 of what is left (never more than one per face).
  size_t budget = c.left();
  uint64_t want_surfs = uint64_t(world.num_faces) + 1;
  size_t fit_surfs = budget / 8 / (sizeof(FrontSurface) + sizeof(SurfaceDraw));
  t.max_surfs = uint32_t(want_surfs < fit_surfs ? want_surfs : fit_surfs);
  t.surfs = c.take<FrontSurface>(t.max_surfs);
  // Edges: up to 3/8 (never more than the faces could make).
  size_t fit_edges = budget * 3 / 8 / (sizeof(FrontEdge) + 3 * sizeof(uint32_t));
  if (fit_edges > 0x7fffffffu) fit_edges = 0x7fffffffu;
  t.max_edges = uint32_t(edge_bound < fit_edges ? edge_bound : fit_edges);
  t.edges = c.take<FrontEdge>(t.max_edges);
  uint32_t* aet_a = c.take<uint32_t>(t.max_edges);
  uint32_t* aet_b = c.take<uint32_t>(t.max_edges);
  uint32_t* incoming = c.take<uint32_t>(t.max_edges);
  SurfaceDraw* out_surfs = c.take<SurfaceDraw>(t.max_surfs);
  // Spans: the rest, shared between the unsorted and the grouped copy.
  size_t fit_spans = c.left() >= 64 ? (c.left() - 64) / (sizeof(TmpSpan) + sizeof(Span)) : 0;
  if (fit_spans > 0x7fffffffu) fit_spans = 0x7fffffffu;
  const uint32_t max_spans = uint32_t(fit_spans);
  TmpSpan* tmp_spans = c.take<TmpSpan>(max_spans);
  Span* out_spans = c.take<Span>(max_spans);

  if (!t.poly_a || !t.poly_b || !t.proj || !t.row_heads || !t.surfs || t.max_surfs < 1 || !t.edges || !aet_a ||
      !aet_b || !incoming || !out_surfs || !tmp_spans || !out_spans || max_spans < uint32_t(view.height) + 1) {
    frame.pop_to(mark0);
    return make_error("build_spans: frame arena '%s' too small for a %dx%d view (%zu bytes free)", frame.name(),
                      view.width, view.height, block_size + slack);
  }

  for (int y = 0; y < view.height; ++y) t.row_heads[y] = kNone;
  FrontSurface& bg = t.surfs[kBackgroundSurface];
  bg = FrontSurface{kBackgroundFace, 0xffffffffu, 0.0f, 0, kNone, kNone, 0, 0};
  t.num_surfs = 1;

  walk_world(world, view, t, st);

  bool spans_overflowed = false;
  uint32_t num_spans = scan_edges(t, aet_a, aet_b, incoming, tmp_spans, max_spans, &spans_overflowed);

  // Group spans per surface (counting sort), keeping surfaces in key order with the
  // background first.
  uint32_t num_out = 0, offset = 0;
  for (uint32_t s = 0; s < t.num_surfs; ++s) {
    FrontSurface& f = t.surfs[s];
    if (f.num_spans == 0) continue;
    out_surfs[num_out++] = SurfaceDraw{f.face, f.nearzi, offset, f.num_spans};
    f.first_span = offset;
    offset += f.num_spans;
  }
  for (uint32_t i = 0; i < num_spans; ++i) {
    const TmpSpan& ts = tmp_spans[i];
    out_spans[t.surfs[ts.surf].first_span++] = Span{ts.x, ts.y, ts.count, 0};
  }

  // Compact the two output arrays down to mark0 and give the rest back.
  uint8_t* dest = align16(frame.base() + mark0);
  std::memmove(dest, out_surfs, size_t(num_out) * sizeof(SurfaceDraw));
  uint8_t* span_dest = align16(dest + size_t(num_out) * sizeof(SurfaceDraw));
  std::memmove(span_dest, out_spans, size_t(num_spans) * sizeof(Span));
  uint8_t* end = span_dest + size_t(num_spans) * sizeof(Span);
  frame.pop_to(size_t(end - frame.base()));

  out->surfaces = reinterpret_cast<SurfaceDraw*>(dest);
  out->num_surfaces = num_out;
  out->spans = reinterpret_cast<Span*>(span_dest);
  out->num_spans = num_spans;

  st.edges = t.num_edges;
  st.surfaces = num_out;
  st.spans = num_spans;
  st.edges_overflowed = t.edges_overflowed;
  st.surfaces_overflowed = t.surfaces_overflowed;
  st.spans_overflowed = spans_overflowed;
  if (t.edges_overflowed) warn_once(world, &WarnState::edges, "edge", t.max_edges);
  if (t.surfaces_overflowed) warn_once(world, &WarnState::surfaces, "surface", t.max_surfs);
  if (spans_overflowed) warn_once(world, &WarnState::spans, "span", max_spans);
  return Status::ok();
}

}  // namespace sb::render
