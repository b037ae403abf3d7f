// tests/support/reference_renderer.cpp: see reference_renderer.h for the method.
//
// Sections:
//   1. view basis and per-pixel rays
//   2. face setup: facing test, clipped polygon (nearzi, screen box), edge planes
//   3. rasterising into the z-buffer
//   4. shading the visible samples
#include "tests/support/reference_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "engine/render/surface_math.h"

namespace sb::test {
namespace {

using glm::dvec3;

dvec3 to_d(const glm::vec3& v) { return dvec3(v.x, v.y, v.z); }
dvec3 to_d(const glm::vec4& v) { return dvec3(v.x, v.y, v.z); }

// ---------------------------------------------------------------------------
// 1. View basis (Quake conventions: x forward, y left, z up; yaw turns left about z,
//    pitch > 0 looks down, roll > 0 tilts `right` downwards) and the pixel-centre rays.
struct View {
  dvec3 origin, forward, right, up;
  double xcenter, ycenter, xscale, yscale;
  int width, height;
  std::vector<dvec3> rays;  // dir(x + 0.5, y + 0.5): unit depth along forward
};

View make_view(const ViewParams& p, int width, int height) {
  constexpr double kDeg = 3.14159265358979323846 / 180.0;
  double y = p.yaw * kDeg, x = p.pitch * kDeg, r = p.roll * kDeg;
  double cy = std::cos(y), sy = std::sin(y), cp = std::cos(x), sp = std::sin(x), cr = std::cos(r),
         sr = std::sin(r);
  View v;
  v.origin = to_d(p.origin);
  v.forward = dvec3(cp * cy, cp * sy, -sp);
  dvec3 right0(sy, -cy, 0.0);               // right before roll (horizontal)
  dvec3 up0(sp * cy, sp * sy, cp);          // up before roll
  v.right = cr * right0 - sr * up0;
  v.up = cr * up0 + sr * right0;
  v.width = width;
  v.height = height;
  v.xcenter = width / 2.0;
  v.ycenter = height / 2.0;
  v.xscale = v.xcenter / std::tan(p.fov_x * kDeg / 2.0);
  v.yscale = v.xscale;
  v.rays.resize(size_t(width) * height);
  for (int py = 0; py < height; ++py)
    for (int px = 0; px < width; ++px) {
      double a = (px + 0.5 - v.xcenter) / v.xscale, b = (py + 0.5 - v.ycenter) / v.yscale;
      v.rays[size_t(py) * width + px] = v.forward + a * v.right - b * v.up;
    }
  return v;
}

// ---------------------------------------------------------------------------
// 2. Face setup.
struct EdgeTest {
  dvec3 normal;       // inside of the face is where dot(normal, ray) > 0
  bool tie_inside;    // a ray with dot == 0 counts as inside (top-left rule)
};

struct FaceSetup {
  bool visible = false;
  dvec3 normal;       // plane normal (file orientation)
  double plane_dist;  // dot(normal, X) = plane_dist on the plane
  std::vector<EdgeTest> edges;
  double nearzi = 0;
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // inclusive pixel box to scan
};

// The face's vertices in surfedge order.
std::vector<uint32_t> face_vertex_indices(const BspWorld& w, const Face& f) {
  std::vector<uint32_t> idx;
  idx.reserve(f.num_edges);
  for (uint32_t i = 0; i < f.num_edges; ++i) {
    int32_t se = w.surfedges[f.first_surfedge + i];
    const Edge& e = w.edges[se >= 0 ? se : -int64_t(se)];
    idx.push_back(se >= 0 ? e.v[0] : e.v[1]);
  }
  // Zero-area spikes (real maps have them: a vertex that goes out and straight back) would
  // make the edge-plane test reject the whole face: drop such vertices, and repeated ones.
  bool changed = true;
  while (changed && idx.size() > 3) {
    changed = false;
    for (size_t i = 0; i < idx.size() && idx.size() > 3; ++i) {
      const dvec3 a = to_d(w.vertices[idx[(i + idx.size() - 1) % idx.size()]]);
      const dvec3 b = to_d(w.vertices[idx[i]]);
      const dvec3 c = to_d(w.vertices[idx[(i + 1) % idx.size()]]);
      const dvec3 d1 = b - a, d2 = c - b;
      const double l1 = glm::length(d1), l2 = glm::length(d2);
      const bool repeated = l1 < 1e-9;
      const bool spike = glm::length(glm::cross(d1, d2)) <= 1e-2 * l1 * l2 && glm::dot(d1, d2) < 0;  // turns back
      if (repeated || spike) {
        idx.erase(idx.begin() + long(i));
        changed = true;
        break;
      }
    }
  }
  return idx;
}

// Clips a convex polygon (view space: x = right, y = up, z = forward) against the four
// frustum planes through the eye. Returns the surviving vertices.
std::vector<dvec3> clip_to_frustum(std::vector<dvec3> poly, double ax, double ay) {
  // Plane value d(p) >= 0 keeps p.
  auto clip = [](const std::vector<dvec3>& in, auto d) {
    std::vector<dvec3> out;
    size_t n = in.size();
    for (size_t i = 0; i < n; ++i) {
      const dvec3& a = in[i];
      const dvec3& b = in[(i + 1) % n];
      double da = d(a), db = d(b);
      if (da >= 0) out.push_back(a);
      if ((da >= 0) != (db >= 0)) {
        double t = da / (da - db);
        out.push_back(a + t * (b - a));
      }
    }
    return out;
  };
  poly = clip(poly, [ax](const dvec3& p) { return p.x + ax * p.z; });   // left
  if (poly.size() < 3) return {};
  poly = clip(poly, [ax](const dvec3& p) { return -p.x + ax * p.z; });  // right
  if (poly.size() < 3) return {};
  poly = clip(poly, [ay](const dvec3& p) { return -p.y + ay * p.z; });  // top
  if (poly.size() < 3) return {};
  poly = clip(poly, [ay](const dvec3& p) { return p.y + ay * p.z; });   // bottom
  if (poly.size() < 3) return {};
  return poly;
}

FaceSetup setup_face(const BspWorld& w, const View& view, const Face& f) {
  FaceSetup fs;
  const Plane& pl = w.planes[f.plane];
  fs.normal = to_d(pl.normal);
  fs.plane_dist = pl.dist;
  double side = glm::dot(fs.normal, view.origin) - fs.plane_dist;
  bool back = (f.flags & kFacePlaneBack) != 0;
  if (back ? !(side < 0) : !(side > 0)) return fs;  // seen from behind or edge-on

  std::vector<uint32_t> idx = face_vertex_indices(w, f);
  size_t n = idx.size();

  // Clipped polygon in view space: nearzi and the screen box.
  std::vector<dvec3> poly;
  poly.reserve(n);
  for (uint32_t i : idx) {
    dvec3 d = to_d(w.vertices[i]) - view.origin;
    poly.emplace_back(glm::dot(d, view.right), glm::dot(d, view.up), glm::dot(d, view.forward));
  }
  double ax = view.xcenter / view.xscale, ay = view.ycenter / view.yscale;
  poly = clip_to_frustum(std::move(poly), ax, ay);
  if (poly.empty()) return fs;
  double sx0 = 1e300, sx1 = -1e300, sy0 = 1e300, sy1 = -1e300;
  bool near_eye = false;
  for (const dvec3& p : poly) {
    if (p.z < 1e-6) { near_eye = true; continue; }
    fs.nearzi = std::max(fs.nearzi, 1.0 / p.z);
    double sx = view.xcenter + view.xscale * p.x / p.z, sy = view.ycenter - view.yscale * p.y / p.z;
    sx0 = std::min(sx0, sx); sx1 = std::max(sx1, sx);
    sy0 = std::min(sy0, sy); sy1 = std::max(sy1, sy);
  }
  if (near_eye) {
    fs.x0 = 0; fs.y0 = 0; fs.x1 = view.width - 1; fs.y1 = view.height - 1;
    if (fs.nearzi == 0) fs.nearzi = 1e6;
  } else {
    // Centres x + 0.5 in [sx0, sx1], with a pixel of margin; the edge tests decide.
    fs.x0 = std::max(0, int(std::floor(sx0 - 0.5)) - 1);
    fs.x1 = std::min(view.width - 1, int(std::ceil(sx1 - 0.5)) + 1);
    fs.y0 = std::max(0, int(std::floor(sy0 - 0.5)) - 1);
    fs.y1 = std::min(view.height - 1, int(std::ceil(sy1 - 0.5)) + 1);
  }

  // Winding: sign of dot(area vector, vertex - eye) makes every edge's inside positive.
  dvec3 area(0.0);
  for (size_t i = 0; i < n; ++i)
    area += glm::cross(to_d(w.vertices[idx[i]]), to_d(w.vertices[idx[(i + 1) % n]]));
  double wind = glm::dot(area, to_d(w.vertices[idx[0]]) - view.origin);
  if (wind == 0) return fs;
  double sigma = wind > 0 ? 1.0 : -1.0;

  for (size_t i = 0; i < n; ++i) {
    uint32_t p = idx[i], q = idx[(i + 1) % n];
    // The plane through the eye and the edge, computed from the lower vertex index first so
    // that two faces sharing the edge compute bit-identical normals (exact complement).
    uint32_t a = std::min(p, q), b = std::max(p, q);
    dvec3 na = glm::cross(to_d(w.vertices[a]) - view.origin, to_d(w.vertices[b]) - view.origin);
    if (na == dvec3(0.0)) continue;  // degenerate edge, or the eye is on its line
    double sgn = (p == a) ? sigma : -sigma;
    EdgeTest e;
    e.normal = sgn * na;
    // Screen gradient of the edge function: x grows along right, y grows along -up.
    double gx = glm::dot(e.normal, view.right), gy = -glm::dot(e.normal, view.up);
    e.tie_inside = gx > 0 || (gx == 0 && gy > 0);
    fs.edges.push_back(e);
  }
  if (fs.edges.size() < 3) return fs;
  fs.visible = true;
  return fs;
}

// ---------------------------------------------------------------------------
// 3. Rasterising: nearest exact depth wins; ties keep the first face.
struct ZBuffer {
  std::vector<double> depth;
  std::vector<uint32_t> face;
};

void rasterise(const View& view, const FaceSetup& fs, uint32_t face_index, ZBuffer& zb) {
  double plane_side = fs.plane_dist - glm::dot(fs.normal, view.origin);
  for (int y = fs.y0; y <= fs.y1; ++y) {
    for (int x = fs.x0; x <= fs.x1; ++x) {
      size_t i = size_t(y) * view.width + x;
      const dvec3& r = view.rays[i];
      double denom = glm::dot(fs.normal, r);
      if (denom == 0) continue;
      double z = plane_side / denom;  // depth along forward (rays have unit depth)
      if (!(z > 0) || z >= zb.depth[i]) continue;
      bool inside = true;
      for (const EdgeTest& e : fs.edges) {
        double d = glm::dot(e.normal, r);
        if (d > 0 || (d == 0 && e.tie_inside)) continue;
        inside = false;
        break;
      }
      if (!inside) continue;
      zb.depth[i] = z;
      zb.face[i] = face_index;
    }
  }
}

}  // namespace

// ---------------------------------------------------------------------------
// 4. Shading.
ReferenceRenderer::ReferenceRenderer(const ReferenceInputs& in) : in_(in) {
  size_t n = in.world->num_faces;
  grids_.resize(n);
  grid_widths_.assign(n, 0);
  grid_done_.assign(n, 0);
}

const std::vector<uint16_t>& ReferenceRenderer::light_grid(uint32_t face, int* grid_width) {
  if (!grid_done_[face]) {
    static const std::vector<int> kNormal(kMaxLightStyleSlots, kLightStyleNormal);
    const Face& f = in_.world->faces[face];
    grids_[face].assign(size_t(render::light_grid_size(f)), 0);
    int gh = 0;
    grid_widths_[face] = render::face_light_grid(*in_.world, f, in_.lightstyles ? in_.lightstyles : kNormal.data(),
                                                 grids_[face].data(), &gh);
    grid_done_[face] = 1;
  }
  *grid_width = grid_widths_[face];
  return grids_[face];
}

int ReferenceRenderer::animated_texture(uint32_t face) const {
  const BspWorld& w = *in_.world;
  return render::animated_texture(w, w.texinfo[w.faces[face].texinfo].texture, in_.time);
}

uint8_t ReferenceRenderer::lit_colour(uint32_t face, int texture, int mip, int u, int v) {
  const Face& f = in_.world->faces[face];
  u = std::max(0, std::min(u, (f.extents[0] >> mip) - 1));
  v = std::max(0, std::min(v, (f.extents[1] >> mip) - 1));
  int gw = 0;
  const std::vector<uint16_t>& grid = light_grid(face, &gw);
  int row = render::shade_at(grid.data(), gw, u, v, mip) >> 8;
  uint8_t texel = render::texture_texel(in_.world->textures[texture], mip, f.texture_mins[0], f.texture_mins[1], u, v);
  return in_.colormap[row * 256 + texel];
}

uint8_t ReferenceRenderer::turb_colour(int texture, double s, double t) const {
  return render::turb_texel(in_.world->textures[texture], float(s), float(t), in_.time);
}

uint8_t ReferenceRenderer::sky_colour(int texture, const glm::dvec3& dir) const {
  return render::sky_texel(in_.world->textures[texture], glm::vec3(dir), in_.time);
}

void ReferenceRenderer::sky_coords(const glm::dvec3& dir, double* qx, double* qy) {
  double x = dir.x, y = dir.y, z = 3.0 * dir.z;
  double len = std::sqrt(x * x + y * y + z * z);
  if (len > 0) {
    x /= len;
    y /= len;
  } else {
    x = 1.0;
    y = 0.0;
  }
  *qx = render::kSkyScale * x;
  *qy = render::kSkyScale * y;
}

uint8_t ReferenceRenderer::sky_colour_at(int texture, double qx, double qy) const {
  const Texture& sky = in_.world->textures[texture];
  const int64_t w = sky.width, h = sky.height, half = w / 2;
  auto wrap = [](int64_t i, int64_t n) { return ((i % n) + n) % n; };
  auto layer = [&](double speed, int64_t base) {
    int64_t s = int64_t(std::floor(speed * in_.time + qx)), t = int64_t(std::floor(speed * in_.time + qy));
    return sky.mips[0][wrap(t, h) * w + base + wrap(s, half)];
  };
  uint8_t front = layer(render::kSkyFrontSpeed, 0);
  return front ? front : layer(render::kSkyBackSpeed, half);
}

bool ReferenceRenderer::face_st(uint32_t face, const glm::dvec3& origin, const glm::dvec3& ray, double* s,
                                double* t) const {
  const BspWorld& w = *in_.world;
  const Face& f = w.faces[face];
  const Plane& pl = w.planes[f.plane];
  dvec3 n = to_d(pl.normal);
  double denom = glm::dot(n, ray);
  if (denom == 0) return false;
  double z = (double(pl.dist) - glm::dot(n, origin)) / denom;
  if (!(z > 0)) return false;
  dvec3 hit = origin + z * ray;
  const TexInfo& ti = w.texinfo[f.texinfo];
  *s = glm::dot(hit, to_d(ti.vecs[0])) + double(ti.vecs[0].w);
  *t = glm::dot(hit, to_d(ti.vecs[1])) + double(ti.vecs[1].w);
  return true;
}

ReferenceFrame ReferenceRenderer::render(const ViewParams& params, int width, int height) {
  const BspWorld& w = *in_.world;
  View view = make_view(params, width, height);
  size_t npix = size_t(width) * height;
  ZBuffer zb;
  zb.depth.assign(npix, std::numeric_limits<double>::infinity());
  zb.face.assign(npix, kNoFace);

  // Model 0's faces only (brush entities are drawn by another pass).
  const SubModel& world_model = w.models[0];
  std::vector<int8_t> face_mip(w.num_faces, 0);
  for (uint32_t fi = world_model.first_face; fi < world_model.first_face + world_model.num_faces; ++fi) {
    const Face& f = w.faces[fi];
    FaceSetup fs = setup_face(w, view, f);
    if (!fs.visible) continue;
    face_mip[fi] = int8_t(render::choose_mip(float(fs.nearzi), float(view.xscale), w.texinfo[f.texinfo].mipadjust));
    rasterise(view, fs, fi, zb);
  }

  ReferenceFrame out;
  out.width = width;
  out.height = height;
  out.origin = view.origin;
  out.forward = view.forward;
  out.right = view.right;
  out.up = view.up;
  out.xcenter = view.xcenter;
  out.ycenter = view.ycenter;
  out.xscale = view.xscale;
  out.yscale = view.yscale;
  out.pixels.assign(npix, 0);
  out.samples.assign(npix, ReferenceSample{});
  std::vector<int> anim(w.num_faces, -2);
  for (size_t i = 0; i < npix; ++i) {
    uint32_t fi = zb.face[i];
    if (fi == kNoFace) continue;
    const Face& f = w.faces[fi];
    const TexInfo& ti = w.texinfo[f.texinfo];
    if (anim[fi] == -2) anim[fi] = animated_texture(fi);
    ReferenceSample& smp = out.samples[i];
    smp.face = fi;
    smp.texture = anim[fi];
    smp.depth = zb.depth[i];
    dvec3 hit = view.origin + zb.depth[i] * view.rays[i];
    smp.s = glm::dot(hit, to_d(ti.vecs[0])) + double(ti.vecs[0].w);
    smp.t = glm::dot(hit, to_d(ti.vecs[1])) + double(ti.vecs[1].w);
    if (f.flags & kFaceSky) {
      smp.kind = SampleKind::Sky;
      out.pixels[i] = sky_colour(smp.texture, view.rays[i]);
    } else if (f.flags & kFaceTurb) {
      smp.kind = SampleKind::Turb;
      out.pixels[i] = turb_colour(smp.texture, smp.s, smp.t);
    } else {
      smp.kind = SampleKind::Lit;
      int mip = face_mip[fi];
      smp.mip = int8_t(mip);
      double scale = double(1 << mip);
      int u = int(std::floor((smp.s - f.texture_mins[0]) / scale));
      int v = int(std::floor((smp.t - f.texture_mins[1]) / scale));
      smp.u = std::max(0, std::min(u, (f.extents[0] >> mip) - 1));
      smp.v = std::max(0, std::min(v, (f.extents[1] >> mip) - 1));
      out.pixels[i] = lit_colour(fi, smp.texture, mip, smp.u, smp.v);
    }
  }
  return out;
}

std::vector<uint8_t> reference_render(const BspWorld& world, const ViewParams& view, int width, int height,
                                      double time, const int* lightstyles, const uint8_t* colormap,
                                      std::vector<uint32_t>* face_ids) {
  ReferenceInputs in;
  in.world = &world;
  in.time = time;
  in.lightstyles = lightstyles;
  in.colormap = colormap;
  ReferenceRenderer r(in);
  ReferenceFrame frame = r.render(view, width, height);
  if (face_ids) {
    face_ids->resize(frame.samples.size());
    for (size_t i = 0; i < frame.samples.size(); ++i) (*face_ids)[i] = frame.samples[i].face;
  }
  return std::move(frame.pixels);
}

}  // namespace sb::test
