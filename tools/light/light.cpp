// tools/light/light.cpp: see light.h. Loads the checked engine view of the BSP, lights the
// faces on worker threads, and writes the lighting lump and face styles back.
#include "tools/light/light.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <thread>

#include "engine/core/log.h"
#include "engine/formats/bsp.h"
#include "memory/arena.h"
#include "tools/common/progress.h"
#include "tools/light/light_bounce.h"
#include "tools/light/light_dirt.h"
#include "tools/light/light_entities.h"
#include "tools/light/light_face.h"
#include "tools/light/light_trace.h"

namespace sb::tools {
namespace {

// The engine's view of a BspData (sb::load_bsp: every index checked, texture_mins and
// extents computed exactly as the engine does). Owns its heap block (tool code).
class EngineWorld {
 public:
  Status load(const char* name, const BspData& bsp) {
    std::vector<uint8_t> bytes;
    BspFormat used;
    Status st = serialize_bsp(bsp, bsp.format, &bytes, &used);
    if (!st) return make_error("%s: cannot re-serialise for checking: %s", name, st.message());
    size_t level = bytes.size() * 6 + (32u << 20), scratch = bytes.size() * 2 + (16u << 20);
    block_.reset(new uint8_t[level + scratch]);
    level_.init("light level", block_.get(), level);
    scratch_.init("light scratch", block_.get() + level, scratch);
    Result<BspWorld*> r = load_bsp(name, bytes.data(), bytes.size(), level_, scratch_);
    if (!r) return r.error();
    world_ = r.value();
    return Status::ok();
  }
  const BspWorld* world() const { return world_; }

