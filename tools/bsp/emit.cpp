// tools/bsp/emit.cpp: see emit.h.
#include "tools/bsp/emit.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace sb::tools::bsp {
namespace {

constexpr double kWeld = 0.01;

double snap(double v) {
  double r = std::floor(v + 0.5);
  return std::fabs(v - r) < kWeld ? r : v;
}

void set_bounds(const Bounds& b, float mins[3], float maxs[3]) {
  for (int i = 0; i < 3; ++i) {
    if (b.empty()) {
      mins[i] = maxs[i] = 0;
      continue;
    }
    mins[i] = float(std::floor(b.mins[i]));
    maxs[i] = float(std::ceil(b.maxs[i]));
  }
}

}  // namespace

void Emitter::begin() {
  DLeaf solid{};
  solid.contents = kContentsSolid;
  solid.visofs = -1;
  bsp_->leaves.push_back(solid);
  bsp_->edges.push_back(DEdge{{0, 0}});
}

int Emitter::plane_index(int canonical) {
  auto it = plane_map_.find(canonical);
  if (it != plane_map_.end()) return it->second;
  const Plane& p = planes_[canonical];
  DPlane d{};
  for (int i = 0; i < 3; ++i) d.normal[i] = float(p.normal[i]);
  d.dist = float(p.dist);
  d.type = p.type;
  int idx = int(bsp_->planes.size());
  bsp_->planes.push_back(d);
  plane_map_[canonical] = idx;
  return idx;
}

uint32_t Emitter::vertex(const Vec3& v0) {
  Vec3 v(snap(v0.x), snap(v0.y), snap(v0.z));
  int64_t cx = int64_t(std::floor(v.x)), cy = int64_t(std::floor(v.y)), cz = int64_t(std::floor(v.z));
  int64_t key = (cx * 73856093) ^ (cy * 19349663) ^ (cz * 83492791);
  std::vector<uint32_t>& bucket = vertex_hash_[key];
  for (uint32_t i : bucket) {
    const float* p = &bsp_->vertices[size_t(i) * 3];
    if (std::fabs(p[0] - v.x) < kWeld && std::fabs(p[1] - v.y) < kWeld && std::fabs(p[2] - v.z) < kWeld) return i;
  }
  uint32_t idx = uint32_t(bsp_->vertices.size() / 3);
  bsp_->vertices.push_back(float(v.x));
  bsp_->vertices.push_back(float(v.y));
  bsp_->vertices.push_back(float(v.z));
  bucket.push_back(idx);
  return idx;
}

int32_t Emitter::edge(uint32_t a, uint32_t b) {
  // An edge walked b -> a by an earlier face, not yet shared: reuse it backwards.
  uint64_t back_key = (uint64_t(b) << 32) | a;
  auto it = open_edges_.find(back_key);
  if (it != open_edges_.end()) {
    int32_t e = it->second;
    open_edges_.erase(it);
    return -e;
  }
  int32_t e = int32_t(bsp_->edges.size());
  bsp_->edges.push_back(DEdge{{a, b}});
  uint64_t key = (uint64_t(a) << 32) | b;
  if (!open_edges_.emplace(key, e).second) stats_.new_edges_for_sharing++;
  return e;
}

void Emitter::add_polygon(const Winding& w0, Polys* out) {
  std::vector<uint32_t> vs;
  vs.reserve(w0.size());
  for (const Vec3& p : w0) {
    uint32_t v = vertex(p);
    if (!vs.empty() && vs.back() == v) continue;
    vs.push_back(v);
  }
  while (vs.size() > 1 && vs.front() == vs.back()) vs.pop_back();
  if (vs.size() < 3) return;
  out->push_back(std::move(vs));
}

void Emitter::write_face(const Face& f, const std::vector<uint32_t>& vs, std::vector<uint32_t>* out_ids) {
  DFace d{};
  d.plane = plane_index(f.plane & ~1);
  d.side = f.plane & 1;
  d.first_edge = int32_t(bsp_->surfedges.size());
  d.num_edges = int32_t(vs.size());
  d.texinfo = f.texinfo;
  for (uint8_t& s : d.styles) s = 255;
  d.lightofs = -1;
  for (size_t i = 0; i < vs.size(); ++i) bsp_->surfedges.push_back(edge(vs[i], vs[(i + 1) % vs.size()]));
  out_ids->push_back(uint32_t(bsp_->faces.size()));
  bsp_->faces.push_back(d);
  face_attr_.push_back(f.attr);
  stats_.faces_out++;
}

