#include "tools/common/bsp_data.h"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace sb::tools {
namespace {

enum Lump {
  kEntities, kPlanes, kTextures, kVertices, kVisibility, kNodes, kTexInfo, kFaces, kLighting,
  kClipNodes, kLeaves, kMarkSurfaces, kEdges, kSurfEdges, kModels, kLumpCount
};
const char* const kLumpNames[kLumpCount] = {
    "entities", "planes", "textures", "vertices", "visibility", "nodes", "texinfo", "faces",
    "lighting", "clipnodes", "leaves", "marksurfaces", "edges", "surfedges", "models"};

constexpr int32_t kVersion29 = 29;
constexpr int32_t kVersionBsp2 = ('B') | ('S' << 8) | ('P' << 16) | ('2' << 24);
constexpr int32_t kVersion2psb = ('2') | ('P' << 8) | ('S' << 16) | ('B' << 24);

// Little-endian field readers over an unaligned byte cursor.
struct Reader {
  const uint8_t* p;
  int32_t i32() { int32_t v; std::memcpy(&v, p, 4); p += 4; return v; }
  uint32_t u32() { uint32_t v; std::memcpy(&v, p, 4); p += 4; return v; }
  int16_t i16() { int16_t v; std::memcpy(&v, p, 2); p += 2; return v; }
  uint16_t u16() { uint16_t v; std::memcpy(&v, p, 2); p += 2; return v; }
  float f32() { float v; std::memcpy(&v, p, 4); p += 4; return v; }
  uint8_t u8() { return *p++; }
};

struct Writer {
  std::vector<uint8_t>& out;
  void raw(const void* d, size_t n) { const auto* b = static_cast<const uint8_t*>(d); out.insert(out.end(), b, b + n); }
  void i32(int32_t v) { raw(&v, 4); }
  void u32(uint32_t v) { raw(&v, 4); }
  void i16(int16_t v) { raw(&v, 2); }
  void u16(uint16_t v) { raw(&v, 2); }
  void f32(float v) { raw(&v, 4); }
  void u8(uint8_t v) { out.push_back(v); }
};

// Disk record sizes per format.
struct Layout {
  size_t node, face, clipnode, leaf, marksurface, edge;
};
Layout layout_for(BspFormat f) {
  switch (f) {
    case BspFormat::Bsp2: return {44, 28, 12, 44, 4, 8};
    case BspFormat::Bsp2rmq: return {32, 28, 12, 32, 4, 8};
    default: return {24, 20, 8, 28, 2, 4};
  }
}

// BSP29 node children: int16, negative = leaf. Read as unsigned beyond 32767 nodes,
// as modern engines do: values >= num_nodes (as unsigned) are leaves 65535 - v.
int32_t child29(uint16_t raw, size_t num_nodes) {
  if (raw < num_nodes && raw < 0x8000u) return raw;
  if (raw >= 0x8000u) return int32_t(int16_t(raw));
  return raw;
}

int16_t clamp16(float v) {
  float r = std::floor(v + 0.5f);
  if (r < -32768.0f) return -32768;
  if (r > 32767.0f) return 32767;
  return int16_t(r);
}

}  // namespace

