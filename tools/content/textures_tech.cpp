// tools/content/textures_tech.cpp: metal, doors, machinery and light fixtures.
// Light-emitting parts are TexelClass::kFullbright so they stay bright in the dark.
#include <algorithm>
#include <cmath>

#include "tools/content/texture_kit.h"
#include "tools/content/textures.h"

namespace sb::content {
using namespace kit;
namespace {

// Brushed steel: horizontal streaks plus a little grime.
Rgb brushed_steel(const PaletteData& pal, float u, float v, int h, float tone, uint32_t seed) {
  float streak = value_noise_xy(u, v, 2, h, seed);
  float grime = fbm_value(u, v, 4, 4, 0.5f, seed + 1);
  return ramp_color(pal, kRampSteel, tone + 0.08f * (streak - 0.5f) - 0.12f * smoothstep(0.55f, 0.8f, grime));
}

// Rivets at the four corners of a block (inset `in` texels): multiplier, *on if on a rivet.
float corner_rivets(float lx, float ly, float w, float h, float in, float r, bool* on) {
  float s = 1.0f;
  *on = false;
  for (float cx : {in, w - 1 - in})
    for (float cy : {in, h - 1 - in}) {
      bool i = false;
      s *= rivet(lx, ly, cx, cy, r, &i);
      if (i) *on = true;
    }
  return s;
}

// Diagonal yellow and black warning stripes, `period` texels.
Rgb hazard(const PaletteData& pal, float x, float y, float period, float wear) {
  float m = std::fmod(x + y, period);
  if (m < 0) m += period;
  bool yellow = m < period / 2;
  Rgb c = yellow ? ramp_color(pal, kRampGold, 0.72f) : ramp_color(pal, kRampGrey, 0.12f);
  return lerp(c, ramp_color(pal, kRampGrey, 0.4f), wear);
}

// A five-pointed star of outer radius r at (cx, cy) (the Starbow emblem).
bool in_star(float x, float y, float cx, float cy, float r) {
  float dx = x - cx, dy = cy - y;
  float a = std::atan2(dy, dx) - 1.5707963f;
  float seg = 6.2831853f / 5;
  float k = std::fmod(a, seg);
  if (k < 0) k += seg;
  k = std::fabs(k - seg / 2);  // angle from the nearest spoke's bisector
  float inner = r * 0.42f;
  // Radius of the star outline at this angle: linear between the point and the notch.
  float t = k / (seg / 2);
  float edge = inner + (r - inner) * t;
  return std::sqrt(dx * dx + dy * dy) <= edge;
}

}  // namespace

// A single metal plate with a bevelled rim and corner rivets.
Image make_metal_plate(const PaletteData& pal, int w, int h, uint32_t seed) {
  return generate(w, h, [&](int x, int y, float u, float v) {
    float fx = float(x), fy = float(y);
    bool on = false;
    float rv = corner_rivets(fx, fy, float(w), float(h), 5.5f, 2.2f, &on);
    if (on) return lit(ramp_color(pal, kRampSteel, 0.55f) * rv);
    Rgb c = brushed_steel(pal, u, v, h, 0.45f, seed);
    return lit(c * bevel(fx, fy, float(w), float(h), 3.0f, 0.25f) * rv);
  });
}

// 2 x 2 riveted panels with rust blooms and streaks running down from the rivets.
Image make_metal_panels(const PaletteData& pal, int w, int h, uint32_t seed) {
  const int pw = w / 2, ph = h / 2;
  return generate(w, h, [&](int x, int y, float u, float v) {
    float lx = float(x % pw), ly = float(y % ph);
    uint32_t id = hash3(x / pw, y / ph, seed);
    float tone = 0.36f + 0.08f * hash01(id);
    Rgb c = brushed_steel(pal, u, v, h, tone, seed);
    float rust = fbm_value(u, v, 4, 5, 0.55f, seed + 7);
    float streak = value_noise_xy(u, v, 16, 2, seed + 8);
    float amount = smoothstep(0.58f, 0.72f, rust) + 0.5f * smoothstep(0.7f, 0.9f, streak) * smoothstep(0.5f, 0.6f, rust);
    c = lerp(c, ramp_color(pal, kRampRust, 0.3f + 0.25f * rust), clamp01(amount));
    float shade = bevel(lx, ly, float(pw), float(ph), 2.0f, 0.25f);
    // Rivets every 16 texels along the panel edges.
    bool on = false;
    for (float p = 8; p < pw; p += 16) {
      bool i = false;
      shade *= rivet(lx, ly, p, 4.5f, 1.6f, &i) * rivet(lx, ly, p, ph - 5.5f, 1.6f, &on);
      on = on || i;
      if (on) break;
    }
    if (on) return lit(ramp_color(pal, kRampSteel, 0.6f) * shade);
    return lit(c * shade);
  });
}

// A heavy door: riveted steel frame, two recessed panels, the Starbow star on the
// upper panel, a warning kick plate at the bottom.
Image make_door(const PaletteData& pal, int w, int h, uint32_t seed) {
  const float frame = 6;
  return generate(w, h, [&](int x, int y, float u, float v) {
    float fx = float(x), fy = float(y);
    float wear = smoothstep(0.6f, 0.8f, fbm_value(u, v, 4, 4, 0.5f, seed + 3));
    if (fy >= h - 14 && fy < h - 4 && fx >= frame && fx < w - frame)
      return lit(hazard(pal, fx, fy, 8, wear * 0.6f) * (fy < h - 13 ? 0.75f : 1.0f));
    Rgb steel = brushed_steel(pal, u, v, h, 0.42f, seed);
    // Panels: upper and lower recesses between the frame and a middle bar.
    float mid = float(h) / 2;
    bool upper = fx >= frame && fx < w - frame && fy >= frame && fy < mid - 3;
    bool lower = fx >= frame && fx < w - frame && fy >= mid + 3 && fy < h - 16;
    if (upper || lower) {
      float top = upper ? frame : mid + 3, bottom = upper ? mid - 3 : float(h) - 16;
      float lx = fx - frame, ly = fy - top, pw = w - 2 * frame, ph = bottom - top;
      // Recessed: the bevel is inverted (shadow on the top left inside edge).
      float shade = 2.0f - bevel(lx, ly, pw, ph, 2.0f, 0.3f);
      Rgb c = ramp_color(pal, kRampSteel, 0.3f + 0.05f * (value_noise_xy(u, v, 2, h, seed + 4) - 0.5f));
      if (upper && in_star(fx, fy, w / 2.0f, (frame + mid - 3) / 2 + 1, w * 0.28f)) {
        bool edge = !in_star(fx, fy, w / 2.0f, (frame + mid - 3) / 2 + 1, w * 0.28f - 1.5f);
        c = ramp_color(pal, kRampGold, edge ? 0.45f : 0.66f);
        shade = edge && (fx > w / 2.0f) ? 0.85f : 1.0f;
      }
      return lit(c * shade);
    }
    bool on = false;
    float rv = corner_rivets(fx, fy, float(w), float(h), 3.0f, 1.5f, &on);
    bool on2 = false;
    float rv2 = rivet(fx, fy, 3.0f, mid, 1.5f, &on2) * rivet(fx, fy, w - 4.0f, mid, 1.5f, &on);
    on = on || on2;
    if (on) return lit(ramp_color(pal, kRampSteel, 0.62f) * rv * rv2);
    float shade = bevel(fx, fy, float(w), float(h), 2.0f, 0.25f) * rv * rv2;
    return lit(steel * shade);
  });
}

// Tech wall: vertical steel panel with a vent grille, grooves and a glowing cyan strip.
Image make_tech_wall(const PaletteData& pal, int w, int h, uint32_t seed) {
  return generate(w, h, [&](int x, int y, float u, float v) {
    float fx = float(x), fy = float(y);
    Rgb c = lerp(brushed_steel(pal, u, v, h, 0.4f, seed), ramp_color(pal, kRampBlue, 0.35f), 0.2f);
    float shade = bevel(fx, fy, float(w), float(h), 2.0f, 0.2f);
    // Vent grille: slits in the upper part.
    if (fx >= 12 && fx < w - 12 && fy >= 12 && fy < 40) {
      int r = (y - 12) % 4;
      if (r == 0) shade *= 1.15f;
      if (r >= 2) return lit(ramp_color(pal, kRampGrey, 0.08f));
    }
    // Grooves framing a lower plate.
    if (fy >= 48 && fy < h - 8 && (fx == 10 || fx == w - 11 || fy == 48 || fy == h - 9)) shade *= 0.6f;
    if (fy >= 48 && fy < h - 8 && (fx == 11 || fy == 49)) shade *= 1.2f;
    // Indicator strip: fullbright cyan, darker housing around it.
    if (fx >= w / 2 - 2 && fx < w / 2 + 2 && fy >= 60 && fy < 100) {
      if (fx >= w / 2 - 1 && fx < w / 2 + 1 && fy >= 61 && fy < 99) {
        float pulse = 0.55f + 0.35f * std::sin(fy * 0.35f);
        return glow(fullbright_color(pal, kFbCyan, 8, pulse));
      }
      return lit(ramp_color(pal, kRampGrey, 0.1f));
    }
    // Status lamps: small green fullbright dots.
    if (fy >= 108 && fy < 111 && (x == 20 || x == 21 || x == 42 || x == 43))
      return glow(fullbright_color(pal, kFbGreen, 4, x < 32 ? 0.9f : 0.4f));
    return lit(c * shade);
  });
}

// A recessed light fixture: steel frame around a glowing warm-white panel.
Image make_light_fixture(const PaletteData& pal, int w, int h, uint32_t seed) {
  return generate(w, h, [&](int x, int y, float u, float v) {
    float fx = float(x), fy = float(y);
    float frame = float(w) / 8;
    if (fx >= frame && fy >= frame && fx < w - frame && fy < h - frame) {
      float cx = (fx + 0.5f) / w - 0.5f, cy = (fy + 0.5f) / h - 0.5f;
      float t = 1.0f - 1.6f * (cx * cx + cy * cy) - 0.05f * value_noise(u, v, 8, seed);
      return glow(fullbright_color(pal, kFbWarmWhite, 8, t));
    }
    return lit(brushed_steel(pal, u, v, h, 0.5f, seed) * bevel(fx, fy, float(w), float(h), 2.0f, 0.3f));
  });
}

// A wall button: steel plate with a round red lamp button in the middle.
Image make_button(const PaletteData& pal, int w, int h, uint32_t seed) {
  return generate(w, h, [&](int x, int y, float u, float v) {
    float fx = float(x) + 0.5f, fy = float(y) + 0.5f;
    float dx = fx - w / 2.0f, dy = fy - h / 2.0f;
    float d = std::sqrt(dx * dx + dy * dy);
    float r = w * 0.3f;
    if (d < r) {
      float t = 0.85f - d / r * 0.6f + (-dx - dy) / r * 0.15f;
      return glow(fullbright_color(pal, kFbFire, 8, t * 0.6f));
    }
    if (d < r + 2) return lit(ramp_color(pal, kRampGrey, d < r + 1 ? 0.1f : 0.25f));
    return lit(brushed_steel(pal, u, v, h, 0.5f, seed) * bevel(float(x), float(y), float(w), float(h), 2.0f, 0.3f));
  });
}

// Yellow and black warning trim with worn paint.
Image make_hazard_trim(const PaletteData& pal, int w, int h, uint32_t seed) {
  return generate(w, h, [&](int x, int y, float u, float v) {
    if (y == 0) return lit(ramp_color(pal, kRampSteel, 0.6f));
    if (y == h - 1) return lit(ramp_color(pal, kRampSteel, 0.2f));
    float wear = smoothstep(0.62f, 0.78f, fbm_value(u, v, 4, 4, 0.5f, seed));
    return lit(hazard(pal, float(x), float(y), float(h), wear * 0.7f));
  });
}

// Animated cyan light panel: frame 0 (+0light) lit, frame 1 (+1light) dimmed.
namespace {
Image anim_light(const PaletteData& pal, int w, int h, uint32_t seed, float level) {
  return generate(w, h, [&](int x, int y, float u, float v) {
    float fx = float(x), fy = float(y);
    float frame = 3;
    if (fx >= frame && fy >= frame && fx < w - frame && fy < h - frame) {
      // Horizontal tube lines inside a diffuser.
      float tube = 0.5f + 0.5f * std::cos((fy - frame) / (h - 2 * frame) * 6.2831853f * 2);
      float t = level * (0.75f + 0.25f * tube) + 0.04f * (value_noise(u, v, 8, seed) - 0.5f);
      if (level < 0.5f) return lit(ramp_color(pal, kRampSky, 0.2f + t));  // off: unlit glass
      return glow(fullbright_color(pal, kFbCyan, 8, t));
    }
    return lit(brushed_steel(pal, u, v, h, 0.35f, seed) * bevel(fx, fy, float(w), float(h), 1.5f, 0.3f));
  });
}
}  // namespace

Image make_anim_light_on(const PaletteData& pal, int w, int h, uint32_t seed) { return anim_light(pal, w, h, seed, 0.95f); }
Image make_anim_light_off(const PaletteData& pal, int w, int h, uint32_t seed) { return anim_light(pal, w, h, seed, 0.3f); }

}  // namespace sb::content
