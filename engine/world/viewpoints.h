// engine/world/viewpoints.h: deterministic camera positions in a world, for
// tests, flythroughs and benchmarks.
#pragma once
#include "engine/formats/bsp.h"
#include "engine/world/view_params.h"

namespace sb {

// Fills out[0..max) and returns how many it wrote (0 only when max <= 0 or the
// world has no non-solid leaf at all). Same world => same list, always.
//
// 1. Point entities with a parsable "origin", in this order of classes, each
//    class in entity-string order: info_player_start; other info_player_*;
//    info_intermission; item_*; weapon_*; monster_*; light*.
//    info_player_* eyes sit at origin + (0, 0, 22); the others at the origin.
//    Angles: "mangle" (pitch yaw roll) when present, else yaw from "angle".
//    Points whose leaf is solid are skipped.
// 2. With no entity viewpoint at all: centres of non-solid world leaves.
// 3. While fewer than max: midpoints of consecutive viewpoints (non-solid only,
//    yaw of the first of the pair), then every viewpoint so far turned by +90,
//    +180, +270 degrees of yaw.
// fov_x is 90 everywhere.
int collect_viewpoints(const BspWorld& world, ViewParams* out, int max);

}  // namespace sb
