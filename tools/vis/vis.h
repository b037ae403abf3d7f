// tools/vis/vis.h: the VIS stage (sbvis): portals (.prt, PRT1 text from sbbsp) in, a
// potentially visible set per world leaf out, written into the BSP's visdata lump.
//
// Conventions (those of tools/bsp's portal writer, tools/bsp/compile.cpp):
//   - PRT leaf i is BSP leaf i + 1 (BSP leaf 0 is the shared solid leaf and has no row).
//   - A portal line "n a b (x y z ) ..." lists its winding clockwise seen from its front;
//     the front (normal from the winding, see winding_normal) faces leaf a.
//   - PVS rows: row_bytes = (visleafs + 7) / 8; bit (i & 7) of byte (i >> 3) is leaf i + 1.
//   - Compression: a non-zero byte is copied; a run of k zero bytes (1..255) is written as
//     0, k (longer runs as several pairs). This is what sb::decompress_pvs reads.
//
// Modes:
//   - fast: for each directed portal, a flood through the portals that are at least partly in
//     front of it and that it is at least partly behind ("might see"); the leaves reached.
//   - full (default): from each directed portal the view is flowed leaf by leaf through the
//     portals it might see; at every step the target portal is clipped by the planes that
//     separate the source winding from the current pass winding (and the source by the
//     reverse ones); a portal whose clipped winding is empty is not seen.
//   Both are conservative: a leaf is hidden only when no straight line from the source leaf's
//   portals reaches it (up to the 0.01-unit plane epsilon).
//   Every leaf sees itself. Rows are not symmetrised (full mode is symmetric up to
//   rounding; -sym ORs the transpose in).
// Full mode handles portals in order of fewest might-see portals first, in fixed batches of
// 32; a finished portal's result bounds later flows through it. Results are published only
// between batches and each thread writes its own portal's row: output is identical for any
// thread count.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "tools/common/bsp_data.h"

namespace sb::tools::vis {

struct PrtPortal {
  std::vector<double> points;  // x, y, z triples, in file order
  int leaf[2] = {0, 0};        // PRT leaf numbers (BSP leaf - 1); the winding faces leaf[0]
};

struct PortalFile {
  int num_leaves = 0;
  std::vector<PrtPortal> portals;
};

// Parses PRT1 text; `name` prefixes error messages ("maps/a.prt: line 5: ...").
Status parse_prt(const char* name, const std::string& text, PortalFile* out);
Status read_prt(const char* path, PortalFile* out);

struct VisOptions {
  bool fast = false;
  bool symmetric = false;
  int threads = 2;
  bool quiet = false;
};

struct VisStats {
  int leaves = 0, portals = 0;      // PRT leaves, PRT portals (directed portals = 2x)
  double mean_visible = 0;          // average visible leaves per leaf (self included)
  double mean_might = 0;            // the same for the fast flood (before full clipping)
  int64_t visible_total = 0;
  size_t row_bytes = 0, visdata_bytes = 0, unique_rows = 0;
  double seconds_fast = 0, seconds_full = 0, seconds_total = 0;
  bool full = false;
};

// Computes uncompressed rows: rows->size() == num_leaves * row_bytes, row i for PRT leaf i.
Status compute_pvs(const PortalFile& prt, const VisOptions& opt, std::vector<uint8_t>* rows, VisStats* stats,
                   void (*progress)(void* user, int done, int total) = nullptr, void* user = nullptr);

// Run-length compression of one row (see the header comment).
void compress_row(const uint8_t* row, size_t bytes, std::vector<uint8_t>* out);

// Writes visdata and every leaf's visofs (leaf 0 and leaves past visleafs get -1); identical
// compressed rows share one copy. Fails when the PRT leaf count is not models[0].visleafs.
Status store_pvs(BspData* bsp, int num_leaves, const std::vector<uint8_t>& rows, VisStats* stats);

// The whole stage: reads bsp_path and <bsp_path minus .bsp>.prt, writes the BSP back in the
// format it was read in. Progress/summary lines go through `log` (may be null).
Status run_vis(const std::string& bsp_path, const VisOptions& opt, VisStats* stats,
               void (*log)(void* user, const char* line) = nullptr, void* user = nullptr);

}  // namespace sb::tools::vis
