// tests/content/sample_map_test.cpp: content/maps/sample.map is well formed (its own
// small parser here, independent of the compiler), sealed (a voxel flood from outside
// reaches no point entity), has the entities the issue asks for, names only textures that
// starbow.wad holds, and - when the build compiled it - loads in the engine.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "engine/formats/bsp.h"
#include "memory/arena.h"
#include "tools/content/textures.h"

namespace {

struct Plane {
  double n[3], d;  // outward normal (unit), n . p = d on the plane
  std::string tex;
};
struct Brush {
  std::vector<Plane> planes;
  int line;
};
struct Entity {
  std::map<std::string, std::string> keys;
  std::vector<Brush> brushes;
  std::string get(const std::string& k) const {
    auto it = keys.find(k);
    return it == keys.end() ? "" : it->second;
  }
};

// Tokens: quoted strings, ( ) [ ] { }, bare words; // comments to end of line.
struct Lexer {
  std::string s;
  size_t i = 0;
  int line = 1;
  bool next(std::string* tok, bool* quoted) {
    for (;;) {
      while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) line += s[i++] == '\n';
      if (i + 1 < s.size() && s[i] == '/' && s[i + 1] == '/') {
        while (i < s.size() && s[i] != '\n') ++i;
        continue;
      }
      break;
    }
    if (i >= s.size()) return false;
    *quoted = s[i] == '"';
    if (*quoted) {
      size_t e = s.find('"', i + 1);
      *tok = s.substr(i + 1, e - i - 1);
      i = e + 1;
      return true;
    }
    if (std::string("()[]{}").find(s[i]) != std::string::npos) {
      *tok = s.substr(i++, 1);
      return true;
    }
    size_t b = i;
    while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i])) && std::string("()[]{}\"").find(s[i]) == std::string::npos) ++i;
    *tok = s.substr(b, i - b);
    return true;
  }
};

