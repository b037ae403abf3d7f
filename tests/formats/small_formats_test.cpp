// Entities tokenizer, WAD2, palette / colormap / qpic.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "engine/formats/entities.h"
#include "engine/formats/lmp.h"
#include "engine/formats/wad.h"
#include "tests/formats/formats_test_util.h"
#include "tests/support/quake_data.h"

namespace sb::test {
namespace {

TEST(Entities, PairsCommentsBareWordsAndErrors) {
  std::string text =
      "// comment { not an entity\n{\n\"classname\" \"worldspawn\"\n\"message\" \"brace } inside\"\n}\n"
      "{ classname light \"origin\" \"1 -2.5 3e1\" \"mangle\" \"10 20 30\" }\n"
      "{ \"classname\" \"info_player_start\" \"angle\" \"-1\" }";
  EntityIterator it(text);
  Entity e;
  ASSERT_TRUE(it.next(&e));
  EXPECT_EQ(e.classname(), "worldspawn");
  std::string_view v;
  ASSERT_TRUE(e.find("message", &v));
  EXPECT_EQ(v, "brace } inside");
  ASSERT_TRUE(it.next(&e));
  EXPECT_EQ(e.classname(), "light");
  glm::vec3 o, ang;
  ASSERT_TRUE(entity_origin(e, &o));
  EXPECT_EQ(o, glm::vec3(1, -2.5f, 30));
  ASSERT_TRUE(entity_angles(e, &ang));
  EXPECT_EQ(ang, glm::vec3(10, 20, 30));
  ASSERT_TRUE(it.next(&e));
  ASSERT_TRUE(entity_angles(e, &ang));
  EXPECT_EQ(ang, glm::vec3(-90, 0, 0));
  EXPECT_FALSE(it.next(&e));
  EXPECT_EQ(it.error(), nullptr);

  EntityIterator bad1("{ \"a\" \"unterminated }");
  EXPECT_FALSE(bad1.next(&e));
  EXPECT_NE(bad1.error(), nullptr);
  EntityIterator bad2("{ \"a\" \"b\" ");
  EXPECT_FALSE(bad2.next(&e));
  EXPECT_NE(bad2.error(), nullptr);
  EntityIterator bad3("\"a\" \"b\" }");
  EXPECT_FALSE(bad3.next(&e));
  EXPECT_NE(bad3.error(), nullptr);
  float f;
  EXPECT_FALSE(parse_float("12abc", &f));
  EXPECT_TRUE(parse_float(" 7 ", &f));
  EXPECT_FALSE(parse_vec3("1 2", &o));
  EXPECT_FALSE(parse_vec3("1 2 3 4", &o));
}

TEST(Lmp, PaletteColormapQpic) {
  std::vector<uint8_t> pal(768, 5), cmap(16385, 1);
  Palette p;
  EXPECT_TRUE(parse_palette("gfx/palette.lmp", pal.data(), pal.size(), &p).is_ok());
  Status st = parse_palette("gfx/palette.lmp", pal.data(), 767, &p);
  EXPECT_NE(std::strstr(st.message(), "gfx/palette.lmp"), nullptr);
  std::vector<uint8_t> table(kColormapBytes);
  int extra = 0;
  cmap[16384] = 32;
  EXPECT_TRUE(parse_colormap("c.lmp", cmap.data(), cmap.size(), table.data(), &extra).is_ok());
  EXPECT_EQ(extra, 32);
  EXPECT_TRUE(parse_colormap("c.lmp", cmap.data(), 16384, table.data(), &extra).is_ok());
  EXPECT_EQ(extra, -1);
  EXPECT_FALSE(parse_colormap("c.lmp", cmap.data(), 16000, table.data(), &extra).is_ok());
  uint8_t pic[8 + 6] = {2, 0, 0, 0, 3, 0, 0, 0, 1, 2, 3, 4, 5, 6};
  QpicView q;
  ASSERT_TRUE(parse_qpic("p.lmp", pic, sizeof pic, &q).is_ok());
  EXPECT_EQ(q.width, 2);
  EXPECT_EQ(q.pixels[5], 6);
  st = parse_qpic("p.lmp", pic, sizeof pic - 1, &q);
  EXPECT_FALSE(st.is_ok());
  pic[0] = 0;
  st = parse_qpic("p.lmp", pic, sizeof pic, &q);
  EXPECT_NE(std::strstr(st.message(), "'width'"), nullptr) << st.message();
}

TEST(Lmp, RealPaletteAndColormap) {
  SB_REQUIRE_QUAKE_DATA();
  auto pal = read_file(quake_dir() + "/lq1/gfx/palette.lmp");
  auto cmap = read_file(quake_dir() + "/lq1/gfx/colormap.lmp");
  Palette p;
  ASSERT_TRUE(parse_palette("palette.lmp", pal.data(), pal.size(), &p).is_ok());
  std::vector<uint8_t> table(kColormapBytes);
  int extra;
  ASSERT_TRUE(parse_colormap("colormap.lmp", cmap.data(), cmap.size(), table.data(), &extra).is_ok());
}

TEST(Wad, RealGfxWad) {
  SB_REQUIRE_QUAKE_DATA();
  auto bytes = read_file(quake_dir() + "/lq1/gfx.wad");
  TestArenas a(1u << 20, 1u << 20);
  auto r = parse_wad("gfx.wad", bytes.data(), bytes.size(), a.level);
  ASSERT_TRUE(r.is_ok()) << r.message();
  const Wad& w = r.value();
  EXPECT_GT(w.count, 10u);
  const WadLump* conchars = w.find("ConChars");  // case-insensitive
  ASSERT_NE(conchars, nullptr);
  EXPECT_GE(conchars->size, 128u * 128u);
  int pics = 0;
  for (uint32_t i = 0; i < w.count; ++i) {
    if (w.lumps[i].type != kWadQpic) continue;
    QpicView q;
    Status st = parse_qpic(w.lumps[i].name, w.lumps[i].data, w.lumps[i].size, &q);
    EXPECT_TRUE(st.is_ok()) << st.message();
    ++pics;
  }
  EXPECT_GT(pics, 5);
  EXPECT_EQ(w.find("no such lump"), nullptr);
}

TEST(Wad, TextureWadMiptexDecodes) {
  SB_REQUIRE_QUAKE_DATA();
  auto bytes = read_file(quake_dir() + "/texture-wads/lq_dev.wad");
  if (bytes.empty()) GTEST_SKIP() << "lq_dev.wad not present";
  TestArenas a(4u << 20, 1u << 20);
  auto r = parse_wad("lq_dev.wad", bytes.data(), bytes.size(), a.level);
  ASSERT_TRUE(r.is_ok()) << r.message();
  int decoded = 0;
  for (uint32_t i = 0; i < r.value().count; ++i) {
    const WadLump& l = r.value().lumps[i];
    if (l.type != kWadMiptex) continue;
    MiptexView mt;
    Status st = decode_miptex("lq_dev.wad", l.name, l.data, l.size, &mt);
    ASSERT_TRUE(st.is_ok()) << st.message();
    EXPECT_TRUE(mt.has_pixels);
    ++decoded;
  }
  EXPECT_GT(decoded, 0);
}

}  // namespace
}  // namespace sb::test
