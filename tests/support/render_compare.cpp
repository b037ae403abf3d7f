// tests/support/render_compare.cpp: see render_compare.h.
#include "tests/support/render_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sb::test {

void MismatchBreakdown::add(const MismatchBreakdown& o) {
  pixels += o.pixels;
  mismatched += o.mismatched;
  edge += o.edge;
  texel += o.texel;
  mip += o.mip;
  unexplained += o.unexplained;
  interpolated += o.interpolated;
}

std::string MismatchBreakdown::summary() const {
  auto pct = [this](uint64_t n) { return pixels ? 100.0 * double(n) / double(pixels) : 0.0; };
  char buf[384];
  std::snprintf(buf, sizeof buf,
                "agreement %.3f%% of %llu pixels (%.3f%% counting the 16-pixel-interpolated texel as agreeing); "
                "mismatched %.3f%%: edge %.3f%%, neighbour texel %.3f%% (interpolated texel %.3f%%), "
                "other mip %.3f%%, unexplained %.3f%%",
                100.0 * agreement(), static_cast<unsigned long long>(pixels), 100.0 * interpolation_agreement(),
                pct(mismatched), pct(edge), pct(texel), pct(interpolated), pct(mip), pct(unexplained));
  return buf;
}

namespace {

bool on_edge(const ReferenceFrame& f, int x, int y) {
  uint32_t me = f.face_at(x, y);
  const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
  for (int k = 0; k < 4; ++k) {
    int nx = x + dx[k], ny = y + dy[k];
    if (nx < 0 || ny < 0 || nx >= f.width || ny >= f.height) continue;
    if (f.face_at(nx, ny) != me) return true;
  }
  return false;
}

// The 16-pixel run of the reference's face run in row y that contains x, the way a span
// drawer with one divide per 16 pixels would walk it: exact values at pixels a and e,
// linear in between. Returns false when x is alone (nothing to interpolate).
bool interpolation_run(const ReferenceFrame& f, int x, int y, int* a, int* e) {
  uint32_t face = f.face_at(x, y);
  int x0 = x, x1 = x;
  while (x0 > 0 && f.face_at(x0 - 1, y) == face) --x0;
  while (x1 + 1 < f.width && f.face_at(x1 + 1, y) == face) ++x1;
  *a = x0 + 16 * ((x - x0) / 16);
  *e = (x1 - *a + 1 > 16) ? *a + 16 : x1;
  return *e > *a;
}

// Candidate coordinates: first the interpolated one (when there is a run), then the exact
// and interpolated ones moved by -1, 0, +1 texel.
void candidates(double exact, double interp, bool has_interp, std::vector<double>* out) {
  out->clear();
  if (has_interp) out->push_back(interp);
  for (int d = -1; d <= 1; ++d) {
    out->push_back(exact + d);
    if (has_interp) out->push_back(interp + d);
  }
}

// 0: no neighbouring texel explains `actual`; 1: exactly the texel the 16-pixel
// interpolation reaches; 2: another candidate within one texel.
int neighbour_texel(ReferenceRenderer& ref, const ReferenceFrame& f, const ReferenceSample& s, int x, int y,
                    uint8_t actual) {
  if (s.kind == SampleKind::None) return 0;
  int a = 0, e = 0;
  bool run = interpolation_run(f, x, y, &a, &e);
  double k = run ? double(x - a) / double(e - a) : 0.0;
  const double py = y + 0.5;
  std::vector<double> cs, ct;
  // Tries every (cs[i], ct[j]); the first pair (i = j = 0) is the interpolated texel.
  auto search = [&](auto colour) {
    for (size_t i = 0; i < cs.size(); ++i)
      for (size_t j = 0; j < ct.size(); ++j)
        if (colour(cs[i], ct[j]) == actual) return (run && i == 0 && j == 0) ? 1 : 2;
    return 0;
  };
  if (s.kind == SampleKind::Sky) {
    double qx, qy, qxa = 0, qya = 0, qxe = 0, qye = 0;
    ReferenceRenderer::sky_coords(f.ray(x + 0.5, py), &qx, &qy);
    if (run) {
      ReferenceRenderer::sky_coords(f.ray(a + 0.5, py), &qxa, &qya);
      ReferenceRenderer::sky_coords(f.ray(e + 0.5, py), &qxe, &qye);
    }
    candidates(qx, qxa + k * (qxe - qxa), run, &cs);
    candidates(qy, qya + k * (qye - qya), run, &ct);
    return search([&](double cx, double cy) { return ref.sky_colour_at(s.texture, cx, cy); });
  }
  double sa = s.s, ta = s.t, se = s.s, te = s.t;
  if (run && !(ref.face_st(s.face, f.origin, f.ray(a + 0.5, py), &sa, &ta) &&
               ref.face_st(s.face, f.origin, f.ray(e + 0.5, py), &se, &te)))
    run = false;
  candidates(s.s, sa + k * (se - sa), run, &cs);
  candidates(s.t, ta + k * (te - ta), run, &ct);
  if (s.kind == SampleKind::Turb)
    return search([&](double cx, double cy) { return ref.turb_colour(s.texture, cx, cy); });
  const Face& face = ref.world().faces[s.face];
  const double scale = double(1 << s.mip);
  return search([&](double cx, double cy) {
    int u = int(std::floor((cx - face.texture_mins[0]) / scale));
    int v = int(std::floor((cy - face.texture_mins[1]) / scale));
    return ref.lit_colour(s.face, s.texture, s.mip, u, v);
  });
}

bool other_mip(ReferenceRenderer& ref, const ReferenceFrame& f, const ReferenceSample& s, uint8_t actual) {
  if (s.kind != SampleKind::Lit) return false;
  const Face& face = ref.world().faces[s.face];
  for (int mip = std::max(0, s.mip - 1); mip <= std::min(3, s.mip + 1); ++mip) {
    if (mip == s.mip) continue;
    double scale = double(1 << mip);
    int u = int(std::floor((s.s - face.texture_mins[0]) / scale));
    int v = int(std::floor((s.t - face.texture_mins[1]) / scale));
    for (int dv = -1; dv <= 1; ++dv)
      for (int du = -1; du <= 1; ++du)
        if (ref.lit_colour(s.face, s.texture, mip, u + du, v + dv) == actual) return true;
  }
  (void)f;
  return false;
}

}  // namespace

