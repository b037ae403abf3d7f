// The surface cache through draw_surfaces: reuse across frames, rebuild on light-style and
// animation changes, graceful exhaustion; and every pixel drawn once across surface kinds.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "engine/core/log.h"
#include "engine/render/render_local.h"
#include "engine/render/span_draw.h"
#include "engine/render/surface_cache.h"
#include "engine/render/surface_math.h"
#include "tests/render_back/back_test_util.h"

namespace sb::test::back {
namespace {

using render::FrameSpans;
using render::Span;
using render::SurfaceDraw;

// N lit faces on the wall x = 128, each given one row of the screen.
struct CacheScene {
  HandWorld tw;
  std::vector<int> faces;
  std::vector<Span> spans;
  std::vector<SurfaceDraw> surfs;
  int anim_a = 0, anim_b = 0;
  static constexpr int W = 256, H = 16;

  explicit CacheScene(int ext = 256) {
    int tex = tw.add_texture("wall", 64, 64, 1);
    anim_a = tw.add_texture("+0slip", 64, 64, 2);
    anim_b = tw.add_texture("+1slip", 64, 64, 3);
    int pl = tw.add_plane({1, 0, 0}, 128);
    int ti = tw.add_texinfo({0, 1, 0, 0}, {0, 0, -1, 0}, tex);
    int ti_anim = tw.add_texinfo({0, 1, 0, 0}, {0, 0, -1, 0}, anim_a);
    for (int i = 0; i < H; ++i) {
      const uint8_t styles[4] = {uint8_t(i % 4), uint8_t(i % 3 == 0 ? 10 : 255), 255, 255};
      faces.push_back(tw.add_face(pl, i == 5 ? ti_anim : ti, -ext / 2, -ext / 2, ext, ext, styles, 100 + i));
    }
    BspWorld& w = tw.world();
    w.textures[anim_a].anim_next = anim_b; w.textures[anim_a].anim_total = 2; w.textures[anim_a].anim_index = 0;
    w.textures[anim_b].anim_next = anim_a; w.textures[anim_b].anim_total = 2; w.textures[anim_b].anim_index = 1;
    for (int i = 0; i < H; ++i) {
      spans.push_back(Span{0, int16_t(i), int16_t(W), 0});
      surfs.push_back(SurfaceDraw{uint32_t(faces[i]), 1.0f, uint32_t(i), 1});  // nearzi 1: mip 0
    }
  }
  FrameSpans frame() {
    FrameSpans f;
    f.spans = spans.data();
    f.num_spans = uint32_t(spans.size());
    f.surfaces = surfs.data();
    f.num_surfaces = uint32_t(surfs.size());
    return f;
  }
};

RenderStats draw(CacheScene& sc, TestMemory& tm, TestFramebuffer& tf, const int* ls, double time,
                 const std::vector<uint8_t>& cm) {
  RenderInputs in;
  in.world = &sc.tw.world();
  in.time = time;
  in.lightstyles = ls;
  in.colormap = cm.data();
  auto view = make_view({0, 0, 0}, 0, 0, 90, CacheScene::W, CacheScene::H, tm.mem.frame_number());
  RenderStats st;
  render::draw_surfaces(sc.tw.world(), view, sc.frame(), in, tf.fb, tm.mem, &st);
  return st;
}

TEST(SurfaceCache, ReusedAcrossFramesAndRebuiltOnLightChange) {
  CacheScene sc;
  TestMemory tm(32);
  auto cm = colormap_or_synthetic();
  int ls[kMaxLightStyleSlots];
  for (int& v : ls) v = 256;
  render_new_level(sc.tw.world());

  tm.mem.begin_frame();
  TestFramebuffer f1(CacheScene::W, CacheScene::H);
  RenderStats s1 = draw(sc, tm, f1, ls, 0.0, cm);
  EXPECT_EQ(s1.surfaces_built, uint32_t(CacheScene::H));
  EXPECT_EQ(s1.surface_cache_hits, 0u);
  EXPECT_EQ(s1.mip_counts[0], uint32_t(CacheScene::H));
  EXPECT_FALSE(s1.cache_exhausted);

  tm.mem.begin_frame();
  TestFramebuffer f2(CacheScene::W, CacheScene::H);
  RenderStats s2 = draw(sc, tm, f2, ls, 0.1, cm);
  EXPECT_EQ(s2.surfaces_built, 0u);
  EXPECT_EQ(s2.surface_cache_hits, uint32_t(CacheScene::H));
  EXPECT_EQ(f1.pixels, f2.pixels);
  std::printf("frame 1: built %u hits %u; frame 2: built %u hits %u\n", s1.surfaces_built, s1.surface_cache_hits,
              s2.surfaces_built, s2.surface_cache_hits);

  // Style 10 flickers: only the faces using it (rows 0, 3, 6, ...) are rebuilt.
  ls[10] = 100;
  tm.mem.begin_frame();
  TestFramebuffer f3(CacheScene::W, CacheScene::H);
  RenderStats s3 = draw(sc, tm, f3, ls, 0.1, cm);
  uint32_t users = 0;
  for (int i = 0; i < CacheScene::H; ++i) users += (i % 3 == 0);
  EXPECT_EQ(s3.surfaces_built, users);
  EXPECT_EQ(s3.surface_cache_hits, uint32_t(CacheScene::H) - users);
  for (int y = 0; y < CacheScene::H; ++y) {
    const bool same = std::memcmp(&f2.pixels[size_t(y) * CacheScene::W], &f3.pixels[size_t(y) * CacheScene::W],
                                  CacheScene::W) == 0;
    EXPECT_EQ(same, y % 3 != 0) << "row " << y;
  }
  // The rebuilt surface equals a fresh build with the same styles (new level = empty handles).
  render_new_level(sc.tw.world());
  tm.mem.begin_frame();
  TestFramebuffer f4(CacheScene::W, CacheScene::H);
  RenderStats s4 = draw(sc, tm, f4, ls, 0.1, cm);
  EXPECT_EQ(s4.surfaces_built, uint32_t(CacheScene::H));
  EXPECT_EQ(f3.pixels, f4.pixels);

  // Animation: at time 0.25 the animated face (row 5) shows its second frame: rebuilt.
  tm.mem.begin_frame();
  TestFramebuffer f5(CacheScene::W, CacheScene::H);
  RenderStats s5 = draw(sc, tm, f5, ls, 0.25, cm);
  EXPECT_EQ(s5.surfaces_built, 1u);
  EXPECT_NE(std::memcmp(&f4.pixels[5 * CacheScene::W], &f5.pixels[5 * CacheScene::W], CacheScene::W), 0);
  EXPECT_TRUE(tm.mem.cache.check_consistency());
}

TEST(SurfaceCache, EvictedSurfacesAreRebuilt) {
  CacheScene sc;
  TestMemory tm(32);
  auto cm = colormap_or_synthetic();
  render_new_level(sc.tw.world());
  tm.mem.begin_frame();
  TestFramebuffer f1(CacheScene::W, CacheScene::H);
  draw(sc, tm, f1, nullptr, 0.0, cm);
  tm.mem.cache.flush();  // everything evicted: handles go stale
  tm.mem.begin_frame();
  TestFramebuffer f2(CacheScene::W, CacheScene::H);
  RenderStats s2 = draw(sc, tm, f2, nullptr, 0.0, cm);
  EXPECT_EQ(s2.surfaces_built, uint32_t(CacheScene::H));
  EXPECT_EQ(f1.pixels, f2.pixels);
}

int g_warnings = 0;
void count_sink(void*, LogLevel level, const char*) { g_warnings += level == LogLevel::Warning; }

TEST(SurfaceCache, ExhaustionFallsBackToUnlitTexture) {
  // 32 MiB block: a 10 MiB cache. Faces of 2048 x 2048 texels need 4 MiB each at mip 0.
  CacheScene sc(2048);
  TestMemory tm(32);
  auto cm = colormap_or_synthetic();
  render_new_level(sc.tw.world());
  g_warnings = 0;
  set_log_sink(count_sink, nullptr);
  tm.mem.begin_frame();
  TestFramebuffer f1(CacheScene::W, CacheScene::H);
  RenderStats s1 = draw(sc, tm, f1, nullptr, 0.0, cm);
  tm.mem.begin_frame();
  TestFramebuffer f2(CacheScene::W, CacheScene::H);
  RenderStats s2 = draw(sc, tm, f2, nullptr, 0.0, cm);
  set_log_sink(nullptr, nullptr);
  EXPECT_TRUE(s1.cache_exhausted);
  EXPECT_TRUE(s2.cache_exhausted);
  EXPECT_EQ(s1.surfaces_built, 2u);
  EXPECT_EQ(g_warnings, 1) << "logged once per level";
  EXPECT_TRUE(tm.mem.cache.check_consistency());
  EXPECT_EQ(s2.surface_cache_hits, 2u);
  EXPECT_EQ(s2.surfaces_built, 0u);
  // Rows other than the two cached ones are the unlit texture, exactly.
  BspWorld& w = sc.tw.world();
  auto view = make_view({0, 0, 0}, 0, 0, 90, CacheScene::W, CacheScene::H);
  for (int i = 2; i < CacheScene::H; ++i) {
    const Face& face = w.faces[sc.faces[i]];
    TestFramebuffer ref(CacheScene::W, CacheScene::H);
    const Texture& tex = w.textures[render::animated_texture(w, w.texinfo[face.texinfo].texture, 0.0)];
    render::draw_texture_spans(&sc.spans[i], 1, render::face_gradients(w, face, view, 0), tex, 0,
                               face.texture_mins[0], face.texture_mins[1], face.extents[0], face.extents[1], ref.fb);
    EXPECT_EQ(std::memcmp(&ref.pixels[size_t(i) * CacheScene::W], &f1.pixels[size_t(i) * CacheScene::W],
                          CacheScene::W), 0) << "row " << i;
    for (int x = 0; x < CacheScene::W; ++x) ASSERT_EQ(f1.coverage[size_t(i) * CacheScene::W + x], 1);
  }
}

TEST(DrawSurfaces, EveryPixelOnceAcrossSurfaceKinds) {
  HandWorld tw;
  int wall = tw.add_texture("wall", 64, 64, 1);
  int water = tw.add_texture("*water", 64, 64, 2, kTexTurb);
  int sky = tw.add_texture("sky1", 256, 128, 3, kTexSky);
  int pl = tw.add_plane({1, 0, 0}, 128);
  int ti_wall = tw.add_texinfo({0, 1, 0, 0}, {0, 0, -1, 0}, wall);
  int ti_water = tw.add_texinfo({0, 1, 0, 0}, {0, 0, -1, 0}, water, kTexSpecial);
  int ti_sky = tw.add_texinfo({0, 1, 0, 0}, {0, 0, -1, 0}, sky, kTexSpecial);
  const uint8_t styles[4] = {0, 255, 255, 255};
  int f_wall = tw.add_face(pl, ti_wall, -512, -512, 1024, 1024, styles, 1);
  int f_water = tw.add_face(pl, ti_water, -512, -512, 1024, 1024, styles, 2, kFaceTurb, false);
  int f_sky = tw.add_face(pl, ti_sky, -512, -512, 1024, 1024, styles, 3, kFaceSky, false);
  BspWorld& w = tw.world();
  const int W = 97, H = 41;
  // Each row split in four runs: background | wall | water | sky, at row-dependent cuts.
  std::vector<Span> per[4];
  for (int y = 0; y < H; ++y) {
    int c1 = (y * 7) % 30, c2 = c1 + (y * 5) % 25, c3 = c2 + (y * 3) % 33;
    int cuts[5] = {0, c1, c2, c3, W};
    for (int k = 0; k < 4; ++k) per[k].push_back(Span{int16_t(cuts[k]), int16_t(y), int16_t(cuts[k + 1] - cuts[k]), 0});
  }
  std::vector<Span> spans;
  std::vector<SurfaceDraw> surfs;
  const uint32_t ids[4] = {render::kBackgroundFace, uint32_t(f_wall), uint32_t(f_water), uint32_t(f_sky)};
  for (int k = 0; k < 4; ++k) {
    surfs.push_back(SurfaceDraw{ids[k], 0.01f, uint32_t(spans.size()), uint32_t(per[k].size())});
    spans.insert(spans.end(), per[k].begin(), per[k].end());
  }
  FrameSpans fs{spans.data(), uint32_t(spans.size()), surfs.data(), uint32_t(surfs.size())};
  TestMemory tm(32);
  auto cm = colormap_or_synthetic();
  render_new_level(w);
  tm.mem.begin_frame();
  TestFramebuffer tf(W, H);
  RenderInputs in;
  in.world = &w;
  in.colormap = cm.data();
  in.time = 2.5;
  RenderStats st;
  render::draw_surfaces(w, make_view({0, 0, 0}, 10, 5, 90, W, H), fs, in, tf.fb, tm.mem, &st);
  for (int i = 0; i < W * H; ++i) ASSERT_EQ(tf.coverage[size_t(i)], 1) << i;
  for (const Span& s : per[0])
    for (int x = s.x; x < s.x + s.count; ++x) EXPECT_EQ(tf.pixels[size_t(s.y) * W + x], 0);
  EXPECT_EQ(st.surfaces_built, 1u);
}

}  // namespace
}  // namespace sb::test::back
