// bench/count_kernels.cpp (starbow_count_kernels): a deterministic driver for instruction
// counting (bench/count.sh). It runs one asm/ kernel variant `reps` times over fixed inputs
// and prints a checksum; no clock reads, no randomness beyond a fixed-seed LCG, so two runs
// with reps N and 2N differ by exactly N repetitions' worth of kernel work and the counting
// tool (valgrind, qemu's insn plugin) can difference them to cancel startup and setup.
//
//   starbow_count_kernels list                       "case variant units" per line, where
//                                                    units = pixels (texels) per repetition
//   starbow_count_kernels <case> <variant> <reps>    run; prints "case variant units checksum"
//
// Cases (units per repetition):
//   span16       one 1920-pixel span of a 256x256 surface in runs of 16 (the engine's calls)
//   span1920     the same span in one call (linear steps): the loop without per-call cost
//   lit16m2      the same kernel at mip 2 (64x64 surface, 16x16 texture): 120 runs of 16 px
//                from their own starts, 0.5-1 texel a pixel, second order (see lit_m2_runs)
//   lit16        single-pass lit span (asm/lit_span.h): span16's runs over a 256x256 surface at
//                mip 0, 64x64 texture, 17x17 light grid (its own variants: scalar, fast, avx2,
//                avx2s where compiled and supported)
//   block_mip<m> surface block builder, 256x256 surface extent at mip m (texels = (256>>m)^2),
//                64x64 texture (>> m), 17x17 light grid
//   z1920        z span fill, 1920 pixels
//   palette      8-bit to 32-bit palette expansion, 320x200 at scale 1 (source pixels)
//   palette2/3/4 the same 320x200 frame at scale 2, 3 and 4 (output pixels: 640x400 ..
//                1280x800, the SDL window's -scale)
//   alias32      alias-model spans: 60 spans of 17-47 pixels (mean 32, pairs 32 - k and 32 + k
//                for k = 0 .. 15, so every length mod 8 occurs), all visible (a 1920-pixel
//                row's worth), 296x194 skin, full light range
//   alias1920h   one 1920-pixel alias span behind a z buffer that hides alternate runs of 16
//   persp1920    the whole-span drawer (asm/span_persp.h): one 1920-pixel span of a 256x256
//                surface in perspective, second-order steps, divides included, drawn as the
//                engine draws a surface's spans: one surface_spans_persp call (a batch of 1)
//   persp64      the same over 30 spans of 50-64 pixels (mean 57; per-span costs weigh more),
//                all 30 in one surface_spans_persp call (the engine's batches)
//   persp64single persp64 with one surface_span_persp call per span (30 calls: the per-span
//                entry, for comparison)
//   persp1920lin persp1920 with linear steps (second_order off: Quake's stepping)
//   persp64lin   persp64 with linear steps (the like-for-like short-span figure), batched
//   persp192     10 spans of 179-205 pixels (mean 192, ten different tail lengths) in one
//                call: the engine's typical long span (second-order spans of more than 80
//                pixels average 150-200 pixels in LibreQuake flythroughs at 320x240-640x480,
//                about half of all pixels drawn)
//   persp192lin  persp192 with linear steps
//   persp32      32 spans of 17-48 pixels (mean 32.5) in one call, second-order steps
//   persp16      32 spans of 1-16 pixels (mean 8.5) in one call, second-order steps: one run
//                each (bench/span_hist.cpp: 880-960 such spans a frame at 320x240, 6-9% of
//                the pixels)
//   persp72      16 spans of 65-80 pixels (mean 72.5) in one call, second-order steps: five runs
//                (persp_long_a64's one-pass shape on aarch64; 5-7% of the pixels at 320x240)
//   (persp: the non-scalar tables all hold the portable "fast" version; listed once, under
//   the first of them: sse2 on x86-64, neon on ARM)
// Variants: every table asm/kernels.h lists for this build and CPU (scalar, sse2, avx2,
// avx2g, neon), except the "tuned" mix (it is one of the others per kernel).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "asm/kernels.h"

