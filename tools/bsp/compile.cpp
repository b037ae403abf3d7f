// tools/bsp/compile.cpp: see compile.h.
#include "tools/bsp/compile.h"

#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <thread>

#include "engine/formats/entities.h"
#include "tools/bsp/brushes.h"
#include "tools/bsp/csg.h"
#include "tools/bsp/emit.h"
#include "tools/bsp/map_file.h"
#include "tools/bsp/textures.h"
#include "tools/bsp/tree.h"

namespace sb::tools::bsp {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

struct Ctx {
  const BspOptions& opt;
  CompileReport* rep;
  LogFn log;
  void* user;
  void say(bool verbose_only, const char* fmt, ...) __attribute__((format(printf, 3, 4))) {
    if (opt.quiet || (verbose_only && !opt.verbose) || !log) return;
    char line[1024];
    va_list ap;
    va_start(ap, fmt);
    std::vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    log(user, line);
  }
  Progress::Mode progress_mode() const {
    return opt.quiet || !opt.progress ? Progress::Mode::Quiet : Progress::Mode::Auto;
  }
  void add_time(const char* stage, double s) {
    for (StageTime& t : rep->times)
      if (t.name == stage) { t.seconds += s; return; }
    rep->times.push_back({stage, s});
  }
};

std::string replace_ext(const std::string& path, const char* ext) {
  size_t slash = path.find_last_of('/');
  size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path + ext;
  return path.substr(0, dot) + ext;
}

std::string dir_of(const std::string& path) {
  size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

std::string entities_text(const MapFile& map, const std::vector<bool>& keep) {
  std::string out;
  for (size_t i = 0; i < map.entities.size(); ++i) {
    if (!keep[i]) continue;
    out += "{\n";
    for (const auto& kv : map.entities[i].pairs) out += "\"" + kv.first + "\" \"" + kv.second + "\"\n";
    out += "}\n";
  }
  return out;
}

bool write_text(const std::string& path, const std::string& text) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  ok = (std::fclose(f) == 0) && ok;
  return ok;
}

// PRT1: world leaves as PVS leaves (output leaf index - 1), portals between two of them.
// A portal's winding (clockwise seen from its front) faces the first leaf written.
std::string portal_text(const Tree& tree, const std::vector<int>& leaf_index, int visleafs, int* count) {
  std::string body;
  *count = 0;
  char buf[128];
  for (const Portal& p : tree.portals) {
    if (!p.alive) continue;
    int a = p.nodes[0] == tree.outside ? -1 : leaf_index[size_t(p.nodes[0])];
    int b = p.nodes[1] == tree.outside ? -1 : leaf_index[size_t(p.nodes[1])];
    if (a <= 0 || b <= 0) continue;
    std::snprintf(buf, sizeof buf, "%zu %d %d", p.w.size(), a - 1, b - 1);
    body += buf;
    for (const Vec3& v : p.w) {
      std::snprintf(buf, sizeof buf, " (%.6g %.6g %.6g )", v.x, v.y, v.z);
      body += buf;
    }
    body += "\n";
    ++*count;
  }
  return "PRT1\n" + std::to_string(visleafs) + "\n" + std::to_string(*count) + "\n" + body;
}

// PRT2 (maps with detail): the portals of the structural tree between vis clusters, then for
// every cluster its PVS leaves (output leaf index - 1) ending with -1:
//   PRT2 / <leaves> / <clusters> / <portals> / "<points> <cluster> <cluster> (x y z ) ..." /
//   "<leaf> <leaf> ... -1" per cluster.
// Clusters without a PVS leaf (all solid after the outside fill) are left out.
std::string portal_text_clusters(const Tree& tree, const ClusterPortals& cp, const std::vector<int>& leaf_index,
                                 int visleafs, int* count, int* clusters) {
  std::vector<int> cluster_of_root(tree.nodes.size(), -1);
  std::string map;
  *clusters = 0;
  for (int root : cp.roots) {
    std::string line;
    std::vector<int> stack{root};
    while (!stack.empty()) {
      int n = stack.back();
      stack.pop_back();
      const TreeNode& node = tree.nodes[size_t(n)];
      if (!node.is_leaf()) {
        stack.push_back(node.children[1]);
        stack.push_back(node.children[0]);
        continue;
      }
      if (leaf_index[size_t(n)] > 0) line += std::to_string(leaf_index[size_t(n)] - 1) + " ";
    }
    if (line.empty()) continue;
    cluster_of_root[size_t(root)] = (*clusters)++;
    map += line + "-1\n";
  }
  std::string body;
  *count = 0;
  char buf[128];
  for (const Portal& p : cp.portals) {
    if (p.nodes[0] == tree.outside || p.nodes[1] == tree.outside) continue;
    int a = cluster_of_root[size_t(p.nodes[0])], b = cluster_of_root[size_t(p.nodes[1])];
    if (a < 0 || b < 0 || a == b) continue;
    std::snprintf(buf, sizeof buf, "%zu %d %d", p.w.size(), a, b);
    body += buf;
    for (const Vec3& v : p.w) {
      std::snprintf(buf, sizeof buf, " (%.6g %.6g %.6g )", v.x, v.y, v.z);
      body += buf;
    }
    body += "\n";
    ++*count;
  }
  return "PRT2\n" + std::to_string(visleafs) + "\n" + std::to_string(*clusters) + "\n" + std::to_string(*count) +
         "\n" + body + map;
}

struct HullTrees {
  int head[3] = {0, -1, -1};
};

}  // namespace

