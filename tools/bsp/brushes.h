// tools/bsp/brushes.h: .map entities to convex brushes, grouped by output model.
//
// Contents (internal values; the output uses Quake's -1..-6):
//   kContentsEmpty -1, Solid -2, Water -3, Slime -4, Lava -5, Sky -6 as Quake;
//   kContentsDetail: func_detail / func_detail_wall / func_detail_fence brushes: solid in the
//     output and in the clip hulls, split only after every structural face, never a vis cluster
//     boundary (PRT2) and never a seal for the outside fill (a map sealed only by detail leaks);
//     func_detail_wall brushes remove only the faces of other brushes that they cover entirely
//     (no splitting), func_detail_fence brushes none; neither clips its own kind;
//   kContentsIllusionary: func_detail_illusionary: faces drawn (detail; front side only, no
//     _mirrorinside), but empty space for collision and leaf contents, absent from clip hulls;
//     removes no face of any other brush;
//   kContentsClip: "clip" brushes, solid in clip hulls 1 and 2 only;
//   kContentsHint: brushes with a face textured "hint": those faces' planes are used as
//     splitters before any other (tree.h); hint brushes draw nothing, are not solid, and their
//     "hintskip" / "skip" faces are ignored.
// A brush's contents come from its textures: sky* -> sky, '*' names -> water/slime/lava by
// name, clip -> clip, hint -> hint; origin brushes are dropped (noted as unsupported); a face
// textured skip/nodraw is not drawn (its brush still bounds space).
// Models: model 0 is worldspawn plus func_group / TrenchBroom layers / func_detail*; every
// other entity with brushes becomes the next submodel (its entity gets "model" "*N").
// A brush with a bad plane (collinear points, NaN) or no volume is skipped with a warning
// naming the file and line.
#pragma once
#include <string>
#include <vector>

#include "tools/bsp/geom.h"
#include "tools/bsp/map_file.h"
#include "tools/bsp/textures.h"
#include "tools/common/face_attrs.h"

namespace sb::tools::bsp {

constexpr int kContentsEmpty = -1;
constexpr int kContentsSolid = -2;
constexpr int kContentsWater = -3;
constexpr int kContentsSlime = -4;
constexpr int kContentsLava = -5;
constexpr int kContentsSky = -6;
constexpr int kContentsDetail = -100;
constexpr int kContentsClip = -101;
constexpr int kContentsIllusionary = -102;
constexpr int kContentsHint = -103;

// Which contents win where brushes overlap: a brush's faces inside a brush of equal or
// higher rank are removed. Solid, sky and detail rank highest; then lava, slime, water, then
// illusionary (0); hint brushes rank -1 (never in CSG).
int contents_rank(int contents);
// The contents written to the file for an internal value.
int output_contents(int contents);
bool is_liquid(int contents);

struct BrushSide {
  int plane = -1;    // PlaneSet index, normal pointing out of the brush
  int texinfo = -1;  // -1 for bevel / hull sides
  Winding w;         // the side's polygon (empty for bevels that touch in an edge only)
  bool nodraw = false;
  bool bevel = false;
  bool hint = false;   // hint brushes: a "hint" face (a forced splitter)
  int plane_tex = -1;  // while building: index of the .map face's texture projection
};

struct Brush {
  std::vector<BrushSide> sides;
  int contents = kContentsSolid;
  Bounds bounds;
  int line = 0;  // .map line of the brush (messages)
  // How the brush removes other brushes' faces in CSG: All (normal), Covered (func_detail_wall:
  // only faces it covers entirely, never another _wall brush's), None (func_detail_fence).
  enum class Clips { All, Covered, None };
  Clips clips = Clips::All;
  int attr = 0;  // index into the light attribute table (build_models; 0: no light keys)
};

struct ModelSource {
  int entity = 0;              // index into MapFile::entities
  std::vector<Brush> brushes;  // drawn hull; clip brushes included with kContentsClip
};

struct BrushStats {
  int map_brushes = 0, skipped = 0, detail = 0, illusionary = 0, clip = 0, liquid = 0, sky = 0, hint = 0,
      origin_dropped = 0;
};

// Brush boxes binned by 256-unit XY cells (each cell's list in brush order), so that the
// brushes near a box or a point are found without testing every brush. The grid keeps
// indices only (no reference to the brushes).
class BrushGrid {
 public:
  explicit BrushGrid(const std::vector<Brush>& brushes);
  // Indices (ascending, each once) of every brush whose box may lie within eps of b.
  void query(const Bounds& b, double eps, std::vector<size_t>* out);
  // The brushes whose box may hold p: one cell's list, ascending (nullptr: none).
  const std::vector<int>* cell_at(const Vec3& p) const;

 private:
  int cell(int axis, double v) const;
  Bounds box_;
  double org_[2] = {0, 0};
  int dim_[2] = {0, 0};
  std::vector<std::vector<int>> cells_;
  std::vector<unsigned> stamp_;
  unsigned generation_ = 0;
};

// Builds every model's brushes. `keep_entity[i]` says whether entity i stays in the entity
// lump (func_group / func_detail / omitted layers are dropped). Submodel entities get their
// "model" key set in `map`. `attrs` (optional) receives the light attribute table
// (face_attrs.h): entry 0 the default, then one entry per brush entity other than worldspawn
// that has a light key ("_minlight", "_minlight_color" or "_mincolor", "_shadow", "_selfshadow",
// "_shadowself", "_lightignore", "_phong", "_phong_angle"); Brush::attr indexes it.
void build_models(MapFile& map, TextureSet& textures, PlaneSet& planes, std::vector<ModelSource>* models,
                  std::vector<bool>* keep_entity, BrushStats* stats, std::vector<std::string>* warnings,
                  std::vector<FaceAttr>* attrs = nullptr);

// The light attribute of entity `index` of `e` (face_attrs.h); false when it has no light key.
bool entity_light_attr(const MapEntity& e, uint32_t index, FaceAttr* out);

// Recomputes every side's winding from the planes; drops sides with no polygon.
// False when fewer than 4 sides remain (no volume).
bool make_brush_windings(Brush* b, const PlaneSet& planes);

// The planes a brush is grown along, the same for every hull size: its sides' planes
// (`brush_sides` of them), then axial bevels at its bounds, then edge bevels (planes through
// an edge, parallel to an axis, with the whole brush behind). Adds bevel planes to `planes`.
struct HullPlanes {
  std::vector<int> planes;
  size_t brush_sides = 0;
};
void hull_planes(const Brush& b, PlaneSet& planes, HullPlanes* out);

// The brush grown by the box hull_mins..hull_maxs (Minkowski sum): every hull plane pushed
// out by the box corner it faces. Contents: solid. The overload without `hp` computes it.
bool expand_brush(const Brush& b, const HullPlanes& hp, const Vec3& hull_mins, const Vec3& hull_maxs,
                  PlaneSet& planes, Brush* out);
bool expand_brush(const Brush& b, const Vec3& hull_mins, const Vec3& hull_maxs, PlaneSet& planes, Brush* out);

}  // namespace sb::tools::bsp
