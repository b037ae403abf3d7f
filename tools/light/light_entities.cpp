// tools/light/light_entities.cpp: see light_entities.h.
#include "tools/light/light_entities.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <string_view>

#include <glm/geometric.hpp>

#include "engine/core/log.h"
#include "engine/formats/entities.h"

namespace sb::tools {
namespace {

constexpr float kPi = 3.14159265358979323846f;

struct EntityInfo {
  Entity e;
  std::string classname;
  bool has_origin = false;
  glm::vec3 origin{0};
};

std::string describe(int index, const EntityInfo& info) {
  char buf[160];
  if (info.has_origin)
    std::snprintf(buf, sizeof buf, "entity %d ('%s' at %g %g %g)", index, info.classname.c_str(), info.origin.x,
                  info.origin.y, info.origin.z);
  else
    std::snprintf(buf, sizeof buf, "entity %d ('%s')", index, info.classname.c_str());
  return buf;
}

bool find_float(const Entity& e, std::string_view key, float* out) {
  std::string_view v;
  return e.find(key, &v) && parse_float(v, out) && std::isfinite(*out);
}

// Colour "r g b", 0..255 or 0..1 (any component above 1 means the 0..255 form).
bool parse_color(std::string_view v, glm::vec3* out) {
  glm::vec3 c;
  if (!parse_vec3(v, &c) || !std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) return false;
  if (c.x > 1 || c.y > 1 || c.z > 1) c /= 255.0f;
  *out = glm::clamp(c, glm::vec3(0), glm::vec3(1));
  return true;
}

float clamp_anglescale(float a) { return a < 0 ? 0 : (a > 1 ? 1 : a); }

// "yaw pitch roll" (light convention, pitch up positive) as a direction, or false.
bool parse_mangle(std::string_view v, glm::vec3* dir) {
  glm::vec3 ypr;
  if (!parse_vec3(v, &ypr) || !std::isfinite(ypr.x) || !std::isfinite(ypr.y)) return false;
  *dir = direction_from_yaw_pitch(ypr.x, ypr.y);
  return true;
}

}  // namespace

glm::vec3 direction_from_yaw_pitch(float yaw_deg, float pitch_deg) {
  float yaw = yaw_deg * kPi / 180.0f, pitch = pitch_deg * kPi / 180.0f;
  return glm::vec3(std::cos(yaw) * std::cos(pitch), std::sin(yaw) * std::cos(pitch), std::sin(pitch));
}

Status parse_light_entities(const char* name, const std::string& entities, int dome_samples, LightSettings* out,
                            std::string* entities_out) {
  *out = LightSettings();
  if (entities_out) entities_out->clear();

  // Pass 1: every entity, with classname and origin.
  std::vector<EntityInfo> all;
  EntityIterator it(entities);
  Entity e;
  while (it.next(&e)) {
    EntityInfo info;
    info.e = e;
    info.classname = std::string(e.classname());
    info.has_origin = entity_origin(e, &info.origin) && std::isfinite(info.origin.x) &&
                      std::isfinite(info.origin.y) && std::isfinite(info.origin.z);
    all.push_back(info);
  }
  if (it.error()) return make_error("%s: entities: %s", name, it.error());
  std::map<std::string, size_t, std::less<>> by_targetname;
  for (size_t i = 0; i < all.size(); ++i) {
    std::string_view tn;
    if (all[i].e.find("targetname", &tn) && !by_targetname.count(tn)) by_targetname.emplace(std::string(tn), i);
  }

  // Worldspawn.
  float sunlight = 0, sunlight2 = 0;
  glm::vec3 sun_dir(0, 0, -1), sun_color(1), sun2_color(1);
  for (size_t i = 0; i < all.size(); ++i) {
    if (all[i].classname != "worldspawn") continue;
    const Entity& w = all[i].e;
    float f;
    std::string_view v;
    if (find_float(w, "light", &f)) out->minlight = f;
    if (find_float(w, "_minlight", &f)) out->minlight = f;
    if (find_float(w, "_anglescale", &f) || find_float(w, "_anglesense", &f)) out->anglescale = clamp_anglescale(f);
    if (find_float(w, "_range", &f) && f > 0) out->rangescale = f;
    if (find_float(w, "_dist", &f) && f > 0) out->dist_scale = f;
    if (find_float(w, "_sunlight", &f)) sunlight = f;
    if (find_float(w, "_sunlight2", &f)) sunlight2 = f;
    // "_sunlight_mangle" and "_sun_mangle" are the same key (both documented);
    // "_sunlight2_color" and "_sunlight_color2" likewise.
    if ((w.find("_sunlight_mangle", &v) || w.find("_sun_mangle", &v)) && !parse_mangle(v, &sun_dir))
      log_warning("%s: %s: bad sun mangle '%.*s' (using straight down)", name, describe(int(i), all[i]).c_str(),
                  int(v.size()), v.data());
    if (w.find("_sunlight_color", &v) && !parse_color(v, &sun_color))
      log_warning("%s: %s: bad \"_sunlight_color\"", name, describe(int(i), all[i]).c_str());
    if ((w.find("_sunlight2_color", &v) || w.find("_sunlight_color2", &v)) && !parse_color(v, &sun2_color))
      log_warning("%s: %s: bad \"_sunlight2_color\"", name, describe(int(i), all[i]).c_str());
    // Bounce and dirt (out-of-range values are clamped; see light_entities.h).
    if (find_float(w, "_bounce", &f)) out->bounce = std::clamp(int(f), 0, 8);
    if (find_float(w, "_bouncescale", &f)) out->bouncescale = std::max(f, 0.0f);
    if (find_float(w, "_bouncecolorscale", &f)) out->bouncecolorscale = std::clamp(f, 0.0f, 1.0f);
    if (find_float(w, "_bouncestyled", &f)) out->bouncestyled = f > 0;
    if (find_float(w, "_dirt", &f)) out->dirt = f > 0 ? 1 : -1;
    if (find_float(w, "_dirtdepth", &f) && f > 0) out->dirtdepth = f;
    if (find_float(w, "_dirtscale", &f)) out->dirtscale = std::max(f, 0.0f);
    if (find_float(w, "_dirtgain", &f) && f > 0) out->dirtgain = f;
    if (find_float(w, "_dirtangle", &f)) out->dirtangle = std::clamp(f, 1.0f, 90.0f);
    if (find_float(w, "_dirtmode", &f)) out->dirtmode = f > 0 ? 1 : 0;
    if (find_float(w, "_sunlight_dirt", &f) && f != 0) out->sunlight_dirt = f > 0 ? 1 : -1;
    if (find_float(w, "_sunlight2_dirt", &f) && f != 0) out->sunlight2_dirt = f > 0 ? 1 : -1;
    if (find_float(w, "_minlight_dirt", &f) && f != 0) out->minlight_dirt = f > 0 ? 1 : -1;
    break;
  }
  out->minlight = std::clamp(out->minlight, 0.0f, 255.0f);
  if (sunlight != 0) {
    Sun s;
    s.dir = glm::normalize(sun_dir);
    s.intensity = sunlight;
    s.color = sun_color;
    s.anglescale = out->anglescale;
    out->suns.push_back(s);
  }
  if (sunlight2 != 0 && dome_samples > 0) {
    // Rings of equal elevation step (k rings from the horizon up, ring r at elevation
    // (r + 0.5) * 90 / (k + 1) degrees, 4k directions each) and one sun at the zenith, each
    // direction an equal share of the intensity: denser towards the zenith than an
    // equal-area spread, so an open floor gets more of the dome than a wall. k is chosen so
    // that 4k^2 + 1 is about `dome_samples`.
    int k = std::max(1, int(std::lround(std::sqrt(double(std::max(dome_samples - 1, 1)) / 4.0))));
    int count = 4 * k * k + 1;
    float step = 0.5f * kPi / float(k + 1);
    for (int d = 0; d < count; ++d) {
      glm::vec3 up(0, 0, 1);  // the zenith sun (last)
      if (d < count - 1) {
        int ring = d / (4 * k), j = d % (4 * k);
        float elev = (float(ring) + 0.5f) * step, az = float(j) * 2.0f * kPi / float(4 * k);
        up = glm::vec3(std::cos(az) * std::cos(elev), std::sin(az) * std::cos(elev), std::sin(elev));
      }
      Sun s;
      s.dir = -up;
      s.intensity = sunlight2 / float(count);
      s.color = sun2_color;
      s.anglescale = out->anglescale;
      s.dome = true;
      out->suns.push_back(s);
    }
  }

  // Lights.
  std::map<std::string, int, std::less<>> switch_styles;  // targetname -> assigned style
  std::vector<std::pair<size_t, int>> style_inserts;      // entity -> style to write
  for (size_t i = 0; i < all.size(); ++i) {
    const EntityInfo& info = all[i];
    if (info.classname.compare(0, 5, "light") != 0) continue;
    const Entity& le = info.e;
    std::string who = describe(int(i), info);
    std::string_view v;
    std::string surface;
    if (le.find("_surface", &v)) {
      surface.assign(v);
      for (char& c : surface) c = char(std::tolower(static_cast<unsigned char>(c)));
      if (surface.empty()) {
        log_warning("%s: %s: empty \"_surface\": skipped", name, who.c_str());
        continue;
      }
    }
    if (!info.has_origin && surface.empty()) {
      log_warning("%s: %s has no valid \"origin\": skipped", name, who.c_str());
      continue;
    }
    PointLight l;
    l.entity = int(i);
    l.origin = info.origin;
    l.anglescale = out->anglescale;
    float f;
    if (le.find("light", &v) || le.find("_light", &v)) {
      if (!parse_float(v, &f) || !std::isfinite(f))
        log_warning("%s: %s: bad \"light\" '%.*s' (using 300)", name, who.c_str(), int(v.size()), v.data());
      else if (f != 0)
        l.intensity = f;
    }
    if (find_float(le, "wait", &f)) {
      if (f > 0) l.wait = f;
      else if (f < 0) log_warning("%s: %s: negative \"wait\" %g (using 1)", name, who.c_str(), f);
    }
    l.wait *= out->dist_scale;
    if (find_float(le, "delay", &f)) {
      int d = int(f);
      if (d < 0 || d > 5 || float(d) != f)
        log_warning("%s: %s: unknown \"delay\" %g (using 0, linear)", name, who.c_str(), f);
      else
        l.falloff = Falloff(d);
    }
    if (le.find("style", &v)) {
      if (!parse_float(v, &f) || f < 0 || f > 254 || float(int(f)) != f)
        log_warning("%s: %s: \"style\" '%.*s' outside 0..254 (using 0)", name, who.c_str(), int(v.size()), v.data());
      else
        l.style = int(f);
    } else if (le.find("targetname", &v) && !v.empty()) {
      auto found = switch_styles.find(v);
      int style;
      if (found != switch_styles.end()) {
        style = found->second;
      } else {
        style = 32 + int(switch_styles.size());
        if (style > 254) {
          log_warning("%s: %s: more than 223 switchable light groups (using style 0)", name, who.c_str());
          style = 0;
        } else {
          switch_styles.emplace(std::string(v), style);
        }
      }
      l.style = style;
      if (style) style_inserts.emplace_back(i, style);
    }
    if (le.find("_color", &v) && !parse_color(v, &l.color))
      log_warning("%s: %s: bad \"_color\" '%.*s' (using white)", name, who.c_str(), int(v.size()), v.data());
    if (find_float(le, "_anglescale", &f) || find_float(le, "_anglesense", &f)) l.anglescale = clamp_anglescale(f);
    if (find_float(le, "_bouncescale", &f)) l.bouncescale = std::max(f, 0.0f);
    if (find_float(le, "_dirt", &f) && f != 0) l.dirt = f > 0 ? 1 : -1;
    if (find_float(le, "_dirtscale", &f) && f >= 0) l.dirtscale = f;
    if (find_float(le, "_dirtgain", &f) && f > 0) l.dirtgain = f;

    // Direction: target, else mangle, else angle (yaw; -1 up, -2 down).
    bool has_dir = false;
    glm::vec3 dir(0, 0, -1);
    if (le.find("target", &v) && !v.empty()) {
      auto t = by_targetname.find(v);
      if (t == by_targetname.end() || !all[t->second].has_origin) {
        log_warning("%s: %s targets '%.*s', which does not exist or has no origin (not a spotlight)", name,
                    who.c_str(), int(v.size()), v.data());
      } else {
        glm::vec3 d = all[t->second].origin - l.origin;
        if (glm::dot(d, d) > 1e-6f) {
          dir = glm::normalize(d);
          has_dir = true;
        }
      }
    }
    if (!has_dir && le.find("mangle", &v)) {
      if (parse_mangle(v, &dir))
        has_dir = true;
      else
        log_warning("%s: %s: bad \"mangle\" '%.*s'", name, who.c_str(), int(v.size()), v.data());
    }
    bool is_sun = find_float(le, "_sun", &f) && f != 0;
    if (is_sun) {
      Sun s;
      s.dir = has_dir ? dir : glm::vec3(0, 0, -1);
      s.intensity = l.intensity;
      s.color = l.color;
      s.anglescale = l.anglescale;
      s.style = l.style;
      s.dirt = l.dirt;
      out->suns.push_back(s);
      continue;
    }
    if (has_dir) {
      float cone = 40, soft = 0;
      if (find_float(le, "angle", &f) && f > 0) cone = f;
      if (cone > 360) cone = 360;
      if (find_float(le, "_softangle", &f) && f > 0 && f < cone) soft = f;
      l.spot = true;
      l.spot_dir = dir;
      l.spot_cos_outer = std::cos(cone * 0.5f * kPi / 180.0f);
      l.spot_cos_inner = soft > 0 ? std::cos(soft * 0.5f * kPi / 180.0f) : l.spot_cos_outer;
    }
    if (!surface.empty())
      out->surface_templates.push_back({surface, l});
    else
      out->lights.push_back(l);
  }

  // Write assigned switchable styles back: "style" "N" right after the entity's '{'.
  if (entities_out && !style_inserts.empty()) {
    std::string& s = *entities_out;
    size_t copied = 0;
    for (const auto& [index, style] : style_inserts) {
      size_t at = all[index].e.offset + 1;
      s.append(entities, copied, at - copied);
      char buf[32];
      std::snprintf(buf, sizeof buf, "\n\"style\" \"%d\"", style);
      s += buf;
      copied = at;
    }
    s.append(entities, copied, std::string::npos);
  }
  return Status::ok();
}

}  // namespace sb::tools
