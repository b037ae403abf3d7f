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
}

std::string MismatchBreakdown::summary() const {
  auto pct = [this](uint64_t n) { return pixels ? 100.0 * double(n) / double(pixels) : 0.0; };
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "agreement %.3f%% of %llu pixels; mismatched %.3f%%: edge %.3f%%, neighbour texel %.3f%%, "
                "other mip %.3f%%, unexplained %.3f%%",
                100.0 * agreement(), static_cast<unsigned long long>(pixels), pct(mismatched), pct(edge),
                pct(texel), pct(mip), pct(unexplained));
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

bool neighbour_texel(ReferenceRenderer& ref, const ReferenceFrame& f, const ReferenceSample& s, int x, int y,
                     uint8_t actual) {
  for (int dv = -1; dv <= 1; ++dv)
    for (int du = -1; du <= 1; ++du) {
      if (du == 0 && dv == 0) continue;
      uint8_t c = 0;
      switch (s.kind) {
        case SampleKind::Lit: c = ref.lit_colour(s.face, s.texture, s.mip, s.u + du, s.v + dv); break;
        case SampleKind::Turb: c = ref.turb_colour(s.texture, s.s + du, s.t + dv); break;
        case SampleKind::Sky: c = ref.sky_colour(s.texture, f.ray(x + 0.5 + du, y + 0.5 + dv)); break;
        case SampleKind::None: return false;
      }
      if (c == actual) return true;
    }
  return false;
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
      } else if (neighbour_texel(ref, frame, s, x, y, a)) {
        c = PixelClass::Texel;
        ++b.texel;
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
