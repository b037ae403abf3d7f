// Single-pass texture + light (RenderInputs::single_pass, engine/render/single_pass.h) against
// the cached path (surface cache + surface span kernel), pixel by pixel.
//
// Each path renders every view three times: with the real colormap, with a colormap whose
// entry (row, index) is the row (the picture is then each pixel's light level) and with one
// whose entry is the index (each pixel's texel). The comparison requires every pixel's light
// level to differ by at most one step and its texel to be identical, and reports how many
// final pixels are identical. A synthetic scene shows the comparison fails on a wrong light
// interpolation or a wrong texel, and tolerates a light rounded differently by one step.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "asm/lit_span.h"
#include "engine/render/render_local.h"
#include "engine/render/single_pass.h"
#include "engine/render/span_draw.h"
#include "engine/render/surface_cache.h"
#include "engine/render/surface_math.h"
#include "tests/render_back/back_test_util.h"
#include "tests/support/quake_data.h"
#include "tests/support/test_world.h"

namespace sb::test::back {
namespace {

using render::Span;

std::vector<uint8_t> light_colormap() {  // (row, index) -> row: the picture is the light level
  std::vector<uint8_t> cm(64 * 256);
  for (int r = 0; r < 64; ++r)
    for (int i = 0; i < 256; ++i) cm[size_t(r) * 256 + i] = uint8_t(r);
  return cm;
}
std::vector<uint8_t> texel_colormap() {  // (row, index) -> index: the picture is the texel
  std::vector<uint8_t> cm(64 * 256);
  for (int r = 0; r < 64; ++r)
    for (int i = 0; i < 256; ++i) cm[size_t(r) * 256 + i] = uint8_t(i);
  return cm;
}

// One path's three pictures of a view.
struct Pictures {
  std::vector<uint8_t> light, texel, color;
};

struct Comparison {
  uint64_t pixels = 0, identical = 0, light_identical = 0, light_one_step = 0, light_more = 0, texel_differs = 0;
  int max_light_diff = 0;
  void add(const Pictures& a, const Pictures& b) {
    for (size_t i = 0; i < a.color.size(); ++i) {
      ++pixels;
      identical += a.color[i] == b.color[i];
      const int d = std::abs(int(a.light[i]) - int(b.light[i]));
      if (d > max_light_diff) max_light_diff = d;
      ++(d == 0 ? light_identical : d == 1 ? light_one_step : light_more);
      texel_differs += a.texel[i] != b.texel[i];
    }
  }
  bool within_one_step() const { return light_more == 0 && texel_differs == 0; }
  double pct(uint64_t n) const { return pixels ? 100.0 * double(n) / double(pixels) : 100.0; }
  std::string summary() const {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "%llu pixels: %.4f%% identical, light identical %.4f%%, one step %.4f%%, more %llu, max light "
                  "diff %d, texel differs %llu",
                  (unsigned long long)pixels, pct(identical), pct(light_identical), pct(light_one_step),
                  (unsigned long long)light_more, max_light_diff, (unsigned long long)texel_differs);
    return buf;
  }
};

// ---------------------------------------------------------------- synthetic: a lit wall

// A big lit wall at x = 128 seen obliquely (every pixel hits it), random lightmap samples
// (strong light gradients), a texture of 48x80 texels (not a power of two: the wrap).
struct Wall {
  HandWorld hw;
  int face = 0;
  Wall() {
    const int tex = hw.add_texture("wall", 48, 80, 77);
    const int pl = hw.add_plane({1, 0, 0}, 128);
    const int ti = hw.add_texinfo({0, 1, 0, 3.0f}, {0, 0, -1, -5.0f}, tex);
    const uint8_t styles[4] = {0, 3, 255, 255};
    face = hw.add_face(pl, ti, -1024, -1024, 2048, 2048, styles, 9);
  }
};

constexpr int kW = 320, kH = 200;

std::vector<Span> full_rows() {
  std::vector<Span> s;
  for (int y = 0; y < kH; ++y) s.push_back(Span{0, int16_t(y), int16_t(kW), 0});
  return s;
}

// The cached path's pixels: surface built with the builder, drawn by the surface span drawer.
std::vector<uint8_t> wall_cached(Wall& w, const render::ViewState& view, int mip, const int* ls,
                                 const std::vector<uint8_t>& cm) {
  BspWorld& world = w.hw.world();
  const Face& f = world.faces[w.face];
  std::vector<uint16_t> grid(size_t(render::light_grid_size(f)));
  const int gw = render::face_light_grid(world, f, ls, grid.data(), nullptr);
  const int sw = f.extents[0] >> mip, sh = f.extents[1] >> mip;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  render::build_surface(grid.data(), gw, world.textures[world.texinfo[f.texinfo].texture], mip, f.texture_mins[0],
                        f.texture_mins[1], sw, sh, cm.data(), surf.data());
  TestFramebuffer tf(kW, kH);
  const std::vector<Span> spans = full_rows();
  render::draw_surface_spans(spans.data(), uint32_t(spans.size()), render::face_gradients(world, f, view, mip),
                             surf.data(), sw, sh, tf.fb);
  return tf.pixels;
}

// The single-pass drawer's pixels with kernel `fn`.
std::vector<uint8_t> wall_single(Wall& w, const render::ViewState& view, int mip, const int* ls,
                                 const std::vector<uint8_t>& cm, simd::LitSpanFn fn) {
  BspWorld& world = w.hw.world();
  const Face& f = world.faces[w.face];
  TestMemory tm(16);
  TestFramebuffer tf(kW, kH);
  RenderInputs in;
  in.world = &world;
  in.lightstyles = ls;
  in.colormap = cm.data();
  RenderStats st;
  const std::vector<Span> spans = full_rows();
  const size_t frame_used = tm.mem.frame().used();
  const bool drawn = render::draw_single_pass_surface(
      world, uint32_t(w.face), mip, world.textures[world.texinfo[f.texinfo].texture],
      render::face_gradients(world, f, view, mip), spans.data(), uint32_t(spans.size()), in, fn, tm.mem, st, tf.fb);
  EXPECT_TRUE(drawn);
  EXPECT_EQ(st.single_pass_surfaces, 1u);
  EXPECT_EQ(tm.mem.frame().used(), frame_used) << "the light grid is popped";
  return tf.pixels;
}

// Wrong kernels the comparison must catch (or, for the rounding, tolerate).
int shade_nearest_corner(const simd::LitSpanSource& s, int U, int V) {  // no interpolation
  const int b = 16 >> s.mip;
  return s.grid[(V / b) * s.grid_width + U / b];
}
int shade_rounded_up(const simd::LitSpanSource& s, int U, int V) {  // rounds instead of truncating
  const int b = 16 >> s.mip, shift = 2 * (4 - s.mip);
  const int gx = U / b, fx = U % b, gy = V / b, fy = V % b;
  const uint16_t* g = s.grid + gy * s.grid_width + gx;
  const int num = (g[0] * (b - fx) + g[1] * fx) * (b - fy) + (g[s.grid_width] * (b - fx) + g[s.grid_width + 1] * fx) * fy;
  const int r = (num + (1 << shift) - 1) >> shift;
  return r > 0x3fff ? 0x3fff : r;
}
int shade_exact(const simd::LitSpanSource& s, int U, int V) { return render::shade_at(s.grid, s.grid_width, U, V, s.mip); }

template <int (*Shade)(const simd::LitSpanSource&, int, int), int kTexelShift>
void broken_kernel(uint8_t* dest, int n, const simd::LitSpanSource& s, int32_t u, int32_t v, int32_t du, int32_t dv,
                   int32_t ddu, int32_t ddv) {
  for (int k = 0; k < n; ++k) {
    const int U = u >> 16, V = v >> 16;
    const int tx = ((U + kTexelShift + s.soff) % s.tex_width + s.tex_width) % s.tex_width;
    const int ty = ((V + s.toff) % s.tex_height + s.tex_height) % s.tex_height;
    dest[k] = s.colormap[(Shade(s, U, V) & 0xff00) + s.texels[ty * s.tex_width + tx]];
    u += du;
    v += dv;
    du += ddu;
    dv += ddv;
  }
}

Comparison compare_wall(Wall& w, simd::LitSpanFn fn, const int* ls) {
  const auto cm = colormap_or_synthetic(), lcm = light_colormap(), tcm = texel_colormap();
  Comparison c;
  const render::ViewState views[] = {make_view({0, 0, 0}, 30, 10, 90, kW, kH), make_view({-900, 300, 40}, -35, -20, 90, kW, kH)};
  for (const render::ViewState& view : views) {
    for (int mip = 0; mip < 4; ++mip) {
      Pictures a{wall_cached(w, view, mip, ls, lcm), wall_cached(w, view, mip, ls, tcm),
                 wall_cached(w, view, mip, ls, cm)};
      Pictures b{wall_single(w, view, mip, ls, lcm, fn), wall_single(w, view, mip, ls, tcm, fn),
                 wall_single(w, view, mip, ls, cm, fn)};
      c.add(a, b);
    }
  }
  return c;
}

TEST(SinglePass, SyntheticWallMatchesCachedPathExactly) {
  Wall w;
  int ls[kMaxLightStyleSlots];
  for (int i = 0; i < kMaxLightStyleSlots; ++i) ls[i] = (i * 131) % 700;
  for (const int* styles : {static_cast<const int*>(nullptr), static_cast<const int*>(ls)}) {
    for (int var = 0; var < simd::lit_span_variant_count(); ++var) {
      const simd::LitSpanVariant v = simd::lit_span_variant(var);
      if (!v.supported) continue;
      const Comparison c = compare_wall(w, v.fn, styles);
      std::printf("[ single   ] wall, kernel %s, %s styles: %s\n", v.name, styles ? "varied" : "normal",
                  c.summary().c_str());
      EXPECT_TRUE(c.within_one_step()) << v.name;
      EXPECT_EQ(c.identical, c.pixels) << v.name;
    }
  }
}

TEST(SinglePass, ComparisonCatchesWrongLightOrTexel) {
  Wall w;
  const Comparison exact = compare_wall(w, broken_kernel<shade_exact, 0>, nullptr);
  const Comparison nearest = compare_wall(w, broken_kernel<shade_nearest_corner, 0>, nullptr);
  const Comparison texel = compare_wall(w, broken_kernel<shade_exact, 1>, nullptr);
  const Comparison rounded = compare_wall(w, broken_kernel<shade_rounded_up, 0>, nullptr);
  std::printf("[ single   ] test kernel, exact:          %s\n", exact.summary().c_str());
  std::printf("[ single   ] test kernel, nearest light:  %s\n", nearest.summary().c_str());
  std::printf("[ single   ] test kernel, texel + 1:      %s\n", texel.summary().c_str());
  std::printf("[ single   ] test kernel, light rounded:  %s\n", rounded.summary().c_str());
  EXPECT_TRUE(exact.within_one_step());
  EXPECT_EQ(exact.identical, exact.pixels);
  EXPECT_FALSE(nearest.within_one_step()) << "no bilinear light: many pixels several steps off";
  EXPECT_GT(nearest.max_light_diff, 1);
  EXPECT_FALSE(texel.within_one_step()) << "wrong texel column";
  EXPECT_GT(texel.texel_differs, texel.pixels / 2);
  EXPECT_TRUE(rounded.within_one_step()) << "a different rounding moves the light at most one step";
  EXPECT_EQ(rounded.max_light_diff, 1);
  EXPECT_LT(rounded.identical, rounded.pixels);
}

// ---------------------------------------------------------------- real maps

// Frees every lit surface so that the next cached render builds them with its colormap (the
// cache key does not include the colormap: it is fixed for a running engine).
void drop_surfaces(TestWorld& tw) {
  BspWorld& w = *tw.world();
  for (uint32_t i = 0; i < w.num_faces; ++i)
    for (int m = 0; m < 4; ++m) tw.memory().cache.free(w.faces[i].cache[m]);
  render_new_level(w);
}

Status render_path(TestWorld& tw, const ViewParams& view, int width, int height, double time, const int* ls,
                   const std::vector<uint8_t>& cm, bool single_pass, std::vector<uint8_t>* pixels, RenderStats* st) {
  if (!single_pass) drop_surfaces(tw);
  pixels->assign(size_t(width) * height, 0);
  tw.memory().begin_frame();
  RenderInputs in;
  in.world = tw.world();
  in.view = view;
  in.time = time;
  in.lightstyles = ls;
  in.colormap = cm.data();
  in.single_pass = single_pass;
  Framebuffer fb;
  fb.pixels = pixels->data();
  fb.width = fb.stride = width;
  fb.height = height;
  return render_world(in, fb, tw.memory(), st);
}

TEST(SinglePass, RealMapsMatchCachedPathWithinOneLightStep) {
  SB_REQUIRE_QUAKE_DATA();
  const auto cm = sb::test::load_colormap(), lcm = light_colormap(), tcm = texel_colormap();
  ASSERT_EQ(cm.size(), 64u * 256u);
  int ls[kMaxLightStyleSlots];
  for (int i = 0; i < kMaxLightStyleSlots; ++i) ls[i] = (i * 97) % 600;
  Comparison all;
  for (const char* map : {"start", "lq_e0m1", "lq_e1m1"}) {
    sb::test::TestWorld tw(map);
    ASSERT_NE(tw.world(), nullptr) << tw.error();
    const std::vector<ViewParams> views = sb::test::test_viewpoints(*tw.world(), 6);
    ASSERT_FALSE(views.empty());
    Comparison per_map;
    uint64_t lit_surfaces = 0;
    for (size_t vi = 0; vi < views.size(); ++vi) {
      for (auto [W, H] : {std::pair{320, 200}, std::pair{1280, 720}}) {
        const int* styles = vi % 2 ? ls : nullptr;
        const double time = 0.5 + double(vi);
        Pictures p[2];
        for (int single = 0; single < 2; ++single) {
          RenderStats st[3];
          const std::vector<uint8_t>* cms[3] = {&lcm, &tcm, &cm};
          std::vector<uint8_t>* out[3] = {&p[single].light, &p[single].texel, &p[single].color};
          for (int k = 0; k < 3; ++k) {
            Status s = render_path(tw, views[vi], W, H, time, styles, *cms[k], single != 0, out[k], &st[k]);
            ASSERT_TRUE(s.is_ok()) << s.message();
            EXPECT_FALSE(st[k].cache_exhausted) << map << " view " << vi;
            if (single) {
              EXPECT_EQ(st[k].surfaces_built + st[k].surface_cache_hits, 0u) << "single pass uses no cache";
              EXPECT_GT(st[k].single_pass_surfaces, 0u);
              lit_surfaces += st[k].single_pass_surfaces;
            } else {
              EXPECT_EQ(st[k].single_pass_surfaces, 0u);
            }
          }
        }
        Comparison c;
        c.add(p[0], p[1]);
        EXPECT_TRUE(c.within_one_step()) << map << " view " << vi << " " << W << "x" << H << ": " << c.summary();
        per_map.add(p[0], p[1]);
        all.add(p[0], p[1]);
      }
    }
    std::printf("[ single   ] %-8s %zu views x 2 sizes (%llu lit surfaces single pass): %s\n", map, views.size(),
                (unsigned long long)lit_surfaces / 3, per_map.summary().c_str());
  }
  std::printf("[ single   ] all maps: %s\n", all.summary().c_str());
  EXPECT_TRUE(all.within_one_step());
  EXPECT_LE(all.max_light_diff, 1);
}

}  // namespace
}  // namespace sb::test::back