Status compile_map(const BspOptions& opt, CompileReport* rep, LogFn log, void* log_user) {
  *rep = CompileReport();
  Ctx c{opt, rep, log, log_user};
  auto t_total = Clock::now();
  auto t = Clock::now();
  MapFile map;
  SB_TRY(read_map(opt.map_path.c_str(), &map));
  rep->warnings = map.warnings;
  int map_brushes = 0;
  for (const MapEntity& e : map.entities) map_brushes += int(e.brushes.size());
  c.add_time("parse", seconds_since(t));
  c.say(false, "parse: %s: %zu entities, %d brushes, %s format (%.2f s)", opt.map_path.c_str(), map.entities.size(),
        map_brushes, map.valve_faces > 0 ? (map.standard_faces > 0 ? "mixed" : "Valve 220") : "standard",
        seconds_since(t));

  t = Clock::now();
  TextureSet textures;
  int wads = textures.load_wads(map.entities[0].get("wad"), dir_of(opt.map_path), opt.wads, &rep->warnings);
  PlaneSet planes;
  std::vector<ModelSource> models;
  std::vector<bool> keep;
  BrushStats bstats;
  std::vector<FaceAttr> attr_table;
  build_models(map, textures, planes, &models, &keep, &bstats, &rep->warnings, &attr_table);
  rep->brushes = bstats.map_brushes;
  rep->skipped_brushes = bstats.skipped;
  rep->models = int(models.size());
  c.add_time("brushes", seconds_since(t));
  c.say(false,
        "brushes: %d brushes (%d skipped, %d detail, %d illusionary, %d clip, %d liquid, %d sky, %d hint, %d origin "
        "dropped), %d models, %d WADs (%.2f s)",
        bstats.map_brushes, bstats.skipped, bstats.detail, bstats.illusionary, bstats.clip, bstats.liquid, bstats.sky,
        bstats.hint, bstats.origin_dropped, int(models.size()), wads, seconds_since(t));

  // Point entity origins for the flood fill. Lights alone are nothing to flood from: a map
  // whose only point entities are lights (LibreQuake's b_*.map item prefabs, lit for preview
  // from outside their brushes) has no inside; its outside is kept and no leak is reported.
  std::vector<Vec3> origins;
  std::vector<size_t> origin_entity;
  bool any_occupant = false;
  for (size_t i = 1; i < map.entities.size(); ++i) {
    const MapEntity& e = map.entities[i];
    if (!keep[i] || !e.brushes.empty()) continue;
    const std::string* o = e.find("origin");
    glm::vec3 v;
    if (!o || !parse_vec3(*o, &v)) continue;
    origins.push_back(Vec3(v));
    origin_entity.push_back(i);
    any_occupant = any_occupant || e.classname().substr(0, 5) != "light";
  }
  if (!any_occupant && !origins.empty()) {
    c.say(true, "fill: %zu point entities, all lights: nothing to flood from", origins.size());
    origins.clear();
    origin_entity.clear();
  }

  BspData& bsp = rep->bsp;
  Emitter emitter(&bsp, planes, textures, opt.subdivide, opt.tjunc);
  emitter.begin();
  std::string prt;
  const Vec3 hull_min[3] = {Vec3(0.0), Vec3(-16, -16, -24), Vec3(-32, -32, -24)};
  const Vec3 hull_max[3] = {Vec3(0.0), Vec3(16, 16, 32), Vec3(32, 32, 64)};
  int total_csg = 0;
  for (size_t m = 0; m < models.size(); ++m) {
    const ModelSource& src = models[m];
    bool world = m == 0;
    // ---- hull 0
    std::vector<Brush> drawn;
    for (const Brush& b : src.brushes)
      if (b.contents != kContentsClip && b.contents != kContentsHint) drawn.push_back(b);
    t = Clock::now();
    std::vector<Face> faces;
    CsgStats cs;
    {
      Progress pr("csg", int64_t(drawn.size()), world ? c.progress_mode() : Progress::Mode::Quiet);
      csg_faces(drawn, planes, &faces, &cs, &pr);
    }
    total_csg += cs.faces_out;
    hint_faces(src.brushes, &faces);
    c.add_time("csg", seconds_since(t));
    if (world)
      c.say(false, "csg: %d brushes -> %d faces (%d merged, %d liquid back faces, %d hidden under detail) (%.2f s)",
            cs.brushes, cs.faces_out, cs.merged, cs.back_faces, cs.hidden, seconds_since(t));
    t = Clock::now();
    Tree tree;
    TreeStats ts;
    {
      Progress pr("bsp", int64_t(faces.size()), world ? c.progress_mode() : Progress::Mode::Quiet);
      build_tree(std::move(faces), planes, &tree, &ts, &pr);
    }
    c.add_time("bsp", seconds_since(t));
    rep->bsp_faces_in += ts.faces_in;
    rep->bsp_faces_after += ts.faces_after;
    if (world)
      c.say(false, "bsp: %d faces -> %d (+%.1f%% from splits), %d nodes, %d leaves, depth %d (%.2f s)", ts.faces_in,
            ts.faces_after, ts.split_percent(), ts.nodes, ts.leaves, ts.max_depth, seconds_since(t));
    t = Clock::now();
    {
      Progress pr("portals", int64_t(tree.nodes.size()), world ? c.progress_mode() : Progress::Mode::Quiet);
      build_portals(&tree, planes, &ts, &pr);
    }
    set_leaf_contents(&tree, drawn, planes);
    c.add_time("portals", seconds_since(t));
    if (world) {
      rep->portals = ts.portals;
      c.say(false, "portals: %d (%.2f s)", ts.portals, seconds_since(t));
      t = Clock::now();
      if (opt.fill) {
        LeakInfo leak;
        int filled = flood_fill_entities(&tree, planes, origins, true, &leak);
        rep->filled_leaves = filled;
        if (leak.leaked) {
          rep->leaked = true;
          const MapEntity& e = map.entities[origin_entity[size_t(leak.entity)]];
          const Vec3& o = origins[size_t(leak.entity)];
          char msg[512];
          std::snprintf(msg, sizeof msg, "leak: %.*s at (%g %g %g) (%s:%d) reaches the outside; no outside fill, no .prt",
                        int(e.classname().size()), e.classname().data(), o.x, o.y, o.z, opt.map_path.c_str(), e.line);
          rep->leak_message = msg;
          c.say(false, "%s", msg);
          if (opt.write_files) {
            std::string pts;
            char line[128];
            // The path, with points every 8 units along each segment for editors.
            for (size_t i = 0; i < leak.path.size(); ++i) {
              if (i > 0) {
                Vec3 a = leak.path[i - 1], b = leak.path[i];
                int steps = int(glm::length(b - a) / 8.0);
                for (int s = 1; s < steps; ++s) {
                  Vec3 p = a + (b - a) * (double(s) / steps);
                  std::snprintf(line, sizeof line, "%g %g %g\n", p.x, p.y, p.z);
                  pts += line;
                }
              }
              std::snprintf(line, sizeof line, "%g %g %g\n", leak.path[i].x, leak.path[i].y, leak.path[i].z);
              pts += line;
            }
            std::string out = opt.bsp_path.empty() ? replace_ext(opt.map_path, ".bsp") : opt.bsp_path;
            rep->pts_path = replace_ext(out, ".pts");
            if (!write_text(rep->pts_path, pts)) return make_error("%s: cannot write the leak file", rep->pts_path.c_str());
          }
        } else if (origins.empty()) {
          rep->outside_kept = true;
          rep->warnings.push_back("no entities to flood from; outside kept");
        }
        c.say(false, "fill: %d leaves filled (%.2f s)", filled, seconds_since(t));
      }
      c.add_time("fill", seconds_since(t));
    }
    t = Clock::now();
    std::vector<std::vector<int>> leaves_of_face;
    face_front_leaves(tree, planes, &leaves_of_face);
    std::vector<bool> visible(tree.faces.size());
    for (size_t f = 0; f < tree.faces.size(); ++f) visible[f] = tree.faces[f].texinfo >= 0 && !leaves_of_face[f].empty();
    prune_solid(&tree, visible);
    std::vector<int> leaf_index;
    int first_leaf = int(bsp.leaves.size());
    DModel dm{};
    HullTrees heads;
    heads.head[0] = emitter.emit_hull0(tree, visible, leaves_of_face, &leaf_index, &dm.first_face, &dm.num_faces);
    if (world) {
      rep->visleafs = int(bsp.leaves.size()) - first_leaf;
      if (!rep->leaked && opt.fill) {
        int count = 0;
        if (has_detail_splits(tree) && !opt.prt1_only) {
          ClusterPortals cp;
          ClusterLimits lim;
          lim.max_leaves = opt.cluster_leaves;
          lim.max_extent = opt.cluster_extent;
          build_cluster_portals(tree, planes, lim, &cp);
          prt = portal_text_clusters(tree, cp, leaf_index, rep->visleafs, &count, &rep->clusters);
        } else {
          prt = portal_text(tree, leaf_index, rep->visleafs, &count);
          rep->clusters = rep->visleafs;
        }
        rep->prt_portals = count;
        rep->prt_format = prt.substr(0, 4);
      }
    }
    c.add_time("emit", seconds_since(t));

    // ---- clip hulls: brushes expanded here (the PlaneSet grows); the trees are built on
    // worker threads that only read it, then emitted in hull order (deterministic).
    t = Clock::now();
    if (opt.clip_hulls) {
      std::vector<Brush> hb[3];
      // Bevel planes are found once per brush (with hull 1) and reused for hull 2.
      std::vector<HullPlanes> hps(src.brushes.size());
      for (int h = 1; h <= 2; ++h)
        for (size_t i = 0; i < src.brushes.size(); ++i) {
          const Brush& b = src.brushes[i];
          if (is_liquid(b.contents) || b.contents == kContentsIllusionary || b.contents == kContentsHint) continue;
          if (h == 1) hull_planes(b, planes, &hps[i]);
          Brush e;
          if (expand_brush(b, hps[i], hull_min[h], hull_max[h], planes, &e)) hb[h].push_back(std::move(e));
        }
      Tree ht[3];
      // Hull progress: one unit per brush through CSG, then the brush count again when the tree is built.
      Progress hull_progress("hulls", 2 * int64_t(hb[1].size() + hb[2].size()),
                             world ? c.progress_mode() : Progress::Mode::Quiet);
      std::string hull_warning[3];
      int pruned[3] = {0, 0, 0}, csg_count[3] = {0, 0, 0};
      auto work = [&](int h) {
        std::vector<Face> hf;
        CsgStats hcs;
        csg_faces(hb[h], planes, &hf, &hcs, &hull_progress);
        csg_count[h] = hcs.faces_out;
        TreeStats hts;
        build_tree(std::move(hf), planes, &ht[h], &hts);
        hull_progress.advance(int64_t(hb[h].size()));
        build_portals(&ht[h], planes, &hts);
        set_leaf_contents(&ht[h], hb[h], planes);
        if (world && opt.fill && !rep->leaked && !origins.empty() && !fill_from_outside(&ht[h], planes, origins))
          hull_warning[h] = "hull " + std::to_string(h) + ": an entity reaches the outside; hull not filled";
        pruned[h] = prune_equal(&ht[h]);
      };
      if (opt.threads > 1) {
        std::thread worker(work, 1);
        work(2);
        worker.join();
      } else {
        work(1);
        work(2);
      }
      hull_progress.finish();
      for (int h = 1; h <= 2; ++h) {
        if (!hull_warning[h].empty()) rep->warnings.push_back(hull_warning[h]);
        size_t before = bsp.clipnodes.size();
        heads.head[h] = emitter.emit_clip(ht[h]);
        if (world)
          c.say(true, "hull %d: %zu brushes -> %d faces, %d nodes pruned, %zu clipnodes", h, hb[h].size(), csg_count[h],
                pruned[h], bsp.clipnodes.size() - before);
      }
    } else {
      heads.head[1] = heads.head[2] = kContentsEmpty;
    }
    c.add_time("hulls", seconds_since(t));
    Bounds mb;
    for (const Brush& b : src.brushes) mb.add(b.bounds);
    for (int i = 0; i < 3; ++i) {
      dm.mins[i] = mb.empty() ? 0.f : float(mb.mins[i]);
      dm.maxs[i] = mb.empty() ? 0.f : float(mb.maxs[i]);
      dm.origin[i] = 0;
    }
    dm.headnode[0] = heads.head[0];
    dm.headnode[1] = heads.head[1];
    dm.headnode[2] = heads.head[2];
    dm.headnode[3] = bsp.clipnodes.empty() ? kContentsEmpty : 0;
    dm.visleafs = world ? rep->visleafs : 0;
    bsp.models.push_back(dm);
  }
  rep->csg_faces = total_csg;
  // Light attributes per output face; kept only when some face has one.
  rep->face_attrs.clear();
  if (attr_table.size() > 1) {
    rep->face_attrs.reserve(emitter.face_attrs().size());
    for (int a : emitter.face_attrs()) rep->face_attrs.push_back(attr_table[size_t(a)]);
  }
  rep->tjunc_vertices = emitter.stats().tjunc_vertices;
  rep->tjunc_face_splits = emitter.stats().tjunc_face_splits;
  rep->split_percent = rep->bsp_faces_in ? 100.0 * (rep->bsp_faces_after - rep->bsp_faces_in) / rep->bsp_faces_in : 0;
  c.say(false, "hulls: %zu clipnodes (%.2f s)", bsp.clipnodes.size(), [&] {
    for (const StageTime& s : rep->times)
      if (s.name == "hulls") return s.seconds;
    return 0.0;
  }());

  // Edge 0 is the unused placeholder (0, 0); a map with no drawn face (only skip or clip
  // brushes) would otherwise leave it naming a vertex that does not exist, which loaders
  // rightly reject. One vertex at the origin keeps the file valid everywhere.
  if (bsp.vertices.empty()) bsp.vertices.assign(3, 0.0f);

  t = Clock::now();
  bsp.texinfo = textures.texinfo();
  textures.build_lump(&bsp.textures, &rep->warnings);
  rep->missing_textures = textures.missing_count();
  bsp.entities = entities_text(map, keep);
  c.add_time("textures", seconds_since(t));

  t = Clock::now();
  std::string why;
  if (opt.format == BspFormat::Bsp29 && !fits_bsp29(bsp, &why))
    return make_error("%s: -bsp29: the map exceeds a BSP29 limit (%s); leave out -bsp29 or use -bsp2",
                      opt.map_path.c_str(), why.c_str());
  if (opt.write_files) {
    std::string out = opt.bsp_path.empty() ? replace_ext(opt.map_path, ".bsp") : opt.bsp_path;
    SB_TRY(write_bsp(out.c_str(), bsp, opt.format, &rep->format_written));
    if (FILE* f = std::fopen(out.c_str(), "rb")) {
      if (std::fseek(f, 0, SEEK_END) == 0) rep->bsp_bytes = std::ftell(f);
      std::fclose(f);
    }
    std::string prt_path = replace_ext(out, ".prt");
    if (!prt.empty()) {
      if (!write_text(prt_path, prt)) return make_error("%s: cannot write the portal file", prt_path.c_str());
      rep->prt_path = prt_path;
    } else {
      std::remove(prt_path.c_str());  // a stale .prt would describe another tree
    }
    if (!rep->leaked) std::remove(replace_ext(out, ".pts").c_str());
    std::string attr_path = face_attr_path(out);
    if (!rep->face_attrs.empty()) {
      SB_TRY(write_face_attrs(attr_path.c_str(), bsp, rep->face_attrs));
      rep->face_attr_path = attr_path;
    } else {
      std::remove(attr_path.c_str());  // a stale side file would describe other faces
    }
  } else {
    std::vector<uint8_t> bytes;
    SB_TRY(serialize_bsp(bsp, opt.format, &bytes, &rep->format_written));
    rep->bsp_bytes = int64_t(bytes.size());
  }
  c.add_time("write", seconds_since(t));
  rep->total_seconds = seconds_since(t_total);
  for (const std::string& w : rep->warnings) c.say(false, "warning: %s", w.c_str());
  if (!opt.quiet && log) {
    std::string s = summary_text(*rep);
    size_t start = 0;
    while (start < s.size()) {
      size_t end = s.find('\n', start);
      if (end == std::string::npos) end = s.size();
      log(log_user, s.substr(start, end - start).c_str());
      start = end + 1;
    }
  }
  return Status::ok();
}

