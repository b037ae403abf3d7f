// engine/formats/bsp_load.cpp: BSP29 / BSP2 / 2PSB parsing and validation.
//
// Sections: 1. errors and header  2. geometry (planes, vertices, edges, surfedges)
// 3. faces (extents, lightmaps, flags)  4. leaves, nodes, clipnodes (tree checks)
// 5. models, entities  6. load_bsp / load_lit
//
// File layout (all little-endian; "BSP29" column / "BSP2" column, bytes per record):
//   header: int32 version (29) or char[4] "BSP2" / "2PSB", then 15 x {int32 offset, int32 length}
//   planes 20/20: float normal[3], dist; int32 type
//   vertices 12/12: float xyz[3]
//   nodes 24/44 (2PSB 32): int32 plane; children 2 x int16 / int32; box 6 x int16 / float (2PSB int16);
//                          first_face, num_faces uint16 / uint32
//   texinfo 40/40: float vecs[2][4]; int32 miptex, flags
//   faces 20/28: plane uint16/int32, side int16/int32, first_edge int32, num_edges uint16/int32,
//                texinfo uint16/int32, uint8 styles[4], int32 lightofs
//   clipnodes 8/12: int32 plane; children 2 x int16 / int32
//   leaves 28/44 (2PSB 32): int32 contents, visofs; box 6 x int16 / float (2PSB int16);
//                          first_mark, num_marks uint16 / uint32; uint8 ambient[4]
//   marksurfaces 2/4, edges 4/8 (2 vertex indices), surfedges 4/4, models 64/64
// BSP29 child fields are read as unsigned: a value below the node (clipnode)
// count is a node, anything else is leaf 65535 - value (contents value - 65536),
// which equals the signed reading for small maps and extends the limits.
#include <cstdio>

#include "engine/core/log.h"
#include "engine/formats/bsp_load_local.h"

