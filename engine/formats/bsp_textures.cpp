// engine/formats/bsp_textures.cpp: the BSP 'textures' and 'texinfo' lumps and
// texture animation chains.
//
// textures lump: int32 nummiptex | int32 dataofs[nummiptex] | miptex...
//   dataofs -1 = missing texture; a miptex whose four mip offsets are all zero
//   has no pixels (external textures). Both become placeholder slots: a 16x16
//   checker (all four mips) that keeps the original name when there is one.
//   One extra placeholder slot is appended (w->placeholder_texture) for texinfo
//   entries whose texture index is out of range.
#include <cctype>
#include <cstdio>

#include "engine/core/log.h"
#include "engine/formats/bsp_load_local.h"
#include "engine/formats/wad.h"

namespace sb::bsp_detail {
namespace {

constexpr uint32_t kPlaceholderSize = 16;
constexpr uint8_t kCheckerDark = 0, kCheckerLight = 15;

TextureKind kind_for_name(const char* name) {
  if (name[0] == '*') return kTexTurb;
  if (std::tolower((unsigned char)name[0]) == 's' && std::tolower((unsigned char)name[1]) == 'k' &&
      std::tolower((unsigned char)name[2]) == 'y')
    return kTexSky;
  return kTexNormal;
}

void init_texture(Texture& t, const char* name) {
  std::snprintf(t.name, sizeof t.name, "%s", name);
  t.kind = kind_for_name(t.name);
  t.anim_next = -1;
  t.alternate = -1;
  t.anim_total = 0;
  t.anim_index = 0;
}

// 16x16 checker with 8-texel squares at mip 0 (8 >> mip at mip levels), shared by all placeholder slots.
const uint8_t* make_checker(LoadContext& c) {
  auto* px = static_cast<uint8_t*>(
      mem_util::push_padded(*c.level, miptex_pixel_bytes(kPlaceholderSize, kPlaceholderSize), "bsp placeholder texture"));
  if (!px) return nullptr;
  uint8_t* p = px;
  for (int m = 0; m < 4; ++m) {
    int size = int(kPlaceholderSize) >> m, square = 8 >> m;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) *p++ = ((x / square + y / square) & 1) ? kCheckerLight : kCheckerDark;
  }
  return px;
}

void set_placeholder(Texture& t, const uint8_t* checker, const char* name) {
  init_texture(t, name);
  t.width = t.height = kPlaceholderSize;
  const uint8_t* p = checker;
  for (int m = 0; m < 4; ++m) {
    t.mips[m] = p;
    p += (kPlaceholderSize >> m) * (kPlaceholderSize >> m);
  }
}

int lower(int ch) { return std::tolower((unsigned char)ch); }

bool same_anim_base(const char* a, const char* b) {
  for (a += 2, b += 2;; ++a, ++b) {
    if (lower(*a) != lower(*b)) return false;
    if (!*a) return true;
  }
}

}  // namespace

Status load_textures(LoadContext& c) {
  const LumpView& l = c.lumps[kLumpTextures];
  BspWorld& w = *c.w;
  uint32_t n = 0;
  if (l.size > 0) {
    if (l.size < 4) return lump_error(c, kLumpTextures, "(length %u) is too short for its count", l.size);
    int32_t count = rd_i32(l.data);
    if (count < 0 || 4 + 4 * uint64_t(count) > l.size)
      return lump_error(c, kLumpTextures, "field 'nummiptex' = %d does not fit the lump (length %u)", count, l.size);
    n = uint32_t(count);
  }
  w.textures = push_records<Texture>(c, uint64_t(n) + 1, "bsp textures");
  c.texture_missing = mem_util::push_array_padded<uint8_t>(*c.scratch, size_t(n) + 1, "bsp texture flags");
  if (!w.textures) return arena_error(c, kLumpTextures, *c.level);
  if (!c.texture_missing) return arena_error(c, kLumpTextures, *c.scratch);
  const uint8_t* checker = make_checker(c);
  if (!checker) return arena_error(c, kLumpTextures, *c.level);

  for (uint32_t i = 0; i < n; ++i) {
    Texture& t = w.textures[i];
    int32_t ofs = rd_i32(l.data + 4 + 4 * size_t(i));
    if (ofs == -1) {
      set_placeholder(t, checker, "missing");
      c.texture_missing[i] = 1;
      continue;
    }
    if (ofs < 0 || uint64_t(ofs) + kMiptexHeaderBytes > l.size)
      return lump_error(c, kLumpTextures, "entry %u field 'dataofs' = %d outside the lump (length %u)", i, ofs, l.size);
    char what[64];
    std::snprintf(what, sizeof what, "lump 'textures' entry %u", i);
    MiptexView view;
    SB_TRY(decode_miptex(c.name, what, l.data + ofs, l.size - uint32_t(ofs), &view));
    if (!view.has_pixels) {
      set_placeholder(t, checker, view.name[0] ? view.name : "missing");
      c.texture_missing[i] = 1;
      continue;
    }
    init_texture(t, view.name);
    t.width = view.width;
    t.height = view.height;
    auto* px = static_cast<uint8_t*>(mem_util::push_padded(*c.level, miptex_pixel_bytes(t.width, t.height), "bsp texture pixels"));
    if (!px) return arena_error(c, kLumpTextures, *c.level);
    for (int m = 0; m < 4; ++m) {
      size_t bytes = size_t(t.width >> m) * (t.height >> m);
      std::memcpy(px, view.mips[m], bytes);
      t.mips[m] = px;
      px += bytes;
    }
  }
  set_placeholder(w.textures[n], checker, "missing");
  c.texture_missing[n] = 1;
  w.num_textures = n + 1;
  w.placeholder_texture = n;
  return Status::ok();
}

