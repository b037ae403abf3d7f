// tests/content/textures_test.cpp: the texture catalogue, mip filtering, determinism and
// the WAD2 writer read back through the engine's parse_wad + decode_miptex.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>
#include <string>

#include "engine/formats/wad.h"
#include "memory/arena.h"
#include "tools/content/content_build.h"
#include "tools/content/noise.h"
#include "tools/content/textures.h"
#include "tools/content/wad_writer.h"

namespace sb::content {
namespace {

const PaletteData& palette() {
  static const PaletteData p = make_palette();
  return p;
}
const std::vector<Miptex>& all_textures() {
  static const std::vector<Miptex> t = make_all_textures(palette(), kDefaultSeed);
  return t;
}
const Miptex* find(const std::string& name) {
  for (const Miptex& t : all_textures())
    if (t.name == name) return &t;
  return nullptr;
}
Rgb mean_colour(const std::vector<uint8_t>& idx) {
  double s[3] = {0, 0, 0};
  for (uint8_t i : idx)
    for (int c = 0; c < 3; ++c) s[c] += palette().bytes[size_t(i) * 3 + size_t(c)];
  double n = double(idx.size()) * 255.0;
  return {float(s[0] / n), float(s[1] / n), float(s[2] / n)};
}

TEST(Textures, CatalogueHasTheNamesTheMapAndEngineNeed) {
  for (const char* name : {"brick1", "stone1", "tile1", "planks1", "metal1", "door1", "light1", "button1", "sky1",
                           "*water1", "*slime1", "*lava1", "*tele1", "+0light", "+1light", "clip", "trigger", "skip"})
    EXPECT_NE(find(name), nullptr) << name;
  std::set<std::string> names;
  for (const Miptex& t : all_textures()) {
    EXPECT_TRUE(names.insert(t.name).second) << "duplicate " << t.name;
    EXPECT_LE(t.name.size(), 15u);
    EXPECT_EQ(t.width % 16, 0) << t.name;
    EXPECT_EQ(t.height % 16, 0) << t.name;
    for (int m = 0; m < 4; ++m)
      EXPECT_EQ(t.mips[size_t(m)].size(), size_t(t.width >> m) * size_t(t.height >> m)) << t.name << " mip " << m;
  }
  const Miptex* sky = find("sky1");
  EXPECT_EQ(sky->width, 256);
  EXPECT_EQ(sky->height, 128);
  for (const char* liquid : {"*water1", "*slime1", "*lava1", "*tele1"}) {
    EXPECT_EQ(find(liquid)->width, 64);
    EXPECT_EQ(find(liquid)->height, 64);
  }
}

TEST(Textures, ReservedIndicesAreRespected) {
  for (const Miptex& t : all_textures())
    for (const auto& m : t.mips)
      for (uint8_t i : m) ASSERT_NE(i, kTransparentIndex) << t.name << " uses the reserved index 255";
  // The sky's front layer has holes (index 0), its back layer has none.
  const Miptex* sky = find("sky1");
  size_t holes_front = 0, holes_back = 0;
  for (int y = 0; y < sky->height; ++y)
    for (int x = 0; x < sky->width; ++x)
      (x < 128 ? holes_front : holes_back) += sky->mips[0][size_t(y) * 256 + size_t(x)] == 0;
  EXPECT_GT(holes_front, 128u * 128u / 5) << "clouds leave the back layer visible";
  EXPECT_LT(holes_front, 128u * 128u * 9 / 10) << "but there are clouds";
  EXPECT_EQ(holes_back, 0u);
  // Fullbright texels: present in the light fixtures, absent from plain masonry.
  auto fullbrights = [](const Miptex& t) {
    size_t n = 0;
    for (uint8_t i : t.mips[0]) n += i >= kFirstFullbright;
    return n;
  };
  for (const char* glowing : {"light1", "+0light", "button1", "tech1", "*lava1"})
    EXPECT_GT(fullbrights(*find(glowing)), 0u) << glowing;
  for (const char* plain : {"brick1", "stone1", "planks1", "metal1", "door1", "+1light", "*water1"})
    EXPECT_EQ(fullbrights(*find(plain)), 0u) << plain;
}

size_t mm_count(const Miptex& t, int m) { return t.mips[size_t(m)].size(); }

TEST(Textures, MipLevelsKeepTheMeanColour) {
  for (const Miptex& t : all_textures()) {
    Rgb m0 = mean_colour(t.mips[0]);
    for (int m = 1; m < 4; ++m) {
      Rgb mm = mean_colour(t.mips[size_t(m)]);
      // Quantisation and the majority-class rule (fullbright vs lit) move small mips most.
      float tol = 0.04f + 0.5f / std::sqrt(float(mm_count(t, m)));
      EXPECT_NEAR(mm.r, m0.r, tol) << t.name << " mip " << m;
      EXPECT_NEAR(mm.g, m0.g, tol) << t.name << " mip " << m;
      EXPECT_NEAR(mm.b, m0.b, tol) << t.name << " mip " << m;
    }
  }
}

TEST(Textures, DownsampleIsABoxFilter) {
  Image img(32, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) img.at(x, y).c = ((x + y) & 1) ? Rgb{1, 0.5f, 0} : Rgb{0, 0.5f, 1};
  Image half = downsample(img, 1);
  ASSERT_EQ(half.width, 16);
  for (const Texel& t : half.texels) {
    EXPECT_FLOAT_EQ(t.c.r, 0.5f);
    EXPECT_FLOAT_EQ(t.c.g, 0.5f);
    EXPECT_FLOAT_EQ(t.c.b, 0.5f);
  }
  // Majority class wins: a block with 3 fullbright texels of 4 stays fullbright.
  Image mixed(16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      if ((x & 1) || (y & 1)) mixed.at(x, y).cls = TexelClass::kFullbright;
  for (const Texel& t : downsample(mixed, 1).texels) EXPECT_EQ(t.cls, TexelClass::kFullbright);
}

TEST(Textures, SameSeedSameBytesOtherSeedOtherBytes) {
  for (const TextureSpec& spec : texture_specs()) {
    Miptex a = make_texture(palette(), spec, kDefaultSeed);
    Miptex b = make_texture(palette(), spec, kDefaultSeed);
    for (int m = 0; m < 4; ++m) ASSERT_EQ(a.mips[size_t(m)], b.mips[size_t(m)]) << spec.name;
  }
  int differ = 0;
  for (const TextureSpec& spec : texture_specs())
    differ += make_texture(palette(), spec, kDefaultSeed).mips[0] != make_texture(palette(), spec, 12345).mips[0];
  EXPECT_GE(differ, int(texture_specs().size()) - 4) << "only the marker textures ignore the seed";
}

TEST(Noise, TilesAtTheEdges) {
  for (int f : {1, 3, 8})
    for (float v : {0.0f, 0.3f, 0.77f}) {
      EXPECT_NEAR(value_noise(0.0f, v, f, 7), value_noise(1.0f, v, f, 7), 1e-5f);
      EXPECT_NEAR(gradient_noise(v, 0.0f, f, 7), gradient_noise(v, 1.0f, f, 7), 1e-5f);
      EXPECT_NEAR(cellular(0.0f, v, f, 0.9f, 7).f1, cellular(1.0f, v, f, 0.9f, 7).f1, 1e-4f);
    }
}

TEST(Wad, RoundTripThroughTheEngineReader) {
  std::string error;
  std::vector<uint8_t> wad = encode_wad(all_textures(), &error);
  ASSERT_FALSE(wad.empty()) << error;
  std::vector<uint8_t> mem(1 << 20);
  mem::Arena arena;
  arena.init("test", mem.data(), mem.size());
  Result<Wad> parsed = parse_wad("starbow.wad", wad.data(), wad.size(), arena);
  ASSERT_TRUE(parsed.is_ok()) << parsed.message();
  ASSERT_EQ(parsed->count, all_textures().size());
  for (const Miptex& t : all_textures()) {
    const WadLump* lump = parsed->find(t.name.c_str());
    ASSERT_NE(lump, nullptr) << t.name;
    EXPECT_EQ(lump->type, kWadMiptex);
    MiptexView view;
    ASSERT_TRUE(decode_miptex("starbow.wad", t.name.c_str(), lump->data, lump->size, &view).is_ok());
    EXPECT_STREQ(view.name, t.name.c_str());
    EXPECT_EQ(int(view.width), t.width);
    EXPECT_EQ(int(view.height), t.height);
    ASSERT_TRUE(view.has_pixels);
    for (int m = 0; m < 4; ++m)
      EXPECT_EQ(std::memcmp(view.mips[m], t.mips[size_t(m)].data(), t.mips[size_t(m)].size()), 0) << t.name << m;
  }
  EXPECT_TRUE(verify_wad(wad, all_textures(), &error)) << error;
}

TEST(Wad, RejectsBadTextures) {
  std::string error;
  Miptex bad = all_textures()[0];
  bad.name = "a_name_that_is_far_too_long";
  EXPECT_TRUE(encode_wad({bad}, &error).empty());
  EXPECT_NE(error.find("name"), std::string::npos);
  bad = all_textures()[0];
  bad.width = 72;
  EXPECT_TRUE(encode_wad({bad}, &error).empty());
  EXPECT_NE(error.find("multiple of 16"), std::string::npos);
  bad = all_textures()[0];
  bad.mips[2].pop_back();
  EXPECT_TRUE(encode_wad({bad}, &error).empty());
  EXPECT_NE(error.find("mip 2"), std::string::npos);
}

TEST(Content, BuildWritesTheGameFolder) {
  std::string dir = std::string(STARBOW_BINARY_DIR) + "/tests/content_out";
  ContentSummary summary;
  std::string error;
  ASSERT_TRUE(build_content(dir, kDefaultSeed, "", &summary, &error)) << error;
  EXPECT_EQ(summary.textures, int(texture_specs().size()));
  for (const char* f : {"/gfx/palette.lmp", "/gfx/colormap.lmp", "/starbow.wad"}) {
    FILE* fp = std::fopen((dir + f).c_str(), "rb");
    ASSERT_NE(fp, nullptr) << f;
    std::fclose(fp);
  }
}

}  // namespace
}  // namespace sb::content