std::string read_text(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

const std::string kMapPath = std::string(STARBOW_SOURCE_DIR) + "/content/maps/sample.map";

// Parses the map; any syntax error fails the calling test with the line.
std::vector<Entity> parse_map(const std::string& text) {
  Lexer lx{text};
  std::vector<Entity> out;
  std::string tok;
  bool q = false;
  auto expect = [&](const char* want) {
    EXPECT_TRUE(lx.next(&tok, &q)) << "line " << lx.line << ": unexpected end, wanted " << want;
    EXPECT_EQ(tok, want) << "line " << lx.line;
  };
  auto number = [&]() {
    EXPECT_TRUE(lx.next(&tok, &q));
    char* end = nullptr;
    double v = std::strtod(tok.c_str(), &end);
    EXPECT_TRUE(end && *end == 0 && !tok.empty()) << "line " << lx.line << ": '" << tok << "' is not a number";
    return v;
  };
  while (lx.next(&tok, &q)) {
    EXPECT_EQ(tok, "{") << "line " << lx.line;
    if (tok != "{") return out;
    Entity e;
    for (;;) {
      bool ok = lx.next(&tok, &q);
      EXPECT_TRUE(ok) << "unbalanced braces: entity not closed";
      if (!ok) return out;
      if (tok == "}" && !q) break;
      if (q) {
        std::string key = tok;
        EXPECT_TRUE(lx.next(&tok, &q) && q) << "line " << lx.line << ": key '" << key << "' without a value";
        e.keys[key] = tok;
        continue;
      }
      EXPECT_EQ(tok, "{") << "line " << lx.line;
      Brush b;
      b.line = lx.line;
      for (;;) {
        EXPECT_TRUE(lx.next(&tok, &q));
        if (tok == "}") break;
        EXPECT_EQ(tok, "(") << "line " << lx.line;
        double p[3][3];
        for (int k = 0; k < 3; ++k) {
          if (k > 0) expect("(");
          for (int c = 0; c < 3; ++c) p[k][c] = number();
          expect(")");
        }
        Plane pl;
        EXPECT_TRUE(lx.next(&pl.tex, &q));
        expect("[");
        for (int c = 0; c < 4; ++c) number();
        expect("]");
        expect("[");
        for (int c = 0; c < 4; ++c) number();
        expect("]");
        for (int c = 0; c < 3; ++c) number();
        // normal = (p0 - p1) x (p2 - p1), pointing out of the brush.
        double a[3], bb[3];
        for (int c = 0; c < 3; ++c) {
          a[c] = p[0][c] - p[1][c];
          bb[c] = p[2][c] - p[1][c];
        }
        double n[3] = {a[1] * bb[2] - a[2] * bb[1], a[2] * bb[0] - a[0] * bb[2], a[0] * bb[1] - a[1] * bb[0]};
        double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        EXPECT_GT(len, 0.0) << "line " << lx.line << ": degenerate plane";
        for (int c = 0; c < 3; ++c) pl.n[c] = n[c] / len;
        pl.d = pl.n[0] * p[1][0] + pl.n[1] * p[1][1] + pl.n[2] * p[1][2];
        b.planes.push_back(pl);
      }
      e.brushes.push_back(b);
    }
    out.push_back(e);
  }
  return out;
}

const std::vector<Entity>& sample() {
  static const std::vector<Entity> e = parse_map(read_text(kMapPath));
  return e;
}

// Corners of the brush: intersections of plane triples inside every plane.
std::vector<std::array<double, 3>> brush_vertices(const Brush& b) {
  std::vector<std::array<double, 3>> v;
  size_t n = b.planes.size();
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j)
      for (size_t k = j + 1; k < n; ++k) {
        const double *a = b.planes[i].n, *c = b.planes[j].n, *d = b.planes[k].n;
        double det = a[0] * (c[1] * d[2] - c[2] * d[1]) - a[1] * (c[0] * d[2] - c[2] * d[0]) + a[2] * (c[0] * d[1] - c[1] * d[0]);
        if (std::fabs(det) < 1e-9) continue;
        double da = b.planes[i].d, dc = b.planes[j].d, dd = b.planes[k].d;
        // Cramer's rule.
        std::array<double, 3> p;
        p[0] = (da * (c[1] * d[2] - c[2] * d[1]) - a[1] * (dc * d[2] - c[2] * dd) + a[2] * (dc * d[1] - c[1] * dd)) / det;
        p[1] = (a[0] * (dc * d[2] - c[2] * dd) - da * (c[0] * d[2] - c[2] * d[0]) + a[2] * (c[0] * dd - dc * d[0])) / det;
        p[2] = (a[0] * (c[1] * dd - dc * d[1]) - a[1] * (c[0] * dd - dc * d[0]) + da * (c[0] * d[1] - c[1] * d[0])) / det;
        bool inside = true;
        for (const Plane& pl : b.planes)
          if (pl.n[0] * p[0] + pl.n[1] * p[1] + pl.n[2] * p[2] - pl.d > 1e-6) inside = false;
        if (inside) v.push_back(p);
      }
  return v;
}

bool point_in_brush(const Brush& b, double x, double y, double z) {
  for (const Plane& pl : b.planes)
    if (pl.n[0] * x + pl.n[1] * y + pl.n[2] * z - pl.d > -1e-9) return false;
  return true;
}

TEST(SampleMap, ParsesAsValve220WithTheRightWorldspawn) {
  ASSERT_FALSE(sample().empty());
  const Entity& world = sample()[0];
  EXPECT_EQ(world.get("classname"), "worldspawn");
  EXPECT_EQ(world.get("mapversion"), "220");
  EXPECT_EQ(world.get("wad"), "starbow.wad");
  size_t brushes = 0;
  for (const Entity& e : sample()) brushes += e.brushes.size();
  EXPECT_GE(brushes, 50u);
  EXPECT_LE(brushes, 150u);
  std::printf("sample.map: %zu entities, %zu brushes\n", sample().size(), brushes);
}

