// tools/bsp/tree.cpp: see tree.h.
#include "tools/bsp/tree.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <deque>

namespace sb::tools::bsp {
namespace {

// Face sets larger than this choose among axial planes only (when there are any).
constexpr size_t kAxialOnlyAbove = 256;

struct Candidate {
  int plane = -1;
  int splits = 0, front = 0, back = 0;
  int detail_splits = 0;  // while choosing structural planes: detail faces split (tie-break)
  bool axial = false;
};

// Lexicographic: fewer splits, then fewer detail splits, then axial, then balance.
bool better(const Candidate& a, const Candidate& b) {
  if (b.plane < 0) return true;
  if (a.splits != b.splits) return a.splits < b.splits;
  if (a.detail_splits != b.detail_splits) return a.detail_splits < b.detail_splits;
  if (a.axial != b.axial) return a.axial;
  return std::abs(a.front - a.back) < std::abs(b.front - b.back);
}

class Builder {
 public:
  Builder(Tree* t, const PlaneSet& planes, TreeStats* st, Progress* progress)
      : t_(t), planes_(planes), st_(st), progress_(progress), original_faces_(int(t->faces.size())) {
    stamp_.assign(size_t(planes.size() / 2 + 1), -1);
  }

  int build(std::vector<int>& ids, int depth) {
    st_->max_depth = std::max(st_->max_depth, depth);
    int n = int(t_->nodes.size());
    t_->nodes.emplace_back();
    if (ids.empty()) {
      st_->leaves++;
      return n;
    }
    bool detail_split = false;
    int plane = choose(ids, &detail_split);
    st_->nodes++;
    t_->nodes[size_t(n)].plane = plane;
    t_->nodes[size_t(n)].detail_split = detail_split;
    const Plane& p = planes_[plane];
    std::vector<int> front, back, on;
    for (int id : ids) {
      Face& f = t_->faces[size_t(id)];
      if ((f.plane & ~1) == plane) {
        on.push_back(id);
        continue;
      }
      Side s = box_side(f.bounds, p);
      if (s == Side::Cross) s = classify_winding(f.w, p);
      if (s == Side::Front) front.push_back(id);
      else if (s == Side::Back) back.push_back(id);
      else if (s == Side::On) on.push_back(id);  // near-coplanar: keep it on this node
      else {
        Winding fw, bw;
        split_winding(f.w, p, &fw, &bw);
        Face fb = f;  // copy before t_->faces may reallocate
        fb.w = std::move(bw);
        f.w = std::move(fw);
        f.update_bounds();
        fb.update_bounds();
        front.push_back(id);
        back.push_back(int(t_->faces.size()));
        t_->faces.push_back(std::move(fb));
      }
    }
    ids.clear();
    ids.shrink_to_fit();
    if (progress_) {
      int placed = 0;
      for (int id : on) placed += id < original_faces_;
      if (placed) progress_->advance(placed);
    }
    t_->nodes[size_t(n)].faces = std::move(on);
    int c0 = build(front, depth + 1);
    int c1 = build(back, depth + 1);
    t_->nodes[size_t(n)].children[0] = c0;
    t_->nodes[size_t(n)].children[1] = c1;
    return n;
  }

