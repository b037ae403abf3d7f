// Light stage on a real LibreQuake map (start.bsp): the output loads in the engine, every
// lit face has a lightmap of the right size, results do not depend on the thread count,
// light falls off with distance and is stopped by walls. Also prints the mean sample value
// of ericw-tools' lighting beside ours (a figure, not a check).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <glm/geometric.hpp>

#include "engine/formats/entities.h"
#include "tests/support/quake_data.h"
#include "tests/tools_light/light_test_util.h"
#include "tools/light/light.h"
#include "tools/light/light_entities.h"
#include "tools/light/light_trace.h"

namespace sb::tools {
namespace {

// start.bsp copied into a fresh temporary folder (the shared data is never written).
std::string copy_start(const char* tag) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / ("sb_light_test_" + std::string(tag));
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  std::filesystem::path dst = dir / "start.bsp";
  std::filesystem::copy_file(sb::test::quake_dir() + "/lq1/maps/start.bsp", dst,
                             std::filesystem::copy_options::overwrite_existing, ec);
  return ec ? std::string() : dst.string();
}

BspData relit(const std::string& path, LightOptions opts, LightStats* stats = nullptr,
              std::vector<uint8_t>* rgb = nullptr) {
  BspData b;
  Status s = read_bsp(path.c_str(), &b);
  EXPECT_TRUE(s.is_ok()) << s.message();
  s = light_bsp(path.c_str(), &b, opts, stats, rgb);
  EXPECT_TRUE(s.is_ok()) << s.message();
  return b;
}

double face_mean(const BspWorld& w, uint32_t f) {
  const Face& face = w.faces[f];
  if (face.light_offset == kNoLightmap) return -1;
  uint32_t n = uint32_t(face.extents[0] / 16 + 1) * uint32_t(face.extents[1] / 16 + 1);
  double sum = 0;
  for (uint32_t k = 0; k < n; ++k) sum += w.lightdata[face.light_offset + k];
  return sum / n;
}

struct FaceShape {
  glm::vec3 normal, centroid;
  std::vector<glm::vec3> verts;
};

FaceShape shape(const BspWorld& w, uint32_t f) {
  const Face& face = w.faces[f];
  FaceShape s;
  s.normal = w.planes[face.plane].normal * ((face.flags & kFacePlaneBack) ? -1.0f : 1.0f);
  s.centroid = glm::vec3(0);
  for (uint32_t k = 0; k < face.num_edges; ++k) {
    int32_t se = w.surfedges[face.first_surfedge + k];
    uint32_t e = uint32_t(se < 0 ? -se : se);
    s.verts.push_back(w.vertices[se < 0 ? w.edges[e].v[1] : w.edges[e].v[0]]);
    s.centroid += s.verts.back();
  }
  s.centroid /= float(s.verts.size());
  return s;
}

TEST(LightStart, OutputLoadsAndEveryLitFaceHasItsLightmap) {
  SB_REQUIRE_QUAKE_DATA();
  std::string path = copy_start("load");
  ASSERT_FALSE(path.empty());
  LightOptions opts;
  opts.threads = 2;
  opts.want_rgb = true;
  LightStats stats;
  std::vector<uint8_t> rgb;
  BspData b = relit(path, opts, &stats, &rgb);
  ASSERT_TRUE(write_bsp(path.c_str(), b, b.format).is_ok());
  std::string lit = path.substr(0, path.size() - 4) + ".lit";
  ASSERT_TRUE(write_lit(lit.c_str(), rgb).is_ok());
  EXPECT_EQ(std::filesystem::file_size(lit), 8 + 3 * b.lighting.size());

  BspData back;
  ASSERT_TRUE(read_bsp(path.c_str(), &back).is_ok());
  EXPECT_EQ(back.lighting, b.lighting);
  test::EngineView v(back);
  ASSERT_NE(v.world(), nullptr) << v.error();
  const BspWorld& w = *v.world();
  size_t expect_offset = 0;
  uint32_t lit_faces = 0;
  for (uint32_t i = 0; i < w.num_faces; ++i) {
    const Face& f = w.faces[i];
    bool special = (w.texinfo[f.texinfo].flags & kTexSpecial) != 0;
    if (special) {
      EXPECT_EQ(f.light_offset, kNoLightmap) << "face " << i;
      continue;
    }
    ASSERT_NE(f.light_offset, kNoLightmap) << "face " << i;
    EXPECT_EQ(f.styles[0], 0) << "face " << i;
    int n = 0;
    while (n < 4 && f.styles[n] != 255) ++n;
    size_t grid = size_t(f.extents[0] / 16 + 1) * size_t(f.extents[1] / 16 + 1);
    EXPECT_EQ(size_t(f.light_offset), expect_offset) << "face " << i << ": lightmaps are not contiguous";
    expect_offset = size_t(f.light_offset) + n * grid;
    ++lit_faces;
  }
  EXPECT_EQ(expect_offset, w.lightdata_size);
  EXPECT_EQ(lit_faces, stats.faces_lit);

  // Beside ericw-tools' lighting (-extra4 -bounce -dirt, plus surface lights we skip).
  BspData original;
  ASSERT_TRUE(read_bsp((sb::test::quake_dir() + "/lq1/maps/start.bsp").c_str(), &original).is_ok());
  double ours = mean_style0_sample(back), theirs = mean_style0_sample(original);
  std::printf("[ light ] start.bsp: mean style-0 sample: sblight %.1f, ericw-tools %.1f (%u faces, %llu samples, "
              "%.3f s)\n",
              ours, theirs, stats.faces_lit, (unsigned long long)stats.samples, stats.seconds);
  EXPECT_GT(ours, 0);
}

TEST(LightStart, SameBytesForOneAndTwoThreads) {
  SB_REQUIRE_QUAKE_DATA();
  std::string path = copy_start("threads");
  ASSERT_FALSE(path.empty());
  for (int extra : {1, 2, 0}) {  // 0: -bounce -dirt (the LibreQuake flags) without -extra
    LightOptions one, two;
    one.threads = 1;
    two.threads = 2;
    one.extra = two.extra = extra ? extra : 1;
    one.quiet = two.quiet = true;
    if (extra == 0) {
      one.bounce = two.bounce = 1;
      one.dirt = two.dirt = 1;
    }
    LightStats st;
    BspData a = relit(path, one), b = relit(path, two, &st);
    if (extra == 0) {
      EXPECT_EQ(st.bounces, 1);
      EXPECT_GT(st.dirt_rays, 0u);
    }
    EXPECT_EQ(a.lighting, b.lighting) << "extra " << extra;
    ASSERT_EQ(a.faces.size(), b.faces.size());
    for (size_t i = 0; i < a.faces.size(); ++i) {
      EXPECT_EQ(a.faces[i].lightofs, b.faces[i].lightofs);
      EXPECT_EQ(0, std::memcmp(a.faces[i].styles, b.faces[i].styles, 4));
    }
  }
}

// One light of the map alone (worldspawn without sun or minimum light): faces near it are
// brighter than faces far away, and a face the light cannot see is darker than one at a
// similar distance that it can.
TEST(LightStart, NearBrighterThanFarAndOccludedDarker) {
  SB_REQUIRE_QUAKE_DATA();
  std::string path = copy_start("single");
  ASSERT_FALSE(path.empty());
  BspData b;
  ASSERT_TRUE(read_bsp(path.c_str(), &b).is_ok());
  LightSettings all;
  ASSERT_TRUE(parse_light_entities("start.bsp", b.entities, 0, &all, nullptr).is_ok());
  ASSERT_FALSE(all.lights.empty());
  test::EngineView geometry(b);
  ASSERT_NE(geometry.world(), nullptr) << geometry.error();
  LineTracer tracer(*geometry.world());
  const PointLight* chosen = nullptr;
  for (const PointLight& l : all.lights)
    if (l.style == 0 && l.falloff == Falloff::Linear && tracer.contents(l.origin) != kContentsSolid) {
      chosen = &l;
      break;
    }
  ASSERT_NE(chosen, nullptr);
  glm::vec3 o = chosen->origin;
  char ent[256];
  std::snprintf(ent, sizeof ent,
                "{\n\"classname\" \"worldspawn\"\n}\n{\n\"classname\" \"light\"\n\"origin\" \"%g %g %g\"\n"
                "\"light\" \"%g\"\n}\n",
                o.x, o.y, o.z, chosen->intensity);
  b.entities = ent;
  LightOptions opts;
  opts.threads = 2;
  ASSERT_TRUE(light_bsp(path.c_str(), &b, opts, nullptr, nullptr).is_ok());
  test::EngineView v(b);
  ASSERT_NE(v.world(), nullptr) << v.error();
  const BspWorld& w = *v.world();
  float range = chosen->intensity / chosen->wait;

  // Probe points: the centroid and the vertices pulled 2 units towards it, 1 unit off the face.
  auto visibility = [&](uint32_t f, int* clear, int* total) {
    FaceShape s = shape(w, f);
    *clear = *total = 0;
    std::vector<glm::vec3> probes = {s.centroid};
    for (const glm::vec3& vtx : s.verts) {
      glm::vec3 to = s.centroid - vtx;
      float len = glm::length(to);
      probes.push_back(vtx + (len > 2 ? to / len * 2.0f : to));
    }
    for (glm::vec3 p : probes) {
      p += s.normal;
      ++*total;
      *clear += tracer.clear(p, o);
    }
  };
  int near_face = -1, far_face = -1, hidden = -1, seen = -1;
  float near_d = 1e9f, far_d = 0, hidden_d = 1e9f, seen_d = 1e9f;
  for (uint32_t f = 0; f < w.num_faces; ++f) {
    if (w.faces[f].light_offset == kNoLightmap || (w.texinfo[w.faces[f].texinfo].flags & kTexSpecial)) continue;
    FaceShape s = shape(w, f);
    float facing = glm::dot(o - s.centroid, s.normal);
    float d = glm::length(o - s.centroid);
    if (facing <= 8) continue;
    int clear, total;
    visibility(f, &clear, &total);
    if (clear == total && d < near_d) near_d = d, near_face = int(f);
    if (d > range * 1.5f && d > far_d) far_d = d, far_face = int(f);
    if (d < range * 0.5f && clear == 0 && d < hidden_d) hidden_d = d, hidden = int(f);
    if (d < range * 0.5f && clear == total && std::fabs(d - range * 0.25f) < std::fabs(seen_d - range * 0.25f))
      seen_d = d, seen = int(f);
  }
  ASSERT_GE(near_face, 0);
  ASSERT_GE(far_face, 0);
  double near_mean = face_mean(w, near_face), far_mean = face_mean(w, far_face);
  std::printf("[ light ] light at (%g %g %g), %g: near face %d (%.0f units) mean %.1f, far face %d (%.0f units) "
              "mean %.1f\n",
              o.x, o.y, o.z, chosen->intensity, near_face, near_d, near_mean, far_face, far_d, far_mean);
  EXPECT_GT(near_mean, far_mean + 10);
  EXPECT_EQ(far_mean, 0);
  ASSERT_GE(hidden, 0) << "no fully occluded face within half the light's range";
  ASSERT_GE(seen, 0);
  double hidden_mean = face_mean(w, hidden), seen_mean = face_mean(w, seen);
  std::printf("[ light ] occluded face %d (%.0f units) mean %.1f, visible face %d (%.0f units) mean %.1f\n", hidden,
              hidden_d, hidden_mean, seen, seen_d, seen_mean);
  EXPECT_LT(hidden_mean, seen_mean);
}

}  // namespace
}  // namespace sb::tools
