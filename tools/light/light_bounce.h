// tools/light/light_bounce.h: bounce (radiosity) for the light stage.
//
// Model: every lit world face is a diffuse (Lambertian) reflector. What it sends out in the
// first pass is its direct light (each light's share times that light's "_bouncescale";
// style 0 only unless bouncestyled) times its reflectivity; in pass k > 1, the light it
// gathered in pass k - 1 times its reflectivity. Reflectivity, as the Quake light tools
// document "_bouncecolorscale" c (0 = ignore the map's textures, the default; 1 = multiply
// the bounced light by the texture colour): (1 - c) * grey + c * texture colour (grey: 127/255
// per channel, so a face returns about half of what it receives), where the
// texture colour is the mean of its mip 0 through the palette (0..1 per channel); without
// a palette, for a missing or placeholder texture: grey 0.5.
//
// Gathering: bounce light is smooth, so it is computed on a receiver grid of every
// LightOptions::bounce_step-th lightmap grid point each way (default 2; plus the last row /
// column) and interpolated bilinearly to the others, except where the receivers around a
// grid point disagree strongly or gathered nothing: there the point gathers itself. Light
// read from a hit face is not clamped to what a byte can show (a surface lit far beyond 255,
// e.g. beside a pool of surface lights, sends all of it on: ericw-tools' output shows the
// room over such a pool lit that brightly). At a receiver, R rays (LightOptions::bounce_rays, default 64; stratified over
// the cosine-weighted hemisphere around the face normal, jittered by a hash of face, grid
// point and ray, so deterministic) are traced to the first solid surface. The face hit is
// found among the faces on the BSP node whose plane the ray entered solid on (facing the
// ray, containing the hit point); its outgoing light there is read bilinearly from its grid.
// With cosine-weighted directions the gathered irradiance is simply the mean of what the
// hit points send out (rays that reach sky send nothing; rays starting inside solid, or
// whose hit face cannot be found, are left out of the mean). Times "_bouncescale".
// Energy: each pass returns at most max(reflectivity) of the light it started from.
#pragma once
#include <cstdint>
#include <vector>

#include "tools/light/light_face.h"

namespace sb::tools {

// Fills scene->hit_faces (geometry and reflectivity of every face). `palette` is 768 bytes or
// empty. Returns false when texture colours were wanted (colorscale > 0) but there was no
// palette (grey 0.5 used for them).
bool prepare_bounce(LightScene* scene, const std::vector<uint8_t>& palette, float colorscale);

// Gathers one pass's bounced light into work->gathered from the emit buffers of `all`.
// Reads only other faces' emit (unchanged during the pass) and writes only *work.
void bounce_gather(const LightScene& scene, uint32_t face_index, const std::vector<FaceWork>& all, FaceWork* work);

// After every face gathered: adds gathered to the face's light (a styled light new to the
// face only when it reaches 2 output units somewhere); when `another_pass`, the
// gathered light times the reflectivity becomes the face's emit for the next pass.
void bounce_commit(const LightScene& scene, uint32_t face_index, FaceWork* work, bool another_pass);

}  // namespace sb::tools