void Emitter::face_polygons(const Face& f, Polys* out) {
  stats_.faces_before_subdivide++;
  const DTexInfo& ti = textures_.texinfo()[size_t(f.texinfo)];
  if ((ti.flags & 1) || subdivide_ <= 0) {
    add_polygon(f.w, out);
    return;
  }
  std::vector<Winding> work{f.w};
  bool split_any = false;
  while (!work.empty()) {
    Winding w = std::move(work.back());
    work.pop_back();
    bool done = true;
    for (int axis = 0; axis < 2 && done; ++axis) {
      Vec3 n(ti.vecs[axis][0], ti.vecs[axis][1], ti.vecs[axis][2]);
      double len = glm::length(n);
      if (len < 1e-9) continue;
      double lo = 1e30, hi = -1e30;
      for (const Vec3& p : w) {
        double s = glm::dot(p, n) + ti.vecs[axis][3];
        lo = std::min(lo, s);
        hi = std::max(hi, s);
      }
      if (hi - lo <= subdivide_) continue;
      Plane cut;
      cut.normal = n / len;
      cut.dist = (lo + subdivide_ - ti.vecs[axis][3]) / len;
      cut.type = 3;
      Winding front, back;
      split_winding(w, cut, &front, &back, 0.01);
      if (front.empty() || back.empty()) continue;
      work.push_back(std::move(front));
      work.push_back(std::move(back));
      done = false;
      split_any = true;
    }
    if (done) add_polygon(w, out);
  }
  if (split_any) stats_.subdivided++;
}

