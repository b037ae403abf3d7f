// engine/formats/wad.cpp: WAD2 directory parsing and miptex decoding.
#include "engine/formats/wad.h"

#include <cstring>

#include "engine/fs/padded_push.h"

namespace sb {
namespace {

int32_t rd_i32(const uint8_t* p) {
  int32_t v;
  std::memcpy(&v, p, 4);
  return v;
}
uint32_t rd_u32(const uint8_t* p) {
  uint32_t v;
  std::memcpy(&v, p, 4);
  return v;
}

int lower(int c) { return c >= 'A' && c <= 'Z' ? c + 32 : c; }

bool equal_nocase(const char* a, const char* b) {
  for (;; ++a, ++b) {
    if (lower(*a) != lower(*b)) return false;
    if (!*a) return true;
  }
}

constexpr size_t kWadHeaderBytes = 12;
constexpr size_t kWadEntryBytes = 32;

}  // namespace

const WadLump* Wad::find(const char* lump_name) const {
  for (uint32_t i = 0; i < count; ++i)
    if (equal_nocase(lumps[i].name, lump_name)) return &lumps[i];
  return nullptr;
}

Result<Wad> parse_wad(const char* wad_name, const uint8_t* data, size_t size, mem::Arena& into) {
  if (size < kWadHeaderBytes)
    return make_error("%s: file is %zu bytes, too short for a WAD2 header (12)", wad_name, size);
  if (std::memcmp(data, "WAD2", 4) != 0) return make_error("%s: header field 'identification' is not \"WAD2\"", wad_name);
  int32_t numlumps = rd_i32(data + 4), infotableofs = rd_i32(data + 8);
  if (numlumps < 0 || uint32_t(numlumps) > kMaxWadLumps)
    return make_error("%s: header field 'numlumps' = %d out of range (0..%u)", wad_name, numlumps, kMaxWadLumps);
  if (infotableofs < int32_t(kWadHeaderBytes) || uint64_t(infotableofs) > size)
    return make_error("%s: header field 'infotableofs' = %d outside the file (12..%zu)", wad_name, infotableofs, size);
  if (uint64_t(infotableofs) + uint64_t(numlumps) * kWadEntryBytes > size)
    return make_error("%s: directory (%d entries at offset %d) runs past the end of the file (%zu bytes)", wad_name,
                      numlumps, infotableofs, size);
  Wad wad;
  wad.name = wad_name;
  wad.lumps = mem_util::push_array_padded<WadLump>(into, numlumps ? size_t(numlumps) : 1, "wad directory");
  if (!wad.lumps) {
    Error e = make_error("%s: ", wad_name);
    into.failure_message(e.message + std::strlen(e.message), sizeof e.message - std::strlen(e.message));
    return e;
  }
  for (int32_t i = 0; i < numlumps; ++i) {
    const uint8_t* raw = data + infotableofs + size_t(i) * kWadEntryBytes;
    WadLump& l = wad.lumps[i];
    std::memcpy(l.name, raw + 16, 16);  // 16 chars without NUL are allowed
    l.name[16] = 0;
    int32_t filepos = rd_i32(raw), disksize = rd_i32(raw + 4);
    uint8_t compression = raw[13];
    l.type = raw[12];
    if (filepos < 0 || uint64_t(filepos) > size)
      return make_error("%s: lump %d ('%s') field 'filepos' = %d outside the file (%zu bytes)", wad_name, i, l.name,
                        filepos, size);
    if (disksize < 0 || uint64_t(filepos) + uint64_t(disksize) > size)
      return make_error("%s: lump %d ('%s') field 'disksize' = %d runs past the end of the file (filepos %d, %zu bytes)",
                        wad_name, i, l.name, disksize, filepos, size);
    if (compression != 0)
      return make_error("%s: lump %d ('%s') field 'compression' = %u is not supported", wad_name, i, l.name,
                        compression);
    l.data = data + filepos;
    l.size = uint32_t(disksize);
  }
  wad.count = uint32_t(numlumps);
  return wad;
}

Status decode_miptex(const char* file, const char* what, const uint8_t* data, size_t size, MiptexView* out) {
  if (size < kMiptexHeaderBytes)
    return make_error("%s: %s is %zu bytes, too short for a miptex header (40)", file, what, size);
  std::memset(out, 0, sizeof *out);
  std::memcpy(out->name, data, 16);
  out->name[16] = 0;
  out->width = rd_u32(data + 16);
  out->height = rd_u32(data + 20);
  const char* dims[2] = {"width", "height"};
  uint32_t vals[2] = {out->width, out->height};
  for (int k = 0; k < 2; ++k)
    if (vals[k] < 16 || vals[k] > kMaxTextureSize || vals[k] % 16 != 0)
      return make_error("%s: %s ('%s') field '%s' = %u is not a multiple of 16 in 16..%u", file, what, out->name,
                        dims[k], vals[k], kMaxTextureSize);
  uint32_t offsets[4];
  bool any = false;
  for (int m = 0; m < 4; ++m) {
    offsets[m] = rd_u32(data + 24 + 4 * m);
    any |= offsets[m] != 0;
  }
  out->has_pixels = any;
  if (!any) return Status::ok();
  for (int m = 0; m < 4; ++m) {
    uint64_t bytes = uint64_t(out->width >> m) * (out->height >> m);
    if (offsets[m] < kMiptexHeaderBytes || uint64_t(offsets[m]) + bytes > size)
      return make_error("%s: %s ('%s') field 'offsets[%d]' = %u: mip %d (%ux%u) lies outside the miptex (40..%zu)",
                        file, what, out->name, m, offsets[m], m, out->width >> m, out->height >> m, size);
    out->mips[m] = data + offsets[m];
  }
  return Status::ok();
}

}  // namespace sb
