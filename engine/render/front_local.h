// engine/render/front_local.h: the insides of the renderer's front end, shared by
// view.cpp, vis_mark.cpp, bsp_walk.cpp, edge_list.cpp, edge_scan.cpp and front_end.cpp.
// Not for use outside those files (tests excepted).
//
// Data flow inside build_spans (front_end.cpp), every array in the frame arena:
//
//   mark_visible()      PVS row -> Leaf/Node::visframe = frame           (vis_mark.cpp)
//   walk_world()        front-to-back BSP walk, node boxes vs frustum,    (bsp_walk.cpp)
//                       faces -> add_face()
//   add_face()          clip to frustum (view space), project, append one (edge_list.cpp)
//                       FrontSurface and its FrontEdges (bucketed by the
//                       first scanline they cross)
//   scan_edges()        active edge list down the screen; the nearest     (edge_scan.cpp)
//                       "in" surface (lowest key) owns each run of pixels
//   counting sort       spans grouped per surface -> FrameSpans           (front_end.cpp)
//
// Sampling rules (render_local.h): an edge crosses scanline y when y + 0.5 lies in
// [ytop, ybottom) of its projected end points; a run of a surface covers pixel x when
// x + 0.5 lies in [xleft, xright). Edge x positions are kept as 16.16 fixed point of
// (x - 0.5), so the first pixel at or right of an edge is ceil() of that value.
#pragma once
#include <cstdint>

#include "engine/render/render_local.h"

namespace sb::render::front {

constexpr uint32_t kNone = 0xffffffffu;
constexpr uint32_t kTrailingBit = 0x80000000u;  // FrontEdge::surf: edge leaves its surface
constexpr uint32_t kBackgroundSurface = 0;      // FrontSurface index 0 is the background

// One non-horizontal polygon edge after projection. Faces do not share edges: each
// face emits its own, computed from the same projected end points in the same
// (top to bottom) order, so two faces sharing an edge step to identical positions.
struct FrontEdge {
  int32_t x;        // 16.16 fixed point of (screen x - 0.5) at the current scanline centre
  int32_t dx;       // 16.16 step per scanline
  uint32_t surf;    // FrontSurface index | kTrailingBit when the edge leaves the surface
  int32_t ybottom;  // first scanline NOT crossed
  uint32_t next;    // next edge starting on the same scanline, or kNone
};

// One emitted face (or the background, index 0). key = BSP order: smaller is nearer.
struct FrontSurface {
  uint32_t face;    // index into world.faces, or kBackgroundFace
  uint32_t key;     // emission order (front to back); background = 0xffffffff
  float nearzi;     // largest 1/z among the clipped vertices
  int32_t winding;  // scan state: crossings of leading minus trailing edges so far this row
  uint32_t prev, next;  // links in the active-surface list (sorted by key)
  uint32_t num_spans;   // spans collected so far
  uint32_t first_span;  // offset in the grouped output (set by the counting sort)
};

// Working state of one frame's edge table. All pointers point into the frame arena.
struct EdgeTable {
  int width = 0, height = 0;
  FrontEdge* edges = nullptr;
  uint32_t num_edges = 0, max_edges = 0;
  uint32_t* row_heads = nullptr;  // height entries: first edge starting on that row, or kNone
  FrontSurface* surfs = nullptr;
  uint32_t num_surfs = 0, max_surfs = 0;  // surfs[0] is the background
  // Polygon scratch (view-space vertices and projected points), poly_cap entries each.
  float* poly_a = nullptr;   // 3 floats per vertex
  float* poly_b = nullptr;   // 3 floats per vertex
  float* proj = nullptr;     // 2 floats per vertex (screen x, y)
  uint32_t poly_cap = 0;
  // Overflow: once set, no further faces are added (the background shows instead).
  bool edges_overflowed = false, surfaces_overflowed = false, full = false;
};

// Collected span before grouping: a Span plus the FrontSurface that owns it.
struct TmpSpan {
  int16_t x, y, count, pad;
  uint32_t surf;
};

// vis_mark.cpp: stamps visframe = view.frame on the leaves visible from view.view_leaf
// (its PVS row from sb::decompress_pvs, pushed onto `frame`) and on all their parents.
// When the view leaf is solid or has no PVS, stamps every leaf and node. Returns the
// number of leaves stamped.
uint32_t mark_visible(BspWorld& world, const ViewState& view, mem::Arena& frame);

// bsp_walk.cpp: walks model 0 front to back, marking the surfaces of visible leaves
// and handing each visible front-facing face to add_face. Counts nodes_visited and
// faces_emitted into stats.
void walk_world(BspWorld& world, const ViewState& view, EdgeTable& table, RenderStats& stats);

// edge_list.cpp: clips face `face_index` to the frustum planes selected by clip_flags
// (bit i = ViewState::frustum[i]), projects it and appends its surface and edges.
// Returns true when the face produced a surface (it covers at least one scanline
// centre). Sets the overflow flags and EdgeTable::full when a buffer is exhausted.
bool add_face(EdgeTable& table, const BspWorld& world, const ViewState& view, uint32_t face_index,
              uint32_t clip_flags);

// edge_scan.cpp: steps the active edge list down the screen and writes spans into
// out[0, max_spans) (max_spans >= height + 1). aet_a/aet_b/incoming hold
// table.max_edges entries each. Every pixel of every row ends in exactly one span.
// Counts FrontSurface::num_spans. Returns the number of spans; sets *overflowed
// when the span buffer ran short (the rest of the screen then goes to the background).
uint32_t scan_edges(EdgeTable& table, uint32_t* aet_a, uint32_t* aet_b, uint32_t* incoming, TmpSpan* out,
                    uint32_t max_spans, bool* overflowed);

}  // namespace sb::render::front
