// tests/tools_bsp/bsp_test_util.cpp: see bsp_test_util.h.
#include "tests/tools_bsp/bsp_test_util.h"

#include <sys/stat.h>

#include <cstdio>
#include <cstring>
#include <algorithm>
#include <set>

#include "tests/support/png_image.h"
#include "tests/support/quake_data.h"
#include "tests/support/reference_renderer.h"
#include "tests/support/render_compare.h"
#include "tests/support/test_world.h"

namespace sb::test {

std::string bsp_scratch_dir() {
  std::string d = std::string(STARBOW_BINARY_DIR) + "/tools_bsp_scratch";
  ::mkdir(d.c_str(), 0755);
  return d;
}

bool write_text_file(const std::string& path, const std::string& text) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  std::fwrite(text.data(), 1, text.size(), f);
  return std::fclose(f) == 0;
}

namespace {

std::string pt(double x, double y, double z) {
  char b[96];
  std::snprintf(b, sizeof b, "( %g %g %g )", x, y, z);
  return b;
}

}  // namespace

std::string box_brush(double x0, double y0, double z0, double x1, double y1, double z1, const std::string& tex,
                      const std::string& tp) {
  std::string s = "{\n";
  auto face = [&](const std::string& a, const std::string& b, const std::string& c) {
    s += a + " " + b + " " + c + " " + tex + " " + tp + "\n";
  };
  face(pt(x1, y1, z0), pt(x1, y0, z0), pt(x1, y0, z1));  // +x
  face(pt(x0, y0, z1), pt(x0, y0, z0), pt(x0, y1, z0));  // -x
  face(pt(x0, y1, z1), pt(x0, y1, z0), pt(x1, y1, z0));  // +y
  face(pt(x1, y0, z0), pt(x0, y0, z0), pt(x0, y0, z1));  // -y
  face(pt(x1, y0, z1), pt(x0, y0, z1), pt(x0, y1, z1));  // +z
  face(pt(x0, y1, z0), pt(x0, y0, z0), pt(x1, y0, z0));  // -z
  return s + "}\n";
}

std::string room_brushes(double x0, double y0, double z0, double x1, double y1, double z1, const std::string& tex,
                         bool open_east) {
  const double t = 16;
  std::string s;
  s += box_brush(x0 - t, y0 - t, z0 - t, x1 + t, y1 + t, z0, tex);  // floor
  s += box_brush(x0 - t, y0 - t, z1, x1 + t, y1 + t, z1 + t, tex);  // ceiling
  s += box_brush(x0 - t, y0 - t, z0, x0, y1 + t, z1, tex);          // west
  if (!open_east) s += box_brush(x1, y0 - t, z0, x1 + t, y1 + t, z1, tex);
  s += box_brush(x0, y0 - t, z0, x1, y0, z1, tex);                  // south
  s += box_brush(x0, y1, z0, x1, y1 + t, z1, tex);                  // north
  return s;
}

std::string entity(const std::string& keys, const std::string& brushes) { return "{\n" + keys + "\n" + brushes + "}\n"; }

std::vector<uint8_t> make_wad(const std::vector<std::string>& names, uint32_t size) {
  std::vector<uint8_t> out(12, 0);
  std::memcpy(out.data(), "WAD2", 4);
  struct Entry { uint32_t pos, len; std::string name; };
  std::vector<Entry> dir;
  for (size_t n = 0; n < names.size(); ++n) {
    uint32_t pos = uint32_t(out.size());
    std::vector<uint8_t> mt(40, 0);
    std::strncpy(reinterpret_cast<char*>(mt.data()), names[n].c_str(), 15);
    uint32_t hdr[6] = {size, size, 40, 0, 0, 0};
    uint32_t off = 40;
    std::vector<uint8_t> pixels;
    for (int m = 0; m < 4; ++m) {
      hdr[2 + m] = off;
      uint32_t s = size >> m;
      for (uint32_t y = 0; y < s; ++y)
        for (uint32_t x = 0; x < s; ++x) pixels.push_back(uint8_t(16 + (n * 37 + x * 3 + y * 7) % 200));
      off += s * s;
    }
    std::memcpy(mt.data() + 16, hdr, sizeof hdr);
    mt.insert(mt.end(), pixels.begin(), pixels.end());
    out.insert(out.end(), mt.begin(), mt.end());
    dir.push_back({pos, uint32_t(mt.size()), names[n]});
  }
  uint32_t count = uint32_t(dir.size()), table = uint32_t(out.size());
  for (const Entry& e : dir) {
    uint8_t rec[32] = {};
    std::memcpy(rec, &e.pos, 4);
    std::memcpy(rec + 4, &e.len, 4);
    std::memcpy(rec + 8, &e.len, 4);
    rec[12] = 0x44;
    std::memcpy(rec + 16, e.name.c_str(), std::min<size_t>(e.name.size(), 16));
    out.insert(out.end(), rec, rec + 32);
  }
  std::memcpy(out.data() + 4, &count, 4);
  std::memcpy(out.data() + 8, &table, 4);
  return out;
}