 private:
  // Hint planes first, then structural planes (detail faces not counted), then detail.
  int choose(const std::vector<int>& ids, bool* detail_split) {
    bool any_structural = false, any_hint = false;
    for (int id : ids) {
      const Face& f = t_->faces[size_t(id)];
      any_hint = any_hint || f.hint;
      any_structural = any_structural || !f.detail;
    }
    *detail_split = !any_structural;
    ++generation_;
    std::vector<int> cands;
    for (int id : ids) {
      const Face& f = t_->faces[size_t(id)];
      if (any_hint && !f.hint) continue;
      if (any_structural && f.detail) continue;
      int pc = f.plane >> 1;
      if (stamp_[size_t(pc)] == generation_) continue;
      stamp_[size_t(pc)] = generation_;
      cands.push_back(pc * 2);
    }
    // Axial planes first: a good early best makes the split-count abort below bite sooner.
    std::sort(cands.begin(), cands.end(), [this](int a, int b) {
      bool aa = planes_[a].type < 3, ab = planes_[b].type < 3;
      if (aa != ab) return aa;
      return a < b;
    });
    // Large sets: axial planes only while there are any (non-axial splitters are kept for
    // the smaller subtrees, where they cost little to evaluate).
    if (ids.size() > kAxialOnlyAbove && !cands.empty() && planes_[cands.front()].type < 3) {
      size_t n = 0;
      while (n < cands.size() && planes_[cands[n]].type < 3) ++n;
      cands.resize(n);
    }
    // What the candidate loop reads, packed in id order (one pass over the faces per plane).
    const size_t count = ids.size();
    items_.resize(count);
    for (size_t i = 0; i < count; ++i) {
      const Face& f = t_->faces[size_t(ids[i])];
      items_[i] = Item{f.bounds, f.plane & ~1, ids[i], f.detail};
    }
    Candidate best;
    for (int plane : cands) {
      const Plane& p = planes_[plane];
      Candidate c;
      c.plane = plane;
      c.axial = p.type < 3;
      // box_side's cases, specialised: canonical axial planes have normal +1 on their axis.
      bool done;
      if (c.axial && p.normal[p.type] == 1.0)
        done = any_structural ? evaluate<true, true>(p, plane, best, &c) : evaluate<true, false>(p, plane, best, &c);
      else
        done = any_structural ? evaluate<false, true>(p, plane, best, &c) : evaluate<false, false>(p, plane, best, &c);
      bool abort = !done;
      if (!abort && better(c, best)) best = c;
    }
    return best.plane;
  }

  // Counts one candidate over items_ the way box_side + classify_winding would; false when
  // it was abandoned (more splits than `best` already has: it cannot win).
  // kAxial: p is axial with normal +1 on its axis; kStructural: detail faces only break ties.
  template <bool kAxial, bool kStructural>
  bool evaluate(const Plane& p, int plane, const Candidate& best, Candidate* c) {
    const double lo_lim = p.dist - kOnEpsilon, hi_lim = p.dist + kOnEpsilon;
    const int axis = kAxial ? p.type : 0;
    const Vec3 n = p.normal;
    for (const Item& it : items_) {
      if (it.plane == plane) continue;
      double lo, hi;
      if (kAxial) {
        lo = it.bounds.mins[axis];
        hi = it.bounds.maxs[axis];
      } else {
        lo = hi = 0;
        for (int i = 0; i < 3; ++i) {
          double a = n[i] * it.bounds.mins[i], b = n[i] * it.bounds.maxs[i];
          lo += std::min(a, b);
          hi += std::max(a, b);
        }
      }
      Side s = lo >= lo_lim ? Side::Front : hi <= hi_lim ? Side::Back : Side::Cross;
      if (s == Side::Cross) s = classify_winding(t_->faces[size_t(it.id)].w, p);
      if (kStructural && it.detail) {  // counted only to break ties
        c->detail_splits += s == Side::Cross;
        continue;
      }
      if (s == Side::Front) c->front++;
      else if (s == Side::Back) c->back++;
      else if (s == Side::Cross) {
        c->splits++;
        c->front++;
        c->back++;
        if (best.plane >= 0 && c->splits > best.splits) return false;
      }
    }
    return true;
  }

