// tests/content/palette_test.cpp: invariants of Starbow's own palette and colormap
// (tools/content/palette.h) and that the engine's parsers accept them.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "engine/formats/lmp.h"
#include "tools/content/palette.h"

namespace sb::content {
namespace {

float luma_of(const PaletteData& p, int i) {
  return luma(rgb8(p.bytes[size_t(i) * 3], p.bytes[size_t(i) * 3 + 1], p.bytes[size_t(i) * 3 + 2]));
}

TEST(Palette, ParsesAndHasDistinctLitColours) {
  PaletteData p = make_palette();
  Palette parsed;
  ASSERT_TRUE(parse_palette("palette.lmp", p.bytes.data(), p.bytes.size(), &parsed).is_ok());
  std::set<std::tuple<int, int, int>> seen;
  for (int i = 0; i < 256; ++i) seen.insert({p.bytes[size_t(i) * 3], p.bytes[size_t(i) * 3 + 1], p.bytes[size_t(i) * 3 + 2]});
  EXPECT_EQ(seen.size(), 256u) << "every palette entry is a distinct colour";
  EXPECT_EQ(p.bytes[0] + p.bytes[1] + p.bytes[2], 0) << "index 0 is black";
  EXPECT_EQ(p.bytes[255 * 3 + 0], 255);  // reserved 255: magenta
  EXPECT_EQ(p.bytes[255 * 3 + 1], 0);
}

TEST(Palette, RampsGoFromDarkToLight) {
  PaletteData p = make_palette();
  for (int r = 0; r < kRampCount; ++r)
    for (int s = 1; s < kRampSize; ++s)
      EXPECT_GT(luma_of(p, ramp_index(r, s)), luma_of(p, ramp_index(r, s - 1))) << "ramp " << r << " shade " << s;
}

TEST(Colormap, SizeTrailingByteAndEngineParse) {
  PaletteData p = make_palette();
  std::vector<uint8_t> cm = make_colormap(p);
  ASSERT_EQ(cm.size(), kColormapBytes + 1);
  EXPECT_EQ(cm.back(), kFullbrightCount);
  std::vector<uint8_t> table(kColormapBytes);
  int extra = 0;
  ASSERT_TRUE(parse_colormap("colormap.lmp", cm.data(), cm.size(), table.data(), &extra).is_ok());
  EXPECT_EQ(extra, kFullbrightCount);
}

TEST(Colormap, Row32IsTheIdentityForLitColours) {
  PaletteData p = make_palette();
  std::vector<uint8_t> cm = make_colormap(p);
  int same = 0;
  for (int i = 0; i < kFirstFullbright; ++i) same += cm[32 * 256 + size_t(i)] == i;
  EXPECT_GE(same, kFirstFullbright * 95 / 100);
  EXPECT_EQ(same, kFirstFullbright) << "with distinct colours the identity row is exact";
}

TEST(Colormap, FullbrightsAreFixedInEveryRow) {
  PaletteData p = make_palette();
  std::vector<uint8_t> cm = make_colormap(p);
  for (int row = 0; row < 64; ++row)
    for (int i = kFirstFullbright; i < 256; ++i) ASSERT_EQ(cm[size_t(row) * 256 + size_t(i)], i) << row << " " << i;
  // And lit colours never turn into fullbrights.
  for (int row = 0; row < 64; ++row)
    for (int i = 0; i < kFirstFullbright; ++i) ASSERT_LT(cm[size_t(row) * 256 + size_t(i)], kFirstFullbright);
}

TEST(Colormap, BrightnessFallsDownTheRows) {
  PaletteData p = make_palette();
  std::vector<uint8_t> cm = make_colormap(p);
  // A mid grey: strictly monotone in luma as long as there are greys to step through.
  // Every lit colour: never lighter (OkLab L) further down. Mid shades: clearly brighter
  // at row 0 than at row 32, near black at row 63.
  int grey = ramp_index(kRampGrey, 8);
  for (int row = 1; row < 64; ++row)
    EXPECT_LE(luma_of(p, cm[size_t(row) * 256 + size_t(grey)]), luma_of(p, cm[size_t(row - 1) * 256 + size_t(grey)]))
        << "grey row " << row;
  for (int i = 0; i < kFirstFullbright; ++i)
    for (int row = 1; row < 64; ++row)
      ASSERT_LE(p.lab[cm[size_t(row) * 256 + size_t(i)]].L, p.lab[cm[size_t(row - 1) * 256 + size_t(i)]].L)
          << "index " << i << " row " << row;
  for (int ramp : {kRampGrey, kRampBrown, kRampGreen, kRampBlue, kRampRed, kRampSteel}) {
    int src = ramp_index(ramp, 8);
    EXPECT_GT(luma_of(p, cm[size_t(src)]), luma_of(p, src) * 1.4f) << "row 0 is overbright";
    EXPECT_LT(luma_of(p, cm[63 * 256 + size_t(src)]), 0.05f) << "row 63 is nearly black";
  }
}

TEST(Colormap, DarkRowsKeepHue) {
  // Row 48 (half light) of a saturated red stays in the red ramp or near black/brown,
  // never in an unrelated hue.
  PaletteData p = make_palette();
  std::vector<uint8_t> cm = make_colormap(p);
  int src = ramp_index(kRampRed, 10);
  int dark = cm[48 * 256 + size_t(src)];
  OkLab a = p.lab[size_t(src)], b = p.lab[size_t(dark)];
  EXPECT_GT(a.a * b.a + a.b * b.b, 0.0f) << "same hue direction in OkLab";
}

}  // namespace
}  // namespace sb::content
