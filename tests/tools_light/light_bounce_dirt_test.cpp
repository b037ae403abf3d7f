// Light stage, bounce (radiosity) and dirt (ambient occlusion) on hand-built closed rooms
// (light_box_world.h): bounce reaches shadowed corners and takes the colour of the surface
// it comes from, bounced energy stays below the direct light that feeds it, dirt darkens
// inside corners and leaves open surfaces alone, and results do not depend on threads.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "tests/tools_light/light_box_world.h"
#include "tests/tools_light/light_test_util.h"
#include "tools/light/light.h"

namespace sb::tools {
namespace {

constexpr uint8_t kRed = 1, kGrey = 2;

// Palette: index 1 a strong red, index 2 a mid grey, the rest black.
std::vector<uint8_t> test_palette() {
  std::vector<uint8_t> p(768, 0);
  p[3] = 220, p[4] = 30, p[5] = 30;
  p[6] = 160, p[7] = 160, p[8] = 160;
  return p;
}

// Room 512 x 256 x 256 (x, y, z from 0) with a slab x 240..272 hanging from the ceiling down
// to z = 128 across the whole width: a light on the left, below the slab's bottom, lights the
// right half's floor through the gap but not its ceiling.
test::BoxWorld divided_room(int floor_tex) {
  test::BoxWorld w;
  w.room = {{0, 0, 0}, {512, 256, 256}};
  w.solids.push_back({{240, 0, 128}, {272, 256, 256}});
  w.textures = {{"grey", kGrey}, {"red", kRed}};
  test::add_room_surfaces(&w, floor_tex, 0, 0);
  w.surfaces.push_back({0, 240, false, {0, 128}, {256, 256}, 0});
  w.surfaces.push_back({0, 272, true, {0, 128}, {256, 256}, 0});
  w.surfaces.push_back({2, 128, false, {240, 0}, {272, 256}, 0});
  return w;
}

// An empty room (no inner solids), size x, y, z.
test::BoxWorld open_room(float x, float y, float z, int floor_tex) {
  test::BoxWorld w;
  w.room = {{0, 0, 0}, {x, y, z}};
  w.textures = {{"grey", kGrey}, {"red", kRed}};
  test::add_room_surfaces(&w, floor_tex, 0, 0);
  return w;
}

std::string entities(const std::string& worldspawn, const std::string& lights) {
  return "{\n\"classname\" \"worldspawn\"\n" + worldspawn + "}\n" + lights;
}

struct Lit {
  BspData bsp;
  std::vector<uint8_t> rgb;
  LightStats stats;
};

Lit light(const test::BoxWorld& world, const std::string& ents, LightOptions opts) {
  Lit r;
  r.bsp = test::build_box_world(world, ents);
  opts.quiet = true;
  if (opts.threads == 0) opts.threads = 1;
  if (opts.palette.empty()) opts.palette = test_palette();
  Status s = light_bsp("room.bsp", &r.bsp, opts, &r.stats, opts.want_rgb ? &r.rgb : nullptr);
  EXPECT_TRUE(s.is_ok()) << s.message();
  return r;
}

// Style-0 sample of the face facing `n` nearest to world point p (channel -1: the mono byte,
// 0..2: the .lit channel). -1 when no face facing n holds p.
int sample_at(const Lit& lit, glm::vec3 p, glm::vec3 n, int channel = -1) {
  test::EngineView v(lit.bsp);
  if (!v.world()) return -1;
  const BspWorld& w = *v.world();
  for (uint32_t i = 0; i < w.num_faces; ++i) {
    const Face& f = w.faces[i];
    const Plane& pl = w.planes[f.plane];
    glm::vec3 facing = (f.flags & kFacePlaneBack) ? -pl.normal : pl.normal;
    if (glm::dot(facing, n) < 0.99f || std::fabs(glm::dot(pl.normal, p) - pl.dist) > 0.5f) continue;
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (uint32_t k = 0; k < f.num_edges; ++k) {
      int32_t se = w.surfedges[f.first_surfedge + k];
      uint32_t e = uint32_t(se < 0 ? -se : se);
      glm::vec3 vert = w.vertices[se < 0 ? w.edges[e].v[1] : w.edges[e].v[0]];
      lo = glm::min(lo, vert);
      hi = glm::max(hi, vert);
    }
    if (glm::any(glm::lessThan(p, lo - 0.5f)) || glm::any(glm::greaterThan(p, hi + 0.5f))) continue;
    if (f.light_offset == kNoLightmap) return -1;
    const TexInfo& ti = w.texinfo[f.texinfo];
    float s = glm::dot(p, glm::vec3(ti.vecs[0])) + ti.vecs[0].w, t = glm::dot(p, glm::vec3(ti.vecs[1])) + ti.vecs[1].w;
    int gw = f.extents[0] / 16 + 1, gh = f.extents[1] / 16 + 1;
    int gx = std::clamp(int(std::lround((s - f.texture_mins[0]) / 16.0f)), 0, gw - 1);
    int gy = std::clamp(int(std::lround((t - f.texture_mins[1]) / 16.0f)), 0, gh - 1);
    size_t at = size_t(f.light_offset) + size_t(gy) * gw + gx;
    if (channel < 0) return at < lit.bsp.lighting.size() ? lit.bsp.lighting[at] : -1;
    return at * 3 + channel < lit.rgb.size() ? lit.rgb[at * 3 + size_t(channel)] : -1;
  }
  return -1;
}

uint64_t total(const Lit& lit) {
  uint64_t sum = 0;
  for (uint8_t b : lit.bsp.lighting) sum += b;
  return sum;
}

const std::string kLeftLight = "{\n\"classname\" \"light\"\n\"origin\" \"100 128 200\"\n\"light\" \"500\"\n}\n";

TEST(LightBounce, TheBoxWorldLoadsAndLights) {
  Lit lit = light(divided_room(0), entities("", kLeftLight), LightOptions());
  test::EngineView v(lit.bsp);
  ASSERT_NE(v.world(), nullptr) << v.error();
  EXPECT_GT(sample_at(lit, {100, 128, 0}, {0, 0, 1}), 50);  // floor under the light
  EXPECT_GT(sample_at(lit, {100, 128, 256}, {0, 0, -1}), 50);  // ceiling above it
  EXPECT_EQ(lit.stats.bounce_rays, 0u);
}

TEST(LightBounce, ReachesTheShadowedCorner) {
  LightOptions direct, bounce;
  bounce.bounce = 1;
  Lit a = light(divided_room(0), entities("", kLeftLight), direct);
  Lit b = light(divided_room(0), entities("", kLeftLight), bounce);
  glm::vec3 corner(496, 240, 256), up(0, 0, 1), down(0, 0, -1);  // the right half's ceiling
  int before = sample_at(a, corner, down), after = sample_at(b, corner, down);
  std::printf("[ light ] shadowed corner: %d direct only, %d with one bounce (%llu bounce rays, %llu unresolved)\n",
              before, after, (unsigned long long)b.stats.bounce_rays, (unsigned long long)b.stats.bounce_misses);
  ASSERT_GE(before, 0);
  EXPECT_EQ(before, 0);  // the slab hides the light
  EXPECT_GE(after, before + 5);
  EXPECT_EQ(b.stats.bounces, 1);
  EXPECT_EQ(b.stats.bounce_misses, 0u);
  // The lit floor over there gets brighter too (from the walls), and nothing gets darker.
  EXPECT_GT(sample_at(b, {400, 128, 0}, up), sample_at(a, {400, 128, 0}, up));
  ASSERT_EQ(a.bsp.lighting.size(), b.bsp.lighting.size());
  for (size_t k = 0; k < a.bsp.lighting.size(); ++k) ASSERT_GE(b.bsp.lighting[k], a.bsp.lighting[k]) << k;
  // The worldspawn key turns it on as well.
  Lit c = light(divided_room(0), entities("\"_bounce\" \"1\"\n", kLeftLight), direct);
  EXPECT_EQ(c.bsp.lighting, b.bsp.lighting);
}

TEST(LightBounce, ARedFloorTintsTheCeilingRed) {
  // A spotlight pointing down lights a disc of the red floor; the ceiling sees no direct light.
  const std::string spot =
      "{\n\"classname\" \"light\"\n\"origin\" \"256 256 200\"\n\"light\" \"600\"\n\"mangle\" \"0 -90 0\"\n"
      "\"angle\" \"60\"\n}\n";
  LightOptions o;
  o.want_rgb = true;
  Lit direct = light(open_room(512, 512, 256, 1), entities("", spot), o);
  o.bounce = 1;
  Lit white = light(open_room(512, 512, 256, 1), entities("", spot), o);
  Lit tinted = light(open_room(512, 512, 256, 1), entities("\"_bouncecolorscale\" \"1\"\n", spot), o);
  glm::vec3 ceiling(256, 256, 256), down(0, 0, -1);
  EXPECT_EQ(sample_at(direct, ceiling, down), 0);
  int wr = sample_at(white, ceiling, down, 0), wg = sample_at(white, ceiling, down, 1);
  int tr = sample_at(tinted, ceiling, down, 0), tg = sample_at(tinted, ceiling, down, 1),
      tb = sample_at(tinted, ceiling, down, 2);
  std::printf("[ light ] ceiling over a red floor: rgb %d %d %d (textures ignored: %d %d)\n", tr, tg, tb, wr, wg);
  EXPECT_GT(wr, 3);
  EXPECT_NEAR(wr, wg, 1);  // bouncecolorscale 0: grey reflection
  EXPECT_GT(tr, 3);
  EXPECT_GT(tr, 3 * tg);   // the floor's red (220, 30, 30)
  EXPECT_NEAR(tg, tb, 1);
  EXPECT_GT(tr, wr);       // textures ignored: grey 127/255; the red (220/255) reflects more
  EXPECT_LT(tg, wg);       // and its green (30/255) less
  EXPECT_FALSE(tinted.stats.palette_missing);
  // Without a palette: grey reflectivity, reported.
  o.palette = std::vector<uint8_t>(10, 0);  // not a palette
  Lit grey = light(open_room(512, 512, 256, 1), entities("\"_bouncecolorscale\" \"1\"\n", spot), o);
  EXPECT_TRUE(grey.stats.palette_missing);
  EXPECT_NEAR(sample_at(grey, ceiling, down, 0), sample_at(grey, ceiling, down, 1), 1);
}

TEST(LightBounce, BouncedEnergyStaysBelowTheDirectLight) {
  LightOptions o;
  const std::string keys = "\"_bouncecolorscale\" \"1\"\n";  // grey texture: reflectivity 0.63
  Lit direct = light(divided_room(0), entities(keys, kLeftLight), o);
  o.bounce = 1;
  Lit one = light(divided_room(0), entities(keys, kLeftLight), o);
  o.bounce = 3;
  Lit three = light(divided_room(0), entities(keys, kLeftLight), o);
  uint64_t d = total(direct), b1 = total(one) - d, b3 = total(three) - d;
  std::printf("[ light ] lightmap totals: direct %llu, + one bounce %llu, + three bounces %llu\n",
              (unsigned long long)d, (unsigned long long)b1, (unsigned long long)b3);
  ASSERT_GT(d, 0u);
  EXPECT_GT(total(one), d);
  EXPECT_LT(b1, d * 7 / 10);        // at most the reflectivity (0.63) of what came in
  EXPECT_GT(b3, b1);                // later passes add light ...
  EXPECT_LT(b3 - b1, b1);           // ... less than the first one did
  EXPECT_EQ(three.stats.bounces, 3);
  // "_bouncescale" 0 on the light: nothing of it bounces.
  const std::string no_bounce_light =
      "{\n\"classname\" \"light\"\n\"origin\" \"100 128 200\"\n\"light\" \"500\"\n\"_bouncescale\" \"0\"\n}\n";
  o.bounce = 1;
  Lit none = light(divided_room(0), entities(keys, no_bounce_light), o);
  EXPECT_EQ(none.bsp.lighting, direct.bsp.lighting);
}

// A 1024 x 1024 x 512 room lit evenly by a light without falloff (delay 3).
const std::string kEvenLight =
    "{\n\"classname\" \"light\"\n\"origin\" \"512 512 256\"\n\"light\" \"300\"\n\"delay\" \"3\"\n}\n";

TEST(LightDirt, DarkensInsideCornersAndLeavesOpenSurfaces) {
  LightOptions plain, dirty;
  dirty.dirt = 1;
  Lit a = light(open_room(1024, 1024, 512, 0), entities("", kEvenLight), plain);
  Lit b = light(open_room(1024, 1024, 512, 0), entities("", kEvenLight), dirty);
  glm::vec3 up(0, 0, 1), west(-1, 0, 0);
  glm::vec3 corner(16, 512, 0), floor_mid(512, 512, 0), wall_mid(1024, 512, 256);
  int c0 = sample_at(a, corner, up), c1 = sample_at(b, corner, up);
  int f0 = sample_at(a, floor_mid, up), f1 = sample_at(b, floor_mid, up);
  int w0 = sample_at(a, wall_mid, west), w1 = sample_at(b, wall_mid, west);
  std::printf("[ light ] dirt: inside corner %d -> %d, floor middle %d -> %d, wall middle %d -> %d (%llu rays)\n",
              c0, c1, f0, f1, w0, w1, (unsigned long long)b.stats.dirt_rays);
  ASSERT_GT(c0, 20);
  ASSERT_GT(w0, 20);
  EXPECT_LT(c1, c0 * 85 / 100);  // the corner darkens clearly
  EXPECT_EQ(f1, f0);             // nothing within the dirt depth: unchanged
  EXPECT_EQ(w1, w0);
  EXPECT_LT(double(c1) / c0, double(w1) / w0);
  EXPECT_TRUE(b.stats.dirt);
  // Closer to the corner is darker; a deeper dirt depth or a larger scale darkens more.
  EXPECT_LT(sample_at(b, {1, 512, 0}, up), c1);
  Lit deep = light(open_room(1024, 1024, 512, 0), entities("\"_dirtdepth\" \"256\"\n\"_dirtscale\" \"2\"\n", kEvenLight),
                   dirty);
  EXPECT_LT(sample_at(deep, corner, up), c1);
  // The worldspawn key alone turns dirt on; a light with "_dirt" "-1" ignores it.
  Lit key = light(open_room(1024, 1024, 512, 0), entities("\"_dirt\" \"1\"\n", kEvenLight), plain);
  EXPECT_EQ(key.bsp.lighting, b.bsp.lighting);
  const std::string clean_light =
      "{\n\"classname\" \"light\"\n\"origin\" \"512 512 256\"\n\"light\" \"300\"\n\"delay\" \"3\"\n\"_dirt\" \"-1\"\n}\n";
  Lit clean = light(open_room(1024, 1024, 512, 0), entities("\"_dirt\" \"1\"\n", clean_light), plain);
  EXPECT_EQ(clean.bsp.lighting, a.bsp.lighting);
  // The minimum light is dirtied too (the "_minlight_dirt" default follows "_dirt").
  Lit dim = light(open_room(1024, 1024, 512, 0), entities("\"light\" \"100\"\n\"_dirt\" \"1\"\n", ""), plain);
  EXPECT_EQ(sample_at(dim, floor_mid, up), 100);
  EXPECT_LT(sample_at(dim, corner, up), 90);
}

TEST(LightBounceDirt, SameBytesForOneTwoAndThreeThreads) {
  LightOptions o;
  o.bounce = 2;
  o.dirt = 1;
  o.dirtmode = 1;  // jittered rays: still a fixed function of face and sample
  o.extra = 2;
  o.want_rgb = true;
  const std::string keys = "\"_bouncecolorscale\" \"0.5\"\n";
  std::vector<Lit> runs;
  for (int threads : {1, 2, 3}) {
    o.threads = threads;
    runs.push_back(light(divided_room(1), entities(keys, kLeftLight), o));
  }
  ASSERT_FALSE(runs[0].bsp.lighting.empty());
  for (size_t k = 1; k < runs.size(); ++k) {
    EXPECT_EQ(runs[k].bsp.lighting, runs[0].bsp.lighting) << "run " << k;
    EXPECT_EQ(runs[k].rgb, runs[0].rgb) << "run " << k;
  }
  EXPECT_GT(runs[0].stats.bounce_rays, 0u);
  EXPECT_GT(runs[0].stats.dirt_rays, 0u);
}

}  // namespace
}  // namespace sb::tools
