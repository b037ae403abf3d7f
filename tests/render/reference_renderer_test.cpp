// tests/render/reference_renderer_test.cpp: the reference renderer checked against
// hand-computed answers on tiny synthetic worlds (no game data needed), so that the
// agreement tests rest on something obviously right.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "tests/support/reference_renderer.h"

namespace sb::test {
namespace {

// A world of axis-aligned quads built in heap vectors. One 16x16 texture whose texel
// (s, t) is t * 16 + s at every mip (so a colour names its texel), no lightmaps (full
// light: colormap row 0), identity colormap row 0.
class SynthWorld {
 public:
  SynthWorld() {
    for (int m = 0; m < 4; ++m) {
      int n = 16 >> m;
      texels_[m].resize(size_t(n) * n);
      for (int t = 0; t < n; ++t)
        for (int s = 0; s < n; ++s) texels_[m][size_t(t) * n + s] = uint8_t(t * 16 + s);
    }
    colormap_.assign(64 * 256, 0);
    for (int r = 0; r < 64; ++r)
      for (int i = 0; i < 256; ++i) colormap_[r * 256 + i] = uint8_t(r == 0 ? i : 255 - r);
  }

  // A convex polygon (corners in order) lying on plane (normal, dist), textured with s = dot(p, sv),
  // t = dot(p, tv). back: its front is the back of the plane.
  void add_quad(const std::vector<glm::vec3>& corners, glm::vec3 normal, float dist, glm::vec3 sv, glm::vec3 tv,
                bool back = false) {
    Plane pl{};
    pl.normal = normal;
    pl.dist = dist;
    planes_.push_back(pl);
    TexInfo ti{};
    ti.vecs[0] = glm::vec4(sv, 0.0f);
    ti.vecs[1] = glm::vec4(tv, 0.0f);
    ti.texture = 0;
    ti.mipadjust = 1.0f;
    texinfo_.push_back(ti);
    Face f{};
    f.plane = uint32_t(planes_.size() - 1);
    f.texinfo = uint32_t(texinfo_.size() - 1);
    f.first_surfedge = uint32_t(surfedges_.size());
    f.num_edges = uint32_t(corners.size());
    f.flags = back ? kFacePlaneBack : 0;
    f.light_offset = kNoLightmap;
    for (int k = 0; k < 4; ++k) f.styles[k] = 255;
    double mn[2] = {1e30, 1e30}, mx[2] = {-1e30, -1e30};
    for (size_t i = 0; i < corners.size(); ++i) {
      uint32_t a = vertex(corners[i]), b = vertex(corners[(i + 1) % corners.size()]);
      edges_.push_back(Edge{{a, b}});
      surfedges_.push_back(int32_t(edges_.size() - 1));
      double st[2] = {glm::dot(corners[i], sv), glm::dot(corners[i], tv)};
      for (int k = 0; k < 2; ++k) mn[k] = std::min(mn[k], st[k]), mx[k] = std::max(mx[k], st[k]);
    }
    for (int k = 0; k < 2; ++k) {
      int lo = int(std::floor(mn[k] / 16)), hi = int(std::ceil(mx[k] / 16));
      f.texture_mins[k] = lo * 16;
      f.extents[k] = (hi - lo) * 16;
    }
    faces_.push_back(f);
  }

  // Model 0 draws faces [first, first + count) (all by default).
  const BspWorld& world(uint32_t first = 0, uint32_t count = 0xffffffffu) {
    tex_ = Texture{};
    tex_.width = tex_.height = 16;
    for (int m = 0; m < 4; ++m) tex_.mips[m] = texels_[m].data();
    tex_.anim_next = tex_.alternate = -1;
    model_ = SubModel{};
    model_.first_face = first;
    model_.num_faces = count == 0xffffffffu ? uint32_t(faces_.size()) : count;
    w_ = BspWorld{};
    w_.planes = planes_.data(); w_.num_planes = uint32_t(planes_.size());
    w_.vertices = vertices_.data(); w_.num_vertices = uint32_t(vertices_.size());
    w_.edges = edges_.data(); w_.num_edges = uint32_t(edges_.size());
    w_.surfedges = surfedges_.data(); w_.num_surfedges = uint32_t(surfedges_.size());
    w_.texinfo = texinfo_.data(); w_.num_texinfo = uint32_t(texinfo_.size());
    w_.textures = &tex_; w_.num_textures = 1;
    w_.faces = faces_.data(); w_.num_faces = uint32_t(faces_.size());
    w_.models = &model_; w_.num_models = 1;
    return w_;
  }

  ReferenceFrame render(const ViewParams& v, int w, int h, uint32_t first = 0, uint32_t count = 0xffffffffu) {
    const BspWorld& bw = world(first, count);
    ReferenceRenderer r(ReferenceInputs{&bw, 0.0, nullptr, colormap_.data()});
    return r.render(v, w, h);
  }