std::string summary_text(const CompileReport& r) {
  const BspData& b = r.bsp;
  char buf[2048];
  std::string s;
  std::string prt = r.prt_format.empty() ? std::string("no .prt")
                    : r.prt_format == "PRT2"
                        ? "PRT2 (" + std::to_string(r.clusters) + " clusters, " + std::to_string(r.prt_portals) +
                              " portals)"
                        : "PRT1 (" + std::to_string(r.prt_portals) + " portals)";
  std::snprintf(buf, sizeof buf,
                "summary: %s, %lld bytes, %d models, %d brushes (%d skipped)\n"
                "  faces %zu (csg %d, +%.1f%% from splits), tjunc vertices added %d (%d faces cut)\n"
                "  leafs %zu (%d visleafs), nodes %zu, clipnodes %zu, planes %zu, vertices %zu\n"
                "  edges %zu, surfedges %zu, marksurfaces %zu, texinfo %zu, textures %zu KiB (%d missing)\n"
                "  portals %d, filled leaves %d, %s%s\n",
                r.format_written == BspFormat::Bsp29 ? "BSP29" : r.format_written == BspFormat::Bsp2 ? "BSP2" : "2PSB", static_cast<long long>(r.bsp_bytes),
                r.models, r.brushes, r.skipped_brushes, b.faces.size(), r.csg_faces, r.split_percent,
                r.tjunc_vertices, r.tjunc_face_splits, b.leaves.size(), r.visleafs, b.nodes.size(), b.clipnodes.size(),
                b.planes.size(), b.vertices.size() / 3, b.edges.size(), b.surfedges.size(), b.marksurfaces.size(),
                b.texinfo.size(), b.textures.size() / 1024, r.missing_textures, r.portals, r.filled_leaves,
                prt.c_str(), r.leaked ? ", LEAKED" : r.outside_kept ? ", outside kept (no entities to flood from)" : "");
  s += buf;
  s += "  times:";
  for (const StageTime& t : r.times) {
    std::snprintf(buf, sizeof buf, " %s %.2f s,", t.name.c_str(), t.seconds);
    s += buf;
  }
  std::snprintf(buf, sizeof buf, " total %.2f s", r.total_seconds);
  s += buf;
  return s;
}

}  // namespace sb::tools::bsp
