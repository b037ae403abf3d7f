// asm/surface_block_x86.h: internal to asm/: the x86 surface block builder, shared by
// asm/sse2.cpp (SSE2) and asm/avx2.cpp (the same source compiled with -mavx2: VEX encoding).
// Include it inside an anonymous namespace after <emmintrin.h> and <cstring>, and after
// asm/variants.h (wrap, kMaxBlockColumns, surface_block_scalar): each file gets its own
// internal copy, so the AVX2 instance can never stand in for the SSE2 one at link time.
//
// As the NEON builder (asm/neon.cpp, section 2): sixteen lanes (16 >> LB blocks side by side)
// walked down their B rows, the light numerators in 32-bit lanes scaled by 4^mip so that the
// colormap row is byte 2 of every lane, stepped by one vector add per four texels and row
// (mip 3: unscaled, in 16-bit lanes, one add per eight texels). The lanes' first numerators
// come from pmaddwd of grid pairs (g00, g10) with weight pairs (B - fx, fx). The rows, packed
// to bytes and interleaved with the texels, make sixteen 16-bit indices row << 8 | texel,
// stored to the stack and read back (four from a register); the sixteen colormap loads are
// independent and are packed into two 64-bit stores.

// dst[x] = row[(c0 + x) mod tw] for x < n (a multiple of 16); writes up to n + 15 (and at
// least 32 bytes must be writable). Narrow textures (tw < 16): 16-byte copies of the row every
// tw bytes up to 32, then 16-byte copies from one period (the first multiple of tw >= 16) back.
inline void tile_row(uint8_t* dst, const uint8_t* row, int tw, int c0, int n, const uint8_t* tex_end) {
  int d;  // a period of the run, >= 16
  if (tw >= 16) {
    const int a = tw - c0 < n ? tw - c0 : n;
    std::memcpy(dst, row + c0, size_t(a));
    if (a < n) std::memcpy(dst + a, row, size_t(c0 < n - a ? c0 : n - a));
    d = tw;
  } else {
    d = tw;
    while (d < 16) d += tw;  // (no divide); at most 30
    __m128i tmp[3];  // the row, when reading 16 + tw bytes from it would pass tex_end
    if (row + tw + 16 > tex_end) {
      tmp[0] = tmp[1] = tmp[2] = _mm_setzero_si128();
      std::memcpy(tmp, row, size_t(tw));
      row = reinterpret_cast<const uint8_t*>(tmp);
    }
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(dst), _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + c0)));
    for (int p = tw - c0; p < 32; p += tw) _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + p), v);
    for (int x = 32; x < n; x += 16)
      _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + x), _mm_loadu_si128(reinterpret_cast<const __m128i*>(dst + x - d)));
    return;
  }
  for (int x = d; x < n; x += 16)
    _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + x), _mm_loadu_si128(reinterpret_cast<const __m128i*>(dst + x - d)));
}

// i mod n (positive): without a divide when i is in -n .. 2n - 1.
inline int wrap_near(int i, int n) {
  if (unsigned(i) < unsigned(n)) return i;
  if (i < 0 && i >= -n) return i + n;
  if (i >= n && i - n < n) return i - n;
  return wrap(i, n);
}

// The colormap base sits in r12 for both lookups: left free, GCC may copy it through a
// temporary of the row before, which costs nothing on hardware but reads as a chain from one
// row to the next to llvm-mca (it times each block as a loop of itself).
//
// Bytes 4..7 of pack8 / pack8m: indices q[4 .. 7] from memory (operands m4 .. m7).
#define SB_PACK8_HIGH \
  "movzwl %[m4], %k[a]\n\t" \
  "movzwl %[m5], %k[b]\n\t" \
  "movzbl (%[cm],%[a]), %k[a]\n\t" \
  "movzbl (%[cm],%[b]), %k[b]\n\t" \
  "shl $32, %[a]\n\t" \
  "shl $40, %[b]\n\t" \
  "or %[a], %[v]\n\t" \
  "or %[b], %[v]\n\t" \
  "movzwl %[m6], %k[a]\n\t" \
  "movzwl %[m7], %k[b]\n\t" \
  "movzbl (%[cm],%[a]), %k[a]\n\t" \
  "movzbl (%[cm],%[b]), %k[b]\n\t" \
  "shl $48, %[a]\n\t" \
  "shl $56, %[b]\n\t" \
  "or %[a], %[v]\n\t" \
  "or %[b], %[v]"