 private:
  uint32_t vertex(glm::vec3 p) {
    for (size_t i = 0; i < vertices_.size(); ++i)
      if (vertices_[i] == p) return uint32_t(i);
    vertices_.push_back(p);
    return uint32_t(vertices_.size() - 1);
  }

  std::vector<Plane> planes_;
  std::vector<glm::vec3> vertices_;
  std::vector<Edge> edges_;
  std::vector<int32_t> surfedges_;
  std::vector<TexInfo> texinfo_;
  std::vector<Face> faces_;
  std::vector<uint8_t> texels_[4], colormap_;
  Texture tex_{};
  SubModel model_{};
  BspWorld w_{};
};

// A wall at x = 100 facing the origin, y and z in [-50, 50]; s = y, t = -z.
void add_wall(SynthWorld& sw) {
  sw.add_quad({{100, -50, -50}, {100, -50, 50}, {100, 50, 50}, {100, 50, -50}}, {-1, 0, 0}, -100, {0, 1, 0},
              {0, 0, -1});
}

int covered(const ReferenceFrame& f) {
  int n = 0;
  for (const ReferenceSample& s : f.samples) n += s.face != kNoFace;
  return n;
}

TEST(ReferenceRenderer, WallCoversExactlyThePixelCentresInsideIt) {
  SynthWorld sw;
  add_wall(sw);
  // 320 wide, fov 90: xscale = 160. The wall spans sx in [80, 240], sy in [20, 180].
  ReferenceFrame f = sw.render(ViewParams{}, 320, 200);
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 320; ++x) {
      bool inside = x >= 80 && x < 240 && y >= 20 && y < 180;  // top-left: left/top edges included
      ASSERT_EQ(f.face_at(x, y) == 0, inside) << x << "," << y;
    }
}

TEST(ReferenceRenderer, PixelCentresOnEdgesFollowTheTopLeftRule) {
  // 257 x 161: the centre of pixel (128, 80) lies exactly on the view axis, so column 128 and
  // row 80 have their centres exactly on the planes y = 0 and z = 0 whatever the projection
  // scale. Four quadrants of a wall at x = 128 meet there (screen right = -y, up = +z).
  SynthWorld sw;
  const float lo = -47.5f, hi = 47.5f;
  auto quadrant = [&](float y0, float y1, float z0, float z1) {
    sw.add_quad({{128, y0, z0}, {128, y0, z1}, {128, y1, z1}, {128, y1, z0}}, {-1, 0, 0}, -128, {0, 1, 0},
                {0, 0, -1});
  };
  quadrant(lo, 0, lo, 0);  // 0: screen right, below
  quadrant(0, hi, lo, 0);  // 1: screen left, below
  quadrant(lo, 0, 0, hi);  // 2: screen right, above
  quadrant(0, hi, 0, hi);  // 3: screen left, above
  std::vector<ReferenceFrame> q;
  for (uint32_t i = 0; i < 4; ++i) q.push_back(sw.render(ViewParams{}, 257, 161, i, 1));
  // Centres on a shared edge go to the face for which it is a left or top edge.
  EXPECT_EQ(q[0].face_at(128, 80), 0u);
  for (int y = 60; y < 100; ++y) EXPECT_EQ(q[y < 80 ? 2 : 0].face_at(128, y), y < 80 ? 2u : 0u) << y;
  for (int x = 100; x < 150; ++x) EXPECT_EQ(q[x < 128 ? 1 : 0].face_at(x, 80), x < 128 ? 1u : 0u) << x;
  // Every pixel centre near the cross is covered exactly once.
  for (int y = 60; y < 100; ++y)
    for (int x = 100; x < 150; ++x) {
      int n = 0;
      for (uint32_t i = 0; i < 4; ++i) n += q[i].face_at(x, y) == i;
      ASSERT_EQ(n, 1) << x << "," << y;
    }
}

TEST(ReferenceRenderer, TexelsFollowTextureAxesAtExactPerspective) {
  SynthWorld sw;
  add_wall(sw);
  ReferenceFrame f = sw.render(ViewParams{}, 320, 200);
  for (int y = 20; y < 180; y += 7)
    for (int x = 80; x < 240; x += 5) {
      // The ray through the centre hits (100, -100 a, -100 b): s = -100 a, t = 100 b.
      double a = (x + 0.5 - 160) / 160.0, b = (y + 0.5 - 100) / 160.0;
      int s = int(std::floor(-100 * a)), t = int(std::floor(100 * b));
      int expect = ((t % 16 + 16) % 16) * 16 + ((s % 16 + 16) % 16);
      ASSERT_EQ(f.pixels[size_t(y) * 320 + x], expect) << x << "," << y;
      ASSERT_EQ(f.samples[size_t(y) * 320 + x].mip, 0);  // nearzi * xscale = 1.6 pixels per texel
    }
}

TEST(ReferenceRenderer, FacesSharingAnEdgeSplitItsPixelsExactly) {
  SynthWorld sw;
  // The wall as two triangles sharing the diagonal, seen off-centre and rolled so the
  // diagonal crosses many pixel centres at odd slopes.
  sw.add_quad({{100, -50, -50}, {100, -50, 50}, {100, 50, 50}}, {-1, 0, 0}, -100, {0, 1, 0}, {0, 0, -1});
  sw.add_quad({{100, -50, -50}, {100, 50, 50}, {100, 50, -50}}, {-1, 0, 0}, -100, {0, 1, 0}, {0, 0, -1});
  for (float roll : {0.0f, 13.0f, 45.0f}) {
    ViewParams v;
    v.origin = {0.0f, 3.25f, -1.5f};
    v.roll = roll;
    ReferenceFrame both = sw.render(v, 320, 200);
    ReferenceFrame first = sw.render(v, 320, 200, 0, 1);
    ReferenceFrame second = sw.render(v, 320, 200, 1, 1);
    SynthWorld whole;
    add_wall(whole);
    ReferenceFrame wall = whole.render(v, 320, 200);
    int overlap = 0, mismatch = 0;
    for (size_t i = 0; i < both.samples.size(); ++i) {
      bool a = first.samples[i].face != kNoFace, b = second.samples[i].face != kNoFace;
      overlap += a && b;
      mismatch += (a || b) != (wall.samples[i].face != kNoFace);
    }
    EXPECT_EQ(overlap, 0) << "roll " << roll;
    EXPECT_EQ(mismatch, 0) << "roll " << roll;
    EXPECT_GT(covered(first), 1000);
    EXPECT_GT(covered(second), 1000);
  }
}

TEST(ReferenceRenderer, ViewAnglesFollowQuakeConventions) {
  SynthWorld sw;
  add_wall(sw);                                                                            // face 0: +x
  sw.add_quad({{-50, 100, -50}, {50, 100, -50}, {50, 100, 50}, {-50, 100, 50}}, {0, 1, 0}, 100, {1, 0, 0},
              {0, 0, -1}, true);                                                           // face 1: +y (north)
  sw.add_quad({{-500, -500, -100}, {500, -500, -100}, {500, 500, -100}, {-500, 500, -100}}, {0, 0, 1}, -100,
              {1, 0, 0}, {0, 1, 0});                                                       // face 2: floor below
  auto centre = [&](ViewParams v) { return sw.render(v, 64, 40).face_at(32, 20); };
  ViewParams v;
  EXPECT_EQ(centre(v), 0u);
  v.yaw = 90;  // turns left, to +y
  EXPECT_EQ(centre(v), 1u);
  v.yaw = 0;
  v.pitch = 90;  // positive pitch looks down
  EXPECT_EQ(centre(v), 2u);
  v.pitch = -90;
  EXPECT_EQ(centre(v), kNoFace);
  // Looking +x with the floor below: positive roll turns the view's right side downwards,
  // so the floor rises into the right half of the picture.
  v.pitch = 0;
  v.roll = 60;
  ReferenceFrame f = sw.render(v, 64, 40);
  EXPECT_EQ(f.face_at(62, 20), 2u);
  EXPECT_NE(f.face_at(1, 20), 2u);
}

TEST(ReferenceRenderer, BackFacesAndNearestSurface) {
  SynthWorld sw;
  add_wall(sw);
  // A smaller wall in front (x = 60), facing the origin, and one behind the eye.
  sw.add_quad({{60, -10, -10}, {60, -10, 10}, {60, 10, 10}, {60, 10, -10}}, {-1, 0, 0}, -60, {0, 1, 0}, {0, 0, -1});
  sw.add_quad({{-60, -10, -10}, {-60, 10, -10}, {-60, 10, 10}, {-60, -10, 10}}, {1, 0, 0}, -60, {0, 1, 0},
              {0, 0, -1});
  ReferenceFrame f = sw.render(ViewParams{}, 320, 200);
  EXPECT_EQ(f.face_at(160, 100), 1u);
  EXPECT_EQ(f.face_at(100, 100), 0u);
  for (const ReferenceSample& s : f.samples) EXPECT_NE(s.face, 2u);
  // From behind (x = 200 looking back at the walls' backs), nothing is drawn.
  ViewParams back;
  back.origin = {200, 0, 0};
  back.yaw = 180;
  EXPECT_EQ(covered(sw.render(back, 320, 200, 0, 2)), 0);
}

}  // namespace
}  // namespace sb::test
