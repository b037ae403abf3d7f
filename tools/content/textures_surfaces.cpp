// tools/content/textures_surfaces.cpp: masonry, wood and natural surfaces.
// Each generator builds a tileable full-colour image from seeded noise (noise.h) and
// colours drawn from the palette's ramps, so quantisation stays close to the design.
#include <algorithm>
#include <cmath>

#include "tools/content/texture_kit.h"
#include "tools/content/textures.h"

namespace sb::content {
using namespace kit;

// Red-brown bricks 32 x 16 texels in running bond, 2-texel mortar, chipped edges.
Image make_brick(const PaletteData& pal, int w, int h, uint32_t seed) {
  const int bw = 32, bh = 16, mortar = 2;
  return generate(w, h, [&](int x, int y, float u, float v) {
    int row = y / bh;
    int sx = x + ((row & 1) ? bw / 2 : 0);
    int col = (sx / bw) % (w / bw);
    float lx = float(sx % bw), ly = float(y % bh);
    uint32_t id = hash3(col, row, seed);
    float grain = fbm_value(u, v, 16, 4, 0.55f, seed + 1);
    float chips = cellular(u, v, 24, 0.9f, seed + 2).f1;
    // Mortar: the last `mortar` texels of each brick, with a ragged edge from noise.
    float ragged = (value_noise(u, v, 32, seed + 3) - 0.5f) * 1.6f;
    if (lx >= bw - mortar + ragged * 0.5f || ly >= bh - mortar + ragged * 0.5f) {
      float t = 0.42f + 0.18f * grain;
      return lit(ramp_color(pal, kRampTan, t) * 0.82f);
    }
    float tone = 0.32f + 0.16f * hash01(id) + 0.22f * (grain - 0.5f);
    Rgb base = ramp_color(pal, kRampRed, tone);
    base = lerp(base, ramp_color(pal, kRampBrown, tone + 0.06f), 0.2f + 0.3f * hash01(rehash(id, 3)));
    float shade = bevel(lx, ly, bw - mortar, bh - mortar, 2.0f, 0.22f);
    if (chips < 0.12f) shade *= 0.78f;  // small pits
    return lit(base * shade);
  });
}

// Large cool-grey ashlar blocks: rows 32 high, widths 32/48/64 per row, dark joints,
// crack lines from ridged noise.
Image make_stone_blocks(const PaletteData& pal, int w, int h, uint32_t seed) {
  const int rh = 32;
  // Per row: block edges (cumulative), chosen from patterns that fill 128 exactly.
  static const int kPatterns[4][4] = {{48, 48, 32, 0}, {64, 64, 0, 0}, {32, 64, 32, 0}, {48, 32, 48, 0}};
  return generate(w, h, [&](int x, int y, float u, float v) {
    int row = y / rh;
    uint32_t rs = hash3(row, 0, seed);
    const int* pat = kPatterns[rs % 4];
    int shift = int((rs >> 4) % 8) * 16;
    int sx = (x + shift) % w;
    int start = 0, idx = 0;
    while (pat[idx] && sx >= start + pat[idx] * w / 128) start += pat[idx++] * w / 128;
    int bw = pat[idx] ? pat[idx] * w / 128 : w - start;
    float lx = float(sx - start), ly = float(y % rh);
    uint32_t id = hash3(row, idx, seed + 9);
    float n = fbm_value(u, v, 8, 5, 0.5f, seed + 1);
    float crack = fbm_ridged(u, v, 4, 4, 0.5f, seed + 2);
    if (lx < 2 || ly < 2) return lit(ramp_color(pal, kRampStone, 0.12f + 0.08f * n));
    float tone = 0.36f + 0.14f * hash01(id) + 0.3f * (n - 0.5f);
    Rgb c = ramp_color(pal, kRampStone, tone);
    c = lerp(c, ramp_color(pal, kRampTan, tone), 0.15f * hash01(rehash(id, 5)));
    float shade = bevel(lx - 2, ly - 2, float(bw - 2), float(rh - 2), 3.0f, 0.2f);
    if (crack > 0.93f) shade *= 0.72f;
    return lit(c * shade);
  });
}

// Rounded cobbles for floors: cellular noise, each cell a stone domed towards its centre.
Image make_cobbles(const PaletteData& pal, int w, int h, uint32_t seed) {
  const int cells = w / 16;
  return generate(w, h, [&](int, int, float u, float v) {
    Cells c = cellular(u, v, cells, 0.8f, seed);
    float gap = c.f2 - c.f1;
    float n = fbm_value(u, v, 16, 3, 0.5f, seed + 1);
    if (gap < 0.07f) return lit(ramp_color(pal, kRampBrown, 0.1f + 0.1f * n));
    float tone = 0.3f + 0.25f * hash01(c.cell) + 0.15f * (n - 0.5f);
    int ramp = (c.cell >> 9) % 3 == 0 ? kRampTan : kRampStone;
    float dome = 1.0f + 0.25f * (0.5f - c.f1) + 0.15f * smoothstep(0.07f, 0.2f, gap) - 0.1f;
    return lit(ramp_color(pal, ramp, tone) * dome);
  });
}

// Glazed ceramic floor tiles 32 x 32 in two alternating tones, grey grout.
Image make_floor_tiles(const PaletteData& pal, int w, int h, uint32_t seed) {
  const int tile = 32;
  return generate(w, h, [&](int x, int y, float u, float v) {
    int tx = x / tile, ty = y / tile;
    float lx = float(x % tile), ly = float(y % tile);
    float n = fbm_value(u, v, 8, 4, 0.5f, seed);
    if (lx < 2 || ly < 2) return lit(ramp_color(pal, kRampGrey, 0.3f + 0.1f * n));
    bool dark = ((tx + ty) & 1) != 0;
    float tone = (dark ? 0.42f : 0.66f) + 0.1f * (n - 0.5f) + 0.04f * hash01(hash3(tx, ty, seed));
    Rgb c = ramp_color(pal, dark ? kRampRust : kRampTan, tone);
    float shade = bevel(lx - 2, ly - 2, tile - 2.0f, tile - 2.0f, 2.0f, 0.15f);
    // A soft glaze highlight across each tile's upper left.
    shade += 0.06f * smoothstep(20, 4, lx + ly * 0.7f);
    return lit(c * shade);
  });
}

// Horizontal wooden planks 16 high with staggered butt joints, grain and nail heads.
Image make_planks(const PaletteData& pal, int w, int h, uint32_t seed) {
  const int ph = 16;
  return generate(w, h, [&](int x, int y, float u, float v) {
    int row = y / ph;
    uint32_t rs = hash3(row, 1, seed);
    int joint = int(rs % uint32_t(w / 16)) * 16;  // one butt joint per plank per tile
    int lx = ((x - joint) % w + w) % w;
    float ly = float(y % ph);
    float warp = fbm_value_xy(u, v, 2, 8, 3, 0.5f, seed + 1);
    float grain = 0.5f + 0.5f * std::sin((ly + warp * 10.0f + hash01(rs) * 6.0f) * 1.3f);
    float fine = value_noise_xy(u, v, 4, h, seed + 2);
    if (ly < 1 || lx < 1) return lit(ramp_color(pal, kRampBrown, 0.08f));
    float tone = 0.38f + 0.12f * hash01(rehash(rs, 4)) + 0.12f * grain + 0.08f * (fine - 0.5f);
    Rgb c = ramp_color(pal, kRampBrown, tone);
    float shade = bevel(float(lx - 1), ly - 1, float(w - 1), ph - 1.0f, 1.5f, 0.18f);
    // Nail heads 3 texels in from each joint.
    bool on = false;
    float s1 = rivet(float(lx), ly, 3.5f, 7.5f, 1.2f, &on);
    if (on) return lit(ramp_color(pal, kRampSteel, 0.35f) * s1);
    float s2 = rivet(float(lx), ly, float(w) - 3.5f, 7.5f, 1.2f, &on);
    if (on) return lit(ramp_color(pal, kRampSteel, 0.35f) * s2);
    return lit(c * shade * s1 * s2);
  });
}

// A wooden crate face: light frame, diagonal brace, darker vertical boards inside.
Image make_crate(const PaletteData& pal, int w, int h, uint32_t seed) {
  const float frame = float(w) / 8;
  return generate(w, h, [&](int x, int y, float u, float v) {
    float fx = float(x), fy = float(y);
    float grain_h = fbm_value_xy(u, v, 2, 16, 3, 0.5f, seed);
    float grain_v = fbm_value_xy(u, v, 16, 2, 3, 0.5f, seed + 1);
    bool on_frame = fx < frame || fy < frame || fx >= w - frame || fy >= h - frame;
    float diag = std::fabs(fx - fy * float(w) / float(h));
    bool on_brace = !on_frame && diag < frame * 0.7f;
    bool rim = false;
    float shade = 1.0f;
    for (float cx : {frame / 2, w - frame / 2})
      for (float cy : {frame / 2, h - frame / 2}) {
        bool in = false;
        shade *= rivet(fx, fy, cx, cy, 1.6f, &in);
        if (in) rim = true;
      }
    if (rim) return lit(ramp_color(pal, kRampSteel, 0.4f) * shade);
    if (on_frame) {
      float edge = std::min(std::min(fx, fy), std::min(w - 1 - fx, h - 1 - fy));
      float s = edge < 1 ? 0.7f : (edge > frame - 1.5f ? 0.8f : 1.0f);
      bool vertical = (fx < frame || fx >= w - frame) && !(fy < frame || fy >= h - frame);
      float g = vertical ? grain_v : grain_h;
      return lit(ramp_color(pal, kRampTan, 0.45f + 0.2f * g) * s * shade);
    }
    if (on_brace) {
      float s = diag > frame * 0.7f - 1.2f ? 0.7f : 1.0f;
      return lit(ramp_color(pal, kRampTan, 0.5f + 0.2f * grain_h) * s);
    }
    float board = grid_dist(fx, float(w) / 4);
    float s = board < 0.8f ? 0.6f : 1.0f;
    // Shadow cast by the frame and brace onto the boards.
    if (fx < frame + 2 || fy < frame + 2) s *= 0.8f;
    if (diag < frame * 0.7f + 2 && fx > fy) s *= 0.85f;
    return lit(ramp_color(pal, kRampBrown, 0.32f + 0.18f * grain_v) * s * shade);
  });
}

// Natural rock: ridged strata warped by noise, brown-grey with darker fissures.
Image make_rock(const PaletteData& pal, int w, int h, uint32_t seed) {
  return generate(w, h, [&](int, int, float u, float v) {
    float warp = fbm_gradient(u, v, 2, 3, 0.5f, seed);
    float strata = 0.5f + 0.5f * std::sin((v * 6.0f + warp * 1.2f) * 6.2831853f);
    float ridge = fbm_ridged(u, v, 4, 5, 0.5f, seed + 1);
    float n = fbm_value(u, v, 8, 4, 0.5f, seed + 2);
    float tone = 0.25f + 0.3f * ridge + 0.12f * strata + 0.1f * (n - 0.5f);
    Rgb c = lerp(ramp_color(pal, kRampStone, tone), ramp_color(pal, kRampBrown, tone), 0.55f + 0.3f * (n - 0.5f));
    float wu = u + 0.05f * fbm_gradient(u, v, 4, 3, 0.5f, seed + 4);
    float wv = v + 0.05f * fbm_gradient(u, v, 4, 3, 0.5f, seed + 5);
    Cells cr = cellular(wu, wv, 3, 1.0f, seed + 3);
    float fissure = smoothstep(0.03f, 0.0f, cr.f2 - cr.f1) * smoothstep(0.45f, 0.6f, ridge);
    c = c * (1.0f - 0.45f * fissure);
    return lit(c);
  });
}

// Grass with dirt patches and lighter blade specks.
Image make_grass(const PaletteData& pal, int w, int h, uint32_t seed) {
  return generate(w, h, [&](int x, int y, float u, float v) {
    float patch = fbm_value(u, v, 3, 3, 0.5f, seed);
    float n = fbm_value(u, v, 8, 4, 0.6f, seed + 1);
    uint32_t hx = hash3(x, y, seed + 2);
    float blade = hash01(hx);
    float dirt = smoothstep(0.36f, 0.3f, patch);
    Rgb g = lerp(ramp_color(pal, kRampGreen, 0.28f + 0.25f * n), ramp_color(pal, kRampMoss, 0.3f + 0.2f * n), 0.35f);
    if (blade > 0.86f) g = ramp_color(pal, kRampGreen, 0.45f + 0.25f * blade);
    if (blade < 0.08f) g = g * 0.7f;
    Rgb d = ramp_color(pal, kRampBrown, 0.3f + 0.2f * n);
    return lit(lerp(g, d, dirt));
  });
}

// Ceiling: square perforated panels in a steel grid.
Image make_ceiling(const PaletteData& pal, int w, int h, uint32_t seed) {
  const int panel = 32;
  return generate(w, h, [&](int x, int y, float u, float v) {
    float lx = float(x % panel), ly = float(y % panel);
    float n = fbm_value(u, v, 8, 3, 0.5f, seed);
    if (lx < 2 || ly < 2) return lit(ramp_color(pal, kRampSteel, 0.3f + 0.08f * n) * (lx < 1 || ly < 1 ? 1.2f : 0.9f));
    bool hole = (x % 4 == 1) && (y % 4 == 1) && lx > 4 && ly > 4 && lx < panel - 3 && ly < panel - 3;
    Rgb c = ramp_color(pal, kRampGrey, 0.62f + 0.1f * (n - 0.5f));
    if (hole) c = ramp_color(pal, kRampGrey, 0.25f);
    return lit(c * bevel(lx - 2, ly - 2, panel - 2.0f, panel - 2.0f, 1.5f, 0.12f));
  });
}

}  // namespace sb::content