// colormap[q[0]] | colormap[q[1]] << 8 | ... | colormap[q[7]] << 56, with q[0 .. 3] given in qa
// (four 16-bit fields) and q[4 .. 7] read from memory: the load ports and the ALUs share the
// work. In asm (scalar only: the same for the SSE2 and the AVX2 instance) because GCC would
// extract every index from the vector that stored it (pextrw: more uops than a load each).
inline uint64_t pack8(const uint8_t* cm, uint64_t qa, const uint16_t* q) {
  register const uint8_t* const cmr asm("r12") = cm;  // (r12: see above)
  uint64_t v, a, b;
  asm(
      "movzwl %w[qa], %k[a]\n\t"
      "mov %k[qa], %k[b]\n\t"
      "shr $16, %k[b]\n\t"
      "shr $32, %[qa]\n\t"
      "movzbl (%[cm],%[a]), %k[v]\n\t"
      "movzbl (%[cm],%[b]), %k[b]\n\t"
      "movzwl %w[qa], %k[a]\n\t"
      "shr $16, %k[qa]\n\t"
      "shl $8, %k[b]\n\t"
      "or %k[b], %k[v]\n\t"
      "movzbl (%[cm],%[a]), %k[a]\n\t"
      "movzbl (%[cm],%[qa]), %k[b]\n\t"
      "shl $16, %k[a]\n\t"
      "shl $24, %k[b]\n\t"
      "or %k[a], %k[v]\n\t"
      "or %k[b], %k[v]\n\t"
      SB_PACK8_HIGH
      : [v] "=&r"(v), [a] "=&r"(a), [b] "=&r"(b), [qa] "+r"(qa)
      : [cm] "r"(cmr), [m4] "m"(q[4]), [m5] "m"(q[5]), [m6] "m"(q[6]), [m7] "m"(q[7]));
  return v;
}

// The same with all eight indices read from memory, the first two by one 32-bit load (one
// load fewer, two ALU operations more).
inline uint64_t pack8m(const uint8_t* cm, const uint16_t* q) {
  register const uint8_t* const cmr asm("r12") = cm;
  uint64_t v, a, b;
  asm("mov %[p0], %k[a]\n\t"
      "movzwl %w[a], %k[b]\n\t"
      "shr $16, %k[a]\n\t"
      "movzbl (%[cm],%[b]), %k[v]\n\t"
      "movzbl (%[cm],%[a]), %k[a]\n\t"
      "shl $8, %k[a]\n\t"
      "or %k[a], %k[v]\n\t"
      "movzwl %[m2], %k[a]\n\t"
      "movzwl %[m3], %k[b]\n\t"
      "movzbl (%[cm],%[a]), %k[a]\n\t"
      "movzbl (%[cm],%[b]), %k[b]\n\t"
      "shl $16, %k[a]\n\t"
      "shl $24, %k[b]\n\t"
      "or %k[a], %k[v]\n\t"
      "or %k[b], %k[v]\n\t"
      SB_PACK8_HIGH
      : [v] "=&r"(v), [a] "=&r"(a), [b] "=&r"(b)
      : [cm] "r"(cmr), [p0] "m"(*reinterpret_cast<const uint16_t(*)[2]>(q + 0)), [m2] "m"(q[2]), [m3] "m"(q[3]), [m4] "m"(q[4]), [m5] "m"(q[5]), [m6] "m"(q[6]), [m7] "m"(q[7]));
  return v;
}

#undef SB_PACK8_HIGH

constexpr int kTileBytes = 16 * (kMaxBlockColumns * 16 + 32);  // B runs of the widest surface

constexpr int kMaxRuns = 2064;  // run pointers: >= kTileBytes / (smallest stride, 32)

