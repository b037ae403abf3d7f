// The back end on real maps: the surface builder on every lit face, and whole frames through
// render_world (every pixel once, cache reuse, timing, agreement with the reference renderer).
// Set STARBOW_BACK_DUMP=<dir> to write the frames as PNGs for looking at.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "engine/render/render_local.h"
#include "engine/render/surface_cache.h"
#include "engine/render/surface_math.h"
#include "engine/world/viewpoints.h"
#include "tests/render_back/back_test_util.h"
#include "tests/support/png_image.h"
#include "tests/support/quake_data.h"
#include "tests/support/reference_renderer.h"
#include "tests/support/render_compare.h"
#include "tests/support/test_world.h"

namespace sb::test::back {
namespace {

const char* dump_dir() {
  const char* d = std::getenv("STARBOW_BACK_DUMP");
  return d && *d ? d : nullptr;
}

TEST(RealMap, SurfaceBuilderMatchesClosedFormOnEveryLitFace) {
  SB_REQUIRE_QUAKE_DATA();
  for (const char* map : {"start", "lq_e1m1"}) {
    sb::test::TestWorld tw(map);
    ASSERT_NE(tw.world(), nullptr) << tw.error();
    const BspWorld& w = *tw.world();
    auto cm = sb::test::load_colormap();
    ASSERT_EQ(cm.size(), 64u * 256u);
    int ls[kMaxLightStyleSlots];
    for (int i = 0; i < kMaxLightStyleSlots; ++i) ls[i] = (i * 97) % 600;
    uint64_t texels = 0, bad = 0, faces = 0;
    std::vector<uint16_t> grid;
    std::vector<uint8_t> out;
    const uint32_t stride = std::string(map) == "start" ? 1 : 7;  // every face of start, a sample of the big map
    for (uint32_t fi = 0; fi < w.num_faces; fi += stride) {
      const Face& f = w.faces[fi];
      if (f.flags & (kFaceSky | kFaceTurb)) continue;
      if (f.extents[0] <= 0 || f.extents[1] <= 0) continue;
      ++faces;
      const Texture& tex = w.textures[w.texinfo[f.texinfo].texture];
      for (const int* styles : {static_cast<const int*>(nullptr), static_cast<const int*>(ls)}) {
        grid.assign(size_t(render::light_grid_size(f)), 0);
        const int gw = render::face_light_grid(w, f, styles, grid.data(), nullptr);
        for (int mip = 0; mip < 4; ++mip) {
          const int sw = f.extents[0] >> mip, sh = f.extents[1] >> mip;
          out.assign(size_t(sw) * sh, 0);
          render::build_surface(grid.data(), gw, tex, mip, f.texture_mins[0], f.texture_mins[1], sw, sh, cm.data(),
                                out.data());
          for (int v = 0; v < sh; ++v)
            for (int u = 0; u < sw; ++u) {
              const int row = render::shade_at(grid.data(), gw, u, v, mip) >> 8;
              const uint8_t want =
                  cm[size_t(row) * 256 + render::texture_texel(tex, mip, f.texture_mins[0], f.texture_mins[1], u, v)];
              ++texels;
              bad += out[size_t(v) * sw + u] != want;
            }
        }
      }
    }
    std::printf("%s: %llu lit faces, %llu texels over 4 mips x 2 style sets, %llu differ\n", map,
                (unsigned long long)faces, (unsigned long long)texels, (unsigned long long)bad);
    EXPECT_GT(faces, 100u);
    EXPECT_EQ(bad, 0u);
  }
}

struct FrameFigures {
  double ms = 0;
  RenderStats stats;
};

TEST(RealMap, RenderWorldFramesCoverEveryPixelOnceAndReuseTheCache) {
  SB_REQUIRE_QUAKE_DATA();
  auto cm = sb::test::load_colormap();
  ASSERT_EQ(cm.size(), 64u * 256u);
  for (const char* map : {"start", "lq_e1m1", "lq_e0m1", "lqdm1"}) {
    sb::test::TestWorld tw(map);
    ASSERT_NE(tw.world(), nullptr) << tw.error();
    BspWorld& w = *tw.world();
    std::vector<ViewParams> views = sb::test::test_viewpoints(w, 6);
    ASSERT_FALSE(views.empty());
    for (size_t vi = 0; vi < views.size(); ++vi) {
      for (auto [W, H] : {std::pair{640, 400}, std::pair{1920, 1080}}) {
        std::vector<uint8_t> pixels, coverage, pixels2;
        RenderStats s1, s2;
        const double time = 1.0 + double(vi);
        Status st = tw.render(views[vi], W, H, time, nullptr, cm.data(), &pixels, &coverage, &s1);
        ASSERT_TRUE(st.is_ok()) << st.message();
        size_t not_once = 0;
        for (uint8_t c : coverage) not_once += c != 1;
        EXPECT_EQ(not_once, 0u) << map << " view " << vi << " " << W << "x" << H;
        // The same view again: every lit surface comes from the cache.
        auto t0 = std::chrono::steady_clock::now();
        st = tw.render(views[vi], W, H, time, nullptr, cm.data(), &pixels2, nullptr, &s2);
        auto t1 = std::chrono::steady_clock::now();
        ASSERT_TRUE(st.is_ok()) << st.message();
        EXPECT_EQ(pixels, pixels2);
        EXPECT_EQ(s2.surfaces_built, 0u);
        EXPECT_EQ(s2.surface_cache_hits, s1.surfaces_built + s1.surface_cache_hits);
        EXPECT_FALSE(s1.cache_exhausted);
        std::printf("%-8s view %zu %4dx%-4d: surfaces %5u spans %6u built %4u (then %u, hits %u) mips %u/%u/%u/%u, "
                    "cached frame %.2f ms\n",
                    map, vi, W, H, s1.surfaces, s1.spans, s1.surfaces_built, s2.surfaces_built,
                    s2.surface_cache_hits, s1.mip_counts[0], s1.mip_counts[1], s1.mip_counts[2], s1.mip_counts[3],
                    std::chrono::duration<double, std::milli>(t1 - t0).count());
        if (dump_dir() && W == 640) {
          dump_png(std::string(dump_dir()) + "/" + map + "_" + std::to_string(vi) + ".png", pixels.data(), W, H, W);
        }
      }
    }
  }
}

TEST(RealMap, LightStyleChangeRebuildsOnlyItsSurfaces) {
  SB_REQUIRE_QUAKE_DATA();
  auto cm = sb::test::load_colormap();
  sb::test::TestWorld tw("start");
  ASSERT_NE(tw.world(), nullptr) << tw.error();
  std::vector<ViewParams> views = sb::test::test_viewpoints(*tw.world(), 4);
  int ls[kMaxLightStyleSlots];
  for (int& v : ls) v = 256;
  for (const ViewParams& v : views) {
    std::vector<uint8_t> px;
    RenderStats a, b, c;
    ASSERT_TRUE(tw.render(v, 320, 200, 0.0, ls, cm.data(), &px, nullptr, &a).is_ok());
    ASSERT_TRUE(tw.render(v, 320, 200, 0.0, ls, cm.data(), &px, nullptr, &b).is_ok());
    EXPECT_EQ(b.surfaces_built, 0u);
    // Every style value changes: every lit surface with a lightmap is rebuilt.
    for (int& s : ls) s = 300;
    ASSERT_TRUE(tw.render(v, 320, 200, 0.0, ls, cm.data(), &px, nullptr, &c).is_ok());
    for (int& s : ls) s = 256;
    EXPECT_GT(c.surfaces_built, 0u);
    EXPECT_EQ(c.surfaces_built + c.surface_cache_hits, b.surface_cache_hits);
  }
}

TEST(RealMap, AgreesWithReferenceRenderer) {
  SB_REQUIRE_QUAKE_DATA();
  auto cm = sb::test::load_colormap();
  for (const char* map : {"start", "lq_e1m1"}) {
    sb::test::TestWorld tw(map);
    ASSERT_NE(tw.world(), nullptr) << tw.error();
    std::vector<ViewParams> views = sb::test::test_viewpoints(*tw.world(), 4);
    MismatchBreakdown total;
    for (size_t vi = 0; vi < views.size(); ++vi) {
      const int W = 320, H = 200;
      const double time = 0.5 + double(vi);
      std::vector<uint8_t> px;
      ASSERT_TRUE(tw.render(views[vi], W, H, time, nullptr, cm.data(), &px).is_ok());
      ReferenceInputs in;
      in.world = tw.world();
      in.time = time;
      in.colormap = cm.data();
      ReferenceRenderer ref(in);
      ReferenceFrame frame = ref.render(views[vi], W, H);
      std::vector<PixelClass> classes;
      MismatchBreakdown b = classify_mismatches(ref, frame, px.data(), W, &classes);
      total.add(b);
      if (dump_dir()) {
        int cw = 0;
        auto rgb = comparison_rgb(frame, px.data(), W, classes, sb::test::load_game_palette(), &cw);
        write_rgb_png(std::string(dump_dir()) + "/cmp_" + map + "_" + std::to_string(vi) + ".png", cw, H, rgb);
      }
    }
    std::printf("%s vs reference: %s\n", map, total.summary().c_str());
    EXPECT_GE(total.agreement(), 0.9) << map;
  }
}


// A view looking at face `fi` from 64 units in front of it (and 48 to the side), or false
// when that eye is in solid space.
bool view_of_face(const BspWorld& w, uint32_t fi, ViewParams* out) {
  const Face& f = w.faces[fi];
  glm::dvec3 c(0.0);
  for (uint32_t k = 0; k < f.num_edges; ++k) {
    const int32_t se = w.surfedges[f.first_surfedge + k];
    const Edge& e = w.edges[se >= 0 ? se : -se];
    c += glm::dvec3(w.vertices[e.v[se >= 0 ? 0 : 1]]);
  }
  c /= double(f.num_edges);
  glm::dvec3 n(w.planes[f.plane].normal);
  if (f.flags & kFacePlaneBack) n = -n;
  glm::dvec3 side = std::fabs(n.z) > 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
  const glm::dvec3 eye = c + 64.0 * n + 48.0 * side;
  if (sb::test::point_contents(w, glm::vec3(eye)) == kContentsSolid) return false;
  const glm::dvec3 d = c - eye;
  out->origin = glm::vec3(eye);
  out->yaw = float(glm::degrees(std::atan2(d.y, d.x)));
  out->pitch = float(-glm::degrees(std::atan2(d.z, std::sqrt(d.x * d.x + d.y * d.y))));
  out->fov_x = 90.0f;
  return true;
}

TEST(RealMap, WaterAndSkyViews) {
  SB_REQUIRE_QUAKE_DATA();
  auto cm = sb::test::load_colormap();
  for (const char* map : {"start", "lq_e1m1", "lqdm1"}) {
    sb::test::TestWorld tw(map);
    ASSERT_NE(tw.world(), nullptr) << tw.error();
    const BspWorld& w = *tw.world();
    for (uint16_t kind : {uint16_t(kFaceTurb), uint16_t(kFaceSky)}) {
      int shown = 0;
      for (uint32_t fi = 0; fi < w.models[0].num_faces && shown < 2; fi += 7) {
        if (!(w.faces[fi].flags & kind)) continue;
        ViewParams v;
        if (!view_of_face(w, fi, &v)) continue;
        ++shown;
        const int W = 320, H = 200;
        const double time = 3.3 * shown;
        std::vector<uint8_t> px, cov;
        ASSERT_TRUE(tw.render(v, W, H, time, nullptr, cm.data(), &px, &cov).is_ok());
        for (uint8_t c : cov) ASSERT_EQ(c, 1);
        ReferenceInputs in;
        in.world = &w;
        in.time = time;
        in.colormap = cm.data();
        ReferenceRenderer ref(in);
        ReferenceFrame frame = ref.render(v, W, H);
        uint64_t kind_pixels = 0;
        for (int i = 0; i < W * H; ++i) {
          const uint32_t rf = frame.samples[size_t(i)].face;
          kind_pixels += rf != kNoFace && (w.faces[rf].flags & kind);
        }
        std::vector<PixelClass> classes;
        MismatchBreakdown b = classify_mismatches(ref, frame, px.data(), W, &classes);
        const char* what = kind == kFaceTurb ? "water" : "sky";
        std::printf("%s %s face %u: %.1f%% of the view; %s\n", map, what, fi, 100.0 * kind_pixels / (W * H),
                    b.summary().c_str());
        EXPECT_GT(kind_pixels, 0u);
        EXPECT_LE(b.unexplained_fraction(), 0.001) << map << " " << what;
        if (dump_dir()) {
          const std::string stem = std::string(dump_dir()) + "/" + map + "_" + what + std::to_string(shown);
          dump_png(stem + ".png", px.data(), W, H, W);
          int cw = 0;
          auto rgb = comparison_rgb(frame, px.data(), W, classes, sb::test::load_game_palette(), &cw);
          write_rgb_png(stem + "_cmp.png", cw, H, rgb);
        }
      }
    }
  }
}


// Figures only (no pass/fail on time): front end vs back end per frame, cached surfaces.
TEST(RealMap, FrameTimeSplit) {
  SB_REQUIRE_QUAKE_DATA();
  auto cm = sb::test::load_colormap();
  for (const char* map : {"start", "lq_e1m1", "lqdm1"}) {
    sb::test::TestWorld tw(map);
    ASSERT_NE(tw.world(), nullptr) << tw.error();
    BspWorld& w = *tw.world();
    mem::MemorySystem& memory = tw.memory();
    std::vector<ViewParams> views = sb::test::test_viewpoints(w, 6);
    for (auto [W, H] : {std::pair{640, 400}, std::pair{1920, 1080}}) {
      std::vector<uint8_t> pixels(size_t(W) * H);
      std::vector<uint16_t> z(size_t(W) * H);
      Framebuffer fb;
      fb.pixels = pixels.data();
      fb.width = W;
      fb.height = H;
      fb.stride = W;
      fb.zbuffer = z.data();
      double front_ms = 0, back_ms = 0, build_ms = 0;
      uint32_t built = 0;
      for (const ViewParams& v : views) {
        RenderInputs in;
        in.world = &w;
        in.view = v;
        in.time = 1.0;
        in.colormap = cm.data();
        for (int rep = 0; rep < 4; ++rep) {  // rep 0 builds surfaces; 1..3 draw from the cache
          memory.begin_frame();
          RenderStats st;
          const render::ViewState view = render::setup_view(w, v, W, H, memory.frame_number());
          render::FrameSpans spans;
          auto t0 = std::chrono::steady_clock::now();
          ASSERT_TRUE(render::build_spans(w, view, memory.frame(), &spans, &st).is_ok());
          auto t1 = std::chrono::steady_clock::now();
          render::draw_surfaces(w, view, spans, in, fb, memory, &st);
          auto t2 = std::chrono::steady_clock::now();
          if (rep == 0) {
            build_ms += std::chrono::duration<double, std::milli>(t2 - t1).count();
            built += st.surfaces_built;
          } else {
            front_ms += std::chrono::duration<double, std::milli>(t1 - t0).count();
            back_ms += std::chrono::duration<double, std::milli>(t2 - t1).count();
          }
        }
      }
      const double n = 3.0 * double(views.size());
      std::printf("%-8s %4dx%-4d per frame: front end %.2f ms, back end %.2f ms (cached); first frame back end "
                  "%.2f ms building %.0f surfaces\n",
                  map, W, H, front_ms / n, back_ms / n, build_ms / double(views.size()),
                  double(built) / double(views.size()));
    }
  }
}

}  // namespace
}  // namespace sb::test::back