  Tree* t_;
  const PlaneSet& planes_;
  TreeStats* st_;
  Progress* progress_;
  int original_faces_;
  std::vector<int> stamp_;
  int generation_ = 0;
  struct Item {
    Bounds bounds;
    int plane;  // canonical (even) index
    int id;
    bool detail;
  };
  std::vector<Item> items_;
};

}  // namespace

void build_tree(std::vector<Face> faces, const PlaneSet& planes, Tree* tree, TreeStats* stats, Progress* progress) {
  *tree = Tree();
  tree->faces = std::move(faces);
  stats->faces_in = int(tree->faces.size());
  for (const Face& f : tree->faces) tree->box.add(f.bounds);
  std::vector<int> ids(tree->faces.size());
  for (size_t i = 0; i < ids.size(); ++i) ids[i] = int(i);
  Builder b(tree, planes, stats, progress);
  tree->root = b.build(ids, 0);
  stats->faces_after = int(tree->faces.size());
}

void build_portals(Tree* t, const PlaneSet& planes, TreeStats* stats, Progress* progress) {
  Bounds box = t->box;
  if (box.empty()) {
    box.mins = Vec3(-16.0);
    box.maxs = Vec3(16.0);
  }
  box.mins -= Vec3(32.0);
  box.maxs += Vec3(32.0);
  t->outside = int(t->nodes.size());
  t->nodes.emplace_back();
  t->nodes.back().contents = kContentsEmpty;
  Plane sides[6];
  for (int i = 0; i < 6; ++i) {
    int axis = i % 3;
    Plane& p = sides[i];
    p.normal = Vec3(0.0);
    if (i < 3) {
      p.normal[axis] = 1;
      p.dist = box.maxs[axis];
    } else {
      p.normal[axis] = -1;
      p.dist = -box.mins[axis];
    }
    p.type = axis;
  }
  for (int i = 0; i < 6; ++i) {
    Portal portal;
    portal.plane = -1;
    Winding w = base_winding(sides[i]);
    for (int j = 0; j < 6; ++j)
      if (j != i && (j % 3) != (i % 3)) w = clip_winding(w, sides[j], false, 0.001);
    portal.w = std::move(w);
    portal.nodes[0] = t->outside;
    portal.nodes[1] = t->root;
    t->portals.push_back(std::move(portal));
    // Store the box plane in the portal via a sentinel: portals keep their own plane below.
  }
  // Portals carry their own planes (the box planes are not in the PlaneSet).
  std::vector<Plane> pplanes(sides, sides + 6);
  for (int i = 0; i < 6; ++i) {
    t->portals[size_t(i)].plane = i;
    t->nodes[size_t(t->root)].portals.push_back(i);
    t->nodes[size_t(t->outside)].portals.push_back(i);
  }
  // Iterative cut, parents before children.
  Winding scratch;
  std::vector<int> stack{t->root};
  while (!stack.empty()) {
    int n = stack.back();
    stack.pop_back();
    if (progress) progress->advance();
    TreeNode& node = t->nodes[size_t(n)];
    if (node.is_leaf()) continue;
    const Plane& P = planes[node.plane];
    int c0 = node.children[0], c1 = node.children[1];
    std::vector<int> list = std::move(node.portals);
    node.portals.clear();
    Winding w = base_winding(P);
    for (int pid : list) {
      const Portal& p = t->portals[size_t(pid)];
      clip_winding_to(w, pplanes[size_t(p.plane)], p.nodes[0] == n, 0.001, &scratch);
      w.swap(scratch);
      if (w.empty()) break;
    }
    if (!w.empty() && winding_area(w) > 0.001) {
      Portal np;
      np.w = std::move(w);
      np.plane = int(pplanes.size());
      pplanes.push_back(P);
      np.nodes[0] = c0;
      np.nodes[1] = c1;
      int id = int(t->portals.size());
      t->portals.push_back(std::move(np));
      t->nodes[size_t(c0)].portals.push_back(id);
      t->nodes[size_t(c1)].portals.push_back(id);
    }
    for (int pid : list) {
      Portal& p = t->portals[size_t(pid)];
      int side = p.nodes[0] == n ? 0 : 1;
      int other = p.nodes[1 - side];
      Winding f, b;
      split_winding(p.w, P, &f, &b, 0.001);
      if (f.empty() && b.empty()) {  // on the node plane: cannot happen for a proper tree
        p.alive = false;
        continue;
      }
      if (b.empty()) {
        p.nodes[side] = c0;
        t->nodes[size_t(c0)].portals.push_back(pid);
      } else if (f.empty()) {
        p.nodes[side] = c1;
        t->nodes[size_t(c1)].portals.push_back(pid);
      } else {
        Portal q;
        q.w = std::move(b);
        q.plane = p.plane;
        q.nodes[0] = p.nodes[0];
        q.nodes[1] = p.nodes[1];
        q.nodes[side] = c1;
        p.w = std::move(f);
        p.nodes[side] = c0;
        int qid = int(t->portals.size());
        t->portals.push_back(std::move(q));
        t->nodes[size_t(c0)].portals.push_back(pid);
        t->nodes[size_t(c1)].portals.push_back(qid);
        t->nodes[size_t(other)].portals.push_back(qid);
      }
    }
    stack.push_back(c1);
    stack.push_back(c0);
  }
  // Convert portal planes: store the plane in a side table by making nodes[] and the
  // winding authoritative; record the oriented plane as the winding's own.
  for (Portal& p : t->portals) {
    if (!p.alive) continue;
    const Plane& pl = pplanes[size_t(p.plane)];
    if (glm::dot(winding_normal(p.w), pl.normal) < 0) p.w = reverse_winding(p.w);
    p.plane = -1;
  }
  // Leaf bounds; drop dead portal ids from lists.
  int live = 0;
  for (const Portal& p : t->portals) live += p.alive;
  stats->portals = live;
  for (TreeNode& node : t->nodes) {
    if (!node.is_leaf()) continue;
    std::vector<int> kept;
    node.bounds = Bounds();
    for (int pid : node.portals) {
      const Portal& p = t->portals[size_t(pid)];
      if (!p.alive || (p.nodes[0] != int(&node - t->nodes.data()) && p.nodes[1] != int(&node - t->nodes.data())))
        continue;
      kept.push_back(pid);
      for (const Vec3& v : p.w) node.bounds.add(v);
    }
    std::sort(kept.begin(), kept.end());
    kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
    node.portals = std::move(kept);
  }
}

void set_leaf_contents(Tree* t, const std::vector<Brush>& brushes, const PlaneSet& planes) {
  const BrushGrid grid(brushes);
  for (size_t n = 0; n < t->nodes.size(); ++n) {
    TreeNode& node = t->nodes[n];
    if (!node.is_leaf() || int(n) == t->outside) continue;
    if (node.portals.empty()) {
      node.contents = kContentsSolid;
      continue;
    }
    Vec3 c(0.0);
    size_t count = 0;
    for (int pid : node.portals)
      for (const Vec3& v : t->portals[size_t(pid)].w) {
        c += v;
        ++count;
      }
    c /= double(count);
    int best = kContentsEmpty, best_rank = -1;
    const std::vector<int>* near = grid.cell_at(c);
    if (!near) {
      node.contents = best;
      continue;
    }
    for (int bi : *near) {
      const Brush& b = brushes[size_t(bi)];
      if (b.contents == kContentsIllusionary || b.contents == kContentsHint) continue;
      if (c.x < b.bounds.mins.x || c.x > b.bounds.maxs.x || c.y < b.bounds.mins.y || c.y > b.bounds.maxs.y ||
          c.z < b.bounds.mins.z || c.z > b.bounds.maxs.z)
        continue;
      bool inside = true;
      for (const BrushSide& s : b.sides)
        if (planes[s.plane].distance(c) > 0.001) { inside = false; break; }
      if (!inside) continue;
      int r = contents_rank(b.contents);
      if (r > best_rank || (r == best_rank && best == kContentsDetail && b.contents != kContentsDetail)) {
        best_rank = r;
        best = b.contents;
      }
    }
    node.contents = best;
  }
}

int point_leaf(const Tree& t, const PlaneSet& planes, const Vec3& p) {
  int n = t.root;
  while (!t.nodes[size_t(n)].is_leaf()) {
    const TreeNode& node = t.nodes[size_t(n)];
    n = node.children[planes[node.plane].distance(p) >= 0 ? 0 : 1];
  }
  return n;
}

namespace {

// Portals a flood may cross: alive and at least kThinPortal wide (thinner ones are cracks).
std::vector<uint8_t> open_portals(const Tree& t) {
  std::vector<uint8_t> open(t.portals.size(), 0);
  for (size_t i = 0; i < t.portals.size(); ++i)
    open[i] = t.portals[i].alive && winding_min_width(t.portals[i].w) >= kThinPortal;
  return open;
}

// Breadth-first flood from `starts` through open portals between passable leaves.
void flood(Tree* t, const std::vector<int>& starts, bool keep_sky, const std::vector<uint8_t>& open) {
  std::deque<int> q;
  for (int s : starts) {
    if (t->nodes[size_t(s)].reached) continue;
    t->nodes[size_t(s)].reached = true;
    t->nodes[size_t(s)].flood_parent_portal = -1;
    q.push_back(s);
  }
  while (!q.empty()) {
    int n = q.front();
    q.pop_front();
    for (int pid : t->nodes[size_t(n)].portals) {
      if (!open[size_t(pid)]) continue;
      const Portal& p = t->portals[size_t(pid)];
      int o = p.nodes[0] == n ? p.nodes[1] : p.nodes[0];
      TreeNode& on = t->nodes[size_t(o)];
      if (on.reached) continue;
      if (keep_sky && on.contents == kContentsSky) {
        on.reached = true;
        continue;
      }
      if (o != t->outside && !passable(on.contents) && on.contents != kContentsDetail) continue;
      on.reached = true;
      on.flood_parent_portal = pid;
      q.push_back(o);
    }
  }
}

// Every leaf within `eps` of p (a point on a node plane touches both sides).
void leaves_at(const Tree& t, const PlaneSet& planes, int n, const Vec3& p, double eps, std::vector<int>* out) {
  while (!t.nodes[size_t(n)].is_leaf()) {
    const TreeNode& node = t.nodes[size_t(n)];
    double d = planes[node.plane].distance(p);
    if (d > eps) {
      n = node.children[0];
    } else if (d < -eps) {
      n = node.children[1];
    } else {
      leaves_at(t, planes, node.children[0], p, eps, out);
      n = node.children[1];
    }
  }
  out->push_back(n);
}

bool flood_passes(const Tree& t, int n) {
  return n == t.outside || passable(t.nodes[size_t(n)].contents) || t.nodes[size_t(n)].contents == kContentsDetail;
}

}  // namespace

void entity_leaves(const Tree& t, const PlaneSet& planes, const Vec3& p, std::vector<int>* out) {
  out->clear();
  leaves_at(t, planes, t.root, p, kEntityTouchEpsilon, out);
  std::sort(out->begin(), out->end());
  out->erase(std::unique(out->begin(), out->end()), out->end());
}

int flood_fill_entities(Tree* t, const PlaneSet& planes, const std::vector<Vec3>& origins, bool fill_unreached,
                        LeakInfo* leak) {
  *leak = LeakInfo();
  const std::vector<uint8_t> open = open_portals(*t);
  for (TreeNode& n : t->nodes) n.reached = false;
  flood(t, {t->outside}, false, open);
  std::vector<int> starts, touch;
  for (size_t i = 0; i < origins.size(); ++i) {
    entity_leaves(*t, planes, origins[i], &touch);
    bool any_passable = false, inside = false;
    int outside_leaf = -1;
    for (int l : touch) {
      const TreeNode& node = t->nodes[size_t(l)];
      any_passable = any_passable || passable(node.contents);
      if (!node.reached) {
        inside = true;
        if (passable(node.contents)) starts.push_back(l);
      } else if (outside_leaf < 0 && passable(node.contents)) {
        outside_leaf = l;
      }
    }
    if (!any_passable || inside || leak->leaked) continue;
    leak->leaked = true;
    leak->entity = int(i);
    leak->path.push_back(origins[i]);
    int n = outside_leaf;
    while (n != t->outside) {
      int pid = t->nodes[size_t(n)].flood_parent_portal;
      if (pid < 0) break;
      const Portal& p = t->portals[size_t(pid)];
      leak->path.push_back(winding_center(p.w));
      n = p.nodes[0] == n ? p.nodes[1] : p.nodes[0];
    }
  }
  if (leak->leaked || starts.empty()) {
    for (TreeNode& n : t->nodes) n.reached = false;
    return 0;
  }
  for (TreeNode& n : t->nodes) n.reached = false;
  flood(t, starts, true, open);
  // Slivers in open space: an unreached passable leaf whose every neighbour the flood could
  // enter was reached (none is the outside) is kept: only a thin portal kept the flood out.
  std::vector<int> slivers;
  for (size_t i = 0; i < t->nodes.size(); ++i) {
    const TreeNode& n = t->nodes[i];
    if (!n.is_leaf() || int(i) == t->outside || n.reached || !passable(n.contents)) continue;
    bool all = true, any = false;
    for (int pid : n.portals) {
      const Portal& p = t->portals[size_t(pid)];
      int o = p.nodes[0] == int(i) ? p.nodes[1] : p.nodes[0];
      if (!flood_passes(*t, o)) continue;
      if (o == t->outside || !t->nodes[size_t(o)].reached) {
        all = false;
        break;
      }
      any = true;
    }
    if (all && any) slivers.push_back(int(i));
  }
  for (int s : slivers) t->nodes[size_t(s)].reached = true;
  int filled = 0;
  for (size_t i = 0; i < t->nodes.size(); ++i) {
    TreeNode& n = t->nodes[i];
    if (!n.is_leaf() || int(i) == t->outside || n.reached) continue;
    if (fill_unreached && n.contents != kContentsSolid) {
      n.contents = kContentsSolid;
      ++filled;
    }
  }
  return filled;
}

bool fill_from_outside(Tree* t, const PlaneSet& planes, const std::vector<Vec3>& origins) {
  const std::vector<uint8_t> open = open_portals(*t);
  for (TreeNode& n : t->nodes) n.reached = false;
  flood(t, {t->outside}, false, open);
  for (const Vec3& o : origins) {
    int l = point_leaf(*t, planes, o);
    if (passable(t->nodes[size_t(l)].contents) && t->nodes[size_t(l)].reached) {
      for (TreeNode& n : t->nodes) n.reached = false;
      return false;
    }
  }
  for (size_t i = 0; i < t->nodes.size(); ++i) {
    TreeNode& n = t->nodes[i];
    if (n.is_leaf() && int(i) != t->outside && n.reached) n.contents = kContentsSolid;
    n.reached = false;
  }
  return true;
}

namespace {

bool visible_leaf(int contents) {
  return contents != kContentsSolid && contents != kContentsDetail && contents != kContentsClip;
}

void push_face(const Tree& t, const PlaneSet& planes, int n, const Winding& w, const Bounds& b, std::vector<int>* out) {
  for (;;) {
    const TreeNode& node = t.nodes[size_t(n)];
    if (node.is_leaf()) {
      if (visible_leaf(node.contents)) out->push_back(n);
      return;
    }
    const Plane& p = planes[node.plane];
    Side s = box_side(b, p, 0.01);
    if (s == Side::Cross) s = classify_winding(w, p, 0.01);
    if (s == Side::Front) { n = node.children[0]; continue; }
    if (s == Side::Back) { n = node.children[1]; continue; }
    if (s == Side::On) {
      push_face(t, planes, node.children[0], w, b, out);
      n = node.children[1];
      continue;
    }
    Winding f, k;
    split_winding(w, p, &f, &k, 0.01);
    Bounds fb, kb;
    for (const Vec3& v : f) fb.add(v);
    for (const Vec3& v : k) kb.add(v);
    if (!f.empty()) push_face(t, planes, node.children[0], f, fb, out);
    if (!k.empty()) push_face(t, planes, node.children[1], k, kb, out);
    return;
  }
}

}  // namespace

void polygon_front_leaves(const Tree& t, const PlaneSet& planes, int start, const Winding& w, std::vector<int>* out) {
  out->clear();
  if (w.size() < 3) return;
  Bounds b;
  for (const Vec3& v : w) b.add(v);
  push_face(t, planes, start, w, b, out);
  std::sort(out->begin(), out->end());
  out->erase(std::unique(out->begin(), out->end()), out->end());
}

void face_front_leaves(const Tree& t, const PlaneSet& planes, std::vector<std::vector<int>>* leaves_of_face) {
  leaves_of_face->assign(t.faces.size(), {});
  for (const TreeNode& node : t.nodes) {
    if (node.is_leaf()) continue;
    for (int fid : node.faces) {
      const Face& f = t.faces[size_t(fid)];
      if (f.texinfo < 0) continue;
      int child = f.plane == node.plane ? node.children[0] : node.children[1];
      std::vector<int>& out = (*leaves_of_face)[size_t(fid)];
      push_face(t, planes, child, f.w, f.bounds, &out);
      std::sort(out.begin(), out.end());
      out.erase(std::unique(out.begin(), out.end()), out.end());
    }
  }
}

namespace {

int prune(Tree* t, int n, const std::vector<bool>& visible, int* removed) {
  TreeNode& node = t->nodes[size_t(n)];
  if (node.is_leaf()) return n;
  int c0 = prune(t, node.children[0], visible, removed);
  int c1 = prune(t, node.children[1], visible, removed);
  TreeNode& a = t->nodes[size_t(c0)];
  TreeNode& b = t->nodes[size_t(c1)];
  TreeNode& me = t->nodes[size_t(n)];
  if (a.is_leaf() && b.is_leaf() && !visible_leaf(a.contents) && !visible_leaf(b.contents)) {
    bool keep = false;
    for (int f : me.faces) keep = keep || visible[size_t(f)];
    if (!keep) {
      me.plane = -1;
      me.contents = kContentsSolid;
      me.faces.clear();
      ++*removed;
    }
  }
  return n;
}

}  // namespace

int prune_solid(Tree* t, const std::vector<bool>& face_visible) {
  int removed = 0;
  prune(t, t->root, face_visible, &removed);
  return removed;
}

namespace {

int prune_eq(Tree* t, int n, int* removed) {
  if (t->nodes[size_t(n)].is_leaf()) return n;
  int c0 = prune_eq(t, t->nodes[size_t(n)].children[0], removed);
  int c1 = prune_eq(t, t->nodes[size_t(n)].children[1], removed);
  const TreeNode& a = t->nodes[size_t(c0)];
  const TreeNode& b = t->nodes[size_t(c1)];
  if (a.is_leaf() && b.is_leaf() && output_contents(a.contents) == output_contents(b.contents)) {
    TreeNode& me = t->nodes[size_t(n)];
    me.contents = output_contents(a.contents);
    me.plane = -1;
    me.faces.clear();
    ++*removed;
  }
  return n;
}

}  // namespace

int prune_equal(Tree* t) {
  int removed = 0;
  prune_eq(t, t->root, &removed);
  return removed;
}

namespace {

// PVS (non-solid) leaves under n and their bounds, for every node of the subtree.
int count_visible(const Tree& t, int n, std::vector<int>* out, std::vector<Bounds>* bb) {
  const TreeNode& node = t.nodes[size_t(n)];
  int c = 0;
  Bounds b;
  if (node.is_leaf()) {
    if (visible_leaf(node.contents)) c = 1, b = node.bounds;
  } else {
    c = count_visible(t, node.children[0], out, bb) + count_visible(t, node.children[1], out, bb);
    for (int k = 0; k < 2; ++k)
      if ((*out)[size_t(node.children[k])]) b.add((*bb)[size_t(node.children[k])]);
  }
  (*out)[size_t(n)] = c;
  (*bb)[size_t(n)] = b;
  return c;
}

}  // namespace

bool has_detail_splits(const Tree& t) {
  for (const TreeNode& n : t.nodes)
    if (!n.is_leaf() && n.detail_split) return true;
  return false;
}

void build_cluster_portals(const Tree& t, const PlaneSet& planes, const ClusterLimits& lim, ClusterPortals* out) {
  *out = ClusterPortals();
  // The structural tree: same indices, detail-split nodes made leaves unless they are too big
  // a cluster (see ClusterLimits): those are portalled like structural nodes.
  Tree s;
  s.nodes.resize(t.nodes.size());
  std::vector<int> vis_count(t.nodes.size(), 0);
  std::vector<Bounds> vis_bounds(t.nodes.size());
  count_visible(t, t.root, &vis_count, &vis_bounds);
  auto extent = [&](size_t i) {
    const Bounds& b = vis_bounds[i];
    if (!vis_count[i]) return 0.0;
    return std::max({b.maxs.x - b.mins.x, b.maxs.y - b.mins.y, b.maxs.z - b.mins.z});
  };
  for (size_t i = 0; i < t.nodes.size(); ++i) {
    const TreeNode& a = t.nodes[i];
    TreeNode& b = s.nodes[i];
    const bool big = lim.max_leaves > 0 && vis_count[i] > lim.max_leaves && extent(i) > lim.max_extent;
    b.plane = a.detail_split && !big ? -1 : a.plane;
    b.children[0] = a.children[0];
    b.children[1] = a.children[1];
  }
  s.root = t.root;
  s.box = t.box;
  TreeStats st;
  build_portals(&s, planes, &st);
  out->root_of.assign(t.nodes.size(), -1);
  std::vector<int> stack{t.root};
  while (!stack.empty()) {
    int n = stack.back();
    stack.pop_back();
    if (!s.nodes[size_t(n)].is_leaf()) {
      stack.push_back(s.nodes[size_t(n)].children[1]);
      stack.push_back(s.nodes[size_t(n)].children[0]);
      continue;
    }
    out->roots.push_back(n);
    std::vector<int> sub{n};
    while (!sub.empty()) {
      int m = sub.back();
      sub.pop_back();
      out->root_of[size_t(m)] = n;
      const TreeNode& node = t.nodes[size_t(m)];
      if (node.is_leaf()) continue;
      sub.push_back(node.children[0]);
      sub.push_back(node.children[1]);
    }
  }
  for (Portal& p : s.portals) {
    if (!p.alive) continue;
    for (int& side : p.nodes)
      if (side == s.outside) side = t.outside;
    out->portals.push_back(std::move(p));
  }
}

}  // namespace sb::tools::bsp
