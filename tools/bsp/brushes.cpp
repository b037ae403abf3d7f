// tools/bsp/brushes.cpp: see brushes.h.
#include "tools/bsp/brushes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>

namespace sb::tools::bsp {

int contents_rank(int c) {
  switch (c) {
    case kContentsSolid: case kContentsSky: case kContentsDetail: case kContentsClip: return 4;
    case kContentsLava: return 3;
    case kContentsSlime: return 2;
    case kContentsWater: return 1;
    case kContentsHint: return -1;
    default: return 0;
  }
}

int output_contents(int c) {
  if (c == kContentsDetail || c == kContentsClip) return kContentsSolid;
  if (c == kContentsIllusionary || c == kContentsHint) return kContentsEmpty;
  return c;
}

bool is_liquid(int c) { return c == kContentsWater || c == kContentsSlime || c == kContentsLava; }

namespace {

std::string where(const MapFile& map, int line) { return map.path + ":" + std::to_string(line); }

double brush_volume(const Brush& b, const PlaneSet& planes) {
  if (b.sides.empty() || b.sides[0].w.empty()) return 0;
  Vec3 ref = b.sides[0].w[0];
  double v = 0;
  for (const BrushSide& s : b.sides) {
    if (s.w.size() < 3) continue;
    double h = -planes[s.plane].distance(ref);  // ref is behind every side
    v += winding_area(s.w) * h / 3.0;
  }
  return v;
}

}  // namespace

bool make_brush_windings(Brush* b, const PlaneSet& planes) {
  std::vector<BrushSide> kept;
  Winding scratch;
  b->bounds = Bounds();
  for (size_t i = 0; i < b->sides.size(); ++i) {
    BrushSide s = b->sides[i];
    Winding w = base_winding(planes[s.plane]);
    for (size_t j = 0; j < b->sides.size() && !w.empty(); ++j) {
      if (j == i) continue;
      int pj = b->sides[j].plane;
      if (pj == s.plane) continue;
      if (pj == (s.plane ^ 1)) { w.clear(); break; }
      clip_winding_to(w, planes[pj], false, 0.001, &scratch);
      w.swap(scratch);
    }
    if (w.size() < 3) {
      if (!s.bevel) continue;
      s.w.clear();
      kept.push_back(s);
      continue;
    }
    s.w = std::move(w);
    for (const Vec3& p : s.w) b->bounds.add(p);
    kept.push_back(std::move(s));
  }
  b->sides = std::move(kept);
  int real = 0;
  for (const BrushSide& s : b->sides)
    if (!s.w.empty()) ++real;
  if (real < 4 || b->bounds.empty()) return false;
  for (int i = 0; i < 3; ++i)
    if (b->bounds.mins[i] < -kWorldExtent * 0.5 || b->bounds.maxs[i] > kWorldExtent * 0.5) return false;
  return brush_volume(*b, planes) > 0.1;
}

namespace {
constexpr double kGridCell = 256;
}  // namespace

BrushGrid::BrushGrid(const std::vector<Brush>& brushes) : stamp_(brushes.size(), 0) {
  for (const Brush& b : brushes) box_.add(b.bounds);
  if (box_.empty()) return;
  for (int a = 0; a < 2; ++a) {
    org_[a] = std::floor(box_.mins[a] / kGridCell) * kGridCell;
    dim_[a] = std::min(1024, int((box_.maxs[a] - org_[a]) / kGridCell) + 1);
  }
  cells_.resize(size_t(dim_[0]) * size_t(dim_[1]));
  for (size_t i = 0; i < brushes.size(); ++i) {
    const Bounds& b = brushes[i].bounds;
    for (int y = cell(1, b.mins.y); y <= cell(1, b.maxs.y); ++y)
      for (int x = cell(0, b.mins.x); x <= cell(0, b.maxs.x); ++x)
        cells_[size_t(y) * size_t(dim_[0]) + size_t(x)].push_back(int(i));
  }
}

int BrushGrid::cell(int a, double v) const {
  double c = std::floor((v - org_[a]) / kGridCell);  // clamped as a double: no overflow, NaN -> 0
  if (!(c >= 0)) return 0;
  return c > dim_[a] - 1 ? dim_[a] - 1 : int(c);
}

void BrushGrid::query(const Bounds& b, double eps, std::vector<size_t>* out) {
  out->clear();
  if (cells_.empty()) return;
  ++generation_;
  for (int y = cell(1, b.mins.y - eps); y <= cell(1, b.maxs.y + eps); ++y)
    for (int x = cell(0, b.mins.x - eps); x <= cell(0, b.maxs.x + eps); ++x)
      for (int i : cells_[size_t(y) * size_t(dim_[0]) + size_t(x)])
        if (stamp_[size_t(i)] != generation_) {
          stamp_[size_t(i)] = generation_;
          out->push_back(size_t(i));
        }
  std::sort(out->begin(), out->end());
}

const std::vector<int>* BrushGrid::cell_at(const Vec3& p) const {
  if (cells_.empty() || p.x < box_.mins.x || p.x > box_.maxs.x || p.y < box_.mins.y || p.y > box_.maxs.y)
    return nullptr;
  return &cells_[size_t(cell(1, p.y)) * size_t(dim_[0]) + size_t(cell(0, p.x))];
}

void hull_planes(const Brush& b, PlaneSet& planes, HullPlanes* out) {
  out->planes.clear();
  std::vector<int>& list = out->planes;
  auto have = [&list](int p) { return std::find(list.begin(), list.end(), p) != list.end(); };
  for (const BrushSide& s : b.sides) {
    if (s.w.empty() || have(s.plane)) continue;
    list.push_back(s.plane);
  }
  out->brush_sides = list.size();
  // Axial bevels at the bounds.
  for (int axis = 0; axis < 3; ++axis)
    for (int dir = 0; dir < 2; ++dir) {
      Vec3 n(0.0);
      n[axis] = dir == 0 ? 1.0 : -1.0;
      double d = dir == 0 ? b.bounds.maxs[axis] : -b.bounds.mins[axis];
      int p = planes.find_or_add(n, d);
      if (!have(p)) list.push_back(p);
    }
  // Edge bevels: planes through an edge, parallel to an axis, with the whole brush behind.
  for (const BrushSide& s : b.sides) {
    const Winding& w = s.w;
    for (size_t i = 0; i < w.size(); ++i) {
      Vec3 a = w[i], e = w[(i + 1) % w.size()] - w[i];
      double len = glm::length(e);
      if (len < 0.5) continue;
      e /= len;
      for (int axis = 0; axis < 3; ++axis) {
        Vec3 ax(0.0);
        ax[axis] = 1.0;
        Vec3 n = glm::cross(e, ax);
        double nl = glm::length(n);
        if (nl < 0.1) continue;
        n /= nl;
        for (int sign = 0; sign < 2; ++sign) {
          Vec3 nn = sign ? -n : n;
          if (std::fabs(nn.x) > 1 - 1e-6 || std::fabs(nn.y) > 1 - 1e-6 || std::fabs(nn.z) > 1 - 1e-6) continue;
          double d = glm::dot(nn, a);
          bool behind = true;
          for (const BrushSide& t : b.sides) {
            for (const Vec3& v : t.w)
              if (glm::dot(nn, v) - d > 0.1) { behind = false; break; }
            if (!behind) break;
          }
          if (!behind) continue;
          int p = planes.find_or_add(nn, d);
          if (!have(p)) list.push_back(p);
        }
      }
    }
  }
}

bool expand_brush(const Brush& b, const HullPlanes& hp, const Vec3& hull_mins, const Vec3& hull_maxs,
                  PlaneSet& planes, Brush* out) {
  *out = Brush();
  out->contents = kContentsSolid;
  out->line = b.line;
  out->sides.reserve(hp.planes.size());
  // Push every plane out by the box corner it faces.
  for (size_t i = 0; i < hp.planes.size(); ++i) {
    const Plane& p = planes[hp.planes[i]];
    Vec3 corner;
    for (int k = 0; k < 3; ++k) corner[k] = p.normal[k] < 0 ? hull_maxs[k] : hull_mins[k];
    BrushSide side;
    side.bevel = i >= hp.brush_sides;
    side.plane = planes.find_or_add(p.normal, p.dist - glm::dot(p.normal, corner));
    out->sides.push_back(std::move(side));
  }
  return make_brush_windings(out, planes);
}

bool expand_brush(const Brush& b, const Vec3& hull_mins, const Vec3& hull_maxs, PlaneSet& planes, Brush* out) {
  HullPlanes hp;
  hull_planes(b, planes, &hp);
  return expand_brush(b, hp, hull_mins, hull_maxs, planes, out);
}

bool entity_light_attr(const MapEntity& e, uint32_t index, FaceAttr* out) {
  *out = FaceAttr();
  bool any = false;
  auto num = [&e, &any](const char* key, double* v) {
    const std::string* s = e.find(key);
    if (!s) return false;
    any = true;
    char* end = nullptr;
    double d = std::strtod(s->c_str(), &end);
    if (end == s->c_str() || !std::isfinite(d)) return false;
    *v = d;
    return true;
  };
  double v = 0;
  if (num("_minlight", &v)) out->minlight = float(std::clamp(v, 0.0, 255.0));
  const std::string* mc = e.find("_minlight_color");
  if (!mc) mc = e.find("_mincolor");
  if (const std::string* s = mc) {
    any = true;
    double c[3];
    if (std::sscanf(s->c_str(), "%lf %lf %lf", &c[0], &c[1], &c[2]) == 3) {
      // 0..1 colours are scaled to 0..255 (as "_color" is read by the light tools).
      bool unit = c[0] <= 1 && c[1] <= 1 && c[2] <= 1;
      for (int k = 0; k < 3; ++k) out->minlight_color[k] = uint8_t(std::clamp(unit ? c[k] * 255 : c[k], 0.0, 255.0) + 0.5);
    }
  }
  if (num("_shadow", &v)) {
    if (v > 0) out->flags |= kFaceAttrShadow;
    if (v < 0) out->flags |= kFaceAttrNoShadow;
  }
  if (num("_selfshadow", &v) && v > 0) out->flags |= kFaceAttrSelfShadow;
  if (num("_shadowself", &v) && v > 0) out->flags |= kFaceAttrSelfShadow;
  if (num("_lightignore", &v) && v > 0) out->flags |= kFaceAttrLightIgnore;
  double angle = 0;
  bool has_angle = num("_phong_angle", &angle) && angle > 0;
  if (num("_phong", &v) && v > 0) out->phong_angle = has_angle ? float(std::min(angle, 180.0)) : 89.0f;
  else if (has_angle) out->phong_angle = float(std::min(angle, 180.0));
  if (!any) {
    *out = FaceAttr();
    return false;
  }
  out->entity = index;
  return true;
}

void build_models(MapFile& map, TextureSet& textures, PlaneSet& planes, std::vector<ModelSource>* models,
                  std::vector<bool>* keep_entity, BrushStats* stats, std::vector<std::string>* warnings,
                  std::vector<FaceAttr>* attrs) {
  if (attrs) attrs->assign(1, FaceAttr());
  models->clear();
  models->push_back(ModelSource{0, {}});
  keep_entity->assign(map.entities.size(), true);
  // TrenchBroom layers marked "omit from export": their ids.
  std::set<std::string> omitted_layers;
  for (const MapEntity& e : map.entities)
    if (e.classname() == "func_group" && e.get("_tb_type") == "_tb_layer" &&
        e.get("_tb_layer_omit_from_export") == "1")
      omitted_layers.insert(std::string(e.get("_tb_id")));

  for (size_t ei = 0; ei < map.entities.size(); ++ei) {
    MapEntity& e = map.entities[ei];
    std::string_view cls = e.classname();
    std::string_view layer = e.get("_tb_layer");
    bool omitted = (!layer.empty() && omitted_layers.count(std::string(layer))) ||
                   (cls == "func_group" && omitted_layers.count(std::string(e.get("_tb_id"))) &&
                    e.get("_tb_type") == "_tb_layer");
    if (omitted) {
      (*keep_entity)[ei] = false;
      continue;
    }
    bool world = ei == 0 || cls == "func_group" || cls == "func_detail" || cls == "func_detail_wall" ||
                 cls == "func_detail_fence" || cls == "func_detail_illusionary";
    bool detail_wall = cls == "func_detail_wall" || cls == "func_detail_fence";
    bool detail = cls == "func_detail" || detail_wall;
    bool illusionary = cls == "func_detail_illusionary";
    if (ei != 0 && world) (*keep_entity)[ei] = false;
    if (e.brushes.empty()) continue;
    // Worldspawn's keys are the light stage's global settings (its minimum light etc.).
    int attr = 0;
    FaceAttr fa;
    if (attrs && ei != 0 && entity_light_attr(e, uint32_t(ei), &fa)) {
      attr = int(attrs->size());
      attrs->push_back(fa);
    }
    ModelSource* model = &(*models)[0];
    if (!world) {
      models->push_back(ModelSource{int(ei), {}});
      model = &models->back();
      e.set("model", "*" + std::to_string(models->size() - 1));
    }
    for (const MapBrush& mb : e.brushes) {
      stats->map_brushes++;
      Brush b;
      b.line = mb.line;
      b.attr = attr;
      bool bad = false, hint = false, origin = false, clip = false;
      int liquid = 0;
      bool sky = false;
      std::set<int> seen;
      struct PendingTex { std::string texture; double vecs[2][4]; };
      std::vector<PendingTex> pending;  // texinfo is made only for brushes that are kept
      for (const MapFace& f : mb.faces) {
        Vec3 n;
        double d;
        if (!plane_from_points(f.points[0], f.points[1], f.points[2], &n, &d)) {
          warnings->push_back(where(map, f.line) + ": brush face has no plane (collinear or invalid points): brush at line " +
                              std::to_string(mb.line) + " skipped");
          bad = true;
          break;
        }
        int p = planes.find_or_add(n, d);
        if (!seen.insert(p).second) continue;  // duplicate plane
        TexClass tc = classify_texture(f.texture);
        if (tc == TexClass::Hint) hint = true;
        bool hint_side = tc == TexClass::Hint;
        if (tc == TexClass::Origin) origin = true;
        if (tc == TexClass::Clip) clip = true;
        if (tc == TexClass::Sky) sky = true;
        if (tc == TexClass::Water && !liquid) liquid = kContentsWater;
        if (tc == TexClass::Slime && !liquid) liquid = kContentsSlime;
        if (tc == TexClass::Lava && !liquid) liquid = kContentsLava;
        BrushSide s;
        s.plane = p;
        s.hint = hint_side;
        s.nodraw = tc == TexClass::Skip || tc == TexClass::Clip || tc == TexClass::Hint || tc == TexClass::HintSkip ||
                   (f.texture.size() > 4 && classify_texture(f.texture) != TexClass::Normal &&
                    f.texture.find("skip") != std::string::npos);
        double vecs[2][4];
        face_texture_vecs(f, planes[p].normal, vecs);
        bool finite = true;
        for (auto& row : vecs)
          for (double v : row) finite = finite && std::isfinite(v);
        if (!finite) {
          warnings->push_back(where(map, f.line) + ": texture axes are not finite: brush at line " +
                              std::to_string(mb.line) + " skipped");
          bad = true;
          break;
        }
        s.texinfo = -1;
        b.sides.push_back(std::move(s));
        pending.push_back({f.texture, {}});
        std::memcpy(pending.back().vecs, vecs, sizeof vecs);
      }
      if (bad) { stats->skipped++; continue; }
      if (origin) { stats->origin_dropped++; continue; }
      for (size_t i = 0; i < b.sides.size(); ++i)
        if (!b.sides[i].nodraw && !hint) b.sides[i].plane_tex = int(i);
      b.contents = hint ? kContentsHint
                   : clip ? kContentsClip
                   : sky ? kContentsSky
                   : liquid ? liquid
                   : detail ? kContentsDetail
                   : illusionary ? kContentsIllusionary
                   : kContentsSolid;
      if (detail_wall && b.contents == kContentsDetail)
        b.clips = cls == "func_detail_fence" ? Brush::Clips::None : Brush::Clips::Covered;
      if (!make_brush_windings(&b, planes)) {
        warnings->push_back(where(map, mb.line) + ": brush has no volume: skipped");
        stats->skipped++;
        continue;
      }
      for (BrushSide& side : b.sides)
        if (side.plane_tex >= 0) {
          const PendingTex& pt = pending[size_t(side.plane_tex)];
          side.texinfo = textures.texinfo_index(pt.vecs, pt.texture);
        }
      if (b.contents == kContentsClip) stats->clip++;
      if (b.contents == kContentsDetail) stats->detail++;
      if (b.contents == kContentsIllusionary) stats->illusionary++;
      if (b.contents == kContentsHint) stats->hint++;
      if (is_liquid(b.contents)) stats->liquid++;
      if (b.contents == kContentsSky) stats->sky++;
      model->brushes.push_back(std::move(b));
    }
  }
}

}  // namespace sb::tools::bsp
