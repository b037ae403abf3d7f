// tools/vis/vis.h: the VIS stage (sbvis): portals (.prt from sbbsp: PRT1, or PRT2 when the
// map has detail brushes) in, a potentially visible set per world leaf out, written into the
// BSP's visdata lump; the potentially hearable set is computed and reported (not stored: the
// engine derives it).
//
// Conventions (those of tools/bsp's portal writer, tools/bsp/compile.cpp):
//   - PRT leaf i is BSP leaf i + 1 (BSP leaf 0 is the shared solid leaf and has no row).
//   - A portal line "n a b (x y z ) ..." lists its winding clockwise seen from its front;
//     the front (normal from the winding, see winding_normal) faces a.
//   - PRT1: a and b are leaves. PRT2 (public cluster format): header "PRT2", leaf count,
//     cluster count, portal count; a and b are clusters; after the portals, for every
//     cluster in order, the numbers of its leaves ended by -1. Portals never cross the
//     inside of a cluster (detail brushes do not block vis).
//   - PVS rows: row_bytes = (visleafs + 7) / 8; bit (i & 7) of byte (i >> 3) is leaf i + 1.
//     With clusters, a leaf's row is the union of the leaves of every cluster its cluster
//     sees (its own included), less (when leaf boxes are known, full mode, not -sym) the ones no
//     line from the leaf's box can reach: a line from leaf L to leaf M of cluster D leaves
//     L's cluster through one of its portals p and enters D through a portal q that p
//     sees, so for some such pair L's box is partly in front of every separator of (q, p)
//     and M's box partly in front of every separator of (p, q) (vis.cpp refine_leaf_rows).
//   - PHS row of a leaf: the union of the PVS rows of the leaves in its PVS.
//   - Compression: a non-zero byte is copied; a run of k zero bytes (1..255) is written as
//     0, k (longer runs as several pairs). This is what sb::decompress_pvs reads.
//
// Modes:
//   - fast: for each directed portal, a flood through the portals that are at least partly in
//     front of it and that it is at least partly behind ("might see"); the nodes reached.
//   - full (default): from each directed portal the view is flowed node by node through the
//     portals it might see, clipping by separating planes (flow.cpp tells how); a portal
//     whose clipped winding is empty is not seen. A portal pair is kept only when the flows
//     of both directions see it.
//   Both are conservative: a leaf is hidden only when no straight line from the source leaf's
//   portals reaches it (up to the 0.01-unit plane epsilon).
//   Sky is opaque (its surface is drawn over whatever lies behind it): run_vis drops the
//   portals into sky leaves (or all-sky clusters) first, as ericw-tools does without
//   -transsky; a sky leaf then sees its own node only. -transsky keeps them.
//   Every leaf sees itself. Rows are not symmetrised (full mode is nearly symmetric;
//   -sym ORs the transpose in).
// Full mode handles portals in order of fewest might-see portals first, in fixed batches; a
// flow reads only results fixed by that order, and each thread writes its own portal's row:
// output is identical for any thread count.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "tools/common/bsp_data.h"

namespace sb::tools::vis {

struct PrtPortal {
  std::vector<double> points;  // x, y, z triples, in file order
  int leaf[2] = {0, 0};        // PRT1: leaf numbers (BSP leaf - 1); PRT2: cluster numbers.
                               // The winding faces leaf[0].
};

struct PortalFile {
  int num_leaves = 0;             // visleafs
  int num_clusters = 0;           // portal graph nodes: num_leaves for PRT1
  std::vector<int> leaf_cluster;  // PRT2: cluster of every leaf; empty for PRT1
  std::vector<PrtPortal> portals;
  // Optional (run_vis fills it from the BSP): every leaf's box, mins then maxs. With it, a
  // PRT2 leaf's row keeps only the clusters that a line from its box can reach (see
  // compute_pvs); without it every leaf of a cluster gets the cluster's row.
  std::vector<float> leaf_boxes;
  bool clustered() const { return !leaf_cluster.empty(); }
};

// Parses PRT1 or PRT2 text; `name` prefixes error messages ("maps/a.prt: line 5: ...").
Status parse_prt(const char* name, const std::string& text, PortalFile* out);
Status read_prt(const char* path, PortalFile* out);

struct VisOptions {
  bool fast = false;
  bool trans_sky = false;   // -transsky: see through sky (run_vis keeps portals into sky)
  bool chop_source = true;  // full mode: also narrow the source by the separators of (pass,
                            // previous pass) (tighter, slower; -nochop turns it off)
  bool symmetric = false;
  int threads = 2;
  bool quiet = false;
};

struct VisStats {
  int leaves = 0, portals = 0;      // PRT leaves, PRT portals (directed portals = 2x)
  int clusters = 0;                 // portal graph nodes (== leaves for PRT1)
  double mean_visible = 0;          // average visible leaves per leaf (self included)
  double mean_might = 0;            // the same for the fast flood (before full clipping)
  double mean_hearable = 0;         // average leaves in a leaf's PHS
  double mean_faces = 0;            // vis_faces: mean over leaves of the marksurfaces of the
                                    // leaves in its PVS (run_vis only; needs the BSP)
  int64_t visible_total = 0;
  int64_t flow_steps = 0;           // full mode: recursion steps (a measure of the work)
  size_t row_bytes = 0, visdata_bytes = 0, unique_rows = 0;
  double seconds_read = 0, seconds_fast = 0, seconds_full = 0, seconds_rows = 0, seconds_write = 0;
  double seconds_total = 0;
  bool full = false;
};

// Sky is opaque (a sky surface is drawn and hides what lies behind it): drops every portal
// with a sky node on either side (a PRT2 cluster is sky when all its leaves are). Sky leaves
// then see only their own node. `leaf_contents[i]` is the contents of PRT leaf i (BSP leaf
// i + 1). Returns the number of portals dropped. run_vis does this unless opt.trans_sky.
int drop_sky_portals(PortalFile* prt, const std::vector<int>& leaf_contents);
std::vector<int> prt_leaf_contents(const BspData& bsp, int num_leaves);
// What run_vis does to the portal file before compute_pvs: drop_sky_portals unless
// opt.trans_sky, and leaf_boxes from the BSP's leaves. Returns the portals dropped.
int prepare_portals(PortalFile* prt, const BspData& bsp, const VisOptions& opt);

// Computes uncompressed rows: rows->size() == num_leaves * row_bytes, row i for PRT leaf i.
// When phs is not null it receives the PHS rows in the same layout. Progress lines go to
// stderr unless opt.quiet.
Status compute_pvs(const PortalFile& prt, const VisOptions& opt, std::vector<uint8_t>* rows, VisStats* stats,
                   std::vector<uint8_t>* phs = nullptr);

// PHS from PVS rows (num_leaves rows of (num_leaves + 7) / 8 bytes): row i is the union of
// the rows of the leaves set in PVS row i. Returns the total number of bits set.
int64_t compute_phs(const std::vector<uint8_t>& pvs, int num_leaves, std::vector<uint8_t>* phs);

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