Status parse_bsp(const char* name, const uint8_t* data, size_t size, BspData* out) {
  if (size < 4 + 8 * kLumpCount) return make_error("%s: file of %zu bytes is too short for a BSP header", name, size);
  Reader h{data};
  int32_t version = h.i32();
  BspFormat fmt;
  if (version == kVersion29) fmt = BspFormat::Bsp29;
  else if (version == kVersionBsp2) fmt = BspFormat::Bsp2;
  else if (version == kVersion2psb) fmt = BspFormat::Bsp2rmq;
  else return make_error("%s: header field 'version' = %d is not BSP29, BSP2 or 2PSB", name, version);
  const Layout L = layout_for(fmt);
  uint32_t ofs[kLumpCount], len[kLumpCount];
  for (int i = 0; i < kLumpCount; ++i) {
    ofs[i] = h.u32();
    len[i] = h.u32();
    if (uint64_t(ofs[i]) + len[i] > size)
      return make_error("%s: lump '%s' (offset %u, length %u) runs past the end of the file (%zu bytes)", name,
                        kLumpNames[i], ofs[i], len[i], size);
  }
  auto check = [&](int lump, size_t rec) -> Status {
    if (len[lump] % rec)
      return make_error("%s: lump '%s' (offset %u, length %u): length is not a multiple of %zu", name,
                        kLumpNames[lump], ofs[lump], len[lump], rec);
    return Status::ok();
  };
  SB_TRY(check(kPlanes, 20));
  SB_TRY(check(kVertices, 12));
  SB_TRY(check(kNodes, L.node));
  SB_TRY(check(kTexInfo, 40));
  SB_TRY(check(kFaces, L.face));
  SB_TRY(check(kClipNodes, L.clipnode));
  SB_TRY(check(kLeaves, L.leaf));
  SB_TRY(check(kMarkSurfaces, L.marksurface));
  SB_TRY(check(kEdges, L.edge));
  SB_TRY(check(kSurfEdges, 4));
  SB_TRY(check(kModels, 64));

  BspData b;
  b.format = fmt;
  const bool wide = fmt != BspFormat::Bsp29;
  const bool float_bounds = fmt == BspFormat::Bsp2;
  {
    const char* e = reinterpret_cast<const char*>(data + ofs[kEntities]);
    size_t n = len[kEntities];
    while (n > 0 && e[n - 1] == '\0') --n;
    b.entities.assign(e, n);
  }
  Reader r{data + ofs[kPlanes]};
  b.planes.resize(len[kPlanes] / 20);
  for (auto& p : b.planes) {
    for (float& c : p.normal) c = r.f32();
    p.dist = r.f32();
    p.type = r.i32();
  }
  b.textures.assign(data + ofs[kTextures], data + ofs[kTextures] + len[kTextures]);
  r = Reader{data + ofs[kVertices]};
  b.vertices.resize(len[kVertices] / 4);
  for (float& v : b.vertices) v = r.f32();
  b.visdata.assign(data + ofs[kVisibility], data + ofs[kVisibility] + len[kVisibility]);
  const size_t num_nodes = len[kNodes] / L.node;
  r = Reader{data + ofs[kNodes]};
  b.nodes.resize(num_nodes);
  for (auto& n : b.nodes) {
    n.plane = r.i32();
    for (int32_t& c : n.children) c = wide ? r.i32() : child29(r.u16(), num_nodes);
    for (float* v : {n.mins, n.maxs})
      for (int k = 0; k < 3; ++k) v[k] = float_bounds ? r.f32() : float(r.i16());
    n.first_face = wide ? r.u32() : r.u16();
    n.num_faces = wide ? r.u32() : r.u16();
  }
  r = Reader{data + ofs[kTexInfo]};
  b.texinfo.resize(len[kTexInfo] / 40);
  for (auto& t : b.texinfo) {
    for (auto& row : t.vecs)
      for (float& c : row) c = r.f32();
    t.miptex = r.i32();
    t.flags = r.i32();
  }
  r = Reader{data + ofs[kFaces]};
  b.faces.resize(len[kFaces] / L.face);
  for (auto& f : b.faces) {
    f.plane = wide ? r.i32() : r.u16();
    f.side = wide ? r.i32() : r.i16();
    f.first_edge = r.i32();
    f.num_edges = wide ? r.i32() : r.u16();
    f.texinfo = wide ? r.i32() : r.u16();
    for (uint8_t& s : f.styles) s = r.u8();
    f.lightofs = r.i32();
  }
  b.lighting.assign(data + ofs[kLighting], data + ofs[kLighting] + len[kLighting]);
  r = Reader{data + ofs[kClipNodes]};
  b.clipnodes.resize(len[kClipNodes] / L.clipnode);
  for (auto& c : b.clipnodes) {
    c.plane = r.i32();
    for (int32_t& ch : c.children) {
      if (wide) { ch = r.i32(); continue; }
      uint16_t raw = r.u16();
      // Contents are -1..-15; anything else is an index (unsigned beyond 32767).
      ch = raw >= 0xfff0u ? int32_t(int16_t(raw)) : int32_t(raw);
    }
  }
  r = Reader{data + ofs[kLeaves]};
  b.leaves.resize(len[kLeaves] / L.leaf);
  for (auto& l : b.leaves) {
    l.contents = r.i32();
    l.visofs = r.i32();
    for (float* v : {l.mins, l.maxs})
      for (int k = 0; k < 3; ++k) v[k] = float_bounds ? r.f32() : float(r.i16());
    l.first_marksurface = wide ? r.u32() : r.u16();
    l.num_marksurfaces = wide ? r.u32() : r.u16();
    for (uint8_t& a : l.ambient) a = r.u8();
  }
  r = Reader{data + ofs[kMarkSurfaces]};
  b.marksurfaces.resize(len[kMarkSurfaces] / L.marksurface);
  for (uint32_t& m : b.marksurfaces) m = wide ? r.u32() : r.u16();
  r = Reader{data + ofs[kEdges]};
  b.edges.resize(len[kEdges] / L.edge);
  for (auto& e : b.edges)
    for (uint32_t& v : e.v) v = wide ? r.u32() : r.u16();
  r = Reader{data + ofs[kSurfEdges]};
  b.surfedges.resize(len[kSurfEdges] / 4);
  for (int32_t& s : b.surfedges) s = r.i32();
  r = Reader{data + ofs[kModels]};
  b.models.resize(len[kModels] / 64);
  for (auto& m : b.models) {
    for (float* v : {m.mins, m.maxs, m.origin})
      for (int k = 0; k < 3; ++k) v[k] = r.f32();
    for (int32_t& hn : m.headnode) hn = r.i32();
    m.visleafs = r.i32();
    m.first_face = r.i32();
    m.num_faces = r.i32();
  }
  *out = std::move(b);
  return Status::ok();
}