// A group's sixteen lanes of one grid row as pmaddwd pairs (g[b], g[b + 1]), quarter j = lanes
// 4j .. 4j + 3; b = the group's first block. Reads g[b .. b + 8] at most (G + 1 entries).
template <int LB>
inline __m128i grid_pairs(const uint16_t* g, int j) {
  if constexpr (LB == 1) {
    const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(g));
    const __m128i c = _mm_loadu_si128(reinterpret_cast<const __m128i*>(g + 1));
    const __m128i p = j < 2 ? _mm_unpacklo_epi16(a, c) : _mm_unpackhi_epi16(a, c);  // blocks 4(j/2) ..
    return j % 2 == 0 ? _mm_unpacklo_epi32(p, p) : _mm_unpackhi_epi32(p, p);
  } else {
    uint32_t v;
    std::memcpy(&v, g + ((4 * j) >> LB), 4);
    return _mm_set1_epi32(int32_t(v));
  }
}

// Mip 3 (B = 2, eight blocks per sixteen lanes): lanes (2b, 2b + 1) get (2 g[b], g[b] + g[b + 1]),
// the grid row's share (B - fx) g[b] + fx g[b + 1] of the numerator, in 16-bit lanes (at most
// 2 * 0x3fff). Reads g[0 .. 8].
inline void edge_sums(const uint16_t* g, __m128i* s) {
  const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(g));
  const __m128i c = _mm_loadu_si128(reinterpret_cast<const __m128i*>(g + 1));
  s[0] = _mm_add_epi16(_mm_unpacklo_epi16(a, a), _mm_unpacklo_epi16(a, c));
  s[1] = _mm_add_epi16(_mm_unpackhi_epi16(a, a), _mm_unpackhi_epi16(a, c));
}

struct Strip {
  const uint16_t* grid;
  const uint8_t* const* run;  // run[first] is the strip's first row; run[] wraps at count
  const uint8_t* colormap;
  uint8_t* out;  // the strip's first row
  int grid_width, bw, by0, nb, first, count, width;
};

// Lanes k = 4j + i: weight pairs (B - fx, fx) << s.
template <int B>
inline __m128i weights(int j, int s) {
  auto pat = [s](int k) { return int32_t((B - k % B) << s | (k % B) << (16 + s)); };
  return _mm_setr_epi32(pat(4 * j), pat(4 * j + 1), pat(4 * j + 2), pat(4 * j + 3));
}

