// engine/host/lightstyles.h: animated light-style values for the renderer.
//
// A face names up to four light styles (0..63); the renderer scales each of the
// face's lightmaps by its style's value (256 = normal brightness). A style's
// value comes from a pattern string stepped at 10 Hz, one letter per step:
//   'a' = 0 (dark), 'm' = 256 (normal), 'z' = 533;  value = (letter - 'a') * 256 / 12.
// Style 0 and styles without a pattern (12..63) stay at 256. Styles 1..11 have
// Starbow's own patterns (flicker, pulse, candle, strobe, ...; see the .cpp).
// Pure functions: no state, no heap.
#pragma once

#include "engine/render/render.h"

namespace sb::host {

constexpr int kLightStyleSteps = 10;  // pattern letters per second

// The pattern for a style, or nullptr when the style is constant (256).
const char* light_style_pattern(int style);

// Value of one pattern letter ('a'..'z'); other characters read as 'm'.
int light_style_letter_value(char c);

// Fills out[kMaxLightStyleSlots] with every style's value at `seconds`.
// When animate is false every style is 256.
void light_styles_at(double seconds, bool animate, int* out);

// Fills out[kMaxLightStyleSlots] with values that all change every frame (240 .. 264 in
// steps of 8, each style a frame ahead of the one before): a benchmark mode in which every
// lit surface in view rebuilds each frame in the cached path (r_lightstyles 2,
// starbow_bench --styles=dynamic).
void light_styles_every_frame(unsigned frame, int* out);

}  // namespace sb::host
