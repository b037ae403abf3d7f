// Differential tests of every asm/ kernel variant the CPU supports against the scalar
// reference, on random and edge inputs: span lengths 0, 1, 15, 16, 17 and 1920, texture
// wrap (negative and large offsets, non-power-of-two sizes), extreme gradients and light,
// every mip level. Each test prints which variants ran and which it skipped (CPU lacks).
// Buffers are exactly sized (AddressSanitizer sees scalar over-reads) and destinations carry
// guard bytes (no variant may write outside its output).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "asm/kernels.h"

namespace {

using sb::simd::Kernels;

// The supported non-scalar variants; prints one line per variant (ran or skipped).
std::vector<const Kernels*> tuned_variants(const char* kernel) {
  std::vector<const Kernels*> out;
  for (int i = 1; i < sb::simd::variant_count(); ++i) {
    const sb::simd::Variant v = sb::simd::variant(i);
    if (!v.kernels) continue;
    if (v.supported) {
      std::printf("[ asm      ] %s: variant %s runs\n", kernel, v.kernels->name);
      out.push_back(v.kernels);
    } else {
      std::printf("[ asm      ] %s: variant %s SKIPPED (this CPU lacks it)\n", kernel, v.kernels->name);
    }
  }
  return out;
}

constexpr int kGuard = 64;
constexpr uint8_t kGuardByte = 0xa5;

// ---------------------------------------------------------------- surface span

struct SpanCase {
  int n, width, height;
  int32_t u, v, du, dv, ddu, ddv;
};

// All u_k, v_k of the case within the surface (the kernel's contract)?
bool span_valid(const SpanCase& c) {
  int64_t u = c.u, v = c.v, du = c.du, dv = c.dv;
  const int64_t umax = (int64_t(c.width) << 16) - 1, vmax = (int64_t(c.height) << 16) - 1;
  for (int k = 0; k < c.n; ++k) {
    if (u < 0 || u > umax || v < 0 || v > vmax) return false;
    u += du;
    v += dv;
    du += c.ddu;
    dv += c.ddv;
  }
  return true;
}

// Steps from a to b over n - 1 pixels, with a random second-order term when it stays valid
// (otherwise linear, which always is).
void make_steps(std::mt19937& rng, int n, int32_t a, int32_t b, int32_t* d, int32_t* dd, bool curve) {
  const int steps = n > 1 ? n - 1 : 1;
  *d = int32_t((int64_t(b) - int64_t(a)) / steps);
  *dd = 0;
  if (!curve || n < 3) return;
  const int64_t delta = int64_t(b) - int64_t(a);
  std::uniform_real_distribution<double> bend(-1.0, 1.0);
  const double c = bend(rng) * 2.0 / steps;
  const int64_t dd2 = int64_t(-2.0 * double(delta) / steps * c / steps);
  const int64_t d0 = (delta - dd2 * steps * (steps - 1) / 2) / steps;
  if (d0 > INT32_MAX || d0 < INT32_MIN || dd2 > INT32_MAX || dd2 < INT32_MIN) return;
  *d = int32_t(d0);
  *dd = int32_t(dd2);
}

SpanCase random_span(std::mt19937& rng, int n, int width, int height, bool curve) {
  std::uniform_int_distribution<int64_t> ur(0, (int64_t(width) << 16) - 1), vr(0, (int64_t(height) << 16) - 1);
  SpanCase c{n, width, height, 0, 0, 0, 0, 0, 0};
  for (int attempt = 0; attempt < 8; ++attempt) {
    c.u = int32_t(ur(rng));
    c.v = int32_t(vr(rng));
    const int32_t u1 = int32_t(ur(rng)), v1 = int32_t(vr(rng));
    make_steps(rng, n, c.u, u1, &c.du, &c.ddu, curve);
    make_steps(rng, n, c.v, v1, &c.dv, &c.ddv, curve);
    if (span_valid(c)) return c;
    make_steps(rng, n, c.u, u1, &c.du, &c.ddu, false);
    make_steps(rng, n, c.v, v1, &c.dv, &c.ddv, false);
    if (span_valid(c)) return c;
  }
  return SpanCase{n, width, height, 0, 0, 0, 0, 0, 0};
}

// Runs `c` through the reference and the variant, comparing the n bytes and the guards.
void check_span(const Kernels& k, const SpanCase& c, const std::vector<uint8_t>& texels, const char* what) {
  std::vector<uint8_t> want(size_t(c.n) + 2 * kGuard, kGuardByte), got(want);
  sb::simd::surface_span_scalar(want.data() + kGuard, c.n, texels.data(), c.width, c.height, c.u, c.v, c.du, c.dv,
                                c.ddu, c.ddv);
  k.surface_span(got.data() + kGuard, c.n, texels.data(), c.width, c.height, c.u, c.v, c.du, c.dv, c.ddu, c.ddv);
  ASSERT_EQ(want, got) << k.name << " " << what << ": n " << c.n << " surface " << c.width << "x" << c.height
                       << " u " << c.u << " v " << c.v << " du " << c.du << " dv " << c.dv << " ddu " << c.ddu
                       << " ddv " << c.ddv;
}

std::vector<uint8_t> random_bytes(std::mt19937& rng, size_t n) {
  std::vector<uint8_t> b(n);
  for (auto& x : b) x = uint8_t(rng());
  return b;
}

TEST(AsmSurfaceSpan, EveryVariantMatchesScalar) {
  std::mt19937 rng(1234);
  const int lengths[] = {0, 1, 2, 3, 7, 8, 9, 15, 16, 17, 31, 32, 33, 320, 1919, 1920};
  struct Size {
    int w, h;
  };
  const Size sizes[] = {{1, 1}, {2, 2}, {1, 4}, {4, 1}, {3, 7}, {16, 16}, {2, 64}, {64, 2}, {33, 17}, {128, 64},
                        {512, 512}, {4096, 8}, {8, 4096}};
  int cases = 0, curved = 0;
  for (const Kernels* k : tuned_variants("surface_span")) {
    for (const Size& s : sizes) {
      const std::vector<uint8_t> texels = random_bytes(rng, size_t(s.w) * size_t(s.h));
      for (int n : lengths) {
        for (int rep = 0; rep < 6; ++rep) {
          const SpanCase c = random_span(rng, n, s.w, s.h, rep % 2 == 1);
          check_span(*k, c, texels, "random");
          ++cases;
          curved += c.ddu != 0 || c.ddv != 0;
        }
        // Extreme gradients: corner to corner in one step, the whole surface per pixel,
        // standing still, and the last texel (the gathers' clamped read).
        const int32_t umax = (s.w << 16) - 1, vmax = (s.h << 16) - 1;
        SpanCase c{n, s.w, s.h, 0, 0, 0, 0, 0, 0};
        make_steps(rng, n, 0, umax, &c.du, &c.ddu, false);
        make_steps(rng, n, vmax, 0, &c.dv, &c.ddv, false);
        c.v = vmax;
        check_span(*k, c, texels, "corner to corner");
        check_span(*k, SpanCase{n, s.w, s.h, umax, vmax, 0, 0, 0, 0}, texels, "last texel");
        check_span(*k, SpanCase{n, s.w, s.h, umax, 0, n > 1 ? -umax / (n - 1) : 0, 0, 0, 0}, texels, "backwards");
        // A strongly bending second-order walk: steps shrink to zero over the span.
        if (n > 2) {
          SpanCase b{n, s.w, s.h, 0, 0, 0, 0, 0, 0};
          const int64_t steps = n - 1;
          const int64_t dd = -int64_t(umax) * 2 / (steps * steps);
          b.ddu = int32_t(dd);
          b.du = int32_t(-dd * (steps - 1));
          if (span_valid(b)) {
            check_span(*k, b, texels, "bending");
            ++curved;
          }
        }
        cases += 4;
      }
    }
  }
  std::printf("[ asm      ] surface_span: %d cases compared (%d with a second-order term)\n", cases, curved);
  EXPECT_GT(curved, cases / 8);
}

// ---------------------------------------------------------------- surface block builder

struct BlockCase {
  int mip, width, height, tw, th, soff, toff, grid_width;
};

// The closed form of asm/surface_block.h, independent of both implementations.
uint8_t closed_form(const BlockCase& c, const std::vector<uint16_t>& grid, const std::vector<uint8_t>& tex,
                    const std::vector<uint8_t>& cm, int x, int y) {
  const int b = 16 >> c.mip, s = 2 * (4 - c.mip);
  const int gx = x / b, fx = x % b, gy = y / b, fy = y % b;
  auto g = [&](int dx, int dy) { return int64_t(grid[size_t((gy + dy) * c.grid_width + gx + dx)]); };
  const int64_t num = (g(0, 0) * (b - fx) + g(1, 0) * fx) * (b - fy) + (g(0, 1) * (b - fx) + g(1, 1) * fx) * fy;
  auto pmod = [](int i, int n) { return ((i % n) + n) % n; };
  const uint8_t t = tex[size_t(pmod(y + c.toff, c.th) * c.tw + pmod(x + c.soff, c.tw))];
  return cm[size_t(((num >> s) & 0xff00) + t)];
}

enum class Light { kRandom, kBrightest, kDarkest, kZero, kAlternating, kSmooth };

void check_block(const Kernels* k, std::mt19937& rng, const BlockCase& c, Light light, bool closed) {
  const int b = 16 >> c.mip;
  const int gh = c.height / b + 1;
  std::vector<uint16_t> grid(size_t(c.grid_width) * size_t(gh));
  for (size_t i = 0; i < grid.size(); ++i) {
    switch (light) {
      case Light::kRandom: grid[i] = uint16_t(rng() % 0x4000); break;
      case Light::kBrightest: grid[i] = 0; break;
      case Light::kDarkest: grid[i] = 0x3fff; break;
      case Light::kZero: grid[i] = 64; break;
      case Light::kAlternating: grid[i] = (i % 2) ? 0x3fff : 0; break;
      case Light::kSmooth: grid[i] = uint16_t(64 + (i * 37) % 0x3f00); break;
    }
  }
  const std::vector<uint8_t> tex = random_bytes(rng, size_t(c.tw) * size_t(c.th));
  const std::vector<uint8_t> cm = random_bytes(rng, 64 * 256);
  const size_t size = size_t(c.width) * size_t(c.height);
  std::vector<uint8_t> want(size + 2 * kGuard, kGuardByte);
  sb::simd::surface_block_scalar(grid.data(), c.grid_width, tex.data(), c.tw, c.th, c.mip, c.soff, c.toff, c.width,
                                 c.height, cm.data(), want.data() + kGuard);
  if (closed) {
    for (int y = 0; y < c.height; ++y)
      for (int x = 0; x < c.width; ++x)
        ASSERT_EQ(want[kGuard + size_t(y) * c.width + x], closed_form(c, grid, tex, cm, x, y))
            << "scalar reference vs closed form, mip " << c.mip << " at " << x << "," << y;
  }
  if (!k) return;
  std::vector<uint8_t> got(size + 2 * kGuard, kGuardByte);
  k->surface_block(grid.data(), c.grid_width, tex.data(), c.tw, c.th, c.mip, c.soff, c.toff, c.width, c.height,
                   cm.data(), got.data() + kGuard);
  ASSERT_EQ(want, got) << k->name << ": mip " << c.mip << " surface " << c.width << "x" << c.height << " texture "
                       << c.tw << "x" << c.th << " offsets " << c.soff << "," << c.toff << " light "
                       << int(light);
}

TEST(AsmSurfaceBlock, ScalarReferenceMatchesClosedForm) {
  std::mt19937 rng(99);
  for (int mip = 0; mip < 4; ++mip) {
    const int b = 16 >> mip;
    for (Light light : {Light::kRandom, Light::kDarkest, Light::kAlternating}) {
      const BlockCase c{mip, 96 >> mip, 48 >> mip, 64 >> mip, 32 >> mip, -3 * b, 5 * b, 96 / 16 + 3};
      check_block(nullptr, rng, c, light, true);
    }
  }
}

TEST(AsmSurfaceBlock, EveryVariantMatchesScalarEveryMip) {
  std::mt19937 rng(4321);
  int cases = 0;
  for (const Kernels* k : tuned_variants("surface_block")) {
    for (int mip = 0; mip < 4; ++mip) {
      const int b = 16 >> mip;
      // Face extents (mip 0 texels, multiples of 16) and texture sizes (multiples of 16).
      const int extents[] = {16, 32, 48, 64, 80, 128, 240, 256, 272, 1024, 4096};
      const int texsizes[] = {16, 32, 48, 64, 80, 128, 256};
      for (int ew : extents) {
        for (int rep = 0; rep < 4; ++rep) {
          const int eh = extents[rng() % 7];
          const int tw = texsizes[rng() % 7], th = texsizes[rng() % 7];
          // texture_mins: multiples of 16, negative and positive, beyond the texture size.
          const int smin = (int(rng() % 129) - 64) * 16, tmin = (int(rng() % 129) - 64) * 16;
          const BlockCase c{mip, ew >> mip, eh >> mip, tw >> mip, th >> mip, smin >> mip, tmin >> mip,
                            ew / 16 + 1 + int(rng() % 3)};
          const Light light = rep == 0 ? Light::kRandom : Light(rng() % 6);
          check_block(k, rng, c, light, false);
          ++cases;
        }
      }
      // Edge shapes: one block; one block row; one block column; texture one block wide.
      check_block(k, rng, BlockCase{mip, b, b, b, b, 0, 0, 2}, Light::kRandom, false);
      check_block(k, rng, BlockCase{mip, 4096 >> mip, b, 16 >> mip, 16 >> mip, -b, 0, 257}, Light::kRandom, false);
      check_block(k, rng, BlockCase{mip, b, 4096 >> mip, 256 >> mip, 16 >> mip, 0, -7 * b, 2}, Light::kRandom, false);
      check_block(k, rng, BlockCase{mip, 48 >> mip, 48 >> mip, b, b, 3 * b, 2 * b, 4}, Light::kAlternating, false);
      // Tall and wide (the tuned builders' texel runs then come in strips of bands), with a
      // texture taller than the surface and with one shorter but too big to lay out at once;
      // widths that are not a multiple of 16 texels at this mip.
      check_block(k, rng, BlockCase{mip, 4096 >> mip, 320 >> mip, 256 >> mip, 512 >> mip, -b, 3 * b, 257},
                  Light::kRandom, false);
      check_block(k, rng, BlockCase{mip, 4080 >> mip, 256 >> mip, 80 >> mip, 96 >> mip, 5 * b, -9 * b, 256},
                  Light::kSmooth, false);
      check_block(k, rng, BlockCase{mip, 272 >> mip, 400 >> mip, 48 >> mip, 32 >> mip, -7 * b, 11 * b, 18},
                  Light::kAlternating, false);
      cases += 3;
      // Wider than the tuned variants' block column limit: they fall back to the reference.
      check_block(k, rng, BlockCase{mip, 4352 >> mip, b, 64 >> mip, 64 >> mip, 0, 0, 273}, Light::kRandom, false);
      cases += 5;
    }
  }
  std::printf("[ asm      ] surface_block: %d cases compared\n", cases);
}

// Textures wider than 16 texels but narrower than the surface (AArch64 mips 0-2 lay out only
// a run's first tw + 15 bytes and read group g at (16 g) mod tw): widths just past 16, not
// multiples of 16 (mips 1-2), just below the surface's, rows at the texture's end.
TEST(AsmSurfaceBlock, RunsRepeatingAcrossTheSurface) {
  std::mt19937 rng(2718);
  int cases = 0;
  for (const Kernels* k : tuned_variants("surface_block")) {
    for (int mip = 0; mip < 3; ++mip) {
      const int b = 16 >> mip;
      for (int tw : {20, 24, 28, 32, 36, 40, 48, 56, 60, 64, 80, 96, 112, 240}) {
        for (int w : {2 * b, 48, 64, 80, 128, 240, 256, 272}) {
          if (w <= tw || w % b || tw % b) continue;
          const int th = b * int(1 + rng() % 6), h = b * int(1 + rng() % 6);
          const int soff = b * (int(rng() % 33) - 16), toff = b * (int(rng() % 33) - 16);
          check_block(k, rng, BlockCase{mip, w, h, tw, th, soff, toff, w / b + 1 + int(rng() % 2)}, Light(rng() % 6),
                      false);
          ++cases;
        }
      }
    }
  }
  std::printf("[ asm      ] surface_block repeating runs: %d cases compared\n", cases);
}

// Texture widths a multiple of 16 (AArch64 mips 0-2 keep such rows unrotated and read group g
// at (c0 + 16 g) mod tw: in place when c0 is a multiple of 16, else from the row laid out
// tw + 16 bytes): every column offset c0 mod 16 the contract allows, all rows at once and in strips (textures
// taller than the surface), rows at the texture's end.
TEST(AsmSurfaceBlock, UnrotatedRuns) {
  std::mt19937 rng(1618);
  int cases = 0;
  for (const Kernels* k : tuned_variants("surface_block")) {
    for (int mip = 0; mip < 3; ++mip) {
      const int b = 16 >> mip;
      for (int tw : {32, 48, 64, 128}) {
        for (int w : {48, 80, 144, 256, 272}) {
          if (w % b) continue;
          const int soff = b * (int(rng() % 25) - 12), toff = b * (int(rng() % 25) - 12);
          const int h = b * int(1 + rng() % 5), th = rng() % 2 ? 2 * h + b : b * int(1 + rng() % 4);
          check_block(k, rng, BlockCase{mip, w, h, tw, th, soff, toff, w / b + 1 + int(rng() % 2)}, Light(rng() % 6),
                      false);
          ++cases;
        }
      }
    }
  }
  std::printf("[ asm      ] surface_block unrotated runs: %d cases compared\n", cases);
}

// Mip 3 has its own AArch64 function (asm/neon_block_mip3.h): bands rotate through three
// loop copies and an entry copy (1..7 bands), a last partial group (widths not a multiple of
// 16), grid reads clamped to the last row, texel rows laid out 16 bytes wide (power-of-two
// widths up to 16, repeating or not), n16 wide (other widths) or read in place, rows at the
// texture's end, and shapes it leaves to the general builder (taller than 512 rows).
TEST(AsmSurfaceBlock, Mip3EdgeShapes) {
  std::mt19937 rng(3303);
  int cases = 0;
  for (const Kernels* k : tuned_variants("surface_block")) {
    for (int bh = 1; bh <= 7; ++bh) {
      for (int w : {2, 6, 14, 16, 18, 30, 32, 34, 48, 64, 510, 512}) {
        for (int tw : {2, 4, 6, 8, 10, 16, 18, 24, 32, 64}) {
          const int th = 2 * int(1 + rng() % 10);
          const int soff = 2 * (int(rng() % 65) - 32), toff = 2 * (int(rng() % 65) - 32);
          const BlockCase c{3, w, 2 * bh, tw, th, soff, toff, w / 2 + 1 + int(rng() % 2)};
          check_block(k, rng, c, Light(rng() % 6), false);
          ++cases;
        }
      }
    }
    // In place (no wrap, texture wider than the surface), tall surfaces, too tall (fallback).
    check_block(k, rng, BlockCase{3, 32, 64, 64, 8, 0, 6, 17}, Light::kRandom, false);
    check_block(k, rng, BlockCase{3, 40, 96, 128, 128, 16, 2, 21}, Light::kRandom, false);
    check_block(k, rng, BlockCase{3, 48, 512, 8, 16, -2, 4, 25}, Light::kSmooth, false);
    check_block(k, rng, BlockCase{3, 16, 514, 8, 8, 2, 0, 9}, Light::kRandom, false);
    check_block(k, rng, BlockCase{3, 512, 64, 14, 6, 4, -6, 257}, Light::kAlternating, false);
    cases += 5;
  }
  std::printf("[ asm      ] surface_block mip 3: %d cases compared\n", cases);
}

// AArch64 neon_a53's lean mip-3 path (asm/neon_block_mip3l.h): texture widths 2..16 and
// heights 2..64 powers of two (the rows laid out once, the band loop's row offset wrapping at
// the texture's end, started at any row), surface widths a multiple of 16 (one group and
// several), band counts around the loop's three copies and taller than the texture; and the
// shapes just outside it (texture of 8 texels, 128 rows, 12 rows, 6 wide).
TEST(AsmSurfaceBlock, Mip3PowerOfTwoTextures) {
  std::mt19937 rng(8088);
  int cases = 0;
  for (const Kernels* k : tuned_variants("surface_block")) {
    for (int tw : {2, 4, 8, 16}) {
      for (int th : {2, 4, 8, 16, 32, 64}) {
        for (int w : {16, 32, 48, 512}) {
          for (int h : {2, 4, 6, 8, 14, 16, 34, 130}) {
            if (rng() % 3 && h > 8 && w > 32) continue;
            const int soff = 2 * (int(rng() % 129) - 64), toff = 2 * (int(rng() % 129) - 64);
            check_block(k, rng, BlockCase{3, w, h, tw, th, soff, toff, w / 2 + 1 + int(rng() % 2)}, Light(rng() % 6),
                        false);
            ++cases;
          }
        }
      }
    }
    check_block(k, rng, BlockCase{3, 32, 32, 2, 4, 2, -2, 17}, Light::kRandom, false);
    check_block(k, rng, BlockCase{3, 32, 40, 8, 128, -6, 90, 17}, Light::kRandom, false);
    check_block(k, rng, BlockCase{3, 48, 40, 8, 12, 6, -10, 25}, Light::kSmooth, false);
    check_block(k, rng, BlockCase{3, 32, 20, 6, 8, 4, 2, 17}, Light::kAlternating, false);
    cases += 4;
  }
  std::printf("[ asm      ] surface_block mip 3, power-of-two textures: %d cases compared\n", cases);
}

// AArch64 neon_a53's fast mip-3 block (asm/neon_block_mip3l.h): textures 8 wide and 2, 4 or 8
// tall (rows laid out by register offsets, repeating every th rows), every row and column
// offset, one group and several, widths at the lean path's limit (512) and just past it.
TEST(AsmSurfaceBlock, Mip3EightWideTextures) {
  std::mt19937 rng(6464);
  int cases = 0;
  for (const Kernels* k : tuned_variants("surface_block")) {
    for (int th : {2, 4, 8}) {
      for (int toff = 0; toff < 2 * th; toff += 2) {
        for (int soff = -8; soff < 8; soff += 2) {
          const int ws[] = {16, 32, 80, 512, 528};
          const int hs[] = {2, 4, 6, 32, 34};
          const int w = ws[rng() % 5], h = hs[rng() % 5];
          check_block(k, rng, BlockCase{3, w, h, 8, th, soff, toff - th, w / 2 + 1 + int(rng() % 2)},
                      Light(rng() % 6), false);
          ++cases;
        }
      }
    }
  }
  std::printf("[ asm      ] surface_block mip 3, 8-wide textures: %d cases compared\n", cases);
}

// AArch64 neon_a53's lean mip-2 path (asm/neon_block_mip2l.h): textures 4, 8, 16 and 32 wide
// (32: even and odd groups read different windows), any height (rows laid out once in surface
// order: repeating, shorter and taller than the surface, heights not a power of two), every row
// offset, surface widths a multiple of 16 (one group and several), heights up to its limit (512)
// and past it, the grid table's limit; and the shapes next to it (12 and 64 wide, widths not a
// multiple of 16: the general builder).
TEST(AsmSurfaceBlock, Mip2LeanPath) {
  std::mt19937 rng(2442);
  int cases = 0;
  for (const Kernels* k : tuned_variants("surface_block")) {
    for (int tw : {4, 8, 12, 16, 32, 64}) {
      for (int th : {4, 8, 12, 16, 20, 32, 64, 128}) {
        for (int w : {16, 32, 48, 64, 68, 80}) {
          for (int h : {4, 8, 12, 16, 20, 64, 68}) {
            if (rng() % 3 && (h > 16 || w > 48)) continue;
            const int soff = 4 * (int(rng() % 65) - 32), toff = 4 * (int(rng() % 65) - 32);
            check_block(k, rng, BlockCase{2, w, h, tw, th, soff, toff, w / 4 + 1 + int(rng() % 3)}, Light(rng() % 6),
                        false);
            ++cases;
          }
        }
      }
      for (int toff = 0; toff < 32; toff += 4) {  // every row offset of a 16- and a 32-row texture
        check_block(k, rng, BlockCase{2, 64, 64, tw, 16, 4 * int(rng() % 8), toff - 16, 17}, Light::kRandom, false);
        check_block(k, rng, BlockCase{2, 32, 40, tw, 32, -4, toff, 9}, Light::kSmooth, false);
        cases += 2;
      }
    }
    // Tall (the lean path's 512 rows, then 516: the general builder), wide (the table's limit:
    // (h / 4 + 3) w <= 16384 bytes, then past it), a 4-row texture under a tall surface.
    check_block(k, rng, BlockCase{2, 16, 512, 16, 16, 8, -12, 5}, Light::kRandom, false);
    check_block(k, rng, BlockCase{2, 16, 516, 16, 16, 8, -12, 5}, Light::kRandom, false);
    check_block(k, rng, BlockCase{2, 256, 244, 8, 64, -8, 4, 65}, Light::kRandom, false);
    check_block(k, rng, BlockCase{2, 256, 248, 8, 64, -8, 4, 65}, Light::kSmooth, false);
    check_block(k, rng, BlockCase{2, 1024, 4, 4, 4, 0, 0, 257}, Light::kAlternating, false);
    check_block(k, rng, BlockCase{2, 48, 300, 4, 4, 12, -4, 13}, Light::kRandom, false);
    check_block(k, rng, BlockCase{2, 80, 512, 32, 32, -20, 8, 21}, Light::kRandom, false);
    check_block(k, rng, BlockCase{2, 256, 100, 32, 12, 28, -36, 65}, Light::kSmooth, false);
    cases += 8;
  }
  std::printf("[ asm      ] surface_block mip 2 lean path: %d cases compared\n", cases);
}

// AArch64 neon_a53's mip-2 16 x 16 block in assembly (asm/neon_block_mip2f.h): every column
// and row offset (multiples of 4, negative too), widths a multiple of 64 (one to
// eight table passes), band counts of every remainder mod 4 (the table's four-row steps and
// single rows), heights up to the limits (512 rows; the table's (h / 4 + 3) w <= 16384 bytes)
// and just past them, and the shapes next to it (widths 16, 48, 80; 8- and 32-tall textures;
// row offsets not a multiple of 4 are outside the contract).
TEST(AsmSurfaceBlock, Mip2SixteenSquareTextures) {
  std::mt19937 rng(1616);
  int cases = 0;
  for (const Kernels* k : tuned_variants("surface_block")) {
    for (int i = 0; i < 32; ++i) {
      const int soff = 4 * (i % 8 - 4), toff = 4 * (int(rng() % 9) - 4);
      const int ws[] = {64, 128, 192, 256, 320, 448, 512};
      const int hs[] = {4, 8, 12, 16, 20, 24, 28, 64, 68};
      const int w = ws[rng() % 7], h = hs[rng() % 9];
      check_block(k, rng, BlockCase{2, w, h, 16, 16, soff, toff, w / 4 + 1 + int(rng() % 3)}, Light(rng() % 6), false);
      ++cases;
    }
    for (int toff = -16; toff < 16; toff += 4) {
      check_block(k, rng, BlockCase{2, 64, 64, 16, 16, 4, toff, 17}, Light::kRandom, false);
      ++cases;
    }
    const BlockCase edge[] = {
        {2, 64, 512, 16, 16, 4, -8, 17},     {2, 64, 516, 16, 16, 4, -8, 17},     // rows: 512, past
        {2, 512, 116, 16, 16, -4, 12, 129},  {2, 512, 120, 16, 16, -4, 12, 129},  // table: at, past
        {2, 448, 132, 16, 16, 8, 4, 113},    {2, 448, 136, 16, 16, 8, 4, 113},
        {2, 128, 500, 16, 16, 8, -4, 33},    {2, 128, 504, 16, 16, 8, -4, 33},
        {2, 16, 64, 16, 16, 0, 0, 5},        {2, 48, 64, 16, 16, 0, 4, 13},       // not a multiple of 64
        {2, 80, 36, 16, 16, 8, 8, 21},       {2, 64, 36, 16, 8, 8, 8, 17},        // th 8
        {2, 64, 36, 16, 32, 8, 8, 17},       {2, 64, 36, 32, 16, 8, 8, 17},       // th 32, tw 32
    };
    for (const BlockCase& c : edge) {
      check_block(k, rng, c, Light(rng() % 6), false);
      ++cases;
    }
  }
  std::printf("[ asm      ] surface_block mip 2, 16 x 16 textures: %d cases compared\n", cases);
}

// ---------------------------------------------------------------- z span

TEST(AsmZSpan, EveryVariantMatchesScalar) {
  std::mt19937 rng(77);
  const int lengths[] = {0, 1, 2, 7, 8, 9, 15, 16, 17, 31, 33, 320, 1919, 1920};
  int cases = 0;
  for (const Kernels* k : tuned_variants("z_span")) {
    for (int n : lengths) {
      for (int rep = 0; rep < 24; ++rep) {
        uint32_t zi = rng(), last = rng();
        if (rep == 0) zi = 0, last = 0xffffffffu;  // the whole range, rising
        if (rep == 1) zi = 0xffffffffu, last = 0;  // falling
        if (rep == 2) last = zi;                   // flat
        if (rep == 3) zi = 0x7fff8000u, last = 0x80008000u;  // across the sign bit
        const uint32_t step = n > 1 ? uint32_t((int64_t(last) - int64_t(zi)) / (n - 1)) : rng();
        std::vector<uint16_t> want(size_t(n) + 2 * kGuard, 0xa5a5), got(want);
        sb::simd::z_span_scalar(want.data() + kGuard, n, zi, step);
        k->z_span(got.data() + kGuard, n, zi, step);
        ASSERT_EQ(want, got) << k->name << ": n " << n << " zi " << zi << " step " << step;
        ++cases;
      }
    }
  }
  std::printf("[ asm      ] z_span: %d cases compared\n", cases);
}

// ---------------------------------------------------------------- palette expansion

TEST(AsmExpandPalette, EveryVariantMatchesScalarEveryScale) {
  std::mt19937 rng(5);
  uint32_t palette[256];
  for (auto& p : palette) p = rng();
  int cases = 0;
  for (const Kernels* k : tuned_variants("expand_palette")) {
    for (int scale : {1, 2, 3, 4, 5, 7, 8, 9, 16}) {
      for (int width : {0, 1, 3, 4, 7, 8, 9, 15, 16, 17, 31, 32, 320, 333}) {
        const int height = 1 + int(rng() % 3);
        const int src_stride = width + int(rng() % 5);
        const std::vector<uint8_t> src = random_bytes(rng, size_t(src_stride) * size_t(height) + 1);
        const ptrdiff_t dst_stride = ptrdiff_t(width) * scale + ptrdiff_t(rng() % 9);
        const size_t dst_size = size_t(dst_stride) * size_t(height) * size_t(scale);
        std::vector<uint32_t> want(dst_size + 2 * kGuard, 0xdeadbeefu), got(want);
        sb::simd::expand_palette_scalar(src.data(), src_stride, width, height, palette, want.data() + kGuard,
                                        dst_stride, scale);
        k->expand_palette(src.data(), src_stride, width, height, palette, got.data() + kGuard, dst_stride, scale);
        ASSERT_EQ(want, got) << k->name << ": width " << width << " height " << height << " scale " << scale;
        ++cases;
      }
    }
  }
  std::printf("[ asm      ] expand_palette: %d cases compared\n", cases);
}

// ---------------------------------------------------------------- dispatch

TEST(AsmDispatch, ForceScalarSwitchesTheActiveTable) {
  std::printf("[ asm      ] tuned choice: %s\n", sb::simd::describe_active());
  const bool before = sb::simd::scalar_forced();
  sb::simd::force_scalar(true);
  EXPECT_EQ(&sb::simd::active(), &sb::simd::scalar_kernels());
  EXPECT_EQ(sb::simd::active().surface_span, &sb::simd::surface_span_scalar);
  sb::simd::force_scalar(false);
  EXPECT_STREQ(sb::simd::active().name, "tuned");
  EXPECT_NE(sb::simd::active().surface_span, nullptr);
  EXPECT_NE(sb::simd::active().surface_block, nullptr);
  EXPECT_NE(sb::simd::active().z_span, nullptr);
  EXPECT_NE(sb::simd::active().expand_palette, nullptr);
  sb::simd::force_scalar(before);
}

}  // namespace
