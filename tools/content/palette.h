// tools/content/palette.h: Starbow's own 256-colour palette and its 64-row colormap.
//
// Palette layout (index ranges are contracts that textures, colormap and tests rely on):
//   0..223    14 ramps of 16 shades, each ordered dark (first) to light (last);
//             ramp k occupies k*16 .. k*16+15 (see kRamp* below). Index 0 is pure black.
//   224..254  fullbright colours: the colormap keeps them unchanged in every row, so
//             they glow in the dark (light panels, lava highlights, indicator lamps).
//   255       reserved: transparent for sprites and models by convention (drawn as
//             magenta if it ever reaches the screen). Textures never use it.
// Sky textures use index 0 as "transparent" in their front layer (surface_math.h).
//
// Colormap: 64 rows x 256 entries (+1 trailing byte = number of fullbright colours,
// 32, as Quake's files carry). Row r lights a colour by factor (64 - r) / 32:
// row 0 = 2x overbright, row 32 = 1x (identity for 0..223), row 63 = 1/32.
// Entry [r][i] = the non-fullbright index nearest (OkLab, lightness weighted) to
// palette[i] * factor(r) (channels clamped to 1), except that an entry is never lighter
// (OkLab L) than the entry one row above; fullbright indices and 255 map to themselves.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "tools/content/color.h"

namespace sb::content {

constexpr int kRampCount = 14;
constexpr int kRampSize = 16;
constexpr int kFirstFullbright = 224;
constexpr int kFullbrightCount = 32;  // 224..255 inclusive (255 itself is reserved)
constexpr int kTransparentIndex = 255;
constexpr int kColormapRowsCount = 64;
constexpr int kColormapIdentityRow = 32;

// Ramps, in palette order. Index of shade s (0 dark .. 15 light) of ramp k: k * 16 + s.
enum Ramp : int {
  kRampGrey, kRampStone, kRampBrown, kRampTan, kRampGreen, kRampMoss, kRampBlue,
  kRampSky, kRampRed, kRampRust, kRampGold, kRampPurple, kRampSteel, kRampTeal,
};
inline int ramp_index(int ramp, int shade) { return ramp * kRampSize + shade; }

// Fullbright groups inside 224..254.
constexpr int kFbWarmWhite = 224;  // 8: amber .. white light panels
constexpr int kFbFire = 232;       // 8: deep red .. yellow (lava, fire)
constexpr int kFbCyan = 240;       // 8: blue .. cyan white (teleporter, screens)
constexpr int kFbGreen = 248;      // 4: indicator greens
constexpr int kFbMagenta = 252;    // 3: pink/magenta lamps

struct PaletteData {
  std::array<Rgb, 256> colors;      // exact float colours
  std::array<uint8_t, 768> bytes;   // palette.lmp contents
  std::array<OkLab, 256> lab;       // OkLab of the byte colours
};

// Builds the palette (deterministic; no inputs).
PaletteData make_palette();

// Which palette entries a quantiser may choose from.
enum class IndexSet : uint8_t {
  kLit,        // 0..223: lit surfaces
  kLitOpaque,  // 1..223: sky front layer texels that must not read as transparent
  kFullbright, // 224..254
};
// Index in `set` nearest to c in OkLab, with the lightness difference scaled by
// lightness_weight (1 = plain OkLab distance, used for textures).
int nearest_index(const PaletteData& pal, Rgb c, IndexSet set, float lightness_weight = 1.0f);
// The colormap weighs lightness twice in its darkening rows (32..63; plain OkLab in the
// overbright rows, where hue matters more): a darkened colour keeps its brightness step
// first and its hue second (ramps are sparse in the dark).
constexpr float kColormapLightnessWeight = 2.0f;

// 64 * 256 + 1 bytes: colormap.lmp contents (see the header comment).
std::vector<uint8_t> make_colormap(const PaletteData& pal);
// Light factor of colormap row r (0..63).
inline float colormap_row_factor(int row) { return float(64 - row) / 32.0f; }

}  // namespace sb::content