 private:
  std::unique_ptr<uint8_t[]> block_;
  mem::Arena level_, scratch_;
  BspWorld* world_ = nullptr;
};

// Command-line values override worldspawn; then every light's and sun's dirt switch and
// dirt scale / gain are resolved (see light_entities.h for the defaults).
void resolve_light_options(const LightOptions& o, LightSettings* s) {
  if (o.bounce >= 0) s->bounce = std::min(o.bounce, 8);
  if (o.bouncescale >= 0) s->bouncescale = o.bouncescale;
  if (o.bouncecolorscale >= 0) s->bouncecolorscale = std::min(o.bouncecolorscale, 1.0f);
  if (o.bouncestyled >= 0) s->bouncestyled = o.bouncestyled > 0;
  if (o.dirt >= 0) s->dirt = o.dirt > 0 ? 1 : -1;
  if (o.dirtdepth > 0) s->dirtdepth = o.dirtdepth;
  if (o.dirtscale >= 0) s->dirtscale = o.dirtscale;
  if (o.dirtgain > 0) s->dirtgain = o.dirtgain;
  if (o.dirtangle >= 0) s->dirtangle = std::clamp(o.dirtangle, 1.0f, 90.0f);
  if (o.dirtmode >= 0) s->dirtmode = o.dirtmode > 0 ? 1 : 0;
  auto pick = [](int own, int fallback) { return own != 0 ? own : fallback; };
  for (PointLight& l : s->lights) {
    l.dirt = pick(l.dirt, s->dirt);
    if (l.dirtscale < 0) l.dirtscale = s->dirtscale;
    if (l.dirtgain <= 0) l.dirtgain = s->dirtgain;
  }
  for (Sun& sun : s->suns) sun.dirt = pick(sun.dirt, pick(sun.dome ? s->sunlight2_dirt : s->sunlight_dirt, s->dirt));
  s->minlight_dirt = pick(s->minlight_dirt, s->dirt);
}

}  // namespace

Status light_bsp(const char* name, BspData* bsp, const LightOptions& opts_in, LightStats* stats,
                 std::vector<uint8_t>* rgb, const std::vector<FaceAttr>* attrs) {
  LightStats st;
  LightOptions opts = opts_in;
  if (opts.extra != 1 && opts.extra != 2 && opts.extra != 4) opts.extra = 1;
  if (rgb) rgb->clear();
  if (!rgb) opts.want_rgb = false;

  // Geometry: the BSP without its old lighting (so stale lightmaps cannot fail the check).
  BspData geometry_only = *bsp;
  geometry_only.lighting.clear();
  for (DFace& f : geometry_only.faces) {
    f.lightofs = -1;
    std::memset(f.styles, 255, sizeof f.styles);
  }
  EngineWorld ew;
  SB_TRY(ew.load(name, geometry_only));
  const BspWorld& w = *ew.world();
  if (w.num_faces != bsp->faces.size())
    return make_error("%s: loaded %u faces but the file has %zu", name, w.num_faces, bsp->faces.size());
  if (w.num_models == 0) return make_error("%s: no models: nothing to light", name);

  LightSettings settings;
  std::string new_entities;
  SB_TRY(parse_light_entities(name, bsp->entities, opts.dome_samples, &settings, &new_entities));
  size_t entity_lights = settings.lights.size();
  int surface_lights = expand_surface_lights(w, &settings);
  if (!settings.surface_templates.empty() && !opts.quiet)
    log_info("%s: %zu surface light template(s) placed %d lights", name, settings.surface_templates.size(),
             surface_lights);
  LineTracer tracer(w);
  for (size_t i = 0; i < entity_lights; ++i) {
    const PointLight& l = settings.lights[i];
    int c = tracer.contents(l.origin);
    if (c == kContentsSolid || c == kContentsSky)
      log_warning("%s: light entity %d at (%g %g %g) is inside %s: it lights nothing", name, l.entity, l.origin.x,
                  l.origin.y, l.origin.z, c == kContentsSolid ? "solid" : "sky");
  }

  resolve_light_options(opts, &settings);
  auto t0 = std::chrono::steady_clock::now();
  LightScene scene;
  scene.world = &w;
  scene.tracer = &tracer;
  scene.opts = opts;
  if (attrs && !attrs->empty()) {
    if (attrs->size() != w.num_faces)
      return make_error("%s: %zu face attributes for %u faces", name, attrs->size(), w.num_faces);
    scene.attrs = *attrs;
    scene.occluders.build(w, tracer, scene.attrs);
    scene.phong.build(w, scene.attrs);
    st.occluder_polygons = uint32_t(scene.occluders.polygons());
    st.phong_faces = uint32_t(scene.phong.faces());
  }
  prepare_scene(&scene, &settings);
  bool any_dirt = settings.minlight_dirt > 0 && settings.minlight > 0;
  for (const PointLight& l : settings.lights) any_dirt |= l.dirt > 0;
  for (const Sun& s : settings.suns) any_dirt |= s.dirt > 0;
  if (any_dirt) scene.dirt_dirs = dirt_directions(settings.dirtangle);
  scene.minlight_dirt = settings.minlight_dirt > 0;
  scene.bounces = settings.bounce;
  if (scene.bounces > 0) {
    st.palette_missing = !prepare_bounce(&scene, opts.palette, settings.bouncecolorscale);
    if (st.palette_missing)
      log_warning("%s: bounce: texture colours wanted (bouncecolorscale %g) but no palette: grey 0.5 used", name,
                  double(settings.bouncecolorscale));
  }

  unsigned threads = opts.threads > 0 ? unsigned(opts.threads) : std::thread::hardware_concurrency();
  if (threads == 0) threads = 1;
  if (threads > 256) threads = 256;
  const Progress::Mode mode = opts.quiet ? Progress::Mode::Quiet : Progress::Mode::Auto;
  // Runs fn(face) for every face on the worker threads, with a progress report.
  auto for_each_face = [&](const char* stage, const auto& fn) -> double {
    Progress progress(stage ? stage : "light", int64_t(w.num_faces), stage ? mode : Progress::Mode::Quiet);
    std::atomic<uint32_t> next{0};
    auto worker = [&]() {
      for (;;) {
        uint32_t f = next.fetch_add(1, std::memory_order_relaxed);
        if (f >= w.num_faces) return;
        fn(f);
        progress.advance();
      }
    };
    if (threads == 1) {
      worker();
    } else {
      std::vector<std::thread> pool;
      for (unsigned i = 0; i < threads; ++i) pool.emplace_back(worker);
      for (std::thread& t : pool) t.join();
    }
    return progress.finish();
  };

  std::vector<FaceWork> work(w.num_faces);
  if (any_dirt) {
    st.dirt = true;
    st.dirt_seconds = for_each_face("light dirt", [&](uint32_t f) {
      face_setup(scene, f, &work[f]);
      dirt_face(scene, f, &work[f]);
    });
  }
  st.direct_seconds = for_each_face("light direct", [&](uint32_t f) {
    if (!any_dirt) face_setup(scene, f, &work[f]);
    light_face_direct(scene, f, &work[f]);
  });
  for (int pass = 1; pass <= scene.bounces; ++pass) {
    char stage[32];
    std::snprintf(stage, sizeof stage, "light bounce %d", pass);
    st.bounce_seconds += for_each_face(stage, [&](uint32_t f) { bounce_gather(scene, f, work, &work[f]); });
    for (uint32_t f = 0; f < w.num_faces; ++f) bounce_commit(scene, f, &work[f], pass < scene.bounces);
    ++st.bounces;
  }
  std::vector<FaceLightmap> results(w.num_faces);
  for (uint32_t f = 0; f < w.num_faces; ++f) {
    st.dirt_rays += work[f].dirt_rays;
    st.bounce_rays += work[f].bounce_rays;
    st.bounce_misses += work[f].bounce_misses;
  }
  for_each_face(nullptr, [&](uint32_t f) {  // quick: no progress report
    finish_face(scene, work[f], &results[f]);
    FaceWork().light.swap(work[f].light);  // free as we go
  });
  std::vector<FaceWork>().swap(work);

  // Assemble the lump in face order.
  std::vector<uint8_t> lighting;
  uint64_t style0_sum = 0, style0_count = 0;
  int drop_messages = 0;
  for (uint32_t i = 0; i < w.num_faces; ++i) {
    FaceLightmap& r = results[i];
    DFace& df = bsp->faces[i];
    std::memset(df.styles, 255, sizeof df.styles);
    df.lightofs = -1;
    st.traces += r.traces;
    if (!r.lit || r.num_styles == 0) continue;
    if (lighting.size() + r.mono.size() > size_t(INT32_MAX))
      return make_error("%s: lighting lump would exceed 2 GiB at face %u", name, i);
    df.lightofs = int32_t(lighting.size());
    for (int k = 0; k < r.num_styles; ++k) df.styles[k] = r.styles[k];
    size_t grid = r.mono.size() / size_t(r.num_styles);
    for (size_t k = 0; k < grid; ++k) style0_sum += r.mono[k];
    style0_count += grid;
    lighting.insert(lighting.end(), r.mono.begin(), r.mono.end());
    if (opts.want_rgb) rgb->insert(rgb->end(), r.rgb.begin(), r.rgb.end());
    ++st.faces_lit;
    st.samples += r.mono.size();
    if (r.styles_dropped) {
      ++st.styles_dropped;
      if (drop_messages++ < 10)
        log_warning("%s: face %u is reached by more than 4 light styles: dropped the weakest (style %d first)",
                    name, i, r.first_dropped_style);
    }
    if (r.degenerate) log_warning("%s: face %u: texture axes lie along the plane normal: lit at its centre", name, i);
    FaceLightmap().mono.swap(r.mono);  // free as we go
  }
  if (drop_messages > 10) log_warning("%s: ... %d faces in all dropped light styles", name, drop_messages);
  bsp->lighting.swap(lighting);
  if (!new_entities.empty()) bsp->entities.swap(new_entities);

  st.faces = w.num_faces;
  st.lights = uint32_t(settings.lights.size());
  st.suns = uint32_t(settings.suns.size());
  st.threads = threads;
  st.mean_sample = style0_count ? double(style0_sum) / double(style0_count) : 0.0;
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (stats) *stats = st;
  return Status::ok();
}

Status write_lit(const char* path, const std::vector<uint8_t>& rgb) {
  std::FILE* f = std::fopen(path, "wb");
  if (!f) return make_error("%s: cannot open for writing", path);
  const uint8_t header[8] = {'Q', 'L', 'I', 'T', 1, 0, 0, 0};
  bool ok = std::fwrite(header, 1, sizeof header, f) == sizeof header;
  if (ok && !rgb.empty()) ok = std::fwrite(rgb.data(), 1, rgb.size(), f) == rgb.size();
  ok = (std::fclose(f) == 0) && ok;
  if (!ok) return make_error("%s: write failed", path);
  return Status::ok();
}

double mean_style0_sample(const BspData& bsp) {
  EngineWorld ew;
  if (!ew.load("mean_style0_sample", bsp)) return -1.0;
  const BspWorld& w = *ew.world();
  uint64_t sum = 0, count = 0;
  for (uint32_t i = 0; i < w.num_faces; ++i) {
    const Face& f = w.faces[i];
    if (f.light_offset == kNoLightmap || (w.texinfo[f.texinfo].flags & kTexSpecial)) continue;
    uint64_t grid = uint64_t(f.extents[0] / 16 + 1) * uint64_t(f.extents[1] / 16 + 1);
    if (uint64_t(f.light_offset) + grid > w.lightdata_size) continue;
    for (uint64_t k = 0; k < grid; ++k) sum += w.lightdata[f.light_offset + k];
    count += grid;
  }
  return count ? double(sum) / double(count) : 0.0;
}

}  // namespace sb::tools
