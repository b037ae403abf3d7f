// tests/support/render_compare.h: explaining where a renderer's picture differs from the
// reference renderer's (tests/support/reference_renderer.h), and pictures of the differences.
//
// Every pixel whose palette index differs is put in the first class that explains it:
//   Edge:      along a polygon edge: the reference's face at this pixel differs from the
//              face at one of its 4-neighbours (sub-pixel edge placement, T-junctions);
//   Texel:     a neighbouring texel (16-pixel interpolation rounding): the actual colour
//              equals the reference colour of the same face and mip at texture coordinates
//              moved by up to one texel in s, t or both, from either the exact coordinates
//              or the ones a span drawer with one divide per 16 pixels reaches here (exact
//              at the ends of the 16-pixel run, linear in between; runs start at the left
//              end of the face's run of pixels in this row). Sky: the same in the sky
//              layers' texel coordinates.
//   Mip:       the actual colour equals the texel of the same face at the same point at the
//              next or previous mip level (nearzi landed on the other side of a threshold);
//   Unexplained: anything else.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "tests/support/reference_renderer.h"

namespace sb::test {

enum class PixelClass : uint8_t { Match, Edge, Texel, Mip, Unexplained };

struct MismatchBreakdown {
  uint64_t pixels = 0, mismatched = 0, edge = 0, texel = 0, mip = 0, unexplained = 0;
  uint64_t interpolated = 0;  // of `texel`: exactly the texel the 16-pixel interpolation reaches
  void add(const MismatchBreakdown& o);
  // Identical palette indices.
  double agreement() const { return pixels ? double(pixels - mismatched) / double(pixels) : 1.0; }
  // Identical, or exactly what a perfect one-divide-per-16-pixels walker draws.
  double interpolation_agreement() const {
    return pixels ? double(pixels - mismatched + interpolated) / double(pixels) : 1.0;
  }
  double unexplained_fraction() const { return pixels ? double(unexplained) / double(pixels) : 0.0; }
  std::string summary() const;  // "agreement 99.12% (mismatched 0.88%: edge 0.50%, ...)"
};

// Compares `actual` (width x height palette indices, rows `stride` bytes apart) with the
// reference frame. `classes` (optional) gets one PixelClass per pixel.
MismatchBreakdown classify_mismatches(ReferenceRenderer& ref, const ReferenceFrame& frame, const uint8_t* actual,
                                      int stride, std::vector<PixelClass>* classes = nullptr);

// A picture for eyes: actual | reference | difference (matching pixels grey, edge blue,
// texel green, mip yellow, unexplained red), side by side, RGB through `palette`.
std::vector<uint8_t> comparison_rgb(const ReferenceFrame& frame, const uint8_t* actual, int stride,
                                    const std::vector<PixelClass>& classes, const std::vector<uint8_t>& palette,
                                    int* out_width);

}  // namespace sb::test
