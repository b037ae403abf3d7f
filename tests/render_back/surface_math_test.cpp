// The shared rules of surface_math.h, checked against their documented formulas, and the
// surface builder against the per-texel closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/render/surface_cache.h"
#include "engine/render/surface_math.h"
#include "tests/render_back/back_test_util.h"

namespace sb::test::back {
namespace {

using render::shade_at;

TEST(SurfaceMath, LightGridSumsStylesAndClamps) {
  HandWorld tw;
  int tex = tw.add_texture("wall", 64, 64, 1);
  int pl = tw.add_plane({1, 0, 0}, 0);
  int ti = tw.add_texinfo({0, 1, 0, 0}, {0, 0, 1, 0}, tex);
  const uint8_t styles[4] = {0, 5, 70, 255};  // style 70 is beyond the 64 slots: counts as 256
  int f = tw.add_face(pl, ti, 0, 0, 48, 32, styles, 7);
  BspWorld& w = tw.world();
  const Face& face = w.faces[f];
  int ls[kMaxLightStyleSlots];
  for (int& v : ls) v = 256;
  ls[0] = 100;
  ls[5] = -20;  // negative counts as 0
  std::vector<uint16_t> grid(size_t(render::light_grid_size(face)));
  int gh = 0;
  const int gw = render::face_light_grid(w, face, ls, grid.data(), &gh);
  ASSERT_EQ(gw, 4);
  ASSERT_EQ(gh, 3);
  const int n = gw * gh;
  for (int i = 0; i < n; ++i) {
    const uint8_t* s = w.lightdata + face.light_offset;
    int l = s[i] * 100 + s[n + i] * 0 + s[2 * n + i] * 256;
    int shade = (255 * 256 - l) >> 2;
    shade = std::clamp(shade, 64, 63 * 256 + 255);
    EXPECT_EQ(grid[size_t(i)], shade) << i;
  }
  // No lightmap: full light everywhere.
  int f2 = tw.add_face(pl, ti, 0, 0, 32, 32, styles, 8, 0, false);
  BspWorld& w2 = tw.world();
  std::vector<uint16_t> g2(size_t(render::light_grid_size(w2.faces[f2])));
  render::face_light_grid(w2, w2.faces[f2], nullptr, g2.data(), nullptr);
  for (uint16_t v : g2) EXPECT_EQ(v, 64);
}

TEST(SurfaceMath, ShadeAtInterpolatesExactly) {
  // 3 x 3 grid; corners equal grid points at every mip, midpoints the mean.
  const uint16_t grid[9] = {64, 1000, 16383, 500, 700, 900, 8000, 4000, 64};
  for (int mip = 0; mip < 4; ++mip) {
    const int b = 16 >> mip;
    for (int gy = 0; gy < 2; ++gy)
      for (int gx = 0; gx < 2; ++gx) EXPECT_EQ(shade_at(grid, 3, gx * b, gy * b, mip), grid[gy * 3 + gx]);
    for (int v = 0; v < 2 * b; ++v)
      for (int u = 0; u < 2 * b; ++u) {
        const int gx = u / b, gy = v / b, fx = u % b, fy = v % b;
        const double a = grid[gy * 3 + gx] * double(b - fx) * (b - fy) + grid[gy * 3 + gx + 1] * double(fx) * (b - fy) +
                         grid[(gy + 1) * 3 + gx] * double(b - fx) * fy + grid[(gy + 1) * 3 + gx + 1] * double(fx) * fy;
        EXPECT_EQ(shade_at(grid, 3, u, v, mip), int(std::floor(a / (b * b)))) << mip << " " << u << " " << v;
      }
  }
}

TEST(SurfaceMath, ChooseMipThresholds) {
  EXPECT_EQ(render::choose_mip(1.0f / 100, 400, 1), 0);  // p = 4
  EXPECT_EQ(render::choose_mip(1.0f / 400, 400, 1), 0);  // p = 1
  EXPECT_EQ(render::choose_mip(1.0f / 500, 400, 1), 1);  // p = 0.8
  EXPECT_EQ(render::choose_mip(1.0f / 1000, 400, 1), 1); // p = 0.4
  EXPECT_EQ(render::choose_mip(1.0f / 1500, 400, 1), 2);
  EXPECT_EQ(render::choose_mip(1.0f / 2000, 400, 1), 2); // p = 0.2
  EXPECT_EQ(render::choose_mip(1.0f / 4000, 400, 1), 3);
  EXPECT_EQ(render::choose_mip(1.0f / 400, 400, 2), 1);  // texture scaled down 2x
  EXPECT_EQ(render::choose_mip(NAN, 400, 1), 3);
  EXPECT_EQ(render::choose_mip(1.0f / 400, 400, 0), 0);  // bad mipadjust counts as 1
}

TEST(SurfaceMath, TextureTexelWraps) {
  HandWorld tw;
  int t = tw.add_texture("w", 48, 32, 3);
  const Texture& tex = tw.world().textures[t];
  for (int mip = 0; mip < 4; ++mip) {
    const int w = 48 >> mip, h = 32 >> mip;
    EXPECT_EQ(render::texture_texel(tex, mip, -16, -32, 0, 0),
              tex.mips[mip][((-32 >> mip) % h + h) % h * w + ((-16 >> mip) % w + w) % w]);
    EXPECT_EQ(render::texture_texel(tex, mip, 0, 0, w + 1, 2 * h + 1), tex.mips[mip][1 * w + 1]);
  }
}

TEST(SurfaceMath, AnimatedTextureFollowsChain) {
  HandWorld tw;
  int a = tw.add_texture("+0lava", 16, 16, 1);
  int b = tw.add_texture("+1lava", 16, 16, 2);
  int c = tw.add_texture("+2lava", 16, 16, 3);
  BspWorld& w = tw.world();
  w.textures[a].anim_next = b; w.textures[a].anim_total = 3; w.textures[a].anim_index = 0;
  w.textures[b].anim_next = c; w.textures[b].anim_total = 3; w.textures[b].anim_index = 1;
  w.textures[c].anim_next = a; w.textures[c].anim_total = 3; w.textures[c].anim_index = 2;
  EXPECT_EQ(render::animated_texture(w, a, 0.0), a);
  EXPECT_EQ(render::animated_texture(w, a, 0.21), b);
  EXPECT_EQ(render::animated_texture(w, b, 0.45), c);
  EXPECT_EQ(render::animated_texture(w, c, 0.61), a);   // frame 3 mod 3 = 0
  EXPECT_EQ(render::animated_texture(w, b, -0.1), c);   // frame -1 mod 3 = 2
  w.textures[b].anim_next = 99999;                       // broken chain: stays put
  EXPECT_EQ(render::animated_texture(w, a, 0.45), a);
}

TEST(SurfaceMath, SkyFrontLayerOverBackLayer) {
  HandWorld tw;
  int t = tw.add_texture("sky1", 256, 128, 9, kTexSky);
  Texture& sky = tw.world().textures[t];
  auto* px = const_cast<uint8_t*>(sky.mips[0]);
  // Looking straight up: n = (0, 0, 1): layer coordinates = speed * time.
  for (int i = 0; i < 256 * 128; ++i) if (px[i] == 0) px[i] = 1;
  EXPECT_EQ(render::sky_texel(sky, {0, 0, 1}, 0.0), px[0]);
  EXPECT_EQ(render::sky_texel(sky, {0, 0, 1}, 1.0), px[16 * 256 + 16]);  // front layer moved 16
  px[16 * 256 + 16] = 0;                                                 // transparent: back layer at 8
  EXPECT_EQ(render::sky_texel(sky, {0, 0, 1}, 1.0), px[8 * 256 + 128 + 8]);
  // Horizontal direction along +x: s = floor(378) mod 128 = 122, t = 0.
  EXPECT_EQ(render::sky_texel(sky, {5, 0, 0}, 0.0), px[122]);
}

TEST(SurfaceMath, TurbulenceWarpsByTheOtherAxis) {
  HandWorld tw;
  int t = tw.add_texture("*water", 64, 64, 4, kTexTurb);
  const Texture& tex = tw.world().textures[t];
  EXPECT_EQ(render::turb_offset(0), 0);
  EXPECT_EQ(render::turb_offset(32), 8 * 65536);
  EXPECT_EQ(render::turb_offset(96), -8 * 65536);
  EXPECT_EQ(render::turb_phase(1.0), 20);
  EXPECT_EQ(render::turb_phase(-0.01), 127);
  // At time 0, t = 32.5: s warps by +8; s = 0.25: t warps by turb_offset(0) = 0.
  EXPECT_EQ(render::turb_texel(tex, 0.25f, 32.5f, 0.0), tex.mips[0][32 * 64 + 8]);
  // Negative coordinates wrap.
  const int s2 = int(std::floor(-3.5 + render::turb_offset((-2 + 0) & 127) / 65536.0));
  const int t2 = int(std::floor(-1.5 + render::turb_offset((-4 + 0) & 127) / 65536.0));
  EXPECT_EQ(render::turb_texel(tex, -3.5f, -1.5f, 0.0), tex.mips[0][((t2 % 64 + 64) % 64) * 64 + ((s2 % 64 + 64) % 64)]);
}

// The builder equals the closed form shade_at + texture_texel per texel, at every mip.
void expect_builder_matches(const BspWorld& w, const Face& face, const int* ls, const uint8_t* colormap) {
  std::vector<uint16_t> grid(size_t(render::light_grid_size(face)));
  const int gw = render::face_light_grid(w, face, ls, grid.data(), nullptr);
  const Texture& tex = w.textures[w.texinfo[face.texinfo].texture];
  for (int mip = 0; mip < 4; ++mip) {
    const int sw = face.extents[0] >> mip, sh = face.extents[1] >> mip;
    std::vector<uint8_t> out(size_t(sw) * sh, 0);
    render::build_surface(grid.data(), gw, tex, mip, face.texture_mins[0], face.texture_mins[1], sw, sh, colormap,
                          out.data());
    int bad = 0;
    for (int v = 0; v < sh; ++v)
      for (int u = 0; u < sw; ++u) {
        const int row = shade_at(grid.data(), gw, u, v, mip) >> 8;
        const uint8_t want =
            colormap[row * 256 + render::texture_texel(tex, mip, face.texture_mins[0], face.texture_mins[1], u, v)];
        if (out[size_t(v) * sw + u] != want && ++bad < 5) ADD_FAILURE() << "mip " << mip << " texel " << u << "," << v;
      }
    EXPECT_EQ(bad, 0) << "mip " << mip;
  }
}

TEST(SurfaceBuilder, MatchesClosedFormEveryMip) {
  HandWorld tw;
  int t1 = tw.add_texture("a", 64, 64, 11);
  int t2 = tw.add_texture("b", 48, 80, 12);  // not a power of two
  int pl = tw.add_plane({1, 0, 0}, 0);
  int ti1 = tw.add_texinfo({0, 1, 0, 0}, {0, 0, 1, 0}, t1);
  int ti2 = tw.add_texinfo({0, 1, 0, 0}, {0, 0, 1, 0}, t2);
  const uint8_t one[4] = {0, 255, 255, 255};
  const uint8_t three[4] = {0, 1, 2, 255};
  std::vector<int> faces = {
      tw.add_face(pl, ti1, 0, 0, 16, 16, one, 1),        tw.add_face(pl, ti1, -48, 32, 128, 64, three, 2),
      tw.add_face(pl, ti2, -1024, 16, 256, 16, one, 3),  tw.add_face(pl, ti2, 160, -2048, 16, 2048, three, 4),
      tw.add_face(pl, ti1, 0, 0, 64, 48, one, 5, 0, false)};
  BspWorld& w = tw.world();
  auto cm = colormap_or_synthetic();
  int ls[kMaxLightStyleSlots];
  for (int i = 0; i < kMaxLightStyleSlots; ++i) ls[i] = 128 + 37 * i;
  for (int f : faces) {
    expect_builder_matches(w, w.faces[f], nullptr, cm.data());
    expect_builder_matches(w, w.faces[f], ls, cm.data());
  }
}

}  // namespace
}  // namespace sb::test::back
