// Light stage on a hand-built world: falloff formulas checked numerically, spot cones,
// shadows, styles, minimum light, switchable styles and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "tests/tools_light/light_test_util.h"
#include "tools/light/light.h"
#include "tools/light/light_entities.h"

namespace sb::tools {
namespace {

constexpr int kGridW = 33, kGridH = 17;

std::string world_with(const std::string& lights, const std::string& worldspawn_extra = "") {
  return "{\n\"classname\" \"worldspawn\"\n" + worldspawn_extra + "}\n" + lights;
}

std::string light_at(float x, float y, float z, const std::string& extra) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "{\n\"classname\" \"light\"\n\"origin\" \"%g %g %g\"\n", x, y, z);
  return buf + extra + "}\n";
}

BspData lit(bool wall, const std::string& entities, LightOptions opts = {}) {
  BspData b = test::make_floor_world(wall, entities);
  opts.threads = 1;
  LightStats stats;
  Status s = light_bsp("floor.bsp", &b, opts, &stats, nullptr);
  EXPECT_TRUE(s.is_ok()) << s.message();
  return b;
}

uint8_t sample(const BspData& b, int style_index, int gx, int gy) {
  size_t at = size_t(b.faces[0].lightofs) + size_t(style_index) * kGridW * kGridH + size_t(gy) * kGridW + gx;
  return at < b.lighting.size() ? b.lighting[at] : 0;
}

// The documented falloffs, written out independently of the implementation.
double expected_value(int delay, double intensity, double wait, double d) {
  double sd = d * wait;
  switch (delay) {
    case 0: return std::max(intensity - sd, 0.0);
    case 1: return intensity * 128.0 / std::max(sd, 32.0);
    case 2: return intensity * std::pow(128.0 / std::max(sd, 64.0), 2);
    case 3: return intensity;
    case 5: return intensity / (std::pow(sd / 128.0, 2) + 1.0);
  }
  return 0;
}

TEST(LightSynthetic, EngineLoadsTheHandBuiltWorld) {
  test::EngineView v(test::make_floor_world(true, world_with("")));
  ASSERT_NE(v.world(), nullptr) << v.error();
  EXPECT_EQ(v.world()->faces[0].extents[0], 512);
  EXPECT_EQ(v.world()->faces[0].extents[1], 256);
}

TEST(LightSynthetic, FalloffFollowsTheDelayFormulas) {
  const double lx = 128, ly = 128, lz = 129, intensity = 300, wait = 1.5;
  for (int delay : {0, 1, 2, 3, 5}) {
    SCOPED_TRACE("delay " + std::to_string(delay));
    char keys[96];
    std::snprintf(keys, sizeof keys, "\"light\" \"%g\"\n\"wait\" \"%g\"\n\"delay\" \"%d\"\n", intensity, wait, delay);
    BspData b = lit(false, world_with(light_at(float(lx), float(ly), float(lz), keys)));
    ASSERT_GE(b.faces[0].lightofs, 0);
    EXPECT_EQ(b.faces[0].styles[0], 0);
    EXPECT_EQ(b.faces[0].styles[1], 255);
    ASSERT_EQ(b.lighting.size(), size_t(kGridW * kGridH));
    int worst = 0;
    for (int gy = 0; gy < kGridH; ++gy)
      for (int gx = 0; gx < kGridW; ++gx) {
        double dx = lx - 16.0 * gx, dy = ly - 16.0 * gy, dz = lz - 1.0;  // samples sit 1 unit up
        double d = std::sqrt(dx * dx + dy * dy + dz * dz);
        double angle = 0.5 + 0.5 * (dz / d);
        double v = expected_value(delay, intensity, wait, d) * angle * 0.5;  // rangescale 0.5
        int want = int(std::floor(std::min(std::max(v, 0.0), 255.0) + 0.5));
        int got = sample(b, 0, gx, gy);
        worst = std::max(worst, std::abs(got - want));
        EXPECT_LE(std::abs(got - want), 1) << "grid " << gx << "," << gy << " d=" << d;
      }
    std::printf("[ light ] delay %d: worst difference to the formula %d\n", delay, worst);
    // Brightness falls with distance along the row under the light (except "no falloff").
    if (delay != 3) {
      for (int gx = 9; gx < kGridW - 1; ++gx) EXPECT_GE(sample(b, 0, gx, 8), sample(b, 0, gx + 1, 8));
    }
  }
}

TEST(LightSynthetic, SpotlightConeAndSupersampling) {
  // Pointing straight down from 200 units: 43 degree cone -> radius 200 * tan(21.5) = 78.8.
  std::string e = world_with(light_at(256, 128, 201, "\"light\" \"400\"\n\"mangle\" \"0 -90 0\"\n\"angle\" \"43\"\n"));
  BspData b = lit(false, e);
  EXPECT_GT(sample(b, 0, 16, 8), 0);       // straight below
  EXPECT_GT(sample(b, 0, 16 + 4, 8), 0);   // 64 units off axis: inside
  EXPECT_EQ(sample(b, 0, 16 + 5, 8), 0);   // 80 units off axis: outside
  // -extra4 averages a 4x4 sub-grid: the cone edge softens, the centre barely changes.
  LightOptions o;
  o.extra = 4;
  BspData s = lit(false, e, o);
  EXPECT_NEAR(sample(s, 0, 16, 8), sample(b, 0, 16, 8), 2);
  EXPECT_GT(sample(s, 0, 16 + 5, 8), 0);  // part of the cell lies inside the cone now
}