MismatchBreakdown classify_mismatches(ReferenceRenderer& ref, const ReferenceFrame& frame, const uint8_t* actual,
                                      int stride, std::vector<PixelClass>* classes) {
  MismatchBreakdown b;
  if (classes) classes->assign(size_t(frame.width) * frame.height, PixelClass::Match);
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x) {
      ++b.pixels;
      size_t i = size_t(y) * frame.width + x;
      uint8_t a = actual[size_t(y) * stride + x];
      if (a == frame.pixels[i]) continue;
      ++b.mismatched;
      const ReferenceSample& s = frame.samples[i];
      PixelClass c;
      if (on_edge(frame, x, y)) {
        c = PixelClass::Edge;
        ++b.edge;
      } else if (int nt = neighbour_texel(ref, frame, s, x, y, a)) {
        c = PixelClass::Texel;
        ++b.texel;
        b.interpolated += nt == 1;
      } else if (other_mip(ref, frame, s, a)) {
        c = PixelClass::Mip;
        ++b.mip;
      } else {
        c = PixelClass::Unexplained;
        ++b.unexplained;
      }
      if (classes) (*classes)[i] = c;
    }
  return b;
}

std::vector<uint8_t> comparison_rgb(const ReferenceFrame& frame, const uint8_t* actual, int stride,
                                    const std::vector<PixelClass>& classes, const std::vector<uint8_t>& palette,
                                    int* out_width) {
  int w = frame.width, h = frame.height, ow = w * 3 + 8;
  *out_width = ow;
  std::vector<uint8_t> rgb(size_t(ow) * h * 3, 0);
  auto put = [&](int x, int y, uint8_t r, uint8_t g, uint8_t bl) {
    uint8_t* p = &rgb[(size_t(y) * ow + x) * 3];
    p[0] = r; p[1] = g; p[2] = bl;
  };
  auto put_index = [&](int x, int y, uint8_t idx) {
    put(x, y, palette[idx * 3], palette[idx * 3 + 1], palette[idx * 3 + 2]);
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      size_t i = size_t(y) * w + x;
      put_index(x, y, actual[size_t(y) * stride + x]);
      put_index(x + w + 4, y, frame.pixels[i]);
      uint8_t grey = uint8_t(palette[frame.pixels[i] * 3 + 1] / 3);
      switch (classes[i]) {
        case PixelClass::Match: put(x + 2 * w + 8, y, grey, grey, grey); break;
        case PixelClass::Edge: put(x + 2 * w + 8, y, 40, 80, 255); break;
        case PixelClass::Texel: put(x + 2 * w + 8, y, 0, 200, 0); break;
        case PixelClass::Mip: put(x + 2 * w + 8, y, 255, 220, 0); break;
        case PixelClass::Unexplained: put(x + 2 * w + 8, y, 255, 0, 0); break;
      }
    }
  return rgb;
}

}  // namespace sb::test