namespace sb::bsp_detail {

const char* const kLumpNames[kNumLumps] = {
    "entities", "planes",   "textures", "vertices", "visibility",   "nodes", "texinfo", "faces",
    "lighting", "clipnodes", "leaves",  "marksurfaces", "edges", "surfedges", "models"};

// ---------------------------------------------------------------- 1. errors and header

Error lump_error(const LoadContext& c, int lump, const char* fmt, ...) {
  Error e;
  int n = std::snprintf(e.message, sizeof e.message, "%s: lump '%s' ", c.name, kLumpNames[lump]);
  if (n < 0 || size_t(n) >= sizeof e.message) return e;
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(e.message + n, sizeof e.message - size_t(n), fmt, args);
  va_end(args);
  return e;
}

Error range_error(const LoadContext& c, int lump, uint32_t entry, const char* field, int64_t value, uint64_t count) {
  if (count == 0)
    return lump_error(c, lump, "entry %u field '%s' = %lld out of range (the lump it indexes is empty)", entry, field,
                      (long long)value);
  return lump_error(c, lump, "entry %u field '%s' = %lld out of range (0..%llu)", entry, field, (long long)value,
                    (unsigned long long)(count - 1));
}

Error arena_error(const LoadContext& c, int lump, const mem::Arena& arena) {
  char msg[200];
  arena.failure_message(msg, sizeof msg);
  return lump_error(c, lump, "cannot be stored: %s", msg);
}

namespace {

constexpr size_t kHeaderBytes = 4 + 8 * kNumLumps;

uint32_t record_size(BspVersion v, int lump) {
  static const uint32_t k29[kNumLumps] = {1, 20, 1, 12, 1, 24, 40, 20, 1, 8, 28, 2, 4, 4, 64};
  static const uint32_t k2[kNumLumps] = {1, 20, 1, 12, 1, 44, 40, 28, 1, 12, 44, 4, 8, 4, 64};
  if (v == BspVersion::Bsp29) return k29[lump];
  if (v == BspVersion::Bsp2rmq && (lump == kLumpNodes || lump == kLumpLeaves)) return 32;
  return k2[lump];
}

Status read_header(LoadContext& c, const uint8_t* data, size_t size) {
  if (size < kHeaderBytes)
    return make_error("%s: file is %zu bytes, too short for a BSP header (%zu)", c.name, size, kHeaderBytes);
  if (std::memcmp(data, "BSP2", 4) == 0) {
    c.version = BspVersion::Bsp2;
  } else if (std::memcmp(data, "2PSB", 4) == 0) {
    c.version = BspVersion::Bsp2rmq;
  } else if (rd_i32(data) == 29) {
    c.version = BspVersion::Bsp29;
  } else {
    return make_error("%s: header field 'version' = %d is not 29, \"BSP2\" or \"2PSB\"", c.name, rd_i32(data));
  }
  for (int i = 0; i < kNumLumps; ++i) {
    int32_t ofs = rd_i32(data + 4 + 8 * i), len = rd_i32(data + 8 + 8 * i);
    LumpView& l = c.lumps[i];
    l = LumpView{nullptr, 0, 0};
    if (len == 0) continue;  // empty lumps may carry any offset
    if (ofs < 0 || len < 0 || uint64_t(ofs) + uint64_t(len) > size)
      return lump_error(c, i, "(offset %d, length %d) lies outside the file (%zu bytes)", ofs, len, size);
    uint32_t rec = record_size(c.version, i);
    if (uint32_t(len) % rec != 0)
      return lump_error(c, i, "(offset %d, length %d): length is not a multiple of %u", ofs, len, rec);
    l = LumpView{data + ofs, uint32_t(ofs), uint32_t(len)};
  }
  return Status::ok();
}

bool finite_in(float v, float limit) { return std::isfinite(v) && std::fabs(v) <= limit; }

// Copies a byte lump (lighting, visibility) into the level arena; never returns null on success.
Status copy_bytes(LoadContext& c, int lump, const uint8_t** out, uint32_t* out_size, const char* what) {
  const LumpView& l = c.lumps[lump];
  auto* p = static_cast<uint8_t*>(mem_util::push_padded(*c.level, l.size, what));
  if (!p) return arena_error(c, lump, *c.level);
  if (l.size) std::memcpy(p, l.data, l.size);
  *out = p;
  *out_size = l.size;
  return Status::ok();
}

// ---------------------------------------------------------------- 2. geometry

constexpr float kMaxCoord = 1e6f;  // world coordinates (BSP29 maps live in +-32768)

Status load_planes(LoadContext& c) {
  const LumpView& l = c.lumps[kLumpPlanes];
  BspWorld& w = *c.w;
  uint32_t n = l.size / 20;
  w.planes = push_records<Plane>(c, n, "bsp planes");
  if (!w.planes) return arena_error(c, kLumpPlanes, *c.level);
  for (uint32_t i = 0; i < n; ++i) {
    const uint8_t* r = l.data + size_t(i) * 20;
    Plane& p = w.planes[i];
    static const char* const kFields[4] = {"normal[0]", "normal[1]", "normal[2]", "dist"};
    for (int k = 0; k < 4; ++k) {
      float v = rd_f32(r + 4 * k);
      if (!finite_in(v, k < 3 ? 2.0f : 2 * kMaxCoord))
        return lump_error(c, kLumpPlanes, "entry %u field '%s' = %g is not a sane finite number", i, kFields[k],
                          double(v));
      if (k < 3) p.normal[k] = v; else p.dist = v;
    }
    // Axial only when the normal is exactly +1 on one axis, so `point[type] - dist` is the distance.
    p.type = p.normal.x == 1.0f ? 0 : p.normal.y == 1.0f ? 1 : p.normal.z == 1.0f ? 2 : 3;
    p.signbits = uint8_t((p.normal.x < 0) | ((p.normal.y < 0) << 1) | ((p.normal.z < 0) << 2));
  }
  w.num_planes = n;
  return Status::ok();
}

Status load_vertices(LoadContext& c) {
  const LumpView& l = c.lumps[kLumpVertices];
  BspWorld& w = *c.w;
  uint32_t n = l.size / 12;
  w.vertices = push_records<glm::vec3>(c, n, "bsp vertices");
  if (!w.vertices) return arena_error(c, kLumpVertices, *c.level);
  for (uint32_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      float v = rd_f32(l.data + size_t(i) * 12 + 4 * k);
      if (!finite_in(v, kMaxCoord))
        return lump_error(c, kLumpVertices, "entry %u field 'point[%d]' = %g is not a finite coordinate in +-1e6", i, k,
                          double(v));
      w.vertices[i][k] = v;
    }
  w.num_vertices = n;
  return Status::ok();
}

Status load_edges(LoadContext& c) {
  const LumpView& l = c.lumps[kLumpEdges];
  BspWorld& w = *c.w;
  bool wide = c.version != BspVersion::Bsp29;
  uint32_t rec = wide ? 8 : 4, n = l.size / rec;
  w.edges = push_records<Edge>(c, n, "bsp edges");
  if (!w.edges) return arena_error(c, kLumpEdges, *c.level);
  for (uint32_t i = 0; i < n; ++i) {
    const uint8_t* r = l.data + size_t(i) * rec;
    for (int k = 0; k < 2; ++k) {
      uint32_t v = wide ? rd_u32(r + 4 * k) : rd_u16(r + 2 * k);
      if (v >= w.num_vertices) return range_error(c, kLumpEdges, i, k ? "v[1]" : "v[0]", v, w.num_vertices);
      w.edges[i].v[k] = v;
    }
  }
  w.num_edges = n;
  return Status::ok();
}

Status load_surfedges(LoadContext& c) {
  const LumpView& l = c.lumps[kLumpSurfedges];
  BspWorld& w = *c.w;
  uint32_t n = l.size / 4;
  w.surfedges = push_records<int32_t>(c, n, "bsp surfedges");
  if (!w.surfedges) return arena_error(c, kLumpSurfedges, *c.level);
  for (uint32_t i = 0; i < n; ++i) {
    int32_t se = rd_i32(l.data + size_t(i) * 4);
    int64_t e = se < 0 ? -int64_t(se) : int64_t(se);
    if (uint64_t(e) >= w.num_edges) return range_error(c, kLumpSurfedges, i, "edge", se, w.num_edges);
    w.surfedges[i] = se;
  }
  w.num_surfedges = n;
  return Status::ok();
}

// ---------------------------------------------------------------- 3. faces

constexpr int kMaxLitExtent = 2048;      // texels, per axis, for faces drawn through the surface cache
constexpr double kMaxTexCoord = 1 << 28; // |s|, |t| beyond this cannot be a real surface

Status load_faces(LoadContext& c) {
  const LumpView& l = c.lumps[kLumpFaces];
  BspWorld& w = *c.w;
  bool wide = c.version != BspVersion::Bsp29;
  uint32_t rec = wide ? 28 : 20, n = l.size / rec;
  w.faces = push_records<Face>(c, n, "bsp faces");
  if (!w.faces) return arena_error(c, kLumpFaces, *c.level);
  mem::ArenaScope scope(*c.scratch);
  uint8_t* uses = mem_util::push_array_padded<uint8_t>(*c.scratch, w.num_edges, "bsp edge use counts");
  if (!uses) return arena_error(c, kLumpFaces, *c.scratch);

  for (uint32_t i = 0; i < n; ++i) {
    const uint8_t* r = l.data + size_t(i) * rec;
    Face& f = w.faces[i];
    int64_t plane, side, first, count, texinfo;
    if (wide) {
      plane = rd_i32(r); side = rd_i32(r + 4); first = rd_i32(r + 8); count = rd_i32(r + 12); texinfo = rd_i32(r + 16);
    } else {
      plane = rd_u16(r); side = rd_i16(r + 2); first = rd_i32(r + 4); count = rd_u16(r + 8); texinfo = rd_u16(r + 10);
    }
    const uint8_t* styles = r + (wide ? 20 : 12);
    int32_t lightofs = rd_i32(r + (wide ? 24 : 16));
    if (plane < 0 || plane >= w.num_planes) return range_error(c, kLumpFaces, i, "plane", plane, w.num_planes);
    if (side != 0 && side != 1) return lump_error(c, kLumpFaces, "entry %u field 'side' = %lld is not 0 or 1", i, (long long)side);
    if (count < 3 || count > kMaxFaceEdges)
      return lump_error(c, kLumpFaces, "entry %u field 'num_edges' = %lld out of range (3..%u)", i, (long long)count,
                        kMaxFaceEdges);
    if (first < 0 || first + count > w.num_surfedges)
      return lump_error(c, kLumpFaces, "entry %u field 'first_edge' = %lld: edges %lld..%lld outside 'surfedges' (0..%u)",
                        i, (long long)first, (long long)first, (long long)(first + count - 1),
                        w.num_surfedges ? w.num_surfedges - 1 : 0);
    if (texinfo < 0 || texinfo >= w.num_texinfo) return range_error(c, kLumpFaces, i, "texinfo", texinfo, w.num_texinfo);
    f.plane = uint32_t(plane);
    f.first_surfedge = uint32_t(first);
    f.num_edges = uint32_t(count);
    f.texinfo = uint32_t(texinfo);
    std::memcpy(f.styles, styles, kMaxLightStyles);

    // Edge loop: each edge must end where the next one starts; s, t over its vertices.
    const TexInfo& ti = w.texinfo[f.texinfo];
    double mins[2] = {1e300, 1e300}, maxs[2] = {-1e300, -1e300};
    for (uint32_t k = 0; k < f.num_edges; ++k) {
      int32_t se = w.surfedges[f.first_surfedge + k];
      uint32_t e = uint32_t(se < 0 ? -int64_t(se) : se);
      uint32_t start = se < 0 ? w.edges[e].v[1] : w.edges[e].v[0];
      uint32_t end = se < 0 ? w.edges[e].v[0] : w.edges[e].v[1];
      int32_t sn = w.surfedges[f.first_surfedge + (k + 1) % f.num_edges];
      uint32_t en = uint32_t(sn < 0 ? -int64_t(sn) : sn);
      uint32_t next_start = sn < 0 ? w.edges[en].v[1] : w.edges[en].v[0];
      if (end != next_start)
        return lump_error(c, kLumpFaces, "entry %u: edge loop is not closed (surfedge %u ends at vertex %u, next starts at %u)",
                          i, f.first_surfedge + k, end, next_start);
      if (uses[e] < 255) ++uses[e];
      const glm::vec3& v = w.vertices[start];
      for (int a = 0; a < 2; ++a) {
        double s = double(v.x) * ti.vecs[a].x + double(v.y) * ti.vecs[a].y + double(v.z) * ti.vecs[a].z + ti.vecs[a].w;
        if (s < mins[a]) mins[a] = s;
        if (s > maxs[a]) maxs[a] = s;
      }
    }
    for (int a = 0; a < 2; ++a) {
      if (mins[a] < -kMaxTexCoord || maxs[a] > kMaxTexCoord)
        return lump_error(c, kLumpFaces, "entry %u: texture coordinate %c in %g..%g is out of range (texinfo %u)", i,
                          a ? 't' : 's', mins[a], maxs[a], f.texinfo);
      int bmin = int(std::floor(mins[a] / 16.0)), bmax = int(std::ceil(maxs[a] / 16.0));
      f.texture_mins[a] = bmin * 16;
      f.extents[a] = (bmax - bmin) * 16;
    }
    const Texture& tex = w.textures[ti.texture];
    bool special = (ti.flags & kTexSpecial) != 0;
    if (side) f.flags |= kFacePlaneBack;
    if (tex.kind == kTexSky) f.flags |= kFaceSky;
    if (tex.kind == kTexTurb) f.flags |= kFaceTurb;
    if (c.texture_missing[ti.texture]) f.flags |= kFaceMissingTexture;
    if (!special && (f.extents[0] > kMaxLitExtent || f.extents[1] > kMaxLitExtent))
      return lump_error(c, kLumpFaces, "entry %u: extents %dx%d texels exceed %d (texinfo %u, texture '%s')", i,
                        f.extents[0], f.extents[1], kMaxLitExtent, f.texinfo, tex.name);

    // Lightmap: every style's block must lie inside the lighting lump.
    f.light_offset = kNoLightmap;
    if (w.lightdata_size == 0 || lightofs == -1) continue;
    if (lightofs < 0)
      return lump_error(c, kLumpFaces, "entry %u field 'lightofs' = %d is negative (only -1 means none)", i, lightofs);
    int nstyles = 0;
    while (nstyles < kMaxLightStyles && f.styles[nstyles] != 255) ++nstyles;
    uint64_t area = uint64_t(f.extents[0] / 16 + 1) * uint64_t(f.extents[1] / 16 + 1) * uint64_t(nstyles);
    if (uint64_t(lightofs) + area > w.lightdata_size) {
      if (special) continue;  // sky / liquids never read their lightmap
      return lump_error(c, kLumpFaces,
                        "entry %u field 'lightofs' = %d: lightmap of %llu bytes (%d styles x %dx%d) runs past "
                        "lump 'lighting' (%u bytes)",
                        i, lightofs, (unsigned long long)area, nstyles, f.extents[0] / 16 + 1, f.extents[1] / 16 + 1,
                        w.lightdata_size);
    }
    f.light_offset = lightofs;
  }
  for (uint32_t e = 0; e < w.num_edges; ++e) w.edges_shared_by_more_than_two_faces += uses[e] > 2;
  w.num_faces = n;
  return Status::ok();
}

Status load_marksurfaces(LoadContext& c) {
  const LumpView& l = c.lumps[kLumpMarksurfaces];
  BspWorld& w = *c.w;
  bool wide = c.version != BspVersion::Bsp29;
  uint32_t rec = wide ? 4 : 2, n = l.size / rec;
  w.marksurfaces = push_records<uint32_t>(c, n, "bsp marksurfaces");
  if (!w.marksurfaces) return arena_error(c, kLumpMarksurfaces, *c.level);
  for (uint32_t i = 0; i < n; ++i) {
    uint32_t f = wide ? rd_u32(l.data + size_t(i) * 4) : rd_u16(l.data + size_t(i) * 2);
    if (f >= w.num_faces) return range_error(c, kLumpMarksurfaces, i, "face", f, w.num_faces);
    w.marksurfaces[i] = f;
  }
  w.num_marksurfaces = n;
  return Status::ok();
}

// ---------------------------------------------------------------- 4. leaves, nodes, clipnodes

// Box at r: 6 x int16 (widened by 1) or 6 x float (finite).
bool read_box(BspVersion v, const uint8_t* r, glm::vec3* mins, glm::vec3* maxs) {
  for (int k = 0; k < 3; ++k) {
    if (v == BspVersion::Bsp2) {
      (*mins)[k] = rd_f32(r + 4 * k);
      (*maxs)[k] = rd_f32(r + 12 + 4 * k);
      if (!finite_in((*mins)[k], kMaxCoord) || !finite_in((*maxs)[k], kMaxCoord)) return false;
    } else {
      (*mins)[k] = float(rd_i16(r + 2 * k)) - 1.0f;
      (*maxs)[k] = float(rd_i16(r + 6 + 2 * k)) + 1.0f;
    }
  }
  return true;
}

Status load_leaves(LoadContext& c) {
  const LumpView& l = c.lumps[kLumpLeaves];
  BspWorld& w = *c.w;
  uint32_t rec = record_size(c.version, kLumpLeaves), n = l.size / rec;
  bool float_box = c.version == BspVersion::Bsp2;
  uint32_t box_bytes = float_box ? 24 : 12;
  w.leaves = push_records<Leaf>(c, n, "bsp leaves");
  if (!w.leaves) return arena_error(c, kLumpLeaves, *c.level);
  for (uint32_t i = 0; i < n; ++i) {
    const uint8_t* r = l.data + size_t(i) * rec;
    Leaf& leaf = w.leaves[i];
    leaf.contents = rd_i32(r);
    if (leaf.contents < kMinContents || leaf.contents > -1)
      return lump_error(c, kLumpLeaves, "entry %u field 'contents' = %d out of range (%d..-1)", i, leaf.contents,
                        kMinContents);
    int32_t visofs = rd_i32(r + 4);
    if (visofs == -1 || w.visdata_size == 0) {
      leaf.vis_offset = -1;
    } else if (visofs < 0 || uint32_t(visofs) >= w.visdata_size) {
      return range_error(c, kLumpLeaves, i, "visofs", visofs, w.visdata_size);
    } else {
      leaf.vis_offset = visofs;
    }
    if (!read_box(c.version, r + 8, &leaf.mins, &leaf.maxs))
      return lump_error(c, kLumpLeaves, "entry %u field 'mins/maxs' is not a finite box in +-1e6", i);
    const uint8_t* m = r + 8 + box_bytes;
    uint64_t first = c.version == BspVersion::Bsp29 ? rd_u16(m) : rd_u32(m);
    uint64_t count = c.version == BspVersion::Bsp29 ? rd_u16(m + 2) : rd_u32(m + 4);
    if (first + count > w.num_marksurfaces)
      return lump_error(c, kLumpLeaves, "entry %u field 'first_marksurface' = %llu: %llu marksurfaces run past 'marksurfaces' (%u)",
                        i, (unsigned long long)first, (unsigned long long)count, w.num_marksurfaces);
    leaf.first_marksurface = uint32_t(first);
    leaf.num_marksurfaces = uint32_t(count);
    std::memcpy(leaf.ambient, m + (c.version == BspVersion::Bsp29 ? 4 : 8), 4);
    leaf.parent = -1;
  }
  w.num_leaves = n;
  return Status::ok();
}

// Topological pass over a child graph (Kahn): rejects cycles, nodes with more than
// one parent, and depths over kMaxTreeDepth. child(i, k) returns a node index or -1.
template <class ChildFn>
Status check_tree(LoadContext& c, int lump, uint32_t n, ChildFn child, int32_t* parent_out) {
  mem::ArenaScope scope(*c.scratch);
  uint32_t* parents = mem_util::push_array_padded<uint32_t>(*c.scratch, n, "bsp tree indegree");
  uint32_t* queue = mem_util::push_array_padded<uint32_t>(*c.scratch, n, "bsp tree queue");
  uint16_t* depth = mem_util::push_array_padded<uint16_t>(*c.scratch, n, "bsp tree depth");
  if (!parents || !queue || !depth) return arena_error(c, lump, *c.scratch);
  for (uint32_t i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k) {
      int64_t ch = child(i, k);
      if (ch < 0) continue;
      if (++parents[ch] > 1)
        return lump_error(c, lump, "entry %lld is a child of more than one node (again of entry %u)", (long long)ch, i);
    }
  uint32_t head = 0, tail = 0;
  for (uint32_t i = 0; i < n; ++i)
    if (parents[i] == 0) queue[tail++] = i;
  while (head < tail) {
    uint32_t i = queue[head++];
    for (int k = 0; k < 2; ++k) {
      int64_t ch = child(i, k);
      if (ch < 0) continue;
      if (parent_out) parent_out[ch] = int32_t(i);
      depth[ch] = uint16_t(depth[i] + 1);
      if (depth[ch] > kMaxTreeDepth)
        return lump_error(c, lump, "entry %lld lies deeper than %d levels below its head node", (long long)ch,
                          kMaxTreeDepth);
      if (--parents[ch] == 0) queue[tail++] = uint32_t(ch);
    }
  }
  if (tail != n) return lump_error(c, lump, "has a cycle (%u of %u entries lie on or below it)", n - tail, n);
  return Status::ok();
}

Status load_nodes(LoadContext& c) {
  const LumpView& l = c.lumps[kLumpNodes];
  BspWorld& w = *c.w;
  uint32_t rec = record_size(c.version, kLumpNodes), n = l.size / rec;
  bool narrow = c.version == BspVersion::Bsp29;
  uint32_t box_bytes = c.version == BspVersion::Bsp2 ? 24 : 12;
  w.nodes = push_records<Node>(c, n, "bsp nodes");
  if (!w.nodes) return arena_error(c, kLumpNodes, *c.level);
  for (uint32_t i = 0; i < n; ++i) {
    const uint8_t* r = l.data + size_t(i) * rec;
    Node& node = w.nodes[i];
    uint32_t plane = rd_u32(r);
    if (plane >= w.num_planes) return range_error(c, kLumpNodes, i, "plane", int64_t(plane), w.num_planes);
    node.plane = plane;
    for (int k = 0; k < 2; ++k) {
      int64_t leaf = -1;
      if (narrow) {
        uint32_t p = rd_u16(r + 4 + 2 * k);
        if (p < n) node.children[k] = int32_t(p); else leaf = 65535 - int64_t(p);
      } else {
        int32_t p = rd_i32(r + 4 + 4 * k);
        if (p >= 0 && uint32_t(p) >= n) return range_error(c, kLumpNodes, i, k ? "children[1]" : "children[0]", p, n);
        if (p >= 0) node.children[k] = p; else leaf = -1 - int64_t(p);
      }
      if (leaf >= 0) {
        if (leaf >= w.num_leaves)
          return lump_error(c, kLumpNodes, "entry %u field 'children[%d]' names leaf %lld out of range (0..%u)", i, k,
                            (long long)leaf, w.num_leaves ? w.num_leaves - 1 : 0);
        node.children[k] = int32_t(-1 - leaf);
      }
    }
    const uint8_t* box = r + (narrow ? 8 : 12);
    if (!read_box(c.version, box, &node.mins, &node.maxs))
      return lump_error(c, kLumpNodes, "entry %u field 'mins/maxs' is not a finite box in +-1e6", i);
    const uint8_t* fr = box + box_bytes;
    uint64_t first = narrow ? rd_u16(fr) : rd_u32(fr);
    uint64_t count = narrow ? rd_u16(fr + 2) : rd_u32(fr + 4);
    if (first + count > w.num_faces)
      return lump_error(c, kLumpNodes, "entry %u field 'first_face' = %llu: %llu faces run past 'faces' (%u)", i,
                        (unsigned long long)first, (unsigned long long)count, w.num_faces);
    node.first_face = uint32_t(first);
    node.num_faces = uint32_t(count);
    node.parent = -1;
  }
  w.num_nodes = n;
  Node* nodes = w.nodes;
  SB_TRY(check_tree(c, kLumpNodes, n, [nodes](uint32_t i, int k) -> int64_t {
    return nodes[i].children[k] >= 0 ? nodes[i].children[k] : -1;
  }, nullptr));
  for (uint32_t i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k) {
      int32_t ch = nodes[i].children[k];
      if (ch >= 0) nodes[ch].parent = int32_t(i); else w.leaves[-1 - ch].parent = int32_t(i);
    }
  return Status::ok();
}

Status load_clipnodes(LoadContext& c) {
  const LumpView& l = c.lumps[kLumpClipnodes];
  BspWorld& w = *c.w;
  bool narrow = c.version == BspVersion::Bsp29;
  uint32_t rec = narrow ? 8 : 12, n = l.size / rec;
  w.clipnodes = push_records<ClipNode>(c, n, "bsp clipnodes");
  if (!w.clipnodes) return arena_error(c, kLumpClipnodes, *c.level);
  for (uint32_t i = 0; i < n; ++i) {
    const uint8_t* r = l.data + size_t(i) * rec;
    ClipNode& cn = w.clipnodes[i];
    uint32_t plane = rd_u32(r);
    if (plane >= w.num_planes) return range_error(c, kLumpClipnodes, i, "plane", int64_t(plane), w.num_planes);
    cn.plane = plane;
    for (int k = 0; k < 2; ++k) {
      int64_t v = narrow ? int64_t(rd_u16(r + 4 + 2 * k)) : int64_t(rd_i32(r + 4 + 4 * k));
      if (narrow && v >= n) v -= 65536;  // contents
      if (v >= int64_t(n) || v < kMinContents)
        return lump_error(c, kLumpClipnodes, "entry %u field 'children[%d]' = %lld is neither a clipnode (0..%lld) nor contents (%d..-1)",
                          i, k, (long long)v, (long long)n - 1, kMinContents);
      cn.children[k] = int32_t(v);
    }
  }
  w.num_clipnodes = n;
  ClipNode* cns = w.clipnodes;
  return check_tree(c, kLumpClipnodes, n, [cns](uint32_t i, int k) -> int64_t {
    return cns[i].children[k] >= 0 ? cns[i].children[k] : -1;
  }, nullptr);
}

// ---------------------------------------------------------------- 5. models, entities

Status load_models(LoadContext& c) {
  const LumpView& l = c.lumps[kLumpModels];
  BspWorld& w = *c.w;
  uint32_t n = l.size / 64;
  if (n == 0) return lump_error(c, kLumpModels, "is empty (the world model 0 is required)");
  w.models = push_records<SubModel>(c, n, "bsp models");
  if (!w.models) return arena_error(c, kLumpModels, *c.level);
  bool no_hulls = false;
  for (uint32_t i = 0; i < n; ++i) {
    const uint8_t* r = l.data + size_t(i) * 64;
    SubModel& m = w.models[i];
    for (int k = 0; k < 9; ++k) {
      float v = rd_f32(r + 4 * k);
      if (!finite_in(v, kMaxCoord))
        return lump_error(c, kLumpModels, "entry %u field '%s[%d]' = %g is not a finite coordinate in +-1e6", i,
                          k < 3 ? "mins" : k < 6 ? "maxs" : "origin", k % 3, double(v));
      (k < 3 ? m.mins : k < 6 ? m.maxs : m.origin)[k % 3] = v;
    }
    for (int h = 0; h < 4; ++h) m.headnode[h] = rd_i32(r + 36 + 4 * h);
    if (m.headnode[0] < 0 || uint32_t(m.headnode[0]) >= w.num_nodes)
      return range_error(c, kLumpModels, i, "headnode[0]", m.headnode[0], w.num_nodes);
    for (int h = 1; h < 4; ++h) {
      if (w.num_clipnodes == 0 && m.headnode[h] >= 0) {  // compiled without clip hulls
        m.headnode[h] = kContentsEmpty;
        no_hulls = true;
        continue;
      }
      if (m.headnode[h] >= int64_t(w.num_clipnodes) || m.headnode[h] < kMinContents)
        return lump_error(c, kLumpModels, "entry %u field 'headnode[%d]' = %d is neither a clipnode (0..%lld) nor contents (%d..-1)",
                          i, h, m.headnode[h], (long long)w.num_clipnodes - 1, kMinContents);
    }
    int32_t visleafs = rd_i32(r + 52), first = rd_i32(r + 56), count = rd_i32(r + 60);
    if (visleafs < 0 || (w.num_leaves && uint32_t(visleafs) > w.num_leaves - 1) || (!w.num_leaves && visleafs))
      return range_error(c, kLumpModels, i, "visleafs", visleafs, w.num_leaves);
    if (first < 0 || count < 0 || uint64_t(first) + uint64_t(count) > w.num_faces)
      return lump_error(c, kLumpModels, "entry %u field 'first_face' = %d: %d faces run past 'faces' (%u)", i, first,
                        count, w.num_faces);
    m.visleafs = uint32_t(visleafs);
    m.first_face = uint32_t(first);
    m.num_faces = uint32_t(count);
  }
  w.num_models = n;
  if (no_hulls) log_warning("%s: no clipnodes: clip hulls 1..3 of every model are empty", c.name);
  return Status::ok();
}

Status load_entities(LoadContext& c) {
  const LumpView& l = c.lumps[kLumpEntities];
  BspWorld& w = *c.w;
  auto* text = static_cast<char*>(mem_util::push_padded(*c.level, size_t(l.size) + 1, "bsp entities"));
  if (!text) return arena_error(c, kLumpEntities, *c.level);
  if (l.size) std::memcpy(text, l.data, l.size);
  text[l.size] = 0;
  w.entities = text;
  w.entities_size = uint32_t(std::strlen(text));
  return Status::ok();
}

Result<BspWorld*> load(LoadContext& c, const uint8_t* data, size_t size) {
  SB_TRY(read_header(c, data, size));
  c.w = mem_util::push_array_padded<BspWorld>(*c.level, 1, "bsp world");
  if (!c.w) return make_error("%s: cannot store the world header", c.name);
  BspWorld& w = *c.w;
  std::snprintf(w.name, sizeof w.name, "%s", c.name);
  w.version = c.version;
  SB_TRY(load_entities(c));
  SB_TRY(load_planes(c));
  SB_TRY(load_vertices(c));
  SB_TRY(load_edges(c));
  SB_TRY(load_surfedges(c));
  SB_TRY(load_textures(c));
  SB_TRY(load_texinfo(c));
  SB_TRY(copy_bytes(c, kLumpLighting, &w.lightdata, &w.lightdata_size, "bsp lighting"));
  SB_TRY(copy_bytes(c, kLumpVisibility, &w.visdata, &w.visdata_size, "bsp visibility"));
  SB_TRY(load_faces(c));
  SB_TRY(load_marksurfaces(c));
  SB_TRY(load_leaves(c));
  SB_TRY(load_nodes(c));
  SB_TRY(load_clipnodes(c));
  SB_TRY(load_models(c));
  resolve_animations(c);

  uint32_t missing_slots = 0;
  const char* first_missing = nullptr;
  for (uint32_t i = 0; i < w.placeholder_texture; ++i)
    if (c.texture_missing[i]) {
      ++missing_slots;
      if (!first_missing) first_missing = w.textures[i].name;
    }
  w.missing_textures += missing_slots;
  if (w.missing_textures)
    log_warning("%s: %u missing textures (%u without pixels%s%s%s, %u texinfo references out of range); drawn as a checker",
                c.name, w.missing_textures, missing_slots, first_missing ? ", first '" : "",
                first_missing ? first_missing : "", first_missing ? "'" : "", w.missing_textures - missing_slots);
  return c.w;
}

}  // namespace
}  // namespace sb::bsp_detail