// One strip: nb bands from grid row by0, the groups of sixteen lanes (G blocks) one after the
// other down the strip. kWide: width >= 16; the last group then overlaps the one before it
// (its texels made twice, the same) so that every group has sixteen lanes on the surface and
// its G + 1 grid entries in each row (grid_width > width / B). Else (width < 16) one group,
// through part[] and pad[].
template <int kMip, bool kWide>
__attribute__((always_inline)) inline void strip_body(const Strip& job) {
  constexpr int B = 16 >> kMip, LB = 4 - kMip, G = 16 / B;
  const uint16_t* const grid = job.grid;
  const uint8_t* const* const run = job.run;
  const uint8_t* __restrict const colormap = job.colormap;
  uint8_t* __restrict const strip = job.out;
  const int grid_width = job.grid_width, bw = job.bw, by0 = job.by0, nb = job.nb, first = job.first,
            count = job.count, width = job.width;
  // Weight pairs << (4 + mip) for the first numerator (the scaled B T, at most 256 per weight:
  // pmaddwd's signed factors stay exact) and << 2 mip for the row steps (U - T, then each next
  // grid row's difference).
  const __m128i A0[4] = {weights<B>(0, 4 + kMip), weights<B>(1, 4 + kMip), weights<B>(2, 4 + kMip),
                         weights<B>(3, 4 + kMip)};
  const __m128i A1[4] = {weights<B>(0, 2 * kMip), weights<B>(1, 2 * kMip), weights<B>(2, 2 * kMip),
                         weights<B>(3, 2 * kMip)};
  uint16_t pad[24];             // narrow: the grid entries, zero padded (never read past a grid row)
  alignas(16) uint16_t ix[16];  // a row's colormap indices
  alignas(16) uint8_t part[16 * B];  // narrow: a band
  for (int col = 0;; col += 16) {
    if (kWide && col > width - 16) col = width - 16;
    const int b0 = col >> LB;
    uint8_t* d = strip + col;
    auto entries = [&](const uint16_t* r) -> const uint16_t* {  // a grid row from the group's first block
      if (kWide || G + 1 <= grid_width) return r;
      for (int i = 0; i < 24; ++i) pad[i] = i <= bw ? r[i] : 0;
      return pad;
    };
    const uint16_t* gr = grid + by0 * grid_width + b0;
    // Mip 3: numerators unscaled (at most 4 * 0x3fff) in 16-bit lanes, two vectors; the
    // colormap row is num >> 10. Else four vectors of 32-bit lanes (see above).
    __m128i num[4], delta[4], prev[4];
    {
      const uint16_t* r0 = entries(gr);
      if constexpr (kMip == 3) {
        edge_sums(r0, prev);
        num[0] = _mm_slli_epi16(prev[0], 1);
        num[1] = _mm_slli_epi16(prev[1], 1);
      } else {
        for (int j = 0; j < 4; ++j) {
          const __m128i e = grid_pairs<LB>(r0, j);
          num[j] = _mm_madd_epi16(e, A0[j]);
          prev[j] = _mm_madd_epi16(e, A1[j]);
        }
      }
    }
    int k = first;  // first, count and the strip's rows are multiples of B: run[] wraps between bands
    for (int band = 0; band < nb; ++band) {
      gr += grid_width;
      const uint16_t* r1 = entries(gr);
      if constexpr (kMip == 3) {  // this band's row step; num continues from the last band
        __m128i next[2];
        edge_sums(r1, next);
        for (int j = 0; j < 2; ++j) {
          delta[j] = _mm_sub_epi16(next[j], prev[j]);
          prev[j] = next[j];
        }
      } else {
#pragma GCC unroll 4
        for (int j = 0; j < 4; ++j) {
          const __m128i next = _mm_madd_epi16(grid_pairs<LB>(r1, j), A1[j]);
          delta[j] = _mm_sub_epi32(next, prev[j]);
          prev[j] = next;
        }
      }
      if (k == count) k = 0;
      const uint8_t* const* rr = run + k;
      k += B;
      uint8_t* dst = kWide ? d : part;
      const int step = kWide ? width : 16;
      auto row = [&](const uint8_t* src) {
        const __m128i t = _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + col));
        // Rows (byte 2 of every lane, nothing above; mip 3: num >> 10) packed to bytes,
        // interleaved with the texels: sixteen 16-bit indices, stored and read back one at a time.
        __m128i r;
        if constexpr (kMip == 3) {
          r = _mm_packus_epi16(_mm_srli_epi16(num[0], 10), _mm_srli_epi16(num[1], 10));
          num[0] = _mm_add_epi16(num[0], delta[0]);
          num[1] = _mm_add_epi16(num[1], delta[1]);
        } else {
          r = _mm_packus_epi16(_mm_packs_epi32(_mm_srli_epi32(num[0], 16), _mm_srli_epi32(num[1], 16)),
                               _mm_packs_epi32(_mm_srli_epi32(num[2], 16), _mm_srli_epi32(num[3], 16)));
#pragma GCC unroll 4
          for (int j = 0; j < 4; ++j) num[j] = _mm_add_epi32(num[j], delta[j]);
        }
        const __m128i i0 = _mm_unpacklo_epi8(t, r), i1 = _mm_unpackhi_epi8(t, r);
        _mm_store_si128(reinterpret_cast<__m128i*>(ix), i0);
        _mm_store_si128(reinterpret_cast<__m128i*>(ix + 8), i1);
        const uint64_t w0 = pack8(colormap, uint64_t(_mm_cvtsi128_si64(i0)), ix), w1 = pack8m(colormap, ix + 8);
        std::memcpy(dst, &w0, 8);
        std::memcpy(dst + 8, &w1, 8);
        dst += step;
      };
      for (int fy = 0; fy < B; ++fy) row(rr[fy]);
      if (!kWide)
        for (int fy = 0; fy < B; ++fy) std::memcpy(d + fy * width, part + 16 * fy, size_t(width));
      d += B * width;
    }
    if (!kWide || col + 16 >= width) break;
  }
}

