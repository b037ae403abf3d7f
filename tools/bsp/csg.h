// tools/bsp/csg.h: constructive solid geometry: brush sides to the skin of solid space.
//
// Every side of every brush is clipped by every other brush that overlaps it; the parts
// inside a brush of equal or higher contents rank (brushes.h contents_rank) are removed.
// On a shared plane: a side facing into another brush counts as inside it; coplanar sides
// facing the same way keep one copy: the higher-ranked brush's, or the later brush's on a
// tie. Liquid faces that survive get a back copy (flipped), so water is seen from inside
// too. Surviving fragments on one plane with one texture are merged where the union is
// convex. func_detail_wall brushes (Brush::clips == Covered) remove only fragments they cover
// entirely, func_detail_fence (None) and illusionary brushes remove none. The pieces of a structural side inside a func_detail
// brush are kept as undrawn faces (texinfo -1): the structural tree then bounds every
// structural brush, so the outside fill cannot leak through a wall that detail overlaps.
// Faces of detail and illusionary brushes are marked detail (split last, tree.h).
#pragma once
#include <vector>

#include "tools/bsp/brushes.h"
#include "tools/common/progress.h"

namespace sb::tools::bsp {

struct Face {
  Winding w;
  int plane = -1;     // oriented PlaneSet index: the face's front is this plane's front
  int texinfo = -1;   // -1: bounds space but is never drawn (skip, hull faces)
  int contents = 0;   // contents of the brush behind the face
  bool detail = false;
  bool hint = false;  // a hint brush's side: chosen as a splitter first, never drawn
  int attr = 0;       // the brush's light attribute (Brush::attr); faces merge only within one
  Bounds bounds;
  void update_bounds() {
    bounds = Bounds();
    for (const Vec3& p : w) bounds.add(p);
  }
};

struct CsgStats {
  int brushes = 0, sides = 0, faces_out = 0, fragments = 0, merged = 0, back_faces = 0;
  int hidden = 0;  // structural pieces inside detail brushes kept undrawn
};

// `progress` (optional) advances by one per brush.
void csg_faces(const std::vector<Brush>& brushes, const PlaneSet& planes, std::vector<Face>* out,
               CsgStats* stats, Progress* progress = nullptr);

// Merges faces of `faces` with equal plane, texinfo, contents, detail flag and attr where they
// share an edge and the result is convex. Returns the number of merges.
int merge_faces(std::vector<Face>* faces, const PlaneSet& planes);

// The "hint" sides of hint brushes (kContentsHint) as undrawn hint faces (texinfo -1).
void hint_faces(const std::vector<Brush>& brushes, std::vector<Face>* out);

}  // namespace sb::tools::bsp
