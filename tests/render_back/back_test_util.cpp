#include "tests/render_back/back_test_util.h"

#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "tests/support/png_image.h"
#include "tests/support/quake_data.h"

namespace sb::test::back {

HandWorld::HandWorld() { std::strcpy(w_.name, "test.bsp"); }

int HandWorld::add_texture(const char* name, int w, int h, uint32_t seed, TextureKind kind) {
  std::mt19937 rng(seed);
  auto data = std::make_unique<std::vector<uint8_t>>();
  size_t total = 0;
  for (int m = 0; m < 4; ++m) total += size_t(w >> m) * size_t(h >> m);
  data->resize(total);
  for (auto& b : *data) b = uint8_t(rng() & 0xff);
  Texture t{};
  std::snprintf(t.name, sizeof t.name, "%s", name);
  t.kind = kind;
  t.width = uint32_t(w);
  t.height = uint32_t(h);
  size_t off = 0;
  for (int m = 0; m < 4; ++m) {
    t.mips[m] = data->data() + off;
    off += size_t(w >> m) * size_t(h >> m);
  }
  t.anim_next = -1;
  t.alternate = -1;
  textures_.push_back(t);
  texels_.push_back(std::move(data));
  return int(textures_.size() - 1);
}

int HandWorld::add_plane(glm::vec3 n, float d) {
  Plane p{};
  p.normal = n;
  p.dist = d;
  p.type = 3;
  planes_.push_back(p);
  return int(planes_.size() - 1);
}

int HandWorld::add_texinfo(glm::vec4 s, glm::vec4 t, int texture, uint32_t flags) {
  TexInfo ti{};
  ti.vecs[0] = s;
  ti.vecs[1] = t;
  ti.texture = texture;
  ti.flags = flags;
  float ls = glm::length(glm::vec3(s)), lt = glm::length(glm::vec3(t));
  ti.mipadjust = std::max(ls, lt);
  texinfo_.push_back(ti);
  return int(texinfo_.size() - 1);
}

int HandWorld::add_face(int plane, int texinfo, int smin, int tmin, int ext_s, int ext_t, const uint8_t styles[4],
                        uint32_t seed, uint16_t flags, bool lit) {
  Face f{};
  f.plane = uint32_t(plane);
  f.texinfo = uint32_t(texinfo);
  f.flags = flags;
  for (int k = 0; k < 4; ++k) f.styles[k] = styles[k];
  f.texture_mins[0] = smin;
  f.texture_mins[1] = tmin;
  f.extents[0] = ext_s;
  f.extents[1] = ext_t;
  f.light_offset = kNoLightmap;
  if (lit) {
    int nstyles = 0;
    while (nstyles < 4 && styles[nstyles] != 255) ++nstyles;
    const size_t n = size_t(ext_s / 16 + 1) * size_t(ext_t / 16 + 1);
    f.light_offset = int32_t(light_.size());
    std::mt19937 rng(seed);
    for (size_t i = 0; i < n * size_t(nstyles); ++i) light_.push_back(uint8_t(rng() & 0xff));
  }
  faces_.push_back(f);
  return int(faces_.size() - 1);
}

BspWorld& HandWorld::world() {
  w_.planes = planes_.data();
  w_.num_planes = uint32_t(planes_.size());
  w_.texinfo = texinfo_.data();
  w_.num_texinfo = uint32_t(texinfo_.size());
  w_.textures = textures_.data();
  w_.num_textures = uint32_t(textures_.size());
  w_.faces = faces_.data();
  w_.num_faces = uint32_t(faces_.size());
  w_.lightdata = light_.empty() ? nullptr : light_.data();
  w_.lightdata_size = uint32_t(light_.size());
  return w_;
}

render::ViewState make_view(glm::vec3 origin, float yaw, float pitch, float fov_x, int width, int height,
                            uint32_t frame) {
  const double y = glm::radians(double(yaw)), p = glm::radians(double(pitch));
  render::ViewState v{};
  v.origin = origin;
  v.forward = glm::vec3(float(std::cos(p) * std::cos(y)), float(std::cos(p) * std::sin(y)), float(-std::sin(p)));
  v.right = glm::vec3(float(std::sin(y)), float(-std::cos(y)), 0.0f);
  v.up = glm::vec3(float(std::cos(y) * std::sin(p)), float(std::sin(y) * std::sin(p)), float(std::cos(p)));
  v.xcenter = width * 0.5f;
  v.ycenter = height * 0.5f;
  v.xscale = float(v.xcenter / std::tan(glm::radians(double(fov_x)) * 0.5));
  v.yscale = v.xscale;
  v.width = width;
  v.height = height;
  v.frame = frame;
  return v;
}

std::vector<uint8_t> colormap_or_synthetic() {
  std::string dir = quake_dir();
  if (!dir.empty()) {
    auto bytes = read_file_bytes(dir + "/lq1/gfx/colormap.lmp");
    if (bytes.size() >= 64 * 256) {
      bytes.resize(64 * 256);
      return bytes;
    }
  }
  std::vector<uint8_t> cm(64 * 256);
  for (int r = 0; r < 64; ++r)
    for (int i = 0; i < 256; ++i) cm[size_t(r) * 256 + i] = uint8_t((i + 4 * r) & 255);
  return cm;
}

std::vector<uint8_t> load_palette_or_grey() {
  std::string dir = quake_dir();
  if (!dir.empty()) {
    auto p = load_palette(dir + "/lq1/gfx/palette.lmp");
    if (p.size() == 768) return p;
  }
  std::vector<uint8_t> p(768);
  for (int i = 0; i < 256; ++i) p[i * 3] = p[i * 3 + 1] = p[i * 3 + 2] = uint8_t(i);
  return p;
}

TestMemory::TestMemory(size_t mib) : block(mib * mem::kMiB) {
  char err[256];
  if (!mem.init(block.data(), block.size(), err, sizeof err)) {
    std::fprintf(stderr, "TestMemory(%zu MiB): %s\n", mib, err);
    std::abort();
  }
}

TestFramebuffer::TestFramebuffer(int w, int h, bool with_z, bool with_coverage)
    : pixels(size_t(w) * h, 0xEE), coverage(with_coverage ? size_t(w) * h : 0), z(with_z ? size_t(w) * h : 0) {
  fb.pixels = pixels.data();
  fb.width = w;
  fb.height = h;
  fb.stride = w;
  fb.zbuffer = with_z ? z.data() : nullptr;
  fb.coverage = with_coverage ? coverage.data() : nullptr;
}

bool exact_st(const BspWorld& world, const Face& face, const render::ViewState& view, double px, double py,
              double* s, double* t, double* zi) {
  const glm::dvec3 f(view.forward), r(view.right), u(view.up), o(view.origin);
  const glm::dvec3 dir = f + ((px - view.xcenter) / view.xscale) * r - ((py - view.ycenter) / view.yscale) * u;
  const Plane& pl = world.planes[face.plane];
  const glm::dvec3 n(pl.normal);
  const double denom = glm::dot(n, dir);
  if (std::fabs(denom) < 1e-12) return false;
  const double depth = (double(pl.dist) - glm::dot(n, o)) / denom;
  if (!(depth > 0)) return false;
  const glm::dvec3 p = o + depth * dir;
  const TexInfo& ti = world.texinfo[face.texinfo];
  *s = glm::dot(p, glm::dvec3(ti.vecs[0])) + ti.vecs[0].w;
  *t = glm::dot(p, glm::dvec3(ti.vecs[1])) + ti.vecs[1].w;
  if (zi) *zi = 1.0 / depth;
  return true;
}

bool dump_png(const std::string& path, const uint8_t* pixels, int width, int height, int stride) {
  IndexedImage img;
  img.width = width;
  img.height = height;
  img.pixels.resize(size_t(width) * height);
  for (int y = 0; y < height; ++y) std::memcpy(&img.pixels[size_t(y) * width], pixels + size_t(y) * stride, width);
  return write_indexed_png(path, img, load_palette_or_grey());
}

}  // namespace sb::test::back