TEST(SampleMap, EveryBrushIsAClosedConvexVolume) {
  for (const Entity& e : sample())
    for (const Brush& b : e.brushes) {
      ASSERT_GE(b.planes.size(), 4u) << "brush at line " << b.line;
      std::vector<std::array<double, 3>> v = brush_vertices(b);
      ASSERT_GE(v.size(), 4u) << "brush at line " << b.line << " has no volume";
      double c[3] = {0, 0, 0};
      for (auto& p : v)
        for (int k = 0; k < 3; ++k) c[k] += p[size_t(k)] / double(v.size());
      EXPECT_TRUE(point_in_brush(b, c[0], c[1], c[2])) << "brush at line " << b.line << ": planes face inwards";
      for (auto& p : v)
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(p[size_t(k)], 8.0 * std::round(p[size_t(k)] / 8.0), 1e-6) << "off the 8-unit grid, line " << b.line;
    }
}

TEST(SampleMap, HasTheRequiredEntitiesAndLightStyles) {
  std::map<std::string, int> count;
  std::set<int> styles;
  for (const Entity& e : sample()) {
    std::string cls = e.get("classname");
    ++count[cls];
    if (cls.rfind("light", 0) == 0) styles.insert(std::atoi(e.get("style").c_str()));
  }
  EXPECT_EQ(count["info_player_start"], 1);
  EXPECT_GE(count["info_player_deathmatch"], 4);
  EXPECT_GE(count["func_door"], 1);
  EXPECT_GE(count["func_plat"], 1);
  for (int s : {0, 1, 5, 10}) EXPECT_TRUE(styles.count(s)) << "light style " << s;
  EXPECT_GE(styles.size(), 6u);
  std::set<std::string> textures;
  for (const Entity& e : sample())
    for (const Brush& b : e.brushes)
      for (const Plane& p : b.planes) textures.insert(p.tex);
  for (const char* t : {"sky1", "*water1", "*lava1", "*slime1", "door1", "clip", "trigger"})
    EXPECT_TRUE(textures.count(t)) << t;
  std::set<std::string> wad;
  for (const auto& s : sb::content::texture_specs()) wad.insert(s.name);
  for (const std::string& t : textures) EXPECT_TRUE(wad.count(t)) << "texture '" << t << "' is not in starbow.wad";
}

// A voxel flood (8-unit cells) from outside the map's bounds through every cell not
// inside a sealing world brush (liquids, clip, trigger do not seal; sky does): no point
// entity may be reached, i.e. the map does not leak.
TEST(SampleMap, IsSealed) {
  const Entity& world = sample()[0];
  std::vector<const Brush*> sealing;
  double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
  for (const Brush& b : world.brushes) {
    bool liquid_or_marker = false;
    for (const Plane& p : b.planes) liquid_or_marker |= p.tex[0] == '*' || p.tex == "clip" || p.tex == "trigger";
    if (liquid_or_marker) continue;
    sealing.push_back(&b);
    for (auto& v : brush_vertices(b))
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], v[size_t(k)]);
        hi[k] = std::max(hi[k], v[size_t(k)]);
      }
  }
  const double cell = 8;
  int n[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] -= 2 * cell;
    hi[k] += 2 * cell;
    n[k] = int((hi[k] - lo[k]) / cell);
  }
  auto idx = [&](int x, int y, int z) { return (size_t(z) * size_t(n[1]) + size_t(y)) * size_t(n[0]) + size_t(x); };
  std::vector<uint8_t> solid(size_t(n[0]) * n[1] * n[2], 0), reached(solid.size(), 0);
  for (const Brush* b : sealing) {
    auto v = brush_vertices(*b);
    double bl[3] = {1e9, 1e9, 1e9}, bh[3] = {-1e9, -1e9, -1e9};
    for (auto& p : v)
      for (int k = 0; k < 3; ++k) {
        bl[k] = std::min(bl[k], p[size_t(k)]);
        bh[k] = std::max(bh[k], p[size_t(k)]);
      }
    int a[3], z[3];
    for (int k = 0; k < 3; ++k) {
      a[k] = std::max(0, int((bl[k] - lo[k]) / cell) - 1);
      z[k] = std::min(n[k] - 1, int((bh[k] - lo[k]) / cell) + 1);
    }
    for (int cz = a[2]; cz <= z[2]; ++cz)
      for (int cy = a[1]; cy <= z[1]; ++cy)
        for (int cx = a[0]; cx <= z[0]; ++cx)
          if (point_in_brush(*b, lo[0] + (cx + 0.5) * cell, lo[1] + (cy + 0.5) * cell, lo[2] + (cz + 0.5) * cell))
            solid[idx(cx, cy, cz)] = 1;
  }
  std::vector<size_t> stack = {idx(0, 0, 0)};
  reached[stack[0]] = 1;
  while (!stack.empty()) {
    size_t i = stack.back();
    stack.pop_back();
    int x = int(i % size_t(n[0])), y = int((i / size_t(n[0])) % size_t(n[1])), zz = int(i / (size_t(n[0]) * n[1]));
    const int d[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (auto& s : d) {
      int X = x + s[0], Y = y + s[1], Z = zz + s[2];
      if (X < 0 || Y < 0 || Z < 0 || X >= n[0] || Y >= n[1] || Z >= n[2]) continue;
      size_t j = idx(X, Y, Z);
      if (solid[j] || reached[j]) continue;
      reached[j] = 1;
      stack.push_back(j);
    }
  }
  int points = 0;
  for (const Entity& e : sample()) {
    std::string o = e.get("origin");
    if (o.empty()) continue;
    double p[3];
    ASSERT_EQ(std::sscanf(o.c_str(), "%lf %lf %lf", &p[0], &p[1], &p[2]), 3);
    int c[3];
    for (int k = 0; k < 3; ++k) c[k] = int((p[k] - lo[k]) / cell);
    EXPECT_FALSE(solid[idx(c[0], c[1], c[2])]) << e.get("classname") << " at " << o << " is inside a wall";
    EXPECT_FALSE(reached[idx(c[0], c[1], c[2])]) << "leak: the outside reaches " << e.get("classname") << " at " << o;
    ++points;
  }
  EXPECT_GT(points, 20);
}

