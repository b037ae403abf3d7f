// Span drawers against exact per-pixel perspective: lit surfaces, span lengths, z, sky,
// turbulence, coverage.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "engine/render/span_draw.h"
#include "engine/render/surface_cache.h"
#include "engine/render/surface_math.h"
#include "tests/render_back/back_test_util.h"

namespace sb::test::back {
namespace {

using render::Span;

struct Agreement {
  uint64_t pixels = 0, exact = 0, off_by_one = 0, other = 0;
  double exact_fraction() const { return pixels ? double(exact) / double(pixels) : 1.0; }
};

// A big lit wall at x = 128 seen obliquely; every pixel of a 90-degree view hits it.
struct WallScene {
  HandWorld tw;
  int face = 0;
  WallScene(bool turb = false) {
    int tex = tw.add_texture(turb ? "*water" : "wall", 64, 64, 21, turb ? kTexTurb : kTexNormal);
    int pl = tw.add_plane({1, 0, 0}, 128);
    int ti = tw.add_texinfo({0, 1, 0, 3.25f}, {0, 0, -1, -7.5f}, tex, turb ? uint32_t(kTexSpecial) : 0u);
    const uint8_t styles[4] = {0, 255, 255, 255};
    face = tw.add_face(pl, ti, -1024, -1024, 2048, 2048, styles, 5, uint16_t(turb ? kFaceTurb : 0), !turb);
  }
};

std::vector<Span> full_rows(int w, int h) {
  std::vector<Span> s;
  for (int y = 0; y < h; ++y) s.push_back(Span{0, int16_t(y), int16_t(w), 0});
  return s;
}

// The drawer's algorithm, modelled independently: exact values at the ends of every run
// (16 pixels; a span's last run ends at its last pixel), linear in between.
// Returns the modelled value of f at pixel x of span sp.
template <class F>
double run_model(const Span& sp, int x, F f) {
  const int k = x - sp.x;
  const int run_start = (k / 16) * 16;
  const int left = sp.count - run_start;
  const double a = f(sp.x + run_start + 0.5);
  if (left > 16) return a + (f(sp.x + run_start + 16.5) - a) * double(k - run_start) / 16.0;
  if (left == 1) return a;
  return a + (f(sp.x + run_start + left - 0.5) - a) * double(k - run_start) / double(left - 1);
}

// Draws `spans` of the wall's lit surface at `mip` and compares each pixel's texel with
// (model = false) the exact perspective texel, drawn with the default second-order stepping,
// or (model = true) the linear 16-pixel model's texel, drawn with linear stepping.
// A mismatch counts as off by one when a neighbouring texel (|du|, |dv| <= 1) matches.
Agreement check_surface_spans(WallScene& sc, const render::ViewState& view, const std::vector<Span>& spans, int mip,
                              TestFramebuffer& tf, bool model) {
  BspWorld& w = sc.tw.world();
  const Face& face = w.faces[sc.face];
  auto cm = colormap_or_synthetic();
  std::vector<uint16_t> grid(size_t(render::light_grid_size(face)));
  const int gw = render::face_light_grid(w, face, nullptr, grid.data(), nullptr);
  const int sw = face.extents[0] >> mip, sh = face.extents[1] >> mip;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  render::build_surface(grid.data(), gw, w.textures[w.texinfo[face.texinfo].texture], mip, face.texture_mins[0],
                        face.texture_mins[1], sw, sh, cm.data(), surf.data());
  render::SpanGradients g = render::face_gradients(w, face, view, mip);
  g.second_order = !model;  // the model is Quake's linear walk; exact comparisons use the default
  render::draw_surface_spans(spans.data(), uint32_t(spans.size()), g, surf.data(), sw, sh, tf.fb);

  const double scale = 1.0 / double(1 << mip);
  Agreement a;
  for (const Span& sp : spans)
    for (int x = sp.x; x < sp.x + sp.count; ++x) {
      const double py = sp.y + 0.5;
      // Clamped exact texel coordinates at screen x (continuous).
      auto uf = [&](double px) {
        double s, t;
        EXPECT_TRUE(exact_st(w, face, view, px, py, &s, &t));
        return std::clamp((s - face.texture_mins[0]) * scale, 0.0, sw - 1e-6);
      };
      auto vf = [&](double px) {
        double s, t;
        EXPECT_TRUE(exact_st(w, face, view, px, py, &s, &t));
        return std::clamp((t - face.texture_mins[1]) * scale, 0.0, sh - 1e-6);
      };
      const double ue = model ? run_model(sp, x, uf) : uf(x + 0.5);
      const double ve = model ? run_model(sp, x, vf) : vf(x + 0.5);
      const int u = std::clamp(int(std::floor(ue)), 0, sw - 1);
      const int v = std::clamp(int(std::floor(ve)), 0, sh - 1);
      const uint8_t got = tf.pixels[size_t(sp.y) * tf.fb.stride + x];
      ++a.pixels;
      if (got == surf[size_t(v) * sw + u]) { ++a.exact; continue; }
      bool near = false;
      for (int dv = -1; dv <= 1 && !near; ++dv)
        for (int du = -1; du <= 1 && !near; ++du) {
          const int uu = u + du, vv = v + dv;
          if (uu >= 0 && uu < sw && vv >= 0 && vv < sh && surf[size_t(vv) * sw + uu] == got) near = true;
        }
      ++(near ? a.off_by_one : a.other);
    }
  return a;
}

void report(const char* what, const Agreement& a) {
  std::printf("%s: exact %.3f%%, off by one %.3f%%, other %.3f%%\n", what, 100.0 * a.exact_fraction(),
              100.0 * double(a.off_by_one) / double(a.pixels), 100.0 * double(a.other) / double(a.pixels));
}

// The drawer does exactly what its algorithm says, for every mip and oblique views.
TEST(SpanDraw, LitSurfaceFollowsSixteenPixelModel) {
  WallScene sc;
  const int W = 320, H = 200;
  const auto spans = full_rows(W, H);
  for (float yaw : {0.0f, 25.0f, -30.0f}) {
    for (int mip = 0; mip < 4; ++mip) {
      TestFramebuffer tf(W, H);
      auto view = make_view({0, 0, 0}, yaw, 15.0f, 90.0f, W, H);
      Agreement a = check_surface_spans(sc, view, spans, mip, tf, true);
      char what[64];
      std::snprintf(what, sizeof what, "model yaw %4.1f mip %d", yaw, mip);
      report(what, a);
      EXPECT_GE(a.exact_fraction(), 0.995) << what;
      EXPECT_EQ(a.other, 0u) << what;
    }
  }
}

// Against exact perspective: a view at the mip choose_mip picks for it (nearest pixel).
Agreement perspective_agreement(float yaw, float pitch, int W, int H) {
  WallScene sc;
  const auto spans = full_rows(W, H);
  auto view = make_view({0, 0, 0}, yaw, pitch, 90.0f, W, H);
  BspWorld& w = sc.tw.world();
  double nearzi = 0;
  for (int y : {0, H - 1})
    for (int x : {0, W - 1}) {
      double s, t, zi;
      if (exact_st(w, w.faces[sc.face], view, x + 0.5, y + 0.5, &s, &t, &zi)) nearzi = std::max(nearzi, zi);
    }
  const int mip = render::choose_mip(float(nearzi), view.xscale, w.texinfo[w.faces[sc.face].texinfo].mipadjust);
  TestFramebuffer tf(W, H);
  return check_surface_spans(sc, view, spans, mip, tf, false);
}

TEST(SpanDraw, LitSurfaceMatchesExactPerspective) {
  for (float yaw : {0.0f, 15.0f, 25.0f}) {
    Agreement a = perspective_agreement(yaw, 15.0f, 1920, 1080);
    char what[64];
    std::snprintf(what, sizeof what, "perspective 1920x1080 yaw %4.1f", yaw);
    report(what, a);
    EXPECT_GE(a.exact_fraction(), 0.98) << what;
    EXPECT_EQ(a.other, 0u) << what;
  }
  // Low resolution, oblique: the 16-pixel runs span more of the view. Linear stepping got
  // 76% here; the second-order step must hold 98% too.
  for (float yaw : {25.0f, 30.0f}) {
    Agreement a = perspective_agreement(yaw, 15.0f, 320, 200);
    char what[64];
    std::snprintf(what, sizeof what, "perspective 320x200 yaw %4.1f", yaw);
    report(what, a);
    EXPECT_GE(a.exact_fraction(), 0.98) << what;
  }
}

TEST(SpanDraw, SpanLengthsAndZ) {
  WallScene sc;
  const int W = 1920, H = 16;
  auto view = make_view({0, 0, 0}, 30.0f, -10.0f, 90.0f, W, H);
  const int lengths[] = {0, 1, 15, 16, 17, 31, 32, 33, 1920, 1000};
  std::vector<Span> spans;
  for (int i = 0; i < int(std::size(lengths)); ++i) {
    const int x = lengths[i] == 1920 ? 0 : 7 + 13 * i;
    spans.push_back(Span{int16_t(x), int16_t(i), int16_t(lengths[i]), 0});
  }
  TestFramebuffer tf(W, H);
  Agreement a = check_surface_spans(sc, view, spans, 0, tf, true);
  EXPECT_GE(a.exact_fraction(), 0.98);
  EXPECT_EQ(a.other, 0u);
  // Coverage: exactly the span pixels, once.
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      int want = 0;
      for (const Span& s : spans) want += (s.y == y && x >= s.x && x < s.x + s.count);
      ASSERT_EQ(tf.coverage[size_t(y) * W + x], want) << x << "," << y;
      if (!want) {
        ASSERT_EQ(tf.pixels[size_t(y) * W + x], 0xEE) << "pixel outside the spans written";
      }
    }
  // z: floor(zi * 0x8000) within one unit.
  const Face& face = sc.tw.world().faces[sc.face];
  for (const Span& s : spans)
    for (int x = s.x; x < s.x + s.count; ++x) {
      double ss, tt, zi;
      ASSERT_TRUE(exact_st(sc.tw.world(), face, view, x + 0.5, s.y + 0.5, &ss, &tt, &zi));
      const double want = std::min(65535.0, std::floor(zi * 0x8000));
      EXPECT_NEAR(double(tf.z[size_t(s.y) * W + x]), want, 1.0) << x << "," << s.y;
    }
}

// Sky: layer coordinates of the rule (before flooring) along the ray through (px, py).
struct SkyRule {
  const render::ViewState& view;
  glm::dvec3 dir(double px, double py) const {
    return glm::dvec3(view.forward) + ((px - view.xcenter) / view.xscale) * glm::dvec3(view.right) -
           ((py - view.ycenter) / view.yscale) * glm::dvec3(view.up);
  }
  // kSkyScale * n.x (axis 0) or n.y (axis 1)
  double coord(double px, double py, int axis) const {
    glm::dvec3 d = dir(px, py);
    d.z *= 3.0;
    d = glm::normalize(d);
    return render::kSkyScale * (axis == 0 ? d.x : d.y);
  }
};

uint8_t sky_from_coords(const Texture& sky, double q, double r, double time) {
  const int w = int(sky.width), h = int(sky.height), half = w / 2;
  auto wrap = [](int64_t i, int n) { return int(((i % n) + n) % n); };
  const double of = render::kSkyFrontSpeed * time, ob = render::kSkyBackSpeed * time;
  const uint8_t c = sky.mips[0][wrap(int64_t(std::floor(of + r)), h) * w + wrap(int64_t(std::floor(of + q)), half)];
  if (c) return c;
  return sky.mips[0][wrap(int64_t(std::floor(ob + r)), h) * w + half + wrap(int64_t(std::floor(ob + q)), half)];
}

Agreement check_sky(const Texture& sky, const render::ViewState& view, double time, bool model, TestFramebuffer& tf) {
  const int W = view.width, H = view.height;
  const auto spans = full_rows(W, H);
  render::draw_sky_spans(spans.data(), uint32_t(spans.size()), view, sky, time, tf.fb);
  SkyRule rule{view};
  Agreement a;
  for (const Span& sp : spans)
    for (int x = sp.x; x < sp.x + sp.count; ++x) {
      const double py = sp.y + 0.5;
      EXPECT_EQ(tf.coverage[size_t(sp.y) * W + x], 1);
      const uint8_t got = tf.pixels[size_t(sp.y) * W + x];
      ++a.pixels;
      uint8_t want;
      if (model) {
        const double q = run_model(sp, x, [&](double px) { return rule.coord(px, py, 0); });
        const double r = run_model(sp, x, [&](double px) { return rule.coord(px, py, 1); });
        want = sky_from_coords(sky, q, r, time);
        if (got == want) { ++a.exact; continue; }
        bool near = false;  // rounding: a 16.16 step away
        for (int dr = -1; dr <= 1 && !near; ++dr)
          for (int dq = -1; dq <= 1 && !near; ++dq) near = got == sky_from_coords(sky, q + dq * 1e-3, r + dr * 1e-3, time);
        ++(near ? a.off_by_one : a.other);
      } else {
        want = render::sky_texel(sky, glm::vec3(rule.dir(x + 0.5, py)), time);
        if (got == want) { ++a.exact; continue; }
        bool near = false;  // the rule's value somewhere within the pixel
        for (double dy = 0.0; dy <= 1.0 && !near; dy += 0.125)
          for (double dx = 0.0; dx <= 1.0 && !near; dx += 0.125)
            near = got == render::sky_texel(sky, glm::vec3(rule.dir(x + dx, sp.y + dy)), time);
        ++(near ? a.off_by_one : a.other);
      }
    }
  return a;
}

struct SkyScene {
  HandWorld tw;
  int t = 0;
  SkyScene() {
    t = tw.add_texture("sky4", 256, 128, 77, kTexSky);
    // A third of the front layer transparent so both layers show.
    auto* px = const_cast<uint8_t*>(tw.world().textures[t].mips[0]);
    for (int y = 0; y < 128; ++y)
      for (int x = 0; x < 128; ++x) {
        if (((x / 8) + (y / 8)) % 3 == 0) px[y * 256 + x] = 0;
      }
  }
  const Texture& sky() { return tw.world().textures[t]; }
};

TEST(SpanDraw, SkyFollowsRunModel) {
  SkyScene sc;
  for (float pitch : {-60.0f, -20.0f, 0.0f, 10.0f}) {
    auto view = make_view({10, 20, 30}, 33.0f, pitch, 100.0f, 400, 300);
    TestFramebuffer tf(400, 300);
    Agreement a = check_sky(sc.sky(), view, 12.34, true, tf);
    char what[64];
    std::snprintf(what, sizeof what, "sky model pitch %5.1f", pitch);
    report(what, a);
    EXPECT_GE(a.exact_fraction(), 0.995) << what;
    EXPECT_EQ(a.other, 0u) << what;
  }
}

TEST(SpanDraw, SkyMatchesSkyTexel) {
  SkyScene sc;
  for (float pitch : {-60.0f, -20.0f, 0.0f}) {
    for (int W : {1920, 400}) {
      const int H = W * 9 / 16;
      auto view = make_view({10, 20, 30}, 33.0f, pitch, 90.0f, W, H);
      TestFramebuffer tf(W, H);
      Agreement a = check_sky(sc.sky(), view, 12.34, false, tf);
      char what[64];
      std::snprintf(what, sizeof what, "sky %dx%d pitch %5.1f", W, H, pitch);
      report(what, a);
      if (W == 1920) {
        EXPECT_GE(a.exact_fraction(), 0.98) << what;
      }
    }
  }
}

TEST(SpanDraw, TurbMatchesTurbTexel) {
  WallScene sc(true);
  BspWorld& w = sc.tw.world();
  const Face& face = w.faces[sc.face];
  const Texture& tex = w.textures[w.texinfo[face.texinfo].texture];
  for (bool model : {true, false}) {
    for (double time : {0.0, 1.3, 77.77}) {
      const int W = model ? 320 : 1920, H = model ? 200 : 1080;
      const auto spans = full_rows(W, H);
      auto view = make_view({0, 0, 0}, model ? 35.0f : 15.0f, 10.0f, 90.0f, W, H);
      TestFramebuffer tf(W, H);
      render::SpanGradients g = render::face_gradients(w, face, view, 0);
      g.second_order = !model;
      render::draw_turb_spans(spans.data(), uint32_t(spans.size()), g, tex, face.texture_mins[0],
                              face.texture_mins[1], face.extents[0], face.extents[1], time, tf.fb);
      Agreement a;
      for (const Span& sp : spans)
        for (int x = sp.x; x < sp.x + sp.count; ++x) {
          const double py = sp.y + 0.5;
          // Exact s, t clamped to the face's extents like the drawer.
          auto sf = [&](double px) {
            double s, t;
            exact_st(w, face, view, px, py, &s, &t);
            return std::clamp(s, double(face.texture_mins[0]), face.texture_mins[0] + face.extents[0] - 1e-6);
          };
          auto tf2 = [&](double px) {
            double s, t;
            exact_st(w, face, view, px, py, &s, &t);
            return std::clamp(t, double(face.texture_mins[1]), face.texture_mins[1] + face.extents[1] - 1e-6);
          };
          const double s = model ? run_model(sp, x, sf) : sf(x + 0.5);
          const double t = model ? run_model(sp, x, tf2) : tf2(x + 0.5);
          const uint8_t got = tf.pixels[size_t(sp.y) * W + x];
          ++a.pixels;
          if (got == render::turb_texel(tex, float(s), float(t), time)) { ++a.exact; continue; }
          bool near = false;
          for (double dt = -1.0; dt <= 1.0 && !near; dt += 0.125)  // s, t within one texel
            for (double ds = -1.0; ds <= 1.0 && !near; ds += 0.125)
              near = got == render::turb_texel(tex, float(s + ds), float(t + dt), time);
          ++(near ? a.off_by_one : a.other);
        }
      char what[64];
      std::snprintf(what, sizeof what, "turb %s time %.2f", model ? "model" : "1920x1080", time);
      report(what, a);
      EXPECT_GE(a.exact_fraction(), model ? 0.995 : 0.98) << what;
      EXPECT_EQ(a.other, 0u) << what;
    }
  }
}

TEST(SpanDraw, SolidAndCoverage) {
  TestFramebuffer tf(64, 8);
  std::vector<Span> spans = {{0, 0, 64, 0}, {3, 1, 5, 0}, {0, 7, 1, 0}};
  render::draw_solid_spans(spans.data(), uint32_t(spans.size()), 0, tf.fb);
  for (int x = 0; x < 64; ++x) EXPECT_EQ(tf.pixels[x], 0);
  EXPECT_EQ(tf.coverage[64 + 2], 0);
  EXPECT_EQ(tf.coverage[64 + 3], 1);
  EXPECT_EQ(tf.coverage[64 + 7], 1);
  EXPECT_EQ(tf.coverage[64 + 8], 0);
  EXPECT_EQ(tf.coverage[7 * 64], 1);
  EXPECT_EQ(tf.z[0], 0);
}

}  // namespace
}  // namespace sb::test::back
