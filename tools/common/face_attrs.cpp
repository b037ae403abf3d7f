// tools/common/face_attrs.cpp: see face_attrs.h.
#include "tools/common/face_attrs.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace sb::tools {
namespace {

void put32(std::vector<uint8_t>* o, uint32_t v) {
  for (int i = 0; i < 4; ++i) o->push_back(uint8_t(v >> (8 * i)));
}
void putf(std::vector<uint8_t>* o, float f) {
  uint32_t v;
  std::memcpy(&v, &f, 4);
  put32(o, v);
}
uint32_t get32(const uint8_t* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}
float getf(const uint8_t* p) {
  uint32_t v = get32(p);
  float f;
  std::memcpy(&f, &v, 4);
  return f;
}

}  // namespace

std::string face_attr_path(const std::string& bsp_path) {
  std::string p = bsp_path;
  if (p.size() > 4 && (p.compare(p.size() - 4, 4, ".bsp") == 0 || p.compare(p.size() - 4, 4, ".BSP") == 0))
    p.resize(p.size() - 4);
  return p + ".faceattr";
}

uint64_t face_attr_hash(const BspData& bsp) {
  uint64_t h = 1469598103934665603ull;
  auto mix = [&h](int32_t v) {
    uint32_t u = uint32_t(v);
    for (int i = 0; i < 4; ++i) {
      h ^= uint8_t(u >> (8 * i));
      h *= 1099511628211ull;
    }
  };
  for (const DFace& f : bsp.faces) {
    mix(f.plane);
    mix(f.side);
    mix(f.first_edge);
    mix(f.num_edges);
    mix(f.texinfo);
  }
  return h;
}

void serialize_face_attrs(const BspData& bsp, const std::vector<FaceAttr>& attrs, std::vector<uint8_t>* out) {
  out->clear();
  out->insert(out->end(), {'S', 'B', 'F', 'A'});
  put32(out, kFaceAttrVersion);
  put32(out, uint32_t(attrs.size()));
  put32(out, kFaceAttrRecordSize);
  uint64_t h = face_attr_hash(bsp);
  put32(out, uint32_t(h));
  put32(out, uint32_t(h >> 32));
  for (const FaceAttr& a : attrs) {
    putf(out, a.minlight);
    out->insert(out->end(), {a.minlight_color[0], a.minlight_color[1], a.minlight_color[2], a.flags});
    putf(out, a.phong_angle);
    put32(out, a.entity);
  }
}

Status write_face_attrs(const char* path, const BspData& bsp, const std::vector<FaceAttr>& attrs) {
  std::vector<uint8_t> bytes;
  serialize_face_attrs(bsp, attrs, &bytes);
  FILE* f = std::fopen(path, "wb");
  if (!f) return make_error("%s: cannot open for writing: %s", path, std::strerror(errno));
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  ok = std::fclose(f) == 0 && ok;
  if (!ok) return make_error("%s: write failed", path);
  return Status::ok();
}

Status parse_face_attrs(const char* name, const uint8_t* data, size_t size, const BspData& bsp,
                        std::vector<FaceAttr>* out) {
  out->clear();
  if (size < kFaceAttrHeaderSize)
    return make_error("%s: offset %zu: file of %zu bytes is too short for the %zu-byte header", name, size, size,
                      kFaceAttrHeaderSize);
  if (std::memcmp(data, "SBFA", 4) != 0) return make_error("%s: offset 0: magic is not \"SBFA\"", name);
  uint32_t version = get32(data + 4), count = get32(data + 8), rec = get32(data + 12);
  if (version != kFaceAttrVersion)
    return make_error("%s: offset 4: version %u is not %u", name, version, kFaceAttrVersion);
  if (rec != kFaceAttrRecordSize)
    return make_error("%s: offset 12: record size %u is not %u", name, rec, kFaceAttrRecordSize);
  if (count != bsp.faces.size())
    return make_error("%s: offset 8: %u faces, but the BSP has %zu (side file from another compile?)", name, count,
                      bsp.faces.size());
  uint64_t h = uint64_t(get32(data + 16)) | uint64_t(get32(data + 20)) << 32;
  if (h != face_attr_hash(bsp))
    return make_error("%s: offset 16: face hash does not match the BSP's faces (side file from another compile?)",
                      name);
  size_t need = kFaceAttrHeaderSize + size_t(count) * kFaceAttrRecordSize;
  if (size != need)
    return make_error("%s: offset %zu: file is %zu bytes, %u records need exactly %zu", name,
                      size < need ? size : need, size, count, need);
  out->resize(count);
  for (uint32_t i = 0; i < count; ++i) {
    size_t off = kFaceAttrHeaderSize + size_t(i) * kFaceAttrRecordSize;
    const uint8_t* p = data + off;
    FaceAttr& a = (*out)[i];
    a.minlight = getf(p);
    a.minlight_color[0] = p[4];
    a.minlight_color[1] = p[5];
    a.minlight_color[2] = p[6];
    a.flags = p[7];
    a.phong_angle = getf(p + 8);
    a.entity = get32(p + 12);
    if (!std::isfinite(a.minlight)) return make_error("%s: offset %zu: face %u: minlight is not finite", name, off, i);
    if (!std::isfinite(a.phong_angle) || a.phong_angle < 0 || a.phong_angle > 180)
      return make_error("%s: offset %zu: face %u: phong angle %g outside 0..180", name, off + 8, i,
                        double(a.phong_angle));
    if (a.flags & ~uint8_t(kFaceAttrShadow | kFaceAttrSelfShadow | kFaceAttrLightIgnore | kFaceAttrNoShadow))
      return make_error("%s: offset %zu: face %u: unknown flags 0x%02x", name, off + 7, i, a.flags);
  }
  return Status::ok();
}

Status read_face_attrs(const char* path, const BspData& bsp, std::vector<FaceAttr>* out, bool* found) {
  out->clear();
  *found = false;
  FILE* f = std::fopen(path, "rb");
  if (!f) {
    if (errno == ENOENT) return Status::ok();
    return make_error("%s: cannot open: %s", path, std::strerror(errno));
  }
  *found = true;
  std::vector<uint8_t> bytes;
  uint8_t buf[65536];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) bytes.insert(bytes.end(), buf, buf + n);
  bool err = std::ferror(f) != 0;
  std::fclose(f);
  if (err) return make_error("%s: read failed", path);
  return parse_face_attrs(path, bytes.data(), bytes.size(), bsp, out);
}

}  // namespace sb::tools