// The build's own compile of the sample map (content/CMakeLists.txt), when the map
// compiler is part of the build: it loads in the engine with its submodels and textures.
TEST(SampleMap, CompiledBspLoads) {
  std::string path = std::string(STARBOW_BINARY_DIR) + "/content/starbow/maps/sample.bsp";
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) GTEST_SKIP() << path << " not built (build the starbow_content target with sbbsp present)";
  std::vector<uint8_t> data;
  uint8_t buf[65536];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) data.insert(data.end(), buf, buf + n);
  std::fclose(f);
  std::string pts = path.substr(0, path.size() - 4) + ".pts";
  FILE* leak = std::fopen(pts.c_str(), "rb");
  EXPECT_EQ(leak, nullptr) << "the compiler wrote a leak file " << pts;
  if (leak) std::fclose(leak);
  std::vector<uint8_t> level_mem(64u << 20), scratch_mem(32u << 20);
  sb::mem::Arena level, scratch;
  level.init("level", level_mem.data(), level_mem.size());
  scratch.init("scratch", scratch_mem.data(), scratch_mem.size());
  sb::Result<sb::BspWorld*> w = sb::load_bsp("maps/sample.bsp", data.data(), data.size(), level, scratch);
  ASSERT_TRUE(w.is_ok()) << w.message();
  const sb::BspWorld& world = *w.value();
  EXPECT_EQ(world.num_models, 5u) << "world + door, plat, button, teleport trigger";
  EXPECT_EQ(world.missing_textures, 0u);
  EXPECT_GT(world.lightdata_size, 0u);
  std::set<std::string> names;
  for (uint32_t i = 0; i < world.num_textures; ++i) names.insert(world.textures[i].name);
  for (const char* t : {"sky1", "*water1", "door1", "+0light"}) EXPECT_TRUE(names.count(t)) << t;
  bool water = false, sky = false, lava = false;
  for (uint32_t i = 0; i < world.num_leaves; ++i) {
    water |= world.leaves[i].contents == sb::kContentsWater;
    lava |= world.leaves[i].contents == sb::kContentsLava;
    sky |= world.leaves[i].contents == sb::kContentsSky;
  }
  EXPECT_TRUE(water && sky && lava) << "water, sky and lava leaves";
  std::printf("sample.bsp: %u faces, %u leaves, %u textures, %u bytes of light\n", world.num_faces, world.num_leaves,
              world.num_textures, world.lightdata_size);
}

}  // namespace
