// tools/bsp/compile.h: sbbsp's entry point as a library: .map in, BspData (+ .prt / .pts) out.
//
//   stages: parse -> brushes -> per model: [hull 0: csg (+ hint faces) -> bsp -> portals ->
//           contents -> flood fill (world) -> face visibility -> prune -> emit (T-junctions
//           fixed) -> .prt: PRT1, or PRT2 clusters when the world has detail splits] +
//           [hulls 1, 2: expand (bevel planes found once per brush, reused for hull 2) ->
//           csg -> bsp -> portals -> contents -> fill from outside (world) -> prune -> emit]
//           -> textures lump -> entities -> write (BSP29 / BSP2 / 2PSB: BspOptions::format)
//           + the light attribute side file (.faceattr, face_attrs.h) when an entity has light keys
// Flood sources: point entities with an origin; when all of them are lights (an item prefab
// lit for preview) there is nothing to flood from: no outside fill, no leak, outside_kept.
// Output is deterministic for the same input, whatever the thread count (threads only build
// independent hull trees; every index is assigned on the calling thread).
// Progress lines go through `log` (plain lines such as "csg: 253 brushes -> 1905 faces (0.02 s)").
// The world's long phases (csg, bsp, portals, hulls) also report through tools/common/progress.h
// on stderr unless quiet or !progress.
#pragma once
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "tools/common/bsp_data.h"
#include "tools/common/face_attrs.h"

namespace sb::tools::bsp {

struct BspOptions {
  std::string map_path;
  std::string bsp_path;            // empty: map_path with ".bsp"
  std::vector<std::string> wads;   // -wad: WAD files or folders to search
  double subdivide = 240;          // texels; 0 disables
  bool fill = true;                // outside removal (-nofill disables)
  bool clip_hulls = true;          // -noclip: hulls 1 and 2 left empty
  bool tjunc = true;               // -notjunc: T-junctions left as they are (emit.h)
  bool prt1_only = false;          // -prt1: PRT1 (leaf portals) even when the map has detail
  int cluster_leaves = 0;          // -clusterleaves / -clusterextent: PRT2 clusters bigger than
  double cluster_extent = 512;     // both are split (tree.h ClusterLimits; 0 leaves: never, the
                                   // default: sbvis refines leaf rows within clusters itself)
  bool progress = true;            // -noprogress: no progress bar / quarter lines on stderr
  bool write_files = true;         // false: compile into memory only (tests)
  int threads = 2;                 // >1: clip hulls 1 and 2 are built on two threads
  // Output format: Auto (BSP29 unless a BSP29 limit is exceeded, then BSP2), Bsp2 (-bsp2),
  // Bsp2rmq (-2psb), Bsp29 (-bsp29: compile_map fails with an error naming the first BSP29
  // limit the map exceeds, and writes nothing).
  BspFormat format = BspFormat::Auto;
  bool verbose = false, quiet = false;
};

struct StageTime {
  std::string name;
  double seconds = 0;
};

struct CompileReport {
  BspData bsp;
  BspFormat format_written = BspFormat::Bsp29;
  bool leaked = false;
  std::string leak_message;        // "leak: info_player_start at (0 0 0) reaches the outside"
  bool outside_kept = false;       // no point entity to flood from (none, or lights only): no
                                   // outside fill, not a leak ("no entities to flood from; outside kept")
  std::string pts_path, prt_path;  // written files (empty when not written)
  // Light attributes per BSP face (tools/common/face_attrs.h), from the light keys of brush
  // entities; empty when no entity has one. Written next to the BSP as face_attr_path(bsp)
  // (removed there when empty).
  std::vector<FaceAttr> face_attrs;
  std::string face_attr_path;
  std::vector<std::string> warnings;
  std::vector<StageTime> times;
  int brushes = 0, skipped_brushes = 0, models = 0;
  int csg_faces = 0, bsp_faces_in = 0, bsp_faces_after = 0;
  double split_percent = 0;
  int portals = 0, visleafs = 0, filled_leaves = 0;
  std::string prt_format;          // "PRT1", "PRT2" (the map has detail) or empty (no .prt)
  int clusters = 0, prt_portals = 0;  // PRT2: vis clusters; portals written to the .prt
  int missing_textures = 0;
  int tjunc_vertices = 0, tjunc_face_splits = 0;
  int64_t bsp_bytes = 0;           // size of the file written (or that would be written)
  double total_seconds = 0;
};

using LogFn = void (*)(void* user, const char* line);

Status compile_map(const BspOptions& opt, CompileReport* report, LogFn log = nullptr, void* log_user = nullptr);

// The end-of-run summary (counts, format, bytes, T-junctions, times per stage); exposed for tests.
std::string summary_text(const CompileReport& r);

}  // namespace sb::tools::bsp