void Emitter::fix_tjunctions(std::vector<Polys>* polys) {
  // The model's vertices in a grid of kCell-unit cells.
  constexpr double kCell = 64;
  constexpr double kEndGap = 0.05;
  auto pos = [this](uint32_t v) {
    const float* p = &bsp_->vertices[size_t(v) * 3];
    return Vec3(p[0], p[1], p[2]);
  };
  auto cell_key = [](int64_t x, int64_t y, int64_t z) {
    return uint64_t((x + (1 << 20)) & 0x1fffff) | (uint64_t((y + (1 << 20)) & 0x1fffff) << 21) |
           (uint64_t((z + (1 << 20)) & 0x1fffff) << 42);
  };
  std::vector<uint32_t> verts;
  for (const Polys& ps : *polys)
    for (const auto& vs : ps) verts.insert(verts.end(), vs.begin(), vs.end());
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  if (verts.empty()) return;
  std::unordered_map<uint64_t, std::vector<uint32_t>> grid;
  for (uint32_t v : verts) {
    Vec3 p = pos(v);
    grid[cell_key(int64_t(std::floor(p.x / kCell)), int64_t(std::floor(p.y / kCell)), int64_t(std::floor(p.z / kCell)))]
        .push_back(v);
  }
  // Per undirected edge (low id, high id): the vertices inside it, ordered from low to high.
  std::unordered_map<uint64_t, std::vector<uint32_t>> cache;
  std::vector<std::pair<double, uint32_t>> found;
  auto inside = [&](uint32_t a, uint32_t b) -> const std::vector<uint32_t>& {
    uint64_t key = (uint64_t(a) << 32) | b;
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
    Vec3 pa = pos(a), pb = pos(b), d = pb - pa;
    double len = glm::length(d);
    found.clear();
    auto test = [&](uint32_t v) {
      if (v == a || v == b) return;
      Vec3 pv = pos(v);
      double t = glm::dot(pv - pa, d) / (len * len);
      if (t * len < kEndGap || (1 - t) * len < kEndGap) return;
      if (glm::length(pv - (pa + d * t)) > kTjuncEpsilon) return;
      found.emplace_back(t, v);
    };
    if (len > 2 * kEndGap) {
      Vec3 lo = glm::min(pa, pb) - Vec3(kTjuncEpsilon), hi = glm::max(pa, pb) + Vec3(kTjuncEpsilon);
      int64_t c0[3] = {0, 0, 0}, c1[3] = {0, 0, 0};
      double cells = 1;
      for (int i = 0; i < 3; ++i) {
        c0[i] = int64_t(std::floor(lo[i] / kCell));
        c1[i] = int64_t(std::floor(hi[i] / kCell));
        cells *= double(c1[i] - c0[i] + 1);
      }
      if (cells > double(verts.size())) {
        for (uint32_t v : verts) test(v);
      } else {
        for (int64_t x = c0[0]; x <= c1[0]; ++x)
          for (int64_t y = c0[1]; y <= c1[1]; ++y)
            for (int64_t z = c0[2]; z <= c1[2]; ++z) {
              auto g = grid.find(cell_key(x, y, z));
              if (g == grid.end()) continue;
              for (uint32_t v : g->second) test(v);
            }
      }
    }
    std::sort(found.begin(), found.end());
    std::vector<uint32_t> list;
    for (const auto& [t, v] : found)
      if (list.empty() || list.back() != v) list.push_back(v);
    return cache.emplace(key, std::move(list)).first->second;
  };
  for (Polys& ps : *polys) {
    Polys out;
    for (std::vector<uint32_t>& vs : ps) {
      std::vector<uint32_t> fixed;
      fixed.reserve(vs.size());
      for (size_t i = 0; i < vs.size(); ++i) {
        uint32_t a = vs[i], b = vs[(i + 1) % vs.size()];
        fixed.push_back(a);
        const std::vector<uint32_t>& mid = inside(std::min(a, b), std::max(a, b));
        size_t before = fixed.size();
        if (a < b) {
          fixed.insert(fixed.end(), mid.begin(), mid.end());
        } else {
          fixed.insert(fixed.end(), mid.rbegin(), mid.rend());
        }
        // A vertex already in this polygon is never inserted again.
        for (size_t k = before; k < fixed.size();) {
          if (std::find(vs.begin(), vs.end(), fixed[k]) != vs.end()) fixed.erase(fixed.begin() + long(k));
          else ++k;
        }
        stats_.tjunc_vertices += int(fixed.size() - before);
      }
      // Too many vertices: halve along a chord (i, i + n/2) whose halves both have area.
      std::vector<std::vector<uint32_t>> work{std::move(fixed)};
      while (!work.empty()) {
        std::vector<uint32_t> w = std::move(work.back());
        work.pop_back();
        size_t n = w.size();
        if (n <= kMaxFaceVertices) {
          out.push_back(std::move(w));
          continue;
        }
        bool cut = false;
        for (size_t i = 0; i < n && !cut; ++i) {
          std::vector<uint32_t> h1, h2;
          for (size_t k = 0; k <= n / 2; ++k) h1.push_back(w[(i + k) % n]);
          for (size_t k = n / 2; k <= n; ++k) h2.push_back(w[(i + k) % n]);
          Winding p1, p2;
          for (uint32_t v : h1) p1.push_back(pos(v));
          for (uint32_t v : h2) p2.push_back(pos(v));
          if (winding_area(p1) < 1.0 || winding_area(p2) < 1.0) continue;
          work.push_back(std::move(h1));
          work.push_back(std::move(h2));
          stats_.tjunc_face_splits++;
          cut = true;
        }
        if (!cut) out.push_back(std::move(w));  // cannot happen for a real polygon
      }
    }
    ps = std::move(out);
  }
}

