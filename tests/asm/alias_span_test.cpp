// The alias-model span drawer (asm/alias_span.h): the scalar reference against the
// contract's closed form (64-bit exact), and every variant the CPU supports against the
// scalar reference on random and edge inputs: lengths 0, 1, 7, 8, 9, 15, 16, 17, 1920,
// skins from 1x1 to 32767 wide, full-range and zero gradients (s, t across the whole skin,
// light over all 64 rows, z over 0 .. 0xffffffff), z buffers that hide all, none, some and
// tie. Skin and colormap buffers are exactly sized (AddressSanitizer catches over-reads);
// dest and the z buffer carry guard bytes on both sides.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "asm/kernels.h"

namespace {

using sb::simd::AliasSpan;
using sb::simd::Kernels;

constexpr int kGuard = 32;

struct Case {
  int n, w, h;
  AliasSpan a;
  int zmode;  // 0 random, 1 all zero (all visible), 2 all 0xffff, 3 ties / near ties, 4 mixed runs
};

// Start and step of a quantity that goes from lo to hi (inclusive bounds of the contract)
// over the span, or stays, with an endpoint chosen per `mode`.
void pick(std::mt19937& rng, int n, int64_t lo, int64_t hi, int mode, int32_t* start, int32_t* step) {
  std::uniform_int_distribution<int64_t> r(lo, hi);
  int64_t a = r(rng), b = r(rng);
  if (mode == 1) a = lo, b = hi;        // the whole range, increasing
  if (mode == 2) a = hi, b = lo;        // the whole range, decreasing
  if (mode == 3) b = a;                 // constant
  if (mode == 4) a = hi, b = hi;        // pinned at the top
  *start = int32_t(uint32_t(a));
  // Truncated toward zero and clamped to 32 bits: every value stays between a and b.
  int64_t d = n > 1 ? (b - a) / (n - 1) : 0;
  d = d > INT32_MAX ? INT32_MAX : (d < INT32_MIN ? INT32_MIN : d);
  *step = n > 1 ? int32_t(d) : int32_t(rng());  // n <= 1: the step is never applied
}

Case random_case(std::mt19937& rng, int n) {
  Case c{};
  c.n = n;
  const int shapes[][2] = {{1, 1}, {1, 300}, {320, 200}, {296, 194}, {32767, 1}, {17, 33}, {64, 64}};
  const auto& sh = shapes[rng() % 7];
  c.w = sh[0];
  c.h = sh[1];
  if (rng() % 3 == 0) {
    c.w = 1 + int(rng() % 512);
    c.h = 1 + int(rng() % 256);
  }
  pick(rng, n, 0, (int64_t(c.w) << 16) - 1, int(rng() % 6), &c.a.s, &c.a.ds);
  pick(rng, n, 0, (int64_t(c.h) << 16) - 1, int(rng() % 6), &c.a.t, &c.a.dt);
  pick(rng, n, 0, (int64_t(64) << 16) - 1, int(rng() % 6), &c.a.light, &c.a.dlight);
  int32_t zi;
  pick(rng, n, 0, 0xffffffffll, int(rng() % 6), &zi, &c.a.dzi);
  c.a.zi = uint32_t(zi);
  c.zmode = int(rng() % 5);
  return c;
}

std::vector<uint16_t> make_zbuf(std::mt19937& rng, const Case& c) {
  std::vector<uint16_t> z(size_t(c.n) + 2 * kGuard, 0x5a5a);
  uint32_t zi = c.a.zi;
  for (int k = 0; k < c.n; ++k, zi += uint32_t(c.a.dzi)) {
    const uint16_t mine = uint16_t(zi >> 16);
    uint16_t v = uint16_t(rng());
    if (c.zmode == 1) v = 0;
    if (c.zmode == 2) v = 0xffff;
    if (c.zmode == 3) v = uint16_t(mine + int(rng() % 3) - 1);  // tie, one nearer, one farther
    if (c.zmode == 4) v = ((k / 5) & 1) ? 0xffff : 0;          // alternating runs of 5
    z[size_t(kGuard + k)] = v;
  }
  return z;
}

struct Out {
  std::vector<uint8_t> dest;
  std::vector<uint16_t> z;
};

Out run(const Kernels& k, const Case& c, const std::vector<uint8_t>& skin, const std::vector<uint8_t>& cm,
        const std::vector<uint8_t>& dest0, const std::vector<uint16_t>& z0) {
  Out o{dest0, z0};
  k.alias_span(o.dest.data() + kGuard, o.z.data() + kGuard, c.n, skin.data(), c.w, cm.data(), c.a);
  return o;
}

TEST(AsmAliasSpan, ScalarReferenceMatchesClosedForm) {
  std::mt19937 rng(11);
  const std::vector<uint8_t> cm = [&] {
    std::vector<uint8_t> v(64 * 256);
    for (auto& b : v) b = uint8_t(rng());
    return v;
  }();
  for (int trial = 0; trial < 300; ++trial) {
    const Case c = random_case(rng, int(rng() % 200));
    std::vector<uint8_t> skin(size_t(c.w) * c.h);
    for (auto& b : skin) b = uint8_t(rng());
    std::vector<uint8_t> dest(size_t(c.n) + 2 * kGuard);
    for (auto& b : dest) b = uint8_t(rng());
    const std::vector<uint16_t> z = make_zbuf(rng, c);
    const Out got = run(sb::simd::scalar_kernels(), c, skin, cm, dest, z);
    for (int k = 0; k < c.n; ++k) {
      const int64_t s = int64_t(c.a.s) + int64_t(k) * c.a.ds, t = int64_t(c.a.t) + int64_t(k) * c.a.dt;
      const int64_t l = int64_t(c.a.light) + int64_t(k) * c.a.dlight;
      const int64_t zi = int64_t(c.a.zi) + int64_t(k) * c.a.dzi;
      ASSERT_TRUE(s >= 0 && s < (int64_t(c.w) << 16) && t >= 0 && t < (int64_t(c.h) << 16) && l >= 0 &&
                  l < (64 << 16) && zi >= 0 && zi <= 0xffffffffll)
          << "test case outside the contract, trial " << trial;
      const size_t i = size_t(kGuard + k);
      const bool visible = uint16_t(zi >> 16) >= z[i];
      const uint8_t want = visible ? cm[size_t((l >> 16) * 256 + skin[size_t((t >> 16) * c.w + (s >> 16))])] : dest[i];
      ASSERT_EQ(got.dest[i], want) << "trial " << trial << " pixel " << k;
      ASSERT_EQ(got.z[i], visible ? uint16_t(zi >> 16) : z[i]) << "trial " << trial << " pixel " << k;
    }
    for (int g = 0; g < kGuard; ++g) {
      ASSERT_EQ(got.dest[size_t(g)], dest[size_t(g)]);
      ASSERT_EQ(got.dest[size_t(kGuard + c.n + g)], dest[size_t(kGuard + c.n + g)]);
    }
  }
}

TEST(AsmAliasSpan, EveryVariantMatchesScalar) {
  std::vector<const Kernels*> variants;
  for (int i = 1; i < sb::simd::variant_count(); ++i) {
    const sb::simd::Variant v = sb::simd::variant(i);
    if (!v.kernels) continue;
    std::printf("[ asm      ] alias_span: variant %s %s\n", v.kernels->name,
                v.supported ? "runs" : "SKIPPED (this CPU lacks it)");
    if (v.supported) variants.push_back(v.kernels);
  }
  std::mt19937 rng(5);
  std::vector<uint8_t> cm(64 * 256);
  for (auto& b : cm) b = uint8_t(rng());
  const int lengths[] = {0, 1, 2, 7, 8, 9, 15, 16, 17, 23, 24, 31, 33, 64, 333, 1920};
  int cases = 0;
  for (int trial = 0; trial < 1200; ++trial) {
    const int n = trial < 16 * 40 ? lengths[trial % 16] : int(rng() % 1921);
    const Case c = random_case(rng, n);
    std::vector<uint8_t> skin(size_t(c.w) * c.h);
    for (auto& b : skin) b = uint8_t(rng());
    std::vector<uint8_t> dest(size_t(c.n) + 2 * kGuard);
    for (auto& b : dest) b = uint8_t(rng());
    const std::vector<uint16_t> z = make_zbuf(rng, c);
    const Out ref = run(sb::simd::scalar_kernels(), c, skin, cm, dest, z);
    for (const Kernels* k : variants) {
      const Out got = run(*k, c, skin, cm, dest, z);
      ASSERT_EQ(ref.dest, got.dest) << k->name << " trial " << trial << " n " << n << " skin " << c.w << "x" << c.h
                                    << " zmode " << c.zmode;
      ASSERT_EQ(ref.z, got.z) << k->name << " trial " << trial << " n " << n << " zmode " << c.zmode;
    }
    ++cases;
  }
  std::printf("[ asm      ] alias_span: %d cases x %zu variants identical to scalar\n", cases, variants.size());
}

}  // namespace
