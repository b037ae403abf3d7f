#include "tests/render_front/front_test_util.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include <glm/geometric.hpp>

namespace sb::test::front {

// ---- HandWorld -----------------------------------------------------------------------

HandWorld::HandWorld() {
  Leaf solid{};
  solid.contents = kContentsSolid;
  solid.vis_offset = -1;
  solid.parent = -1;
  leaves.push_back(solid);
  TexInfo ti{};
  ti.vecs[0] = glm::vec4(1, 0, 0, 0);
  ti.vecs[1] = glm::vec4(0, 1, 0, 0);
  ti.texture = 0;
  ti.mipadjust = 1.0f;
  texinfo.push_back(ti);
  Texture tex{};
  std::snprintf(tex.name, sizeof tex.name, "hand");
  tex.width = tex.height = 16;
  tex.anim_next = tex.alternate = -1;
  textures.push_back(tex);
}

uint32_t HandWorld::add_plane(const glm::vec3& normal, float dist) {
  Plane p{};
  p.normal = normal;
  p.dist = dist;
  p.type = 3;
  for (int a = 0; a < 3; ++a)
    if (normal[a] == 1.0f) p.type = uint8_t(a);
  p.signbits = uint8_t((normal.x < 0 ? 1 : 0) | (normal.y < 0 ? 2 : 0) | (normal.z < 0 ? 4 : 0));
  planes.push_back(p);
  return uint32_t(planes.size() - 1);
}

uint32_t HandWorld::add_face(uint32_t plane, bool back, const std::vector<glm::vec3>& verts) {
  Face f{};
  f.plane = plane;
  f.first_surfedge = uint32_t(surfedges.size());
  f.num_edges = uint32_t(verts.size());
  f.texinfo = 0;
  f.flags = back ? kFacePlaneBack : 0;
  for (int i = 0; i < kMaxLightStyles; ++i) f.styles[i] = 255;
  f.light_offset = kNoLightmap;
  uint32_t base = uint32_t(vertices.size());
  for (const auto& v : verts) vertices.push_back(v);
  for (size_t i = 0; i < verts.size(); ++i) {
    Edge e{};
    e.v[0] = base + uint32_t(i);
    e.v[1] = base + uint32_t((i + 1) % verts.size());
    if (edges.empty()) edges.push_back(Edge{});  // edge 0 is never used by a face
    edges.push_back(e);
    // Alternate directions to exercise both signs of surfedges.
    int32_t idx = int32_t(edges.size() - 1);
    if (i % 2) {
      std::swap(edges.back().v[0], edges.back().v[1]);
      surfedges.push_back(-idx);
    } else {
      surfedges.push_back(idx);
    }
  }
  faces.push_back(f);
  return uint32_t(faces.size() - 1);
}

int32_t HandWorld::add_leaf(int32_t contents, const glm::vec3& mins, const glm::vec3& maxs,
                            const std::vector<uint32_t>& marks, int32_t vis_offset) {
  Leaf l{};
  l.contents = contents;
  l.vis_offset = vis_offset;
  l.mins = mins;
  l.maxs = maxs;
  l.first_marksurface = uint32_t(marksurfaces.size());
  l.num_marksurfaces = uint32_t(marks.size());
  for (uint32_t m : marks) marksurfaces.push_back(m);
  l.parent = -1;
  leaves.push_back(l);
  return -int32_t(leaves.size());
}

int32_t HandWorld::add_node(uint32_t plane, int32_t front, int32_t back, const std::vector<uint32_t>& node_faces) {
  Node n{};
  n.plane = plane;
  n.children[0] = front;
  n.children[1] = back;
  // Faces of a node must be contiguous: this builder adds each node's faces just before it.
  n.first_face = node_faces.empty() ? 0 : node_faces.front();
  n.num_faces = uint32_t(node_faces.size());
  for (size_t i = 1; i < node_faces.size(); ++i)
    if (node_faces[i] != node_faces[0] + i) std::abort();
  n.parent = -1;
  nodes.push_back(n);
  return int32_t(nodes.size() - 1);
}

namespace {

void grow(glm::vec3& mn, glm::vec3& mx, const glm::vec3& p) {
  mn = glm::min(mn, p);
  mx = glm::max(mx, p);
}

void fix(HandWorld& h, int32_t child, int32_t parent, glm::vec3& mn, glm::vec3& mx) {
  if (child < 0) {
    Leaf& l = h.leaves[size_t(-child - 1)];
    if (l.contents == kContentsSolid) return;
    l.parent = parent;
    grow(mn, mx, l.mins);
    grow(mn, mx, l.maxs);
    return;
  }
  Node& n = h.nodes[size_t(child)];
  n.parent = parent;
  glm::vec3 a(1e30f), b(-1e30f);
  for (int s = 0; s < 2; ++s) fix(h, h.nodes[size_t(child)].children[s], child, a, b);
  for (uint32_t f = 0; f < h.nodes[size_t(child)].num_faces; ++f) {
    const Face& face = h.faces[h.nodes[size_t(child)].first_face + f];
    for (uint32_t e = 0; e < face.num_edges; ++e) {
      int32_t se = h.surfedges[face.first_surfedge + e];
      uint32_t vi = se >= 0 ? h.edges[size_t(se)].v[0] : h.edges[size_t(-se)].v[1];
      grow(a, b, h.vertices[vi]);
    }
  }
  h.nodes[size_t(child)].mins = a;
  h.nodes[size_t(child)].maxs = b;
  grow(mn, mx, a);
  grow(mn, mx, b);
}

}  // namespace

void HandWorld::finish(int32_t head, uint32_t visleafs) {
  glm::vec3 mn(1e30f), mx(-1e30f);
  fix(*this, head, -1, mn, mx);
  SubModel m{};
  m.mins = mn;
  m.maxs = mx;
  m.headnode[0] = head;
  m.visleafs = visleafs;
  m.first_face = 0;
  m.num_faces = uint32_t(faces.size());
  models.assign(1, m);

  BspWorld& w = world;
  w = BspWorld{};
  std::snprintf(w.name, sizeof w.name, "hand-built");
  w.planes = planes.data(); w.num_planes = uint32_t(planes.size());
  w.vertices = vertices.data(); w.num_vertices = uint32_t(vertices.size());
  w.edges = edges.data(); w.num_edges = uint32_t(edges.size());
  w.surfedges = surfedges.data(); w.num_surfedges = uint32_t(surfedges.size());
  w.texinfo = texinfo.data(); w.num_texinfo = uint32_t(texinfo.size());
  w.textures = textures.data(); w.num_textures = uint32_t(textures.size());
  w.faces = faces.data(); w.num_faces = uint32_t(faces.size());
  w.marksurfaces = marksurfaces.data(); w.num_marksurfaces = uint32_t(marksurfaces.size());
  w.nodes = nodes.data(); w.num_nodes = uint32_t(nodes.size());
  w.leaves = leaves.data(); w.num_leaves = uint32_t(leaves.size());
  w.models = models.data(); w.num_models = 1;
  w.visdata = visdata.empty() ? nullptr : visdata.data();
  w.visdata_size = uint32_t(visdata.size());
  w.entities = "";
}

namespace {

// Side s of box [mn, mx]: axis s / 2, at mn (even s) or mx (odd s); faces inwards.
uint32_t add_wall(HandWorld& h, const glm::vec3& mn, const glm::vec3& mx, int s) {
  int a = s / 2, b = (a + 1) % 3, c = (a + 2) % 3;
  float v = (s & 1) ? mx[a] : mn[a];
  glm::vec3 n(0.0f);
  n[a] = 1.0f;
  uint32_t plane = h.add_plane(n, v);
  std::vector<glm::vec3> q(4);
  const float bs[4] = {mn[b], mx[b], mx[b], mn[b]};
  const float cs[4] = {mn[c], mn[c], mx[c], mx[c]};
  for (int i = 0; i < 4; ++i) {
    q[i][a] = v;
    q[i][b] = bs[i];
    q[i][c] = cs[i];
  }
  return h.add_face(plane, (s & 1) != 0, q);
}

// A chain of nodes bounding a convex box leaf on the sides in `walls` (bit s = side s).
// Extra faces (bordering the leaf, lying on other nodes) join its marksurfaces.
int32_t add_box_leaf(HandWorld& h, const glm::vec3& mn, const glm::vec3& mx, unsigned walls,
                     const std::vector<uint32_t>& extra_marks, int32_t vis_offset = -1) {
  std::vector<std::pair<int, uint32_t>> wall_faces;
  for (int s = 0; s < 6; ++s)
    if (walls & (1u << s)) wall_faces.push_back({s, add_wall(h, mn, mx, s)});
  std::vector<uint32_t> marks = extra_marks;
  for (auto& wf : wall_faces) marks.push_back(wf.second);
  int32_t child = h.add_leaf(kContentsEmpty, mn, mx, marks, vis_offset);
  for (auto it = wall_faces.rbegin(); it != wall_faces.rend(); ++it) {
    const Face& f = h.faces[it->second];
    bool odd = it->first & 1;
    child = h.add_node(f.plane, odd ? -1 : child, odd ? child : -1, {it->second});
  }
  return child;
}

}  // namespace

std::unique_ptr<HandWorld> make_box_room(const glm::vec3& mins, const glm::vec3& maxs, bool with_vis) {
  auto h = std::make_unique<HandWorld>();
  if (with_vis) h->visdata = {0x01};
  int32_t head = add_box_leaf(*h, mins, maxs, 0x3f, {}, with_vis ? 0 : -1);
  h->finish(head, 1);
  return h;
}

std::unique_ptr<HandWorld> make_pillar_room() {
  auto h = std::make_unique<HandWorld>();
  const glm::vec3 rmn(-256, -128, -64), rmx(256, 128, 64);
  const float px0 = 32, px1 = 64, py0 = -16, py1 = 16;
  // Pillar faces first (each on its own node, added right before it).
  uint32_t pa = h->add_plane(glm::vec3(1, 0, 0), px0);
  uint32_t pw = h->add_face(pa, true, {{px0, py0, rmn.z}, {px0, py1, rmn.z}, {px0, py1, rmx.z}, {px0, py0, rmx.z}});
  uint32_t pb = h->add_plane(glm::vec3(1, 0, 0), px1);
  uint32_t pe = h->add_face(pb, false, {{px1, py0, rmn.z}, {px1, py0, rmx.z}, {px1, py1, rmx.z}, {px1, py1, rmn.z}});
  uint32_t pc = h->add_plane(glm::vec3(0, 1, 0), py1);
  uint32_t pn = h->add_face(pc, false, {{px0, py1, rmn.z}, {px1, py1, rmn.z}, {px1, py1, rmx.z}, {px0, py1, rmx.z}});
  uint32_t pd = h->add_plane(glm::vec3(0, 1, 0), py0);
  uint32_t ps = h->add_face(pd, true, {{px0, py0, rmn.z}, {px0, py0, rmx.z}, {px1, py0, rmx.z}, {px1, py0, rmn.z}});

  // Walls: -x 1, +x 2, -y 4, +y 8, -z 16, +z 32.
  int32_t l1 = add_box_leaf(*h, rmn, {px0, rmx.y, rmx.z}, 1 | 4 | 8 | 16 | 32, {pw});
  int32_t l2 = add_box_leaf(*h, {px1, rmn.y, rmn.z}, rmx, 2 | 4 | 8 | 16 | 32, {pe});
  int32_t l3 = add_box_leaf(*h, {px0, py1, rmn.z}, {px1, rmx.y, rmx.z}, 8 | 16 | 32, {pn});
  int32_t l4 = add_box_leaf(*h, {px0, rmn.y, rmn.z}, {px1, py0, rmx.z}, 4 | 16 | 32, {ps});

  // Node faces must be contiguous and belong to that node only: the pillar faces are
  // 0..3, one per node below.
  int32_t d = h->add_node(pd, -1, l4, {ps});
  int32_t c = h->add_node(pc, l3, d, {pn});
  int32_t b = h->add_node(pb, l2, c, {pe});
  int32_t a = h->add_node(pa, b, l1, {pw});
  h->finish(a, 4);
  return h;
}

// ---- FrontRunner ---------------------------------------------------------------------

size_t FrontFrame::bad_coverage() const {
  size_t bad = 0;
  for (uint8_t c : coverage) bad += c != 1;
  return bad;
}

FrontRunner::FrontRunner(size_t frame_bytes) : block_(new uint8_t[frame_bytes]) {
  arena_.init("frame", block_.get(), frame_bytes);
}

FrontFrame FrontRunner::run(BspWorld& world, const ViewParams& params, int width, int height) {
  FrontFrame fr;
  fr.width = width;
  fr.height = height;
  arena_.reset();
  fr.view = render::setup_view(world, params, width, height, next_frame_++);
  render::FrameSpans spans;
  auto t0 = std::chrono::steady_clock::now();
  Status s = render::build_spans(world, fr.view, arena_, &spans, &fr.stats);
  auto t1 = std::chrono::steady_clock::now();
  fr.build_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  fr.status = s ? "ok" : s.message();
  if (!s) return fr;
  fr.num_spans = spans.num_spans;
  fr.num_surfaces = spans.num_surfaces;
  fr.face_at.assign(size_t(width) * height, kNoFace);
  fr.coverage.assign(size_t(width) * height, 0);

  char buf[256];
  auto fail = [&](const char* msg) {
    if (fr.contract_error.empty()) fr.contract_error = msg;
  };
  // The arrays must live in the frame arena below its current top.
  auto inside = [&](const void* p, size_t bytes) {
    auto* b = static_cast<const uint8_t*>(p);
    return b >= arena_.base() && b + bytes <= arena_.base() + arena_.used();
  };
  if (spans.num_surfaces && !inside(spans.surfaces, spans.num_surfaces * sizeof(render::SurfaceDraw)))
    fail("surfaces outside the used frame arena");
  if (spans.num_spans && !inside(spans.spans, spans.num_spans * sizeof(render::Span)))
    fail("spans outside the used frame arena");
  if (fr.stats.surfaces != spans.num_surfaces || fr.stats.spans != spans.num_spans) fail("stats disagree with output");

  std::vector<std::pair<uint32_t, uint32_t>> ranges;
  uint64_t total = 0;
  for (uint32_t i = 0; i < spans.num_surfaces; ++i) {
    const render::SurfaceDraw& sd = spans.surfaces[i];
    if (sd.num_spans == 0) fail("surface without spans listed");
    if (sd.face != render::kBackgroundFace && sd.face >= world.num_faces) fail("surface face index out of range");
    if (uint64_t(sd.first_span) + sd.num_spans > spans.num_spans) {
      fail("surface span range out of bounds");
      continue;
    }
    ranges.push_back({sd.first_span, sd.num_spans});
    total += sd.num_spans;
    for (uint32_t k = 0; k < sd.num_spans; ++k) {
      const render::Span& sp = spans.spans[sd.first_span + k];
      if (sp.count <= 0 || sp.x < 0 || sp.x + sp.count > width || sp.y < 0 || sp.y >= height) {
        std::snprintf(buf, sizeof buf, "span out of bounds: x %d y %d count %d", sp.x, sp.y, sp.count);
        fail(buf);
        continue;
      }
      size_t row = size_t(sp.y) * width;
      for (int x = sp.x; x < sp.x + sp.count; ++x) {
        if (fr.coverage[row + x] < 255) ++fr.coverage[row + x];
        fr.face_at[row + x] = sd.face;
      }
    }
  }
  std::sort(ranges.begin(), ranges.end());
  for (size_t i = 1; i < ranges.size(); ++i)
    if (ranges[i - 1].first + ranges[i - 1].second > ranges[i].first) fail("surface span ranges overlap");
  if (total != spans.num_spans) fail("surface span ranges do not add up to num_spans");
  return fr;
}

// ---- RayCaster -----------------------------------------------------------------------

RayCaster::RayCaster(const BspWorld& world) {
  const SubModel& m = world.models[0];
  for (uint32_t i = m.first_face; i < m.first_face + m.num_faces && i < world.num_faces; ++i) {
    const Face& f = world.faces[i];
    const Plane& p = world.planes[f.plane];
    RefFace rf;
    rf.index = i;
    double sign = (f.flags & kFacePlaneBack) ? -1.0 : 1.0;
    rf.normal = glm::dvec3(p.normal) * sign;
    rf.dist = double(p.dist) * sign;
    for (uint32_t e = 0; e < f.num_edges; ++e) {
      int32_t se = world.surfedges[f.first_surfedge + e];
      uint32_t vi = se >= 0 ? world.edges[se].v[0] : world.edges[uint32_t(-int64_t(se))].v[1];
      rf.verts.push_back(glm::dvec3(world.vertices[vi]));
    }
    // Point in polygon by crossing number in the plane's dominant projection: exact for
    // convex faces, and unbothered by the zero-area spikes and repeated vertices that real
    // compilers leave in some faces (an edge-plane test would reject every point there).
    glm::dvec3 an = glm::abs(rf.normal);
    int k = an.x >= an.y && an.x >= an.z ? 0 : (an.y >= an.z ? 1 : 2);
    rf.axis_u = (k + 1) % 3;
    rf.axis_v = (k + 2) % 3;
    for (const auto& v : rf.verts) {
      rf.us.push_back(v[rf.axis_u]);
      rf.vs.push_back(v[rf.axis_v]);
    }
    if (rf.verts.size() >= 3) faces_.push_back(std::move(rf));
  }
}

std::vector<uint32_t> RayCaster::cast(const render::ViewState& v) const {
  const int W = v.width + 2, H = v.height + 2;
  std::vector<uint32_t> out(size_t(W) * H, kNoFace);
  const glm::dvec3 o(v.origin), fw(v.forward), rt(v.right), up(v.up);
  const double xc = v.xcenter, yc = v.ycenter, xs = v.xscale, ys = v.yscale;

  std::vector<const RefFace*> front;
  for (const RefFace& f : faces_)
    if (glm::dot(f.normal, o) - f.dist > 0.0) front.push_back(&f);

  // Planes (through the eye) bounding screen rectangle [x0, x1] x [y0, y1].
  auto outside_rect = [&](const RefFace* f, double x0, double x1, double y0, double y1) {
    const glm::dvec3 n[4] = {xs * rt + (xc - x0) * fw, -xs * rt + (x1 - xc) * fw, (yc - y0) * fw - ys * up,
                             (y1 - yc) * fw + ys * up};
    for (int p = 0; p < 4; ++p) {
      bool all_out = true;
      for (const auto& vert : f->verts)
        if (glm::dot(n[p], vert - o) >= 0.0) { all_out = false; break; }
      if (all_out) return true;
    }
    return false;
  };

  const double margin = 0.25;
  std::vector<const RefFace*> big, small;
  for (int ty = -1; ty < v.height + 1; ty += 64) {
    for (int tx = -1; tx < v.width + 1; tx += 64) {
      int tx1 = std::min(tx + 64, v.width + 1), ty1 = std::min(ty + 64, v.height + 1);
      big.clear();
      for (const RefFace* f : front)
        if (!outside_rect(f, tx - margin, tx1 + margin, ty - margin, ty1 + margin)) big.push_back(f);
      for (int sy0 = ty; sy0 < ty1; sy0 += 8) {
        for (int sx0 = tx; sx0 < tx1; sx0 += 8) {
          int sx1 = std::min(sx0 + 8, tx1), sy1 = std::min(sy0 + 8, ty1);
          small.clear();
          for (const RefFace* f : big)
            if (!outside_rect(f, sx0 - margin, sx1 + margin, sy0 - margin, sy1 + margin)) small.push_back(f);
          for (int py = sy0; py < sy1; ++py) {
            for (int px = sx0; px < sx1; ++px) {
              glm::dvec3 dir = fw + ((px + 0.5 - xc) / xs) * rt - ((py + 0.5 - yc) / ys) * up;
              double best = std::numeric_limits<double>::infinity();
              uint32_t best_face = kNoFace;
              for (const RefFace* f : small) {
                double denom = glm::dot(f->normal, dir);
                if (denom >= 0.0) continue;
                double t = (f->dist - glm::dot(f->normal, o)) / denom;
                if (!(t > 0.0) || t >= best) continue;
                glm::dvec3 hit = o + t * dir;
                const double hu = hit[f->axis_u], hv = hit[f->axis_v];
                bool in = false;
                const size_t nv = f->us.size();
                for (size_t a = nv - 1, b = 0; b < nv; a = b++) {
                  double ua = f->us[a], va = f->vs[a], ub = f->us[b], vb = f->vs[b];
                  if ((va > hv) != (vb > hv) && hu < ua + (hv - va) * (ub - ua) / (vb - va)) in = !in;
                }
                if (!in) continue;
                best = t;
                best_face = f->index;
              }
              out[size_t(py + 1) * W + (px + 1)] = best_face;
            }
          }
        }
      }
    }
  }
  return out;
}

// ---- compare -------------------------------------------------------------------------

void Agreement::add(const Agreement& o) {
  pixels += o.pixels;
  agree += o.agree;
  near_edge += o.near_edge;
  far_from_edge += o.far_from_edge;
  reference_empty += o.reference_empty;
  if (examples.size() < 400) examples += o.examples;
}

std::string Agreement::describe() const {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%.4f%% agree (%zu px; %zu mismatches near an edge, %zu far; ref empty %zu)",
                100.0 * ratio(), pixels, near_edge, far_from_edge, reference_empty);
  return buf;
}

Agreement compare(const FrontFrame& frame, const std::vector<uint32_t>& ref) {
  Agreement a;
  const int W = frame.width + 2;
  for (int y = 0; y < frame.height; ++y) {
    for (int x = 0; x < frame.width; ++x) {
      ++a.pixels;
      uint32_t r = ref[size_t(y + 1) * W + x + 1];
      uint32_t e = frame.face_at[size_t(y) * frame.width + x];
      if (r == kNoFace) ++a.reference_empty;
      if (r == e) {
        ++a.agree;
        continue;
      }
      bool changes = false;
      for (int dy = -1; dy <= 1 && !changes; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (ref[size_t(y + 1 + dy) * W + x + 1 + dx] != r) { changes = true; break; }
      if (changes) {
        ++a.near_edge;
      } else {
        ++a.far_from_edge;
        if (a.examples.size() < 300) {
          char buf[96];
          std::snprintf(buf, sizeof buf, " (%d,%d): ref %d got %d;", x, y, int(r), int(e));
          a.examples += buf;
        }
      }
    }
  }
  return a;
}

}  // namespace sb::test::front
