// Front end on hand-built worlds: view setup, analytic box room, pillar room against the
// ray caster, PVS marking, degenerate views and buffer overflow.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "engine/render/front_local.h"
#include "tests/render_front/front_test_util.h"

namespace sb::test::front {
namespace {

const int kSizes[][2] = {{320, 200}, {640, 480}, {1280, 720}, {1920, 1080}, {333, 197}};

void expect_near(const glm::vec3& a, const glm::vec3& b) {
  EXPECT_NEAR(a.x, b.x, 1e-5f);
  EXPECT_NEAR(a.y, b.y, 1e-5f);
  EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(FrontView, BasisFollowsQuakeConventions) {
  auto room = make_box_room({-64, -64, -64}, {64, 64, 64}, false);
  ViewParams p;
  render::ViewState v = render::setup_view(room->world, p, 320, 200, 1);
  expect_near(v.forward, {1, 0, 0});
  expect_near(v.right, {0, -1, 0});
  expect_near(v.up, {0, 0, 1});
  EXPECT_FLOAT_EQ(v.xcenter, 160.0f);
  EXPECT_FLOAT_EQ(v.ycenter, 100.0f);
  EXPECT_NEAR(v.xscale, 160.0f, 1e-3f);
  EXPECT_EQ(v.xscale, v.yscale);
  EXPECT_EQ(v.view_leaf, 1);

  p.yaw = 90;
  v = render::setup_view(room->world, p, 320, 200, 1);
  expect_near(v.forward, {0, 1, 0});
  expect_near(v.right, {1, 0, 0});
  p.yaw = 0;
  p.pitch = 90;  // straight down
  v = render::setup_view(room->world, p, 320, 200, 1);
  expect_near(v.forward, {0, 0, -1});
  expect_near(v.up, {1, 0, 0});
  p.pitch = 0;
  p.roll = 90;
  v = render::setup_view(room->world, p, 320, 200, 1);
  expect_near(v.forward, {1, 0, 0});
  EXPECT_NEAR(std::fabs(v.right.z), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(v.right, v.up), 0.0f, 1e-5f);

  // Frustum planes: pixel-centre rays just inside each border are inside every plane;
  // rays just outside a border are outside that border's plane.
  p = ViewParams{};
  p.yaw = 33;
  p.pitch = -17;
  p.roll = 9;
  p.fov_x = 75;
  for (auto& sz : kSizes) {
    v = render::setup_view(room->world, p, sz[0], sz[1], 1);
    auto dir = [&](float sx, float sy) {
      return v.forward + ((sx - v.xcenter) / v.xscale) * v.right - ((sy - v.ycenter) / v.yscale) * v.up;
    };
    auto dist = [&](int plane, glm::vec3 d) { return glm::dot(v.frustum[plane].normal, v.origin + d) - v.frustum[plane].dist; };
    for (int i = 0; i < 4; ++i) {
      EXPECT_GT(dist(i, dir(0.5f, 0.5f)), 0.0f);
      EXPECT_GT(dist(i, dir(sz[0] - 0.5f, sz[1] - 0.5f)), 0.0f);
      EXPECT_NEAR(glm::length(v.frustum[i].normal), 1.0f, 1e-5f);
    }
    EXPECT_LT(dist(0, dir(-0.01f, 10.0f)), 0.0f);
    EXPECT_LT(dist(1, dir(sz[0] + 0.01f, 10.0f)), 0.0f);
    EXPECT_LT(dist(2, dir(10.0f, -0.01f)), 0.0f);
    EXPECT_LT(dist(3, dir(10.0f, sz[1] + 0.01f)), 0.0f);
    EXPECT_NEAR(dist(0, dir(0.0f, 50.0f)), 0.0f, 1e-4f);
    EXPECT_NEAR(dist(1, dir(float(sz[0]), 50.0f)), 0.0f, 1e-4f);
    EXPECT_NEAR(dist(2, dir(50.0f, 0.0f)), 0.0f, 1e-4f);
    EXPECT_NEAR(dist(3, dir(50.0f, float(sz[1]))), 0.0f, 1e-4f);
  }
}

// Which wall of box [mn, mx] the ray from o along d leaves through (face index of the
// box room: walls are added in side order -x, +x, -y, +y, -z, +z), or -1 when two walls
// are within `tie` of each other.
int exit_wall(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& mn, const glm::dvec3& mx, double tie) {
  double best = 1e300, second = 1e300;
  int wall = -1;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) continue;
    int side = d[a] > 0 ? 1 : 0;
    double t = ((side ? mx[a] : mn[a]) - o[a]) / d[a];
    if (t < best) {
      second = best;
      best = t;
      wall = a * 2 + side;
    } else if (t < second) {
      second = t;
    }
  }
  return second - best < tie * best ? -1 : wall;
}

TEST(FrontBoxRoom, FarWallIsTheExactRectangle) {
  // Looking down +x from the origin at the far wall x = 256, 128 units square: with
  // fov 90 at 320x200 (xscale 160) it projects to [120, 200) x [60, 140).
  auto room = make_box_room({-64, -64, -64}, {256, 64, 64}, false);
  FrontRunner runner;
  FrontFrame f = runner.run(room->world, ViewParams{}, 320, 200);
  ASSERT_TRUE(f.ok()) << f.status;
  ASSERT_EQ(f.contract_error, "");
  EXPECT_EQ(f.bad_coverage(), 0u);
  const uint32_t far_wall = 1;  // side +x
  for (int y = 0; y < 200; ++y) {
    for (int x = 0; x < 320; ++x) {
      bool in = x >= 120 && x < 200 && y >= 60 && y < 140;
      ASSERT_EQ(f.face_at[size_t(y) * 320 + x] == far_wall, in) << "pixel " << x << "," << y;
    }
  }
  EXPECT_EQ(f.stats.faces_emitted, 5u);  // the -x wall is behind the eye
  // nearzi: the far wall is wholly at z = 256; the +y wall (face 3), clipped by the left
  // frustum plane (x = y at fov 90), comes no nearer than z = 64.
  int found = 0;
  render::FrameSpans spans;
  runner.arena().reset();
  render::ViewState v2 = render::setup_view(room->world, ViewParams{}, 320, 200, runner.next_frame());
  ASSERT_TRUE(render::build_spans(room->world, v2, runner.arena(), &spans, nullptr).is_ok());
  for (uint32_t i = 0; i < spans.num_surfaces; ++i) {
    if (spans.surfaces[i].face == far_wall) { EXPECT_NEAR(spans.surfaces[i].nearzi, 1.0f / 256, 1e-7f); ++found; }
    if (spans.surfaces[i].face == 3) { EXPECT_NEAR(spans.surfaces[i].nearzi, 1.0f / 64, 1e-6f); ++found; }
  }
  EXPECT_EQ(found, 2);
  EXPECT_EQ(f.stats.surfaces, 5u);       // five walls; the background has no pixel, so it is not listed
}

TEST(FrontBoxRoom, EveryPixelMatchesTheAnalyticWall) {
  const glm::vec3 mn(-96, -64, -48), mx(256, 160, 72);
  auto room = make_box_room(mn, mx, true);
  FrontRunner runner;
  const float views[][5] = {{0, 0, 0, 0, 90},  {37, 10, 0, 0, 90},   {200, -30, 5, 0, 110}, {91, 45, 0, 20, 60},
                            {-45, 89, 0, 0, 90}, {180, -89, 0, 0, 140}, {10, 5, 3, -90, 170}, {300, 12, 0, 0, 10}};
  const glm::vec3 eyes[] = {{0, 0, 0}, {200, 100, 50}, {-90, -60, -40}, {100, 20, 0}};
  size_t checked = 0;
  for (auto& e : eyes) {
    for (auto& vw : views) {
      ViewParams p;
      p.origin = e;
      p.yaw = vw[0];
      p.pitch = vw[1];
      p.roll = vw[3];
      p.fov_x = vw[4];
      for (auto& sz : kSizes) {
        FrontFrame f = runner.run(room->world, p, sz[0], sz[1]);
        ASSERT_TRUE(f.ok()) << f.status;
        ASSERT_EQ(f.contract_error, "");
        ASSERT_EQ(f.bad_coverage(), 0u);
        EXPECT_GE(f.stats.visible_leaves, 1u);
        const render::ViewState& v = f.view;
        size_t wrong = 0;
        for (int y = 0; y < sz[1]; ++y) {
          for (int x = 0; x < sz[0]; ++x) {
            glm::dvec3 d = glm::dvec3(v.forward) + ((x + 0.5 - v.xcenter) / v.xscale) * glm::dvec3(v.right) -
                           ((y + 0.5 - v.ycenter) / v.yscale) * glm::dvec3(v.up);
            int w = exit_wall(glm::dvec3(v.origin), d, glm::dvec3(mn), glm::dvec3(mx), 1e-3);
            if (w < 0) continue;
            ++checked;
            if (f.face_at[size_t(y) * sz[0] + x] != uint32_t(w)) ++wrong;
          }
        }
        EXPECT_EQ(wrong, 0u) << "eye " << e.x << "," << e.y << "," << e.z << " yaw " << vw[0] << " pitch " << vw[1]
                             << " roll " << vw[3] << " fov " << vw[4] << " size " << sz[0] << "x" << sz[1];
      }
    }
  }
  EXPECT_GT(checked, 1000000u);
}

TEST(FrontPillarRoom, MatchesRayCaster) {
  auto room = make_pillar_room();
  RayCaster caster(room->world);
  FrontRunner runner;
  Agreement total;
  const glm::vec3 eyes[] = {{-200, 0, 0}, {200, 100, 30}, {48, 100, -50}, {-20, -120, 60}, {48, -40, 0}};
  for (auto& e : eyes) {
    for (float yaw = 0; yaw < 360; yaw += 45) {
      for (float pitch : {-30.0f, 0.0f, 40.0f}) {
        ViewParams p;
        p.origin = e;
        p.yaw = yaw;
        p.pitch = pitch;
        for (auto& sz : {kSizes[0], kSizes[4]}) {
          FrontFrame f = runner.run(room->world, p, sz[0], sz[1]);
          ASSERT_TRUE(f.ok()) << f.status;
          ASSERT_EQ(f.contract_error, "");
          ASSERT_EQ(f.bad_coverage(), 0u);
          Agreement a = compare(f, caster.cast(f.view));
          EXPECT_EQ(a.far_from_edge, 0u) << a.describe() << a.examples;
          total.add(a);
        }
      }
    }
  }
  std::printf("pillar room: %s\n", total.describe().c_str());
  EXPECT_GE(total.ratio(), 0.999);
}

TEST(FrontVis, MarksPvsLeavesAndParents) {
  // Pillar room with a PVS in which leaf 1 sees leaves 1 and 3 only.
  auto room = make_pillar_room();
  room->visdata = {0x05};  // bits 0 and 2: leaves 1 and 3
  for (size_t i = 1; i < room->leaves.size(); ++i) room->leaves[i].vis_offset = 0;
  room->world.visdata = room->visdata.data();
  room->world.visdata_size = 1;
  FrontRunner runner;
  ViewParams p;
  p.origin = {-200, 0, 0};
  FrontFrame f = runner.run(room->world, p, 320, 200);
  ASSERT_TRUE(f.ok());
  EXPECT_EQ(f.bad_coverage(), 0u);
  const uint32_t frame = f.view.frame;
  int leaf1 = f.view.view_leaf;
  EXPECT_EQ(room->leaves[size_t(leaf1)].visframe, frame);
  EXPECT_EQ(f.stats.visible_leaves, 2u);
  for (size_t i = 1; i < room->leaves.size(); ++i) {
    bool visible = i == 1 || i == 3;
    EXPECT_EQ(room->leaves[i].visframe == frame, visible) << "leaf " << i;
    if (visible) {  // every ancestor is stamped
      for (int32_t n = room->leaves[i].parent; n >= 0; n = room->nodes[size_t(n)].parent)
        EXPECT_EQ(room->nodes[size_t(n)].visframe, frame);
    }
  }
  // Nothing of the invisible leaves' walls is drawn.
  for (uint32_t face : f.face_at) {
    if (face == kNoFace) continue;
    bool in_leaf1_or_3 = false;
    for (size_t l : {size_t(1), size_t(3)}) {
      const Leaf& leaf = room->leaves[l];
      for (uint32_t m = 0; m < leaf.num_marksurfaces; ++m)
        in_leaf1_or_3 |= room->marksurfaces[leaf.first_marksurface + m] == face;
    }
    ASSERT_TRUE(in_leaf1_or_3) << "face " << face;
  }
  // The next frame from inside the pillar (solid): everything is visible.
  p.origin = {48, 0, 0};
  f = runner.run(room->world, p, 320, 200);
  ASSERT_TRUE(f.ok());
  EXPECT_EQ(f.view.view_leaf, 0);
  EXPECT_EQ(f.stats.visible_leaves, uint32_t(room->leaves.size() - 1));
  EXPECT_EQ(f.bad_coverage(), 0u);
}

TEST(FrontDegenerate, OddViewsStillCoverEveryPixel) {
  auto room = make_pillar_room();
  RayCaster caster(room->world);
  FrontRunner runner;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  struct Case { glm::vec3 origin; float yaw, pitch, roll, fov; int w, h; bool compare; };
  const Case cases[] = {
      {{48, 0, 0}, 0, 0, 0, 90, 320, 200, true},           // inside the solid pillar
      {{48, 0, 0}, 180, 20, 0, 90, 333, 197, true},
      {{-200, 0, 0}, 0, 0, 0, 10, 640, 480, true},         // narrowest fov
      {{-200, 0, 0}, 0, 0, 0, 170, 640, 480, true},        // widest fov
      {{-200, 0, 0}, 0, 0, 0, 0.001f, 320, 200, false},    // below the range: clamped
      {{-200, 0, 0}, 0, 0, 0, 400, 320, 200, false},
      {{-200, 0, 0}, 0, 0, 0, nan, 320, 200, false},
      {{-200, 0, 0}, 45, 0, 0, 90, 1, 1, true},
      {{-200, 0, 0}, 45, 0, 0, 90, 2, 3, true},
      {{-200, 0, 0}, 45, 0, 0, 90, 3000, 17, true},
      {{-200, 0, 0}, 45, 0, 0, 90, 17, 2000, true},
      {{-200, 0, 0}, 1e9f, -1e9f, 7e8f, 90, 320, 200, false},
      {{1e9f, -1e9f, 1e9f}, 0, 0, 0, 90, 320, 200, false},  // far outside the world
      {{1e30f, 0, 0}, 0, 0, 0, 90, 320, 200, false},
      {{nan, 0, 0}, 0, 0, 0, 90, 320, 200, false},
      {{inf, -inf, 0}, nan, inf, 0, 90, 320, 200, false},
      {{-256, 0, 0}, 0, 0, 0, 90, 320, 200, false},         // exactly on a wall plane
      {{32, 16, 0}, 225, 0, 0, 90, 320, 200, false},        // on the pillar's corner edge
      {{-255.95f, -127.95f, -63.95f}, 30, -20, 0, 90, 640, 480, true},  // in a corner, 0.05 from 3 walls
  };
  for (const Case& c : cases) {
    ViewParams p;
    p.origin = c.origin;
    p.yaw = c.yaw;
    p.pitch = c.pitch;
    p.roll = c.roll;
    p.fov_x = c.fov;
    FrontFrame f = runner.run(room->world, p, c.w, c.h);
    ASSERT_TRUE(f.ok()) << f.status;
    EXPECT_EQ(f.contract_error, "");
    EXPECT_EQ(f.bad_coverage(), 0u) << c.origin.x << " fov " << c.fov << " " << c.w << "x" << c.h;
    if (c.compare) {
      Agreement a = compare(f, caster.cast(f.view));
      EXPECT_EQ(a.far_from_edge, 0u) << "case " << (&c - cases) << ": " << a.describe() << a.examples;
    }
  }
  // Sizes the contract cannot express are refused, not drawn.
  render::ViewState bad = render::setup_view(room->world, ViewParams{}, 40000, 10, runner.next_frame());
  render::FrameSpans spans;
  EXPECT_FALSE(render::build_spans(room->world, bad, runner.arena(), &spans, nullptr).is_ok());
}

TEST(FrontOverflow, SmallFrameArenaStillCoversEveryPixel) {
  auto room = make_pillar_room();
  ViewParams p;
  p.origin = {-200, 60, 20};
  p.yaw = -10;
  // Enough for the fixed parts but not for one span per pixel run: spans overflow.
  for (size_t bytes : {size_t(40000), size_t(60000), size_t(200000)}) {
    FrontRunner runner(bytes);
    FrontFrame f = runner.run(room->world, p, 1280, 720);
    if (!f.ok()) {  // too small even for the reserve: refused with a message
      EXPECT_NE(f.status.find("too small"), std::string::npos) << f.status;
      continue;
    }
    EXPECT_EQ(f.contract_error, "");
    EXPECT_EQ(f.bad_coverage(), 0u) << bytes;
    std::printf("frame arena %zu bytes: spans %u overflow %d/%d/%d\n", bytes, f.num_spans, f.stats.edges_overflowed,
                f.stats.surfaces_overflowed, f.stats.spans_overflowed);
  }
  FrontRunner tiny(30000);
  FrontFrame f = tiny.run(room->world, p, 1920, 1080);
  EXPECT_FALSE(f.ok());
}

}  // namespace
}  // namespace sb::test::front
