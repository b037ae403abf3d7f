// tests/tools_lightkeys/light_keys_test.cpp: the light keys of brush entities end to end:
// hand-made .map sources compiled by sbbsp (which writes the .faceattr side file), relit by
// the light stage with the attributes read back from that file, lightmap bytes checked at
// chosen points: "_minlight" / "_minlight_color" on func_detail, "_shadow" on func_door and
// func_detail_illusionary, "_phong" across a shallow ridge, "_lightignore", and corrupt or
// mismatched side files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "tests/tools_bsp/bsp_test_util.h"
#include "tests/tools_light/light_test_util.h"
#include "tools/common/face_attrs.h"
#include "tools/light/light.h"

namespace sb::test {
namespace {

using tools::BspData;
using tools::FaceAttr;

const char* kWorld = "\"classname\" \"worldspawn\"\n\"wad\" \"lightkeys.wad\"";
const char* kPlayer = "\"classname\" \"info_player_start\"\n\"origin\" \"-200 0 24\"";

void write_wad() {
  static bool done = [] {
    std::vector<uint8_t> w = make_wad({"wall", "floor", "rock"});
    std::string path = bsp_scratch_dir() + "/lightkeys.wad";
    FILE* f = std::fopen(path.c_str(), "wb");
    std::fwrite(w.data(), 1, w.size(), f);
    std::fclose(f);
    return true;
  }();
  (void)done;
}

// A room x -256..256, y -128..128, z 0..192 plus `entities` (each a complete entity).
std::string room(const std::string& entities) {
  write_wad();
  return entity(kWorld, room_brushes(-256, -128, 0, 256, 128, 192, "wall")) + entity(kPlayer) + entities;
}

std::string light_at(double x, double y, double z, const std::string& extra = "\"light\" \"300\"") {
  char buf[128];
  std::snprintf(buf, sizeof buf, "\"classname\" \"light\"\n\"origin\" \"%g %g %g\"\n", x, y, z);
  return entity(buf + extra);
}

// A convex brush from outward planes (normal, dist): three points on each plane, ordered so
// that sbbsp's plane_from_points gives that normal.
struct PlaneDef {
  glm::dvec3 n;
  double d;
};
std::string plane_brush(const std::vector<PlaneDef>& planes, const std::string& tex) {
  std::string s = "{\n";
  for (const PlaneDef& p : planes) {
    glm::dvec3 n = glm::normalize(p.n);
    glm::dvec3 any = std::fabs(n.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    glm::dvec3 u = glm::normalize(glm::cross(any, n)), v = glm::cross(n, u);
    glm::dvec3 p1 = n * (p.d / glm::length(p.n)), p0 = p1 + u * 64.0, p2 = p1 + v * 64.0;
    char buf[256];
    std::snprintf(buf, sizeof buf, "( %.6f %.6f %.6f ) ( %.6f %.6f %.6f ) ( %.6f %.6f %.6f ) %s 0 0 0 1 1\n", p0.x,
                  p0.y, p0.z, p1.x, p1.y, p1.z, p2.x, p2.y, p2.z, tex.c_str());
    s += buf;
  }
  return s + "}\n";
}

struct Lit {
  Status status;
  BspData bsp;
  std::vector<FaceAttr> attrs;
  bool attrs_found = false;
  std::vector<uint8_t> rgb;
  std::unique_ptr<tools::test::EngineView> view;
  std::string bsp_path;
};

// Compiles `text`, reads the side file back (when written) and lights with it.
void compile_and_light(const std::string& name, const std::string& text, Lit* out) {
  CompileRun run = compile_text(name, text);
  out->status = run.status;
  if (!run.status) return;
  out->bsp_path = run.bsp_path;
  out->bsp = run.report.bsp;
  out->status = tools::read_face_attrs(tools::face_attr_path(run.bsp_path).c_str(), out->bsp, &out->attrs,
                                       &out->attrs_found);
  if (!out->status) return;
  tools::LightOptions opts;
  opts.threads = 2;
  opts.quiet = true;
  opts.want_rgb = true;
  out->status = tools::light_bsp(name.c_str(), &out->bsp, opts, nullptr, &out->rgb, &out->attrs);
  if (!out->status) return;
  out->view = std::make_unique<tools::test::EngineView>(out->bsp);
}

// The lightmap byte (style 0) of the face facing `normal` whose polygon holds `p`, at the
// grid point nearest p; -1 when no such face. *rgb_out (optional) gets the .lit colour.
int sample(const Lit& lit, glm::vec3 p, glm::vec3 normal, glm::ivec3* rgb_out = nullptr) {
  const BspWorld* w = lit.view ? lit.view->world() : nullptr;
  if (!w) return -1;
  normal = glm::normalize(normal);
  for (uint32_t i = 0; i < w->num_faces; ++i) {
    const Face& f = w->faces[i];
    if (f.light_offset < 0) continue;
    glm::vec3 n = w->planes[f.plane].normal;
    float dist = w->planes[f.plane].dist;
    if (f.flags & kFacePlaneBack) n = -n, dist = -dist;
    if (glm::dot(n, normal) < 0.999f || std::fabs(glm::dot(n, p) - dist) > 0.5f) continue;
    std::vector<glm::vec3> vs;
    for (uint32_t k = 0; k < f.num_edges; ++k) {
      int32_t se = w->surfedges[f.first_surfedge + k];
      uint32_t e = uint32_t(se < 0 ? -se : se);
      vs.push_back(w->vertices[se < 0 ? w->edges[e].v[1] : w->edges[e].v[0]]);
    }
    bool pos = true, neg = true;  // p on the inner side of every edge (either winding)
    for (size_t k = 0; k < vs.size(); ++k) {
      glm::vec3 a = vs[k], b = vs[(k + 1) % vs.size()];
      float side = glm::dot(glm::cross(b - a, p - a), n) / std::max(glm::length(b - a), 1e-6f);
      pos = pos && side >= -0.1f;
      neg = neg && side <= 0.1f;
    }
    if (!pos && !neg) continue;
    const TexInfo& ti = w->texinfo[f.texinfo];
    float s = glm::dot(p, glm::vec3(ti.vecs[0])) + ti.vecs[0].w;
    float t = glm::dot(p, glm::vec3(ti.vecs[1])) + ti.vecs[1].w;
    int gw = f.extents[0] / 16 + 1, gh = f.extents[1] / 16 + 1;
    int gx = std::clamp(int(std::lround((s - f.texture_mins[0]) / 16.0f)), 0, gw - 1);
    int gy = std::clamp(int(std::lround((t - f.texture_mins[1]) / 16.0f)), 0, gh - 1);
    size_t at = size_t(f.light_offset) + size_t(gy) * gw + gx;
    if (rgb_out) *rgb_out = glm::ivec3(lit.rgb[at * 3], lit.rgb[at * 3 + 1], lit.rgb[at * 3 + 2]);
    return w->lightdata[at];
  }
  return -1;
}

const glm::vec3 kUp(0, 0, 1);

TEST(LightKeys, MinlightOnFuncDetailLightsItsFacesOnly) {
  // No light at all: the world stays black; the func_detail block gets its floor, red in .lit.
  std::string text = room(entity("\"classname\" \"func_detail\"\n\"_minlight\" \"100\"\n\"_minlight_color\" \"255 0 0\"",
                                 box_brush(-32, -32, 0, 32, 32, 48, "rock")));
  Lit lit;
  compile_and_light("keys_minlight", text, &lit);
  ASSERT_TRUE(lit.status.is_ok()) << lit.status.message();
  ASSERT_TRUE(lit.attrs_found);
  glm::ivec3 rgb;
  EXPECT_GE(sample(lit, {0, 0, 48}, kUp, &rgb), 100);
  EXPECT_EQ(rgb, glm::ivec3(100, 0, 0));
  EXPECT_GE(sample(lit, {32, 0, 24}, {1, 0, 0}), 100);
  EXPECT_EQ(sample(lit, {128, 0, 0}, kUp), 0);  // the world floor next to it
  EXPECT_EQ(sample(lit, {-128, 0, 192}, -kUp), 0);

  // Without the key: no side file, everything dark.
  std::string plain = room(entity("\"classname\" \"func_detail\"", box_brush(-32, -32, 0, 32, 32, 48, "rock")));
  Lit dark;
  compile_and_light("keys_minlight_none", plain, &dark);
  ASSERT_TRUE(dark.status.is_ok()) << dark.status.message();
  EXPECT_FALSE(dark.attrs_found);
  EXPECT_EQ(sample(dark, {0, 0, 48}, kUp), 0);
}

// Floor value under a box at x -32..32, y -32..32, z 64..80 lit from (0, 0, 176), and the
// floor value at the same distance from the light beside it, for a brush entity `keys`.
void shadow_case(const std::string& name, const std::string& keys, int* under, int* beside) {
  std::string text = room(entity(keys, box_brush(-32, -32, 64, 32, 32, 80, "rock")) + light_at(0, 0, 176));
  Lit lit;
  compile_and_light(name, text, &lit);
  ASSERT_TRUE(lit.status.is_ok()) << lit.status.message();
  *under = sample(lit, {0, 0, 0}, kUp);
  *beside = sample(lit, {0, 96, 0}, kUp);
}

TEST(LightKeys, FuncDoorCastsAShadowOnlyWithShadowKey) {
  int under = -1, beside = -1;
  shadow_case("keys_door", "\"classname\" \"func_door\"", &under, &beside);
  EXPECT_GT(under, 60);              // no shadow by default: lit as the open floor
  EXPECT_GE(under, beside);          // (it is nearer the light)
  int su = -1, sb = -1;
  shadow_case("keys_door_shadow", "\"classname\" \"func_door\"\n\"_shadow\" \"1\"", &su, &sb);
  EXPECT_LT(su, under / 4) << "the door casts no shadow with \"_shadow\" \"1\"";
  EXPECT_NEAR(sb, beside, 2);        // the open floor beside it is unchanged
}

TEST(LightKeys, FuncDetailIllusionaryCastsAShadowOnlyWithShadowKey) {
  int under = -1, beside = -1;
  shadow_case("keys_illu", "\"classname\" \"func_detail_illusionary\"", &under, &beside);
  EXPECT_GT(under, 60);
  int su = -1, sb = -1;
  shadow_case("keys_illu_shadow", "\"classname\" \"func_detail_illusionary\"\n\"_shadow\" \"1\"", &su, &sb);
  EXPECT_LT(su, under / 4);
  EXPECT_NEAR(sb, beside, 2);
  // func_detail is solid in the world: a shadow without any key.
  int du = -1, db = -1;
  shadow_case("keys_detail", "\"classname\" \"func_detail\"", &du, &db);
  EXPECT_LT(du, under / 4);
}

TEST(LightKeys, SelfShadowShadowsOnlyTheEntityItself) {
  // A func_wall made of a slab (z 64..80) over a low block (z 0..16): with "_selfshadow" the
  // slab shadows the block's top but not the world floor.
  std::string wall = box_brush(-64, -64, 64, 64, 64, 80, "rock") + box_brush(-16, -16, 0, 16, 16, 16, "rock");
  auto run = [&](const std::string& name, const std::string& keys, int* block, int* floor) {
    Lit lit;
    compile_and_light(name, room(entity(keys, wall) + light_at(0, 0, 176)), &lit);
    ASSERT_TRUE(lit.status.is_ok()) << lit.status.message();
    *block = sample(lit, {0, 0, 16}, kUp);
    *floor = sample(lit, {40, 0, 0}, kUp);
  };
  int b0 = -1, f0 = -1, b1 = -1, f1 = -1;
  run("keys_self_none", "\"classname\" \"func_wall\"", &b0, &f0);
  run("keys_self", "\"classname\" \"func_wall\"\n\"_selfshadow\" \"1\"", &b1, &f1);
  EXPECT_GT(b0, 60);
  EXPECT_LT(b1, b0 / 4);
  EXPECT_NEAR(f1, f0, 2);
}

TEST(LightKeys, LightIgnoreGetsOnlyItsMinimumLight) {
  std::string text = room(entity("\"classname\" \"func_detail\"\n\"_lightignore\" \"1\"\n\"_minlight\" \"20\"",
                                 box_brush(-32, -32, 0, 32, 32, 48, "rock")) +
                          light_at(0, 0, 176));
  Lit lit;
  compile_and_light("keys_lightignore", text, &lit);
  ASSERT_TRUE(lit.status.is_ok()) << lit.status.message();
  EXPECT_EQ(sample(lit, {0, 0, 48}, kUp), 20);
  EXPECT_GT(sample(lit, {128, 0, 0}, kUp), 25);
}

// A ridge along y (x -128..128, ridge z 32 at x 0, slopes of 14 degrees) lit by a light without
// falloff and full angle attenuation from the +x side: the two slopes at the ridge.
void ridge_case(const std::string& name, const std::string& keys, int* left, int* right, int* right_mid) {
  std::vector<PlaneDef> planes = {
      {{0, 0, -1}, 0}, {{0, 1, 0}, 64}, {{0, -1, 0}, 64}, {{32, 0, 128}, 32 * 128}, {{-32, 0, 128}, 32 * 128}};
  std::string text = room(entity(keys, plane_brush(planes, "rock")) +
                          light_at(240, 0, 176, "\"light\" \"200\"\n\"delay\" \"3\"\n\"_anglescale\" \"1\""));
  Lit lit;
  compile_and_light(name, text, &lit);
  ASSERT_TRUE(lit.status.is_ok()) << lit.status.message();
  glm::vec3 nr(32, 0, 128), nl(-32, 0, 128);
  *left = sample(lit, {-1, 0, 31.75f}, nl);
  *right = sample(lit, {1, 0, 31.75f}, nr);
  *right_mid = sample(lit, {64, 0, 16}, nr);
}

TEST(LightKeys, PhongSmoothsTheRidgeAndFlatShowsAStep) {
  int l0 = -1, r0 = -1, m0 = -1;
  ridge_case("keys_ridge_flat", "\"classname\" \"func_detail\"", &l0, &r0, &m0);
  ASSERT_GE(l0, 0);
  ASSERT_GE(r0, 0);
  EXPECT_GT(r0 - l0, 20) << "flat shading: a step at the ridge (" << l0 << " vs " << r0 << ")";
  int l1 = -1, r1 = -1, m1 = -1;
  ridge_case("keys_ridge_phong", "\"classname\" \"func_detail\"\n\"_phong\" \"1\"\n\"_phong_angle\" \"30\"", &l1, &r1,
             &m1);
  std::printf("ridge: flat %d | %d (mid %d), phong %d | %d (mid %d)\n", l0, r0, m0, l1, r1, m1);
  EXPECT_LE(std::abs(r1 - l1), 3) << "phong: continuous across the ridge (" << l1 << " vs " << r1 << ")";
  EXPECT_GT(m1, r1 + 5) << "phong: the normal turns towards the slope's own further down";
  EXPECT_GT(r1, l0 + 5);
  EXPECT_LT(r1, r0 - 5);
}

TEST(LightKeys, CorruptOrMismatchedSideFileIsAClearError) {
  std::string text = room(entity("\"classname\" \"func_detail\"\n\"_minlight\" \"50\"", box_brush(-32, -32, 0, 32, 32, 48, "rock")));
  CompileRun run = compile_text("keys_side", text);
  ASSERT_TRUE(run.status.is_ok()) << run.status.message();
  const std::string path = tools::face_attr_path(run.bsp_path);
  EXPECT_EQ(run.report.face_attr_path, path);
  std::vector<uint8_t> bytes;
  {
    FILE* f = std::fopen(path.c_str(), "rb");
    ASSERT_NE(f, nullptr);
    uint8_t buf[4096];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) bytes.insert(bytes.end(), buf, buf + n);
    std::fclose(f);
  }
  const BspData& bsp = run.report.bsp;
  ASSERT_EQ(bytes.size(), tools::kFaceAttrHeaderSize + bsp.faces.size() * tools::kFaceAttrRecordSize);
  std::vector<FaceAttr> attrs;
  ASSERT_TRUE(tools::parse_face_attrs("x.faceattr", bytes.data(), bytes.size(), bsp, &attrs).is_ok());
  EXPECT_EQ(attrs, run.report.face_attrs);

  auto error_of = [&](std::vector<uint8_t> b) {
    Status s = tools::parse_face_attrs("x.faceattr", b.data(), b.size(), bsp, &attrs);
    return s.is_ok() ? std::string("ok") : std::string(s.message());
  };
  std::vector<uint8_t> b = bytes;
  b.resize(b.size() - 5);
  EXPECT_NE(error_of(b).find("x.faceattr: offset"), std::string::npos) << error_of(b);
  EXPECT_NE(error_of({bytes.begin(), bytes.begin() + 10}).find("too short"), std::string::npos);
  b = bytes;
  b[0] = 'X';
  EXPECT_NE(error_of(b).find("offset 0: magic"), std::string::npos) << error_of(b);
  b = bytes;
  b[4] = 9;
  EXPECT_NE(error_of(b).find("offset 4: version 9"), std::string::npos) << error_of(b);
  b = bytes;
  b[tools::kFaceAttrHeaderSize + 8 + 3] = 0x7f;  // first record's phong angle: NaN
  b[tools::kFaceAttrHeaderSize + 8 + 2] = 0xc0;
  EXPECT_NE(error_of(b).find("offset 32: face 0"), std::string::npos) << error_of(b);

  // Another map's BSP: the face count or the face hash does not match.
  std::string other = room(entity("\"classname\" \"func_detail\"", box_brush(-40, -32, 0, 32, 32, 48, "rock")) +
                           entity("\"classname\" \"func_detail\"", box_brush(100, -32, 0, 132, 32, 48, "rock")));
  CompileRun run2 = compile_text("keys_side_other", other);
  ASSERT_TRUE(run2.status.is_ok());
  Status s = tools::parse_face_attrs("x.faceattr", bytes.data(), bytes.size(), run2.report.bsp, &attrs);
  ASSERT_FALSE(s.is_ok());
  EXPECT_TRUE(std::string(s.message()).find("offset 8:") != std::string::npos ||
              std::string(s.message()).find("offset 16:") != std::string::npos)
      << s.message();
  EXPECT_NE(std::string(s.message()).find("another compile"), std::string::npos);
  // Same face count, other faces: the hash.
  BspData moved = bsp;
  moved.faces[0].texinfo ^= 1;
  s = tools::parse_face_attrs("x.faceattr", bytes.data(), bytes.size(), moved, &attrs);
  EXPECT_NE(std::string(s.message()).find("offset 16: face hash"), std::string::npos) << s.message();

  // Read from disk: a missing file is no error; a corrupt one names the path.
  bool found = true;
  EXPECT_TRUE(tools::read_face_attrs((path + ".absent").c_str(), bsp, &attrs, &found).is_ok());
  EXPECT_FALSE(found);
  {
    FILE* f = std::fopen(path.c_str(), "wb");
    std::fwrite(bytes.data(), 1, 30, f);
    std::fclose(f);
  }
  s = tools::read_face_attrs(path.c_str(), bsp, &attrs, &found);
  EXPECT_TRUE(found);
  EXPECT_NE(std::string(s.message()).find(path + ": offset"), std::string::npos) << s.message();

  // The light stage refuses attributes that do not fit the BSP.
  BspData copy = bsp;
  std::vector<FaceAttr> short_attrs(bsp.faces.size() - 1);
  s = tools::light_bsp("keys.bsp", &copy, tools::LightOptions(), nullptr, nullptr, &short_attrs);
  EXPECT_FALSE(s.is_ok());
}

TEST(LightKeys, MapsWithoutLightKeysGetNoSideFileAndTheSameBsp) {
  // A stale side file is removed; the BSP equals one compiled from the keyless source.
  std::string with = room(entity("\"classname\" \"func_wall\"\n\"_minlight\" \"30\"", box_brush(-32, -32, 0, 32, 32, 48, "rock")));
  std::string without = room(entity("\"classname\" \"func_wall\"", box_brush(-32, -32, 0, 32, 32, 48, "rock")));
  CompileRun a = compile_text("keys_stale", with);
  ASSERT_TRUE(a.status.is_ok());
  const std::string path = tools::face_attr_path(a.bsp_path);
  FILE* f = std::fopen(path.c_str(), "rb");
  ASSERT_NE(f, nullptr);
  std::fclose(f);
  CompileRun b = compile_text("keys_stale", without);
  ASSERT_TRUE(b.status.is_ok());
  EXPECT_TRUE(b.report.face_attrs.empty());
  f = std::fopen(path.c_str(), "rb");
  EXPECT_EQ(f, nullptr);
  if (f) std::fclose(f);
  // A brush model's faces never merge with the world's: the keys leave the BSP as it was
  // (but for the keys themselves in the entity lump).
  std::vector<uint8_t> ba, bb;
  BspData a_bsp = a.report.bsp;
  a_bsp.entities = b.report.bsp.entities;
  ASSERT_TRUE(tools::serialize_bsp(a_bsp, tools::BspFormat::Auto, &ba, nullptr).is_ok());
  ASSERT_TRUE(tools::serialize_bsp(b.report.bsp, tools::BspFormat::Auto, &bb, nullptr).is_ok());
  EXPECT_EQ(ba.size(), bb.size());
  EXPECT_TRUE(ba == bb);
}

}  // namespace
}  // namespace sb::test