Status read_bsp(const char* path, BspData* out) {
  std::FILE* f = std::fopen(path, "rb");
  if (!f) return make_error("%s: cannot open for reading", path);
  std::vector<uint8_t> bytes;
  uint8_t buf[1 << 16];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) bytes.insert(bytes.end(), buf, buf + n);
  bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if (failed) return make_error("%s: read error", path);
  return parse_bsp(path, bytes.data(), bytes.size(), out);
}

bool fits_bsp29(const BspData& b, std::string* why) {
  char msg[128];
  auto over = [&](const char* what, size_t n, size_t limit) {
    if (n <= limit) return false;
    std::snprintf(msg, sizeof msg, "%s: %zu > %zu", what, n, limit);
    if (why) *why = msg;
    return true;
  };
  if (over("nodes", b.nodes.size(), 32767) || over("leaves", b.leaves.size(), 32767) ||
      over("clipnodes", b.clipnodes.size(), 32767) || over("planes", b.planes.size(), 32767) ||
      over("faces", b.faces.size(), 65535) || over("marksurfaces", b.marksurfaces.size(), 65535) ||
      over("vertices", b.vertices.size() / 3, 65535) || over("texinfo", b.texinfo.size(), 32767))
    return false;
  for (const auto& f : b.faces)
    if (over("edges of one face", size_t(f.num_edges), 32767)) return false;
  for (const auto& n : b.nodes)
    for (int k = 0; k < 3; ++k)
      if (n.mins[k] < -32768.0f || n.maxs[k] > 32767.0f) {
        if (why) *why = "node bounds outside -32768..32767";
        return false;
      }
  for (const auto& l : b.leaves)
    for (int k = 0; k < 3; ++k)
      if (l.mins[k] < -32768.0f || l.maxs[k] > 32767.0f) {
        if (why) *why = "leaf bounds outside -32768..32767";
        return false;
      }
  for (const auto& n : b.nodes)
    if (n.first_face + n.num_faces > 65535) {
      if (why) *why = "node face range beyond 65535";
      return false;
    }
  for (const auto& l : b.leaves)
    if (l.first_marksurface + l.num_marksurfaces > 65535) {
      if (why) *why = "leaf marksurface range beyond 65535";
      return false;
    }
  return true;
}

