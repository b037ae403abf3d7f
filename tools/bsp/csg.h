// tools/bsp/csg.h: constructive solid geometry: brush sides to the skin of solid space.
//
// Every side of every brush is clipped by every other brush that overlaps it; the parts
// inside a brush of equal or higher contents rank (brushes.h contents_rank) are removed.
// On a shared plane: a side facing into another brush counts as inside it; coplanar sides
// facing the same way keep one copy: the higher-ranked brush's, or the later brush's on a
// tie. Liquid faces that survive get a back copy (flipped), so water is seen from inside
// too. Surviving fragments on one plane with one texture are merged where the union is
// convex.
#pragma once
#include <vector>

#include "tools/bsp/brushes.h"

namespace sb::tools::bsp {

struct Face {
  Winding w;
  int plane = -1;     // oriented PlaneSet index: the face's front is this plane's front
  int texinfo = -1;   // -1: bounds space but is never drawn (skip, hull faces)
  int contents = 0;   // contents of the brush behind the face
  bool detail = false;
  Bounds bounds;
  void update_bounds() {
    bounds = Bounds();
    for (const Vec3& p : w) bounds.add(p);
  }
};

struct CsgStats {
  int brushes = 0, sides = 0, faces_out = 0, fragments = 0, merged = 0, back_faces = 0;
};

void csg_faces(const std::vector<Brush>& brushes, const PlaneSet& planes, std::vector<Face>* out,
               CsgStats* stats);

// Merges faces of `faces` with equal plane, texinfo, contents and detail flag where they
// share an edge and the result is convex. Returns the number of merges.
int merge_faces(std::vector<Face>* faces, const PlaneSet& planes);

}  // namespace sb::tools::bsp