int Emitter::emit_node(const Tree& tree, int n, const std::vector<bool>& face_visible, const std::vector<int>& leaf_index,
                       const std::vector<Polys>& polys, std::vector<std::vector<uint32_t>>* face_ids_of) {
  const TreeNode& node = tree.nodes[size_t(n)];
  if (node.is_leaf()) return -(leaf_index[size_t(n)] + 1);
  int idx = int(bsp_->nodes.size());
  bsp_->nodes.emplace_back();
  uint32_t first = uint32_t(bsp_->faces.size());
  Bounds b;
  for (int f : node.faces) {
    if (!face_visible[size_t(f)]) continue;
    for (const auto& vs : polys[size_t(f)]) write_face(tree.faces[size_t(f)], vs, &(*face_ids_of)[size_t(f)]);
    b.add(tree.faces[size_t(f)].bounds);
  }
  uint32_t count = uint32_t(bsp_->faces.size()) - first;
  int c0 = emit_node(tree, node.children[0], face_visible, leaf_index, polys, face_ids_of);
  int c1 = emit_node(tree, node.children[1], face_visible, leaf_index, polys, face_ids_of);
  DNode& d = bsp_->nodes[size_t(idx)];
  d.plane = plane_index(node.plane);
  d.children[0] = c0;
  d.children[1] = c1;
  d.first_face = first;
  d.num_faces = count;
  // Bounds: faces here plus the children's boxes.
  for (int c : {c0, c1}) {
    const float* mn;
    const float* mx;
    if (c >= 0) {
      mn = bsp_->nodes[size_t(c)].mins;
      mx = bsp_->nodes[size_t(c)].maxs;
    } else if (-(c + 1) != 0) {
      mn = bsp_->leaves[size_t(-(c + 1))].mins;
      mx = bsp_->leaves[size_t(-(c + 1))].maxs;
    } else {
      continue;
    }
    if (mn[0] > mx[0]) continue;
    b.add(Vec3(mn[0], mn[1], mn[2]));
    b.add(Vec3(mx[0], mx[1], mx[2]));
  }
  set_bounds(b, d.mins, d.maxs);
  if (b.empty()) {  // nothing visible below: an inverted box that culls everything
    for (int i = 0; i < 3; ++i) {
      d.mins[i] = 0;
      d.maxs[i] = 0;
    }
  }
  return idx;
}