Status serialize_bsp(const BspData& b, BspFormat format, std::vector<uint8_t>* out, BspFormat* used) {
  if (format == BspFormat::Auto) format = fits_bsp29(b, nullptr) ? BspFormat::Bsp29 : BspFormat::Bsp2;
  std::string why;
  if (format == BspFormat::Bsp29 && !fits_bsp29(b, &why))
    return make_error("BSP29 cannot hold this map (%s); write BSP2", why.c_str());
  if (used) *used = format;
  const bool wide = format != BspFormat::Bsp29;
  const bool float_bounds = format == BspFormat::Bsp2;
  std::vector<uint8_t>& o = *out;
  o.clear();
  Writer w{o};
  const int32_t version = format == BspFormat::Bsp29 ? kVersion29 : format == BspFormat::Bsp2 ? kVersionBsp2 : kVersion2psb;
  w.i32(version);
  const size_t dir_at = o.size();
  o.resize(o.size() + 8 * kLumpCount, 0);
  uint32_t ofs[kLumpCount], len[kLumpCount];
  auto begin = [&](int lump) {
    while (o.size() % 4) o.push_back(0);
    ofs[lump] = uint32_t(o.size());
  };
  auto end = [&](int lump) { len[lump] = uint32_t(o.size() - ofs[lump]); };

  begin(kEntities); w.raw(b.entities.data(), b.entities.size()); w.u8(0); end(kEntities);
  begin(kPlanes);
  for (const auto& p : b.planes) { for (float c : p.normal) w.f32(c); w.f32(p.dist); w.i32(p.type); }
  end(kPlanes);
  begin(kTextures); w.raw(b.textures.data(), b.textures.size()); end(kTextures);
  begin(kVertices); for (float v : b.vertices) w.f32(v); end(kVertices);
  begin(kVisibility); w.raw(b.visdata.data(), b.visdata.size()); end(kVisibility);
  begin(kNodes);
  for (const auto& n : b.nodes) {
    w.i32(n.plane);
    for (int32_t c : n.children) wide ? w.i32(c) : w.i16(int16_t(c));
    for (const float* v : {n.mins, n.maxs})
      for (int k = 0; k < 3; ++k) float_bounds ? w.f32(v[k]) : w.i16(clamp16(k < 3 ? v[k] : 0));
    wide ? w.u32(n.first_face) : w.u16(uint16_t(n.first_face));
    wide ? w.u32(n.num_faces) : w.u16(uint16_t(n.num_faces));
  }
  end(kNodes);
  begin(kTexInfo);
  for (const auto& t : b.texinfo) {
    for (const auto& row : t.vecs) for (float c : row) w.f32(c);
    w.i32(t.miptex);
    w.i32(t.flags);
  }
  end(kTexInfo);
  begin(kFaces);
  for (const auto& f : b.faces) {
    wide ? w.i32(f.plane) : w.u16(uint16_t(f.plane));
    wide ? w.i32(f.side) : w.i16(int16_t(f.side));
    w.i32(f.first_edge);
    wide ? w.i32(f.num_edges) : w.u16(uint16_t(f.num_edges));
    wide ? w.i32(f.texinfo) : w.u16(uint16_t(f.texinfo));
    for (uint8_t s : f.styles) w.u8(s);
    w.i32(f.lightofs);
  }
  end(kFaces);
  begin(kLighting); w.raw(b.lighting.data(), b.lighting.size()); end(kLighting);
  begin(kClipNodes);
  for (const auto& c : b.clipnodes) {
    w.i32(c.plane);
    for (int32_t ch : c.children) wide ? w.i32(ch) : w.u16(uint16_t(int16_t(ch)));
  }
  end(kClipNodes);
  begin(kLeaves);
  for (const auto& l : b.leaves) {
    w.i32(l.contents);
    w.i32(l.visofs);
    for (const float* v : {l.mins, l.maxs})
      for (int k = 0; k < 3; ++k) float_bounds ? w.f32(v[k]) : w.i16(clamp16(v[k]));
    wide ? w.u32(l.first_marksurface) : w.u16(uint16_t(l.first_marksurface));
    wide ? w.u32(l.num_marksurfaces) : w.u16(uint16_t(l.num_marksurfaces));
    for (uint8_t a : l.ambient) w.u8(a);
  }
  end(kLeaves);
  begin(kMarkSurfaces);
  for (uint32_t m : b.marksurfaces) wide ? w.u32(m) : w.u16(uint16_t(m));
  end(kMarkSurfaces);
  begin(kEdges);
  for (const auto& e : b.edges) for (uint32_t v : e.v) wide ? w.u32(v) : w.u16(uint16_t(v));
  end(kEdges);
  begin(kSurfEdges); for (int32_t s : b.surfedges) w.i32(s); end(kSurfEdges);
  begin(kModels);
  for (const auto& m : b.models) {
    for (const float* v : {m.mins, m.maxs, m.origin}) for (int k = 0; k < 3; ++k) w.f32(v[k]);
    for (int32_t hn : m.headnode) w.i32(hn);
    w.i32(m.visleafs);
    w.i32(m.first_face);
    w.i32(m.num_faces);
  }
  end(kModels);
  for (int i = 0; i < kLumpCount; ++i) {
    std::memcpy(o.data() + dir_at + 8 * i, &ofs[i], 4);
    std::memcpy(o.data() + dir_at + 8 * i + 4, &len[i], 4);
  }
  return Status::ok();
}

Status write_bsp(const char* path, const BspData& bsp, BspFormat format, BspFormat* used) {
  std::vector<uint8_t> bytes;
  SB_TRY(serialize_bsp(bsp, format, &bytes, used));
  // Write to a temporary name first so a failure never leaves a half-written BSP behind.
  std::string tmp = std::string(path) + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) return make_error("%s: cannot open for writing", tmp.c_str());
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  ok = (std::fclose(f) == 0) && ok;
  if (!ok) {
    std::remove(tmp.c_str());
    return make_error("%s: write failed (disk full?)", path);
  }
  if (std::rename(tmp.c_str(), path) != 0) {
    std::remove(tmp.c_str());
    return make_error("%s: cannot replace the file", path);
  }
  return Status::ok();
}

}  // namespace sb::tools
