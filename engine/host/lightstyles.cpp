#include "engine/host/lightstyles.h"

#include <cmath>
#include <cstring>

namespace sb::host {
namespace {

// Starbow's own light-style patterns (one letter per 0.1 s). Index = style number.
// Written for this project: rhythms chosen to read clearly on screen, not taken
// from any other engine or game.
constexpr const char* kPatterns[] = {
    nullptr,                                // 0: steady
    "mmlmnmmkmmonmmlmpmmjmmnm",             // 1: restless flicker
    "bdfhjlnprtvxzxvtrpnljhfd",             // 2: deep, quick breathing pulse
    "mmmlmmnnmmmkmmlmmnommlm",              // 3: candle
    "mmazmmaz",                             // 4: fast strobe
    "jklmnopqponmlk",                       // 5: gentle pulse
    "nmlkmnomlmnmkjmnm",                    // 6: second flicker
    "mmnmmlmmmnommmlmmnm",                  // 7: second candle
    "mmmmnmmmlmmmmommmnmmmm",               // 8: calm candle
    "zzzzzaaaaa",                           // 9: slow strobe (1 s period)
    "mmmmmmamcmmmmmmmmbmmmmam",             // 10: failing fluorescent tube
    "ghijklmnopqrsrqponmlkjih",             // 11: slow pulse that never goes dark
};
constexpr int kNumPatterns = int(sizeof kPatterns / sizeof kPatterns[0]);

}  // namespace

const char* light_style_pattern(int style) {
  return style > 0 && style < kNumPatterns ? kPatterns[style] : nullptr;
}

int light_style_letter_value(char c) {
  if (c < 'a' || c > 'z') c = 'm';
  return (c - 'a') * kLightStyleNormal / 12;
}

void light_styles_every_frame(unsigned frame, int* out) {
  for (int i = 0; i < kMaxLightStyleSlots; ++i) out[i] = 240 + 8 * int((frame + unsigned(i)) % 4u);
}

void light_styles_at(double seconds, bool animate, int* out) {
  for (int i = 0; i < kMaxLightStyleSlots; ++i) out[i] = kLightStyleNormal;
  if (!animate) return;
  if (!(seconds >= 0.0)) seconds = 0.0;  // also catches NaN
  long step = long(std::floor(seconds * kLightStyleSteps));
  for (int s = 1; s < kNumPatterns; ++s) {
    const char* p = kPatterns[s];
    long len = long(std::strlen(p));
    out[s] = light_style_letter_value(p[step % len]);
  }
}

}  // namespace sb::host