Status load_texinfo(LoadContext& c) {
  const LumpView& l = c.lumps[kLumpTexinfo];
  BspWorld& w = *c.w;
  constexpr uint32_t kRec = 40;
  uint32_t n = l.size / kRec;
  w.texinfo = push_records<TexInfo>(c, n, "bsp texinfo");
  if (!w.texinfo) return arena_error(c, kLumpTexinfo, *c.level);
  for (uint32_t i = 0; i < n; ++i) {
    const uint8_t* r = l.data + size_t(i) * kRec;
    TexInfo& ti = w.texinfo[i];
    for (int a = 0; a < 2; ++a)
      for (int k = 0; k < 4; ++k) {
        float v = rd_f32(r + 16 * a + 4 * k);
        if (!std::isfinite(v) || std::fabs(v) > 1e7f)
          return lump_error(c, kLumpTexinfo, "entry %u field 'vecs[%d][%d]' = %g is not a finite number in +-1e7", i,
                            a, k, double(v));
        ti.vecs[a][k] = v;
      }
    int32_t miptex = rd_i32(r + 32);
    ti.flags = rd_u32(r + 36);
    if (miptex < 0 || uint32_t(miptex) >= w.placeholder_texture) {
      ti.texture = int32_t(w.placeholder_texture);
      ++w.missing_textures;
    } else {
      ti.texture = miptex;
    }
    if (w.textures[ti.texture].kind != kTexNormal) ti.flags |= kTexSpecial;
    float len0 = std::sqrt(ti.vecs[0].x * ti.vecs[0].x + ti.vecs[0].y * ti.vecs[0].y + ti.vecs[0].z * ti.vecs[0].z);
    float len1 = std::sqrt(ti.vecs[1].x * ti.vecs[1].x + ti.vecs[1].y * ti.vecs[1].y + ti.vecs[1].z * ti.vecs[1].z);
    ti.mipadjust = len0 > len1 ? len0 : len1;
    if (ti.mipadjust < 1e-3f) ti.mipadjust = 1e-3f;
  }
  w.num_texinfo = n;
  return Status::ok();
}

void resolve_animations(LoadContext& c) {
  BspWorld& w = *c.w;
  uint32_t n = w.num_textures;
  mem::ArenaScope scope(*c.scratch);
  uint8_t* done = mem_util::push_array_padded<uint8_t>(*c.scratch, n, "bsp anim flags");
  if (!done) {
    log_warning("%s: no scratch memory to resolve texture animations; textures will not animate", c.name);
    return;
  }
  for (uint32_t i = 0; i < n; ++i) {
    const Texture& ti = w.textures[i];
    if (ti.name[0] != '+' || done[i]) continue;
    int32_t prim[10], alt[10];
    for (int k = 0; k < 10; ++k) prim[k] = alt[k] = -1;
    int nprim = 0, nalt = 0;
    bool bad = std::strlen(ti.name) < 2;
    for (uint32_t j = i; j < n && !bad; ++j) {
      const Texture& tj = w.textures[j];
      if (tj.name[0] != '+' || std::strlen(tj.name) < 2 || !same_anim_base(ti.name, tj.name)) continue;
      done[j] = 1;
      int ch = lower(tj.name[1]);
      if (ch >= '0' && ch <= '9') {
        int k = ch - '0';
        if (prim[k] < 0) prim[k] = int32_t(j);
        nprim = nprim > k + 1 ? nprim : k + 1;
      } else if (ch >= 'a' && ch <= 'j') {
        int k = ch - 'a';
        if (alt[k] < 0) alt[k] = int32_t(j);
        nalt = nalt > k + 1 ? nalt : k + 1;
      } else {
        bad = true;
      }
    }
    for (int k = 0; k < nprim; ++k) bad |= prim[k] < 0;
    for (int k = 0; k < nalt; ++k) bad |= alt[k] < 0;
    if (bad) {
      log_warning("%s: texture animation '%s' has missing or bad frames; drawn without animation", c.name, ti.name);
      continue;
    }
    for (int k = 0; k < nprim; ++k) {
      Texture& t = w.textures[prim[k]];
      t.anim_next = prim[(k + 1) % nprim];
      t.anim_total = uint16_t(nprim);
      t.anim_index = uint16_t(k);
      t.alternate = nalt ? alt[0] : -1;
    }
    for (int k = 0; k < nalt; ++k) {
      Texture& t = w.textures[alt[k]];
      t.anim_next = alt[(k + 1) % nalt];
      t.anim_total = uint16_t(nalt);
      t.anim_index = uint16_t(k);
      t.alternate = nprim ? prim[0] : -1;  // an alternate-only sequence is allowed
    }
  }
}

}  // namespace sb::bsp_detail
