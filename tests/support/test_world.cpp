// tests/support/test_world.cpp: see test_world.h.
#include "tests/support/test_world.h"

#include <cmath>
#include <cstdlib>
#include <cstring>

#include "engine/world/viewpoints.h"
#include "tests/support/png_image.h"
#include "tests/support/quake_data.h"

namespace sb::test {

TestWorld::TestWorld(const std::string& map, size_t block_mib) {
  size_t size = block_mib * mem::kMiB;
  block_.reset(new uint8_t[size]);
  char err[256] = {};
  if (!memory_.init(block_.get(), size, err, sizeof err)) {
    error_ = err;
    return;
  }
  std::string path = quake_dir() + "/lq1/maps/" + map + ".bsp";
  file_ = read_file_bytes(path);
  if (file_.empty()) {
    error_ = path + ": cannot read";
    return;
  }
  std::string name = "maps/" + map + ".bsp";
  Result<BspWorld*> r = load_bsp(name.c_str(), file_.data(), file_.size(), memory_.level, memory_.scratch);
  if (!r) {
    error_ = r.message();
    return;
  }
  world_ = r.value();
  render_new_level(*world_);
}

Status TestWorld::render(const ViewParams& view, int width, int height, double time, const int* lightstyles,
                         const uint8_t* colormap, std::vector<uint8_t>* pixels, std::vector<uint8_t>* coverage,
                         RenderStats* stats) {
  pixels->assign(size_t(width) * height, 0);
  if (coverage) coverage->assign(size_t(width) * height, 0);
  memory_.begin_frame();
  RenderInputs in;
  in.world = world_;
  in.view = view;
  in.time = time;
  in.lightstyles = lightstyles;
  in.colormap = colormap;
  Framebuffer fb;
  fb.pixels = pixels->data();
  fb.width = width;
  fb.height = height;
  fb.stride = width;
  fb.coverage = coverage ? coverage->data() : nullptr;
  return render_world(in, fb, memory_, stats);
}

std::vector<uint8_t> load_colormap() {
  std::vector<uint8_t> c = read_file_bytes(quake_dir() + "/lq1/gfx/colormap.lmp");
  if (c.size() < 64 * 256) return {};
  c.resize(64 * 256);
  return c;
}

std::vector<uint8_t> load_game_palette() { return load_palette(quake_dir() + "/lq1/gfx/palette.lmp"); }

int32_t point_contents(const BspWorld& w, const glm::vec3& p) {
  int32_t n = w.models[0].headnode[0];
  while (n >= 0) {
    const Node& node = w.nodes[n];
    const Plane& pl = w.planes[node.plane];
    float d = pl.normal.x * p.x + pl.normal.y * p.y + pl.normal.z * p.z - pl.dist;
    n = node.children[d >= 0 ? 0 : 1];
  }
  return w.leaves[-(n + 1)].contents;
}

namespace {

struct EntityPoint {
  glm::vec3 eye;
  float yaw;
  int priority;  // 0 players, 1 monsters/items/weapons, 2 lights and the rest
};

// Walks "{ "key" "value" ... }" blocks; calls f(keys) per entity.
template <class F>
void for_each_entity(const char* text, F f) {
  std::vector<std::pair<std::string, std::string>> kv;
  const char* p = text;
  auto token = [&p](std::string* out) -> bool {
    while (*p && (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')) ++p;
    if (!*p) return false;
    if (*p == '"') {
      const char* e = std::strchr(p + 1, '"');
      if (!e) return false;
      out->assign(p + 1, e);
      p = e + 1;
    } else {
      out->assign(p, 1);
      ++p;
    }
    return true;
  };
  std::string a, b;
  while (token(&a)) {
    if (a == "{") {
      kv.clear();
    } else if (a == "}") {
      f(kv);
    } else {
      if (!token(&b)) return;
      kv.emplace_back(a, b);
    }
  }
}

}  // namespace

std::vector<ViewParams> entity_viewpoints(const BspWorld& world, int count) {
  std::vector<EntityPoint> pts;
  if (world.entities) {
    for_each_entity(world.entities, [&](const std::vector<std::pair<std::string, std::string>>& kv) {
      std::string cls, origin, angle, model;
      for (const auto& [k, v] : kv) {
        if (k == "classname") cls = v;
        else if (k == "origin") origin = v;
        else if (k == "angle") angle = v;
        else if (k == "model") model = v;
      }
      if (origin.empty() || !model.empty()) return;
      float x, y, z;
      if (std::sscanf(origin.c_str(), "%f %f %f", &x, &y, &z) != 3) return;
      EntityPoint e;
      e.yaw = angle.empty() ? 0.0f : float(std::atof(angle.c_str()));
      bool player = cls.rfind("info_player", 0) == 0 || cls == "info_intermission";
      bool thing = cls.rfind("monster_", 0) == 0 || cls.rfind("item_", 0) == 0 || cls.rfind("weapon_", 0) == 0;
      e.priority = player ? 0 : thing ? 1 : 2;
      e.eye = glm::vec3(x, y, z + (e.priority == 2 ? 0.0f : 22.0f));
      // In open space: 8 units of clearance along every axis (not on a floor or in a wall).
      const glm::vec3 probes[7] = {{0, 0, 0}, {8, 0, 0}, {-8, 0, 0}, {0, 8, 0}, {0, -8, 0}, {0, 0, 8}, {0, 0, -8}};
      for (const glm::vec3& d : probes)
        if (point_contents(world, e.eye + d) != kContentsEmpty) return;
      pts.push_back(e);
    });
  }
  // Players first, then things, then the rest; spread the picks evenly within that order.
  std::vector<EntityPoint> ordered;
  for (int pr = 0; pr <= 2; ++pr)
    for (const EntityPoint& e : pts)
      if (e.priority == pr) ordered.push_back(e);
  std::vector<ViewParams> out;
  if (ordered.empty()) return out;
  const float pitches[6] = {0.0f, 20.0f, -15.0f, 30.0f, -25.0f, 10.0f};
  for (int i = 0; i < count; ++i) {
    size_t pick = ordered.size() >= size_t(count) ? size_t(i) * ordered.size() / size_t(count) : size_t(i) % ordered.size();
    const EntityPoint& e = ordered[pick];
    ViewParams v;
    v.origin = e.eye;
    v.yaw = std::fmod(e.yaw + 137.50776f * float(i), 360.0f);
    v.pitch = pitches[i % 6];
    v.fov_x = 90.0f;
    out.push_back(v);
  }
  return out;
}

std::vector<ViewParams> test_viewpoints(const BspWorld& world, int count) {
  std::vector<ViewParams> all(1024);
  all.resize(size_t(collect_viewpoints(world, all.data(), int(all.size()))));
  std::vector<ViewParams> open;
  const glm::vec3 probes[7] = {{0, 0, 0}, {8, 0, 0}, {-8, 0, 0}, {0, 8, 0}, {0, -8, 0}, {0, 0, 8}, {0, 0, -8}};
  for (const ViewParams& v : all) {
    bool ok = true;
    for (const glm::vec3& d : probes) ok = ok && point_contents(world, v.origin + d) != kContentsSolid;
    if (ok) open.push_back(v);
  }
  if (open.size() < size_t(count)) return entity_viewpoints(world, count);
  const float pitches[6] = {0.0f, 20.0f, -15.0f, 30.0f, -25.0f, 10.0f};
  std::vector<ViewParams> out;
  for (int i = 0; i < count; ++i) {
    ViewParams v = open[size_t(i) * open.size() / size_t(count)];
    if (v.pitch == 0.0f) v.pitch = pitches[i % 6];
    v.fov_x = 90.0f;
    out.push_back(v);
  }
  return out;
}

}  // namespace sb::test