namespace {

using sb::simd::Kernels;

constexpr int kSpan = 1920, kSurf = 256, kPalW = 320, kPalH = 200;

struct Lcg {
  uint32_t s = 12345;
  uint32_t next() { return s = s * 1664525u + 1013904223u; }
};

struct Run {
  int offset, n;
  int32_t u, v, du, dv;
};

// A span crossing the surface diagonally with a perspective bend: u, v at each run's ends
// exact (integer-only, so every target computes the same inputs), linear within a run.
std::vector<Run> span_runs() {
  std::vector<Run> runs;
  const int64_t umax = (int64_t(kSurf) << 16) - 1;
  auto at = [&](int x, int32_t* u, int32_t* v) {
    // u = umax * x / (x + span/2) * 1.5 (bends towards the far end), v = linear 0.1 .. 0.9
    const int64_t uu = umax * 3 * x / (2 * (int64_t(x) + kSpan / 2)) ;
    const int64_t vv = umax / 10 + umax * 8 * x / (10 * int64_t(kSpan));
    *u = int32_t(uu < umax ? uu : umax);
    *v = int32_t(vv < umax ? vv : umax);
  };
  for (int x = 0; x < kSpan; x += 16) {
    const int n = kSpan - x < 16 ? kSpan - x : 16;
    int32_t ua, va, ub, vb;
    at(x, &ua, &va);
    at(x + n - 1, &ub, &vb);
    const int steps = n > 1 ? n - 1 : 1;
    runs.push_back({x, n, ua, va, (ub - ua) / steps, (vb - va) / steps});
  }
  return runs;
}

const Kernels* find_variant(const char* name) {
  for (int i = 0; i < sb::simd::variant_count(); ++i) {
    const sb::simd::Variant v = sb::simd::variant(i);
    if (v.kernels && v.supported && std::strcmp(v.kernels->name, name) == 0) return v.kernels;
  }
  return nullptr;
}

const char* const kCases[] = {"span16", "span1920", "lit16", "lit16m2", "block_mip0", "block_mip1",
                              "block_mip2", "block_mip3", "z1920", "palette", "palette2", "palette3", "palette4", "alias32", "alias1920h",
                              "persp1920", "persp64", "persp1920lin", "persp64lin", "persp64single",
                              "persp192", "persp192lin", "persp32", "persp16", "persp72", "persp32mix"};

// The span lengths of a persp case, left to right along one 1920-pixel row. Mixed lengths, so
// the spans end in different last runs as the engine's do: a span of 16 k pixels (or a long
// one that leaves 32 after its passes) takes the full-run tail, which no other length does.
//   persp192*: ten lengths around 192 (mean 192, 1920 pixels; left after the 32-pixel
//              passes 17 .. 48, ten different values)
//   persp64*:  30 four-run spans of 50 .. 64 pixels, each length twice (mean 57, 1710
//              pixels; last runs of 2 .. 16 pixels), neighbours of different lengths
//   persp32:   32 spans of 17 .. 48 pixels, each length once (mean 32.5, 1040 pixels; two and
//              three runs, last runs of 1 .. 16 pixels), neighbours of different lengths
//   persp16:   32 spans of 1 .. 16 pixels, each length twice (mean 8.5, 272 pixels: one run),
//              neighbours of different lengths (16 1 15 2 .. 9 8, then back again)
//   persp72:   16 spans of 65 .. 80 pixels, each length once (80 65 79 66 .. 73 72; mean 72.5,
//              1160 pixels: five runs, last runs of 1 .. 16 pixels)
//   persp32mix: 24 spans of a mixed surface's batch (818 pixels): two linear spans first
//              (40, 56) and a 100-pixel second-order one, then second-order spans of 17 .. 48
//              pixels interleaved with ones of 1 .. 16 and 49 .. 64 and one linear (36), as in
//              frames (bench/span_hist.md): 17 .. 48 pixel spans both right after a one-run
//              span and after linear, 49 .. 64 and long ones (the batch loop's mid-batch case)
//   persp1920*: one span of 1920
// persp32mix's lengths; a negative one is a linear span (second_order off) of that length.
const int kMixLens[] = {-40, -56, 100, 32, 20, 45, 8, 60, 27, 38, 3, 17,
                        48,  52,  24,  12, 41, 30, -36, 19, 44, 5, 35, 26};
std::vector<int> persp_lengths(const char* c) {
  if (std::strcmp(c, "persp32mix") == 0) {
    std::vector<int> l;
    for (int n : kMixLens) l.push_back(n < 0 ? -n : n);
    return l;
  }
  // persp192 and persp192lin exactly (persp1920 and persp1920lin share their first 8 characters)
  if (std::strcmp(c, "persp192") == 0 || std::strcmp(c, "persp192lin") == 0)
    return {179, 205, 182, 202, 185, 199, 188, 196, 191, 193};
  if (std::strncmp(c, "persp64", 7) == 0) {
    std::vector<int> l;
    for (int i = 0; i < 15; ++i) l.push_back(i % 2 ? 50 + i / 2 : 64 - i / 2);  // 64 50 63 51 .. 57
    for (int i = 0; i < 15; ++i) l.push_back(l[14 - i]);                         // and back again
    return l;
  }
  if (std::strcmp(c, "persp32") == 0) {
    std::vector<int> l;
    for (int i = 0; i < 32; ++i) l.push_back(i % 2 ? 17 + i / 2 : 48 - i / 2);  // 48 17 47 18 .. 33 32
    return l;
  }
  if (std::strcmp(c, "persp72") == 0) {
    std::vector<int> l;
    for (int i = 0; i < 16; ++i) l.push_back(i % 2 ? 65 + i / 2 : 80 - i / 2);  // 80 65 79 66 .. 73 72
    return l;
  }
  if (std::strcmp(c, "persp16") == 0) {
    std::vector<int> l;
    for (int i = 0; i < 16; ++i) l.push_back(i % 2 ? 1 + i / 2 : 16 - i / 2);  // 16 1 15 2 .. 9 8
    for (int i = 0; i < 16; ++i) l.push_back(l[15 - i]);                        // and back again
    return l;
  }
  return {kSpan};
}

long units_of(const char* c) {
  if (std::strncmp(c, "persp", 5) == 0) {
    long sum = 0;
    for (int n : persp_lengths(c)) sum += n;
    return sum;
  }
  if (std::strncmp(c, "span", 4) == 0 || std::strcmp(c, "z1920") == 0 || std::strncmp(c, "alias", 5) == 0 ||
      std::strncmp(c, "lit16", 5) == 0)
    return kSpan;
  if (std::strncmp(c, "block_mip", 9) == 0) {
    const int e = kSurf >> (c[9] - '0');
    return long(e) * e;
  }
  if (std::strncmp(c, "palette", 7) == 0) {
    const long scale = c[7] ? c[7] - '0' : 1;
    return long(kPalW) * kPalH * scale * scale;
  }
  return 0;
}

uint32_t checksum(const uint8_t* p, size_t n) {
  uint32_t h = 2166136261u;
  for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 16777619u;
  return h;
}

// Runs case c of kernel table k reps times; returns a checksum of the last output.
uint32_t run_case(const char* c, const Kernels& k, long reps) {
  Lcg rng;
  if (std::strncmp(c, "span", 4) == 0) {
    std::vector<uint8_t> surf(size_t(kSurf) * kSurf), dest(kSpan);
    for (auto& t : surf) t = uint8_t(rng.next() >> 24);
    const std::vector<Run> runs = span_runs();
    const bool one_call = std::strcmp(c, "span1920") == 0;
    const int32_t du = int32_t(((kSurf - 1) << 16) / kSpan);
    for (long r = 0; r < reps; ++r) {
      if (one_call) {
        k.surface_span(dest.data(), kSpan, surf.data(), kSurf, kSurf, 0, 0, du, du / 2, 0, 0);
      } else {
        for (const Run& x : runs)
          k.surface_span(dest.data() + x.offset, x.n, surf.data(), kSurf, kSurf, x.u, x.v, x.du, x.dv, 0, 0);
      }
    }
    return checksum(dest.data(), dest.size());
  }
  if (std::strncmp(c, "block_mip", 9) == 0) {
    const int mip = c[9] - '0';
    const int w = kSurf >> mip, tex = 64 >> mip, gw = kSurf / 16 + 1;
    std::vector<uint16_t> grid(size_t(gw) * gw);
    for (auto& g : grid) g = uint16_t(64 + (rng.next() >> 8) % 0x3000);
    std::vector<uint8_t> texels(size_t(tex) * tex), cm(64 * 256), out(size_t(w) * w);
    for (auto& t : texels) t = uint8_t(rng.next() >> 24);
    for (auto& t : cm) t = uint8_t(rng.next() >> 24);
    for (long r = 0; r < reps; ++r)
      k.surface_block(grid.data(), gw, texels.data(), tex, tex, mip, 16 >> mip, -(32 >> mip), w, w, cm.data(),
                      out.data());
    return checksum(out.data(), out.size());
  }
  if (std::strcmp(c, "z1920") == 0) {
    std::vector<uint16_t> z(kSpan);
    for (long r = 0; r < reps; ++r) k.z_span(z.data(), kSpan, 0x12340000u + uint32_t(r & 255), 0x00012345u);
    return checksum(reinterpret_cast<const uint8_t*>(z.data()), z.size() * 2);
  }
  if (std::strncmp(c, "alias", 5) == 0) {
    // 296x194 skin (a typical Quake player skin), colormap, z buffer: for alias32 all zero
    // (every pixel visible, and after the first repetition every pixel ties: still visible);
    // for alias1920h alternate runs of 16 nearer than the span (hidden) and zero (visible).
    constexpr int kSkinW = 296, kSkinH = 194;
    std::vector<uint8_t> skin(size_t(kSkinW) * kSkinH), cm(64 * 256), dest(kSpan);
    for (auto& t : skin) t = uint8_t(rng.next() >> 24);
    for (auto& t : cm) t = uint8_t(rng.next() >> 24);
    const bool hidden = std::strcmp(c, "alias1920h") == 0;
    std::vector<uint16_t> z(kSpan);
    for (int x = 0; x < kSpan; ++x) z[size_t(x)] = hidden && (x / 16) % 2 ? 0xffff : 0;
    std::vector<int> lens;
    if (hidden) lens.push_back(kSpan);
    for (int i = 0; !hidden && i < 30; ++i) {
      const int d = (i * 7) % 16;  // 0 7 14 5 12 3 ..: neighbours of different lengths
      lens.push_back(32 - d);
      lens.push_back(32 + d);
    }
    std::vector<sb::simd::AliasSpan> spans;  // made once: the repetitions time the kernel only
    for (int len : lens) {
      sb::simd::AliasSpan a{};
      a.s = 3 << 16;
      a.t = 150 << 16;
      a.light = 2 << 16;
      a.zi = 0x40000000u;
      a.ds = int32_t(((kSkinW - 8) << 16) / len);  // across most of the skin
      a.dt = -int32_t((100 << 16) / len);
      a.dlight = int32_t((60 << 16) / len);
      a.dzi = 0x3000;
      spans.push_back(a);
    }
    for (long r = 0; r < reps; ++r)
      for (size_t i = 0, x = 0; i < lens.size(); x += size_t(lens[i++]))
        k.alias_span(dest.data() + x, z.data() + x, lens[i], skin.data(), kSkinW, cm.data(), spans[i]);
    return checksum(dest.data(), dest.size());
  }
  if (std::strncmp(c, "persp", 5) == 0) {
    // A floor-like plane: 1/z falls 4x across the row, u and v cross the surface.
    std::vector<uint8_t> surf(size_t(kSurf) * kSurf), dest(kSpan);
    for (auto& t : surf) t = uint8_t(rng.next() >> 24);
    const bool lin = std::strstr(c, "lin") != nullptr;
    const std::vector<int> lens = persp_lengths(c);
    sb::simd::PerspSpan p{};
    p.zi0 = 0.004;
    p.dzi = -0.003 / kSpan;
    p.uz0 = 0.0;
    p.duz = 0.9 * kSurf * 0.001 / kSpan;
    p.vz0 = 0.1 * kSurf * 0.004;
    p.dvz = -0.0001 * kSurf / kSpan;
    p.umax = (kSurf << 16) - 1;
    p.vmax = (kSurf << 16) - 1;
    p.second_order = !lin;
    if (std::strstr(c, "single") != nullptr) {
      for (long r = 0; r < reps; ++r)
        for (int x = 0, i = 0; i < int(lens.size()); x += lens[i++]) {
          p.px0 = x + 0.5;
          k.surface_span_persp(dest.data() + x, lens[i], surf.data(), kSurf, kSurf, p);
        }
      return checksum(dest.data(), dest.size());
    }
    // One batch per repetition, filled once (the engine fills its items as it goes: a few
    // stores a span, not counted here).
    std::vector<sb::simd::PerspItem> items;
    const bool mix = std::strcmp(c, "persp32mix") == 0;
    for (int x = 0, i = 0; i < int(lens.size()); x += lens[i++]) {
      p.px0 = x + 0.5;
      p.second_order = !lin && !(mix && kMixLens[i] < 0);
      items.push_back(sb::simd::PerspItem{dest.data() + x, lens[i], p});
    }
    for (long r = 0; r < reps; ++r) k.surface_spans_persp(items.data(), int(items.size()), surf.data(), kSurf, kSurf);
    return checksum(dest.data(), dest.size());
  }
  if (std::strncmp(c, "palette", 7) == 0) {
    const int scale = c[7] ? c[7] - '0' : 1;
    std::vector<uint8_t> src(size_t(kPalW) * kPalH);
    for (auto& s : src) s = uint8_t(rng.next() >> 24);
    uint32_t pal[256];
    for (auto& p : pal) p = rng.next();
    std::vector<uint32_t> dst(src.size() * scale * scale);
    for (long r = 0; r < reps; ++r)
      k.expand_palette(src.data(), kPalW, kPalW, kPalH, pal, dst.data(), kPalW * scale, scale);
    return checksum(reinterpret_cast<const uint8_t*>(dst.data()), dst.size() * 4);
  }
  return 0;
}

// lit16: the lit span kernel's own variants (asm/lit_span.h keeps its own table).
sb::simd::LitSpanFn find_lit_variant(const char* name) {
  for (int i = 0; i < sb::simd::lit_span_variant_count(); ++i) {
    const sb::simd::LitSpanVariant v = sb::simd::lit_span_variant(i);
    if (v.supported && std::strcmp(v.name, name) == 0) return v.fn;
  }
  return nullptr;
}

// lit16m2: 120 runs of 16 pixels at mip 2 (64x64 surface, 16x16 texture, B = 4), each from
// its own start, 0.5-1 texel a pixel along u, -0.3-0.3 along v, second order (the step
// drifts by up to 0.01 texel a pixel): the engine's steps at a mip above 0, where an
// 8-pixel group spans two or three light cells.
std::vector<Run> lit_m2_runs(Lcg& rng, std::vector<int32_t>& dd) {
  std::vector<Run> runs;
  const int surf = kSurf >> 2;
  for (int x = 0; x < kSpan; x += 16) {
    const int32_t du = int32_t(32768 + rng.next() % 32768), dv = int32_t(rng.next() % 39322) - 19661;
    const int32_t ddu = int32_t(rng.next() % 1311) - 655, ddv = int32_t(rng.next() % 1311) - 655;
    // 16 pixels move at most 16 * 1.2 texels: start inside [20, surf - 20) texels.
    const int32_t u = int32_t((20 << 16) + rng.next() % uint32_t((surf - 40) << 16));
    const int32_t v = int32_t((20 << 16) + rng.next() % uint32_t((surf - 40) << 16));
    runs.push_back({x, 16, u, v, du, dv});
    dd.push_back(ddu);
    dd.push_back(ddv);
  }
  return runs;
}

uint32_t run_lit(sb::simd::LitSpanFn fn, long reps, bool mip2) {
  Lcg rng;
  constexpr int kTex = 64, kGrid = (kSurf - 1) / 16 + 2;
  std::vector<uint8_t> tex(kTex * kTex), cm(64 * 256), dest(kSpan);
  for (auto& t : tex) t = uint8_t(rng.next() >> 24);
  for (auto& t : cm) t = uint8_t(rng.next() >> 24);
  std::vector<uint16_t> grid(size_t(kGrid) * kGrid);
  for (auto& g : grid) g = uint16_t((rng.next() >> 16) & 0x3fff);
  std::vector<uint32_t> wide(grid.size());
  sb::simd::LitSpanSource src;
  src.texels = tex.data();
  src.tex_width = src.tex_height = kTex;
  src.soff = 8;  // a face whose texture_mins are not a multiple of the texture size
  src.toff = -24;
  src.grid = grid.data();
  src.grid_width = kGrid;
  src.mip = 0;
  src.width = src.height = kSurf;
  src.colormap = cm.data();
  std::vector<int32_t> dd;
  std::vector<Run> runs = span_runs();
  if (mip2) {  // the same grid (17 x 17 covers 64 texels at B = 4), texture 16x16
    src.mip = 2;
    src.width = src.height = kSurf >> 2;
    src.tex_width = src.tex_height = kTex >> 2;
    src.soff = 2;
    src.toff = -6;
    runs = lit_m2_runs(rng, dd);
  }
  sb::simd::lit_span_prepare(src, int(grid.size()), wide.data());
  if (!mip2) {  // lit16's loop as it always was (its rows' driver instructions unchanged)
    for (long r = 0; r < reps; ++r)
      for (const Run& run : runs) fn(dest.data() + run.offset, run.n, src, run.u, run.v, run.du, run.dv, 0, 0);
  } else {
    for (long r = 0; r < reps; ++r)
      for (size_t i = 0; i < runs.size(); ++i) {
        const Run& run = runs[i];
        fn(dest.data() + run.offset, run.n, src, run.u, run.v, run.du, run.dv, dd[2 * i], dd[2 * i + 1]);
      }
  }
  return checksum(dest.data(), dest.size());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "list") == 0) {
    for (const char* c : kCases) {
      if (std::strncmp(c, "lit16", 5) == 0) {
        for (int i = 0; i < sb::simd::lit_span_variant_count(); ++i)
          if (sb::simd::lit_span_variant(i).supported)
            std::printf("%s %s %ld\n", c, sb::simd::lit_span_variant(i).name, units_of(c));
        continue;
      }
      for (int i = 0; i < sb::simd::variant_count(); ++i) {
        const sb::simd::Variant v = sb::simd::variant(i);
        if (!v.kernels || !v.supported || std::strcmp(v.kernels->name, "tuned") == 0) continue;
        // z_span and expand_palette have no gather variant: avx2g's entries are other ones.
        if (std::strcmp(v.kernels->name, "avx2g") == 0 && (c[0] == 'z' || c[0] == 'p')) continue;
        // alias_span: the avx2 tables hold the sse2 variant.
        if (c[0] == 'a' && std::strncmp(v.kernels->name, "avx2", 4) == 0) continue;
        // neon_a53 differs from neon in surface_block only.
        if (std::strcmp(v.kernels->name, "neon_a53") == 0 && c[0] != 'b') continue;
        // persp: one non-scalar table (they all hold the portable fast version).
        if (std::strncmp(c, "persp", 5) == 0 && i > 1) continue;
        std::printf("%s %s %ld\n", c, v.kernels->name, units_of(c));
      }
    }
    return 0;
  }
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s list | <case> <variant> <reps>\n", argv[0]);
    return 2;
  }
  const long units = units_of(argv[1]), reps = std::atol(argv[3]);
  if (std::strncmp(argv[1], "lit16", 5) == 0) {
    const sb::simd::LitSpanFn fn = find_lit_variant(argv[2]);
    if (!fn || reps < 0) {
      std::fprintf(stderr, "unknown variant (or unsupported here): %s %s\n", argv[1], argv[2]);
      return 2;
    }
    std::printf("%s %s %ld %08x\n", argv[1], argv[2], units, run_lit(fn, reps, argv[1][5] == 'm'));
    return 0;
  }
  const Kernels* k = find_variant(argv[2]);
  if (!k || units == 0 || reps < 0) {
    std::fprintf(stderr, "unknown case or variant (or unsupported here): %s %s\n", argv[1], argv[2]);
    return 2;
  }
  const uint32_t sum = run_case(argv[1], *k, reps);
  std::printf("%s %s %ld %08x\n", argv[1], argv[2], units, sum);
  return 0;
}