namespace sb {

Result<BspWorld*> load_bsp(const char* name, const uint8_t* data, size_t size, mem::Arena& level, mem::Arena& scratch) {
  bsp_detail::LoadContext c{};
  c.name = name;
  c.level = &level;
  c.scratch = &scratch;
  size_t level_mark = mem_util::align_mark(level);
  mem_util::align_mark(scratch);
  mem::ArenaScope scratch_scope(scratch);
  Result<BspWorld*> r = bsp_detail::load(c, data, size);
  if (!r) level.pop_to(level_mark);
  return r;
}

Status load_lit(BspWorld& world, const char* name, const uint8_t* data, size_t size, mem::Arena& level) {
  if (size < 8) return make_error("%s: file is %zu bytes, too short for a QLIT header (8)", name, size);
  if (std::memcmp(data, "QLIT", 4) != 0) return make_error("%s: header field 'ident' is not \"QLIT\"", name);
  int32_t version = bsp_detail::rd_i32(data + 4);
  if (version != 1) return make_error("%s: header field 'version' = %d is not 1", name, version);
  uint64_t need = uint64_t(world.lightdata_size) * 3;
  if (size - 8 < need)
    return make_error("%s: %zu bytes of samples, %s needs %llu (3 x %u)", name, size - 8, world.name,
                      (unsigned long long)need, world.lightdata_size);
  auto* rgb = static_cast<uint8_t*>(mem_util::push_padded(level, size_t(need), "bsp lit"));
  if (!rgb) {
    char msg[200];
    level.failure_message(msg, sizeof msg);
    return make_error("%s: cannot be stored: %s", name, msg);
  }
  if (need) std::memcpy(rgb, data + 8, size_t(need));
  world.lightdata_rgb = rgb;
  return Status::ok();
}

}  // namespace sb