TEST(LightSynthetic, WallCastsAShadow) {
  std::string e = world_with(light_at(100, 128, 100, "\"light\" \"600\"\n"));
  BspData open = lit(false, e), walled = lit(true, e);
  // x = 400: behind the wall as seen from the light (the ray passes x = 240 at z ~ 54).
  EXPECT_GT(sample(open, 0, 25, 8), 20);
  EXPECT_EQ(sample(walled, 0, 25, 8), 0);
  // On the light's side nothing changes.
  for (int gx = 0; gx < 14; ++gx) EXPECT_EQ(sample(open, 0, gx, 8), sample(walled, 0, gx, 8)) << gx;
  std::printf("[ light ] x=400: %d unoccluded, %d behind the wall\n", sample(open, 0, 25, 8), sample(walled, 0, 25, 8));
}

TEST(LightSynthetic, StylesKeepStyleZeroFirstAndTheStrongestThree) {
  std::string lights = light_at(30, 128, 64, "\"style\" \"5\"\n\"light\" \"100\"\n") +  // weakest
                       light_at(100, 128, 64, "\"light\" \"200\"\n") +                   // style 0
                       light_at(200, 128, 64, "\"style\" \"1\"\n\"light\" \"300\"\n") +
                       light_at(300, 128, 64, "\"style\" \"2\"\n\"light\" \"300\"\n") +
                       light_at(400, 128, 64, "\"style\" \"33\"\n\"light\" \"300\"\n");
  BspData b = lit(false, world_with(lights));
  const uint8_t* st = b.faces[0].styles;
  EXPECT_EQ(st[0], 0);
  EXPECT_EQ(st[1], 1);
  EXPECT_EQ(st[2], 2);
  EXPECT_EQ(st[3], 33);
  EXPECT_EQ(b.lighting.size(), size_t(4 * kGridW * kGridH));
  // Style 1's map is bright under its own light and dark far from it.
  EXPECT_GT(sample(b, 1, 12, 8), sample(b, 1, 31, 8));
}

TEST(LightSynthetic, MinimumLightAndNoLights) {
  BspData b = lit(false, world_with("", "\"light\" \"20\"\n"));
  for (int gx = 0; gx < kGridW; ++gx) EXPECT_EQ(sample(b, 0, gx, 3), 20);
  BspData dark = lit(false, world_with(""));
  ASSERT_GE(dark.faces[0].lightofs, 0);
  EXPECT_EQ(sample(dark, 0, 5, 5), 0);
}

TEST(LightSynthetic, SwitchableLightsGetStylesFrom32) {
  std::string lights = light_at(100, 128, 64, "\"targetname\" \"lamp\"\n") +
                       light_at(300, 128, 64, "\"targetname\" \"other\"\n") +
                       light_at(400, 128, 64, "\"targetname\" \"lamp\"\n");
  BspData b = lit(false, world_with(lights));
  EXPECT_EQ(b.faces[0].styles[0], 0);
  EXPECT_EQ(b.faces[0].styles[1], 32);
  EXPECT_EQ(b.faces[0].styles[2], 33);
  EXPECT_NE(b.entities.find("\"style\" \"32\""), std::string::npos);
  EXPECT_NE(b.entities.find("\"style\" \"33\""), std::string::npos);
  LightSettings s;
  ASSERT_TRUE(parse_light_entities("again", b.entities, 0, &s, nullptr).is_ok());
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.lights[0].style, 32);
  EXPECT_EQ(s.lights[2].style, 32);
}

TEST(LightSynthetic, BadInputIsAnErrorOrAWarningNeverACrash) {
  // Entity syntax error: an error naming the file.
  BspData b = test::make_floor_world(false, "{ \"classname\" \"worldspawn\" \n{ \"classname\" \"light\" \"origin\" \"1 2");
  Status s = light_bsp("broken.bsp", &b, LightOptions(), nullptr, nullptr);
  EXPECT_FALSE(s.is_ok());
  EXPECT_NE(std::string(s.message()).find("broken.bsp"), std::string::npos) << s.message();
  // Bad values: warnings and defaults.
  std::string odd = world_with(light_at(100, 128, 64, "\"light\" \"nan\"\n\"delay\" \"9\"\n\"style\" \"300\"\n"
                                                      "\"wait\" \"-2\"\n\"_color\" \"x\"\n\"target\" \"nobody\"\n") +
                               "{ \"classname\" \"light\" }\n" +
                               light_at(1e30f, 0, 0, "") + light_at(100, 128, -50, ""));  // in solid
  BspData o = lit(false, odd);
  EXPECT_GT(sample(o, 0, 6, 8), 0);
  // Broken geometry: the engine loader's error, not a crash.
  BspData g = test::make_floor_world(false, world_with(""));
  g.faces[0].texinfo = 7;
  s = light_bsp("badface.bsp", &g, LightOptions(), nullptr, nullptr);
  EXPECT_FALSE(s.is_ok());
  std::printf("[ light ] %s\n", s.message());
  BspData none;
  EXPECT_FALSE(light_bsp("empty.bsp", &none, LightOptions(), nullptr, nullptr).is_ok());
  // Truncated files.
  std::vector<uint8_t> bytes;
  ASSERT_TRUE(serialize_bsp(test::make_floor_world(false, world_with("")), BspFormat::Bsp29, &bytes, nullptr).is_ok());
  for (size_t cut : {size_t(0), size_t(3), bytes.size() / 2, bytes.size() - 1}) {
    BspData t;
    if (parse_bsp("cut.bsp", bytes.data(), cut, &t).is_ok())
      (void)light_bsp("cut.bsp", &t, LightOptions(), nullptr, nullptr);
  }
}

}  // namespace
}  // namespace sb::tools