// The strip functions: small and aligned so that their loops never straddle a page (the
// instruction counter splits blocks there; the loops are the same either way).
template <int kMip>
__attribute__((noinline, aligned(2048))) void block_strip(const Strip& job) {
  strip_body<kMip, true>(job);
}

template <int kMip>
__attribute__((noinline)) void block_strip_narrow(const Strip& job) {
  strip_body<kMip, false>(job);
}

template <int kMip>
void surface_block_groups(const uint16_t* grid, int grid_width, const uint8_t* texels, int tw, int th, int soff,
                          int toff, int width, int height, const uint8_t* __restrict colormap,
                          uint8_t* __restrict out) {
  constexpr int B = 16 >> kMip;
  const int bw = width / B, bh = height / B;
  const int n16 = (width + 15) & ~15, stride = n16 + 16;
  const int c0 = wrap_near(soff, tw), t0 = wrap_near(toff, th);
  alignas(16) uint8_t buf[kTileBytes];  // 64 KiB of stack
  const uint8_t* run[kMaxRuns];         // texel run of each row (cyclic, see below)
  const uint8_t* const tex_end = texels + tw * th;
  auto in_place = [&](int t) { return c0 + width <= tw && texels + t * tw + c0 + n16 <= tex_end; };
  // Rows repeat every th: when the texture is shorter than the surface and all its rows fit,
  // they are laid out once and the whole surface is one strip reading run[] cyclically from
  // t0. Else strips of as many bands as the buffer holds, their rows laid out per strip.
  const bool all_rows = th < height && th * stride <= kTileBytes && th <= kMaxRuns;
  if (all_rows)
    for (int t = 0; t < th; ++t)
      run[t] = in_place(t) ? texels + t * tw + c0 : (tile_row(buf + t * stride, texels + t * tw, tw, c0, n16, tex_end),
                                                     buf + t * stride);
  int strip_bands = bh;
  if (!all_rows) {
    const int fit = (kTileBytes / stride < kMaxRuns ? kTileBytes / stride : kMaxRuns) / B;  // >= 1
    strip_bands = fit < bh ? fit : bh;
  }

  for (int by0 = 0; by0 < bh; by0 += strip_bands) {
    const int nb = bh - by0 < strip_bands ? bh - by0 : strip_bands;
    int first = 0, count = th;  // run[first] is the strip's first row; run[] wraps at count
    if (all_rows) {
      first = wrap_near(t0 + by0 * B, th);
    } else {
      count = nb * B;
      int t = wrap_near(t0 + by0 * B, th);
      for (int r = 0; r < count; ++r) {
        run[r] = in_place(t) ? texels + t * tw + c0
                             : (tile_row(buf + r * stride, texels + t * tw, tw, c0, n16, tex_end),
                                buf + r * stride);
        if (++t == th) t = 0;
      }
    }
    const Strip job{grid, run, colormap, out + by0 * B * width, grid_width, bw, by0, nb, first, count, width};
    if (width >= 16)
      block_strip<kMip>(job);
    else
      block_strip_narrow<kMip>(job);
  }
}

inline void surface_block_x86(const uint16_t* grid, int grid_width, const uint8_t* texels, int tex_width,
                              int tex_height, int mip, int soff, int toff, int width, int height,
                              const uint8_t* colormap, uint8_t* out) {
  if (width <= 0 || height <= 0) return;
  if (mip < 0 || mip > 3 || (width >> (4 - mip)) > kMaxBlockColumns) {
    surface_block_scalar(grid, grid_width, texels, tex_width, tex_height, mip, soff, toff, width, height, colormap,
                         out);
    return;
  }
  switch (mip) {
    case 0: return surface_block_groups<0>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    case 1: return surface_block_groups<1>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    case 2: return surface_block_groups<2>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    default: return surface_block_groups<3>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
  }
}