CompileRun compile_file(const std::string& map_path, const std::string& bsp_path) {
  CompileRun r;
  r.map_path = map_path;
  r.bsp_path = bsp_path;
  tools::bsp::BspOptions opt;
  opt.map_path = map_path;
  opt.bsp_path = bsp_path;
  opt.quiet = true;
  opt.prt1_only = true;
  r.status = tools::bsp::compile_map(opt, &r.report);
  return r;
}

CompileRun compile_text(const std::string& name, const std::string& text, const std::vector<std::string>& wads) {
  return compile_text(name, text, wads, tools::bsp::BspOptions());
}

CompileRun compile_text(const std::string& name, const std::string& text, const std::vector<std::string>& wads,
                        const tools::bsp::BspOptions& base) {
  std::string dir = bsp_scratch_dir();
  std::string map = dir + "/" + name + ".map";
  write_text_file(map, text);
  CompileRun r;
  r.map_path = map;
  r.bsp_path = dir + "/" + name + ".bsp";
  std::remove(r.bsp_path.c_str());
  tools::bsp::BspOptions opt = base;
  opt.map_path = map;
  opt.bsp_path = r.bsp_path;
  opt.wads = wads;
  opt.quiet = true;
  r.status = tools::bsp::compile_map(opt, &r.report);
  return r;
}

LoadedBsp::LoadedBsp(const std::string& path, size_t block_mib) {
  size_t size = block_mib * mem::kMiB;
  block_.reset(new uint8_t[size]);
  char err[256] = {};
  if (!memory_.init(block_.get(), size, err, sizeof err)) {
    error_ = err;
    return;
  }
  file_ = read_file_bytes(path);
  if (file_.empty()) {
    error_ = path + ": cannot read";
    return;
  }
  Result<BspWorld*> r = load_bsp(path.c_str(), file_.data(), file_.size(), memory_.level, memory_.scratch);
  if (!r) {
    error_ = r.message();
    return;
  }
  world_ = r.value();
  render_new_level(*world_);
}

Status LoadedBsp::render(const ViewParams& view, int w, int h, const uint8_t* colormap, std::vector<uint8_t>* pixels,
                         std::vector<uint8_t>* coverage) {
  pixels->assign(size_t(w) * h, 0);
  coverage->assign(size_t(w) * h, 0);
  memory_.begin_frame();
  RenderInputs in;
  in.world = world_;
  in.view = view;
  in.time = 0.5;
  in.colormap = colormap;
  Framebuffer fb;
  fb.pixels = pixels->data();
  fb.width = w;
  fb.height = h;
  fb.stride = w;
  fb.coverage = coverage->data();
  return render_world(in, fb, memory_, nullptr);
}

std::vector<uint8_t> test_colormap() {
  std::vector<uint8_t> c;
  if (!quake_dir().empty()) c = load_colormap();
  if (c.size() >= 64 * 256) return c;
  c.assign(64 * 256, 0);
  for (int l = 0; l < 64; ++l)
    for (int i = 0; i < 256; ++i) c[size_t(l) * 256 + i] = uint8_t(i);
  return c;
}

RenderCheck check_render(LoadedBsp& bsp, int count, int width, int height) {
  RenderCheck out;
  std::vector<uint8_t> colormap = test_colormap();
  std::vector<ViewParams> views = test_viewpoints(*bsp.world(), count);
  MismatchBreakdown total;
  std::set<uint32_t> seen;
  std::vector<uint8_t> pixels, coverage;
  for (const ViewParams& v : views) {
    Status s = bsp.render(v, width, height, colormap.data(), &pixels, &coverage);
    if (!s) {
      if (out.error.empty()) out.error = s.message();
      continue;
    }
    for (uint8_t c : coverage) out.coverage_errors += c != 1;
    ReferenceRenderer ref(ReferenceInputs{bsp.world(), 0.5, nullptr, colormap.data()});
    ReferenceFrame frame = ref.render(v, width, height);
    total.add(classify_mismatches(ref, frame, pixels.data(), width));
    for (const ReferenceSample& smp : frame.samples)
      if (smp.face != kNoFace) seen.insert(smp.face);
    out.views++;
  }
  out.agreement = total.agreement();
  out.unexplained = total.pixels ? double(total.unexplained + total.mip) / double(total.pixels) : 0;
  out.summary = total.summary();
  out.faces_drawn.assign(seen.begin(), seen.end());
  return out;
}

}  // namespace sb::test