int Emitter::emit_hull0(const Tree& tree, const std::vector<bool>& face_visible,
                        const std::vector<std::vector<int>>& leaves_of_face, std::vector<int>* leaf_index,
                        int* first_face, int* num_faces) {
  leaf_index->assign(tree.nodes.size(), -1);
  // Leaves in tree order (front first).
  std::vector<int> order;
  std::vector<int> stack{tree.root};
  while (!stack.empty()) {
    int n = stack.back();
    stack.pop_back();
    const TreeNode& node = tree.nodes[size_t(n)];
    if (node.is_leaf()) {
      order.push_back(n);
      continue;
    }
    stack.push_back(node.children[1]);
    stack.push_back(node.children[0]);
  }
  int first_leaf = int(bsp_->leaves.size());
  for (int n : order) {
    const TreeNode& node = tree.nodes[size_t(n)];
    int oc = output_contents(node.contents);
    if (oc == kContentsSolid) {
      (*leaf_index)[size_t(n)] = 0;
      continue;
    }
    (*leaf_index)[size_t(n)] = int(bsp_->leaves.size());
    DLeaf l{};
    l.contents = oc;
    l.visofs = -1;
    set_bounds(node.bounds, l.mins, l.maxs);
    bsp_->leaves.push_back(l);
  }
  *first_face = int(bsp_->faces.size());
  std::vector<std::vector<uint32_t>> face_ids_of(tree.faces.size());
  std::vector<int> face_start(tree.faces.size(), -1);  // child of its node the face points into
  int head;
  if (tree.nodes[size_t(tree.root)].is_leaf()) {
    // A model needs a node: one whose children are both the root leaf.
    head = int(bsp_->nodes.size());
    DNode d{};
    if (planes_.size() > 0) {
      d.plane = plane_index(0);
    } else {
      d.plane = int(bsp_->planes.size());
      bsp_->planes.push_back(DPlane{{0, 0, 1}, 0, 2});
    }
    int c = -((*leaf_index)[size_t(tree.root)] + 1);
    d.children[0] = d.children[1] = c;
    bsp_->nodes.push_back(d);
  } else {
    // Polygons of every visible face on a reachable node (subdivided, welded), T-junctions
    // fixed across the model, then the nodes and faces written.
    std::vector<Polys> polys(tree.faces.size());
    std::vector<int> todo{tree.root};
    while (!todo.empty()) {
      const TreeNode& node = tree.nodes[size_t(todo.back())];
      todo.pop_back();
      if (node.is_leaf()) continue;
      for (int f : node.faces) {
        if (!face_visible[size_t(f)]) continue;
        face_polygons(tree.faces[size_t(f)], &polys[size_t(f)]);
        face_start[size_t(f)] = tree.faces[size_t(f)].plane == node.plane ? node.children[0] : node.children[1];
      }
      todo.push_back(node.children[1]);
      todo.push_back(node.children[0]);
    }
    if (fix_tjunctions_) fix_tjunctions(&polys);
    head = emit_node(tree, tree.root, face_visible, *leaf_index, polys, &face_ids_of);
  }
  *num_faces = int(bsp_->faces.size()) - *first_face;
  // Marksurfaces.
  std::vector<std::vector<uint32_t>> marks(bsp_->leaves.size() - size_t(first_leaf));
  // A face cut into several pieces (subdivision, T-junction splits) marks each piece only in
  // the leaves that piece touches (it is walked down the tree again from the face's node); a
  // piece that finds none (degenerate) falls back to all the face's leaves.
  auto mark = [&](int leaf, uint32_t id) {
    int out = (*leaf_index)[size_t(leaf)];
    if (out <= 0) return;
    marks[size_t(out - first_leaf)].push_back(id);
  };
  std::vector<int> touched, kept;
  Winding w;
  for (size_t f = 0; f < tree.faces.size(); ++f) {
    const std::vector<uint32_t>& ids = face_ids_of[f];
    if (ids.empty()) continue;
    if (ids.size() == 1 || leaves_of_face[f].size() == 1 || face_start[f] < 0) {
      for (int leaf : leaves_of_face[f])
        for (uint32_t id : ids) mark(leaf, id);
      continue;
    }
    for (uint32_t id : ids) {
      const DFace& d = bsp_->faces[id];
      w.clear();
      for (int32_t k = 0; k < d.num_edges; ++k) {
        int32_t se = bsp_->surfedges[size_t(d.first_edge + k)];
        const DEdge& e = bsp_->edges[size_t(se < 0 ? -se : se)];
        uint32_t v = se < 0 ? e.v[1] : e.v[0];
        w.emplace_back(bsp_->vertices[3 * v], bsp_->vertices[3 * v + 1], bsp_->vertices[3 * v + 2]);
      }
      polygon_front_leaves(tree, planes_, face_start[f], w, &touched);
      // Within the face's own leaves (welding may move a vertex by up to 0.01 units).
      kept.clear();
      std::set_intersection(touched.begin(), touched.end(), leaves_of_face[f].begin(), leaves_of_face[f].end(),
                            std::back_inserter(kept));
      for (int leaf : kept.empty() ? leaves_of_face[f] : kept) mark(leaf, id);
    }
  }
  for (size_t i = 0; i < marks.size(); ++i) {
    DLeaf& l = bsp_->leaves[size_t(first_leaf) + i];
    l.first_marksurface = uint32_t(bsp_->marksurfaces.size());
    l.num_marksurfaces = uint32_t(marks[i].size());
    bsp_->marksurfaces.insert(bsp_->marksurfaces.end(), marks[i].begin(), marks[i].end());
  }
  return head;
}

int Emitter::emit_clip_node(const Tree& tree, int n) {
  const TreeNode& node = tree.nodes[size_t(n)];
  if (node.is_leaf()) return output_contents(node.contents);
  int idx = int(bsp_->clipnodes.size());
  bsp_->clipnodes.emplace_back();
  int c0 = emit_clip_node(tree, node.children[0]);
  int c1 = emit_clip_node(tree, node.children[1]);
  DClipNode& d = bsp_->clipnodes[size_t(idx)];
  d.plane = plane_index(node.plane);
  d.children[0] = c0;
  d.children[1] = c1;
  return idx;
}

int Emitter::emit_clip(const Tree& tree) { return emit_clip_node(tree, tree.root); }

}  // namespace sb::tools::bsp
