// tests/tools_vis/vis_check_test.cpp: sbvis checked against ground truth that needs no
// portals: straight lines of sight (a brute-force conservativeness check) on a synthetic
// corridor of box cells and on LibreQuake's start.map; the PHS against the union of PVS
// rows; PRT2 clusters against the same corridor as PRT1 leaves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <filesystem>

#include "tests/support/quake_data.h"
#include "tests/support/test_world.h"
#include "tests/tools_bsp/bsp_test_util.h"
#include "tools/bsp/compile.h"
#include "tools/common/bsp_data.h"
#include "tools/vis/vis.h"

namespace sb::test {
namespace {

using tools::vis::PortalFile;
using tools::vis::VisOptions;
using tools::vis::VisStats;

constexpr double kCell = 64;  // units: cell size of the synthetic corridor

// A U-shaped corridor of 64-unit cubes on a grid: four cells east, three north, three west.
// The first cell cannot see the last (the walls between the arms block every line).
const int kCells[][2] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}, {2, 3}, {1, 3}, {0, 3}};
constexpr int kNumCells = 10;

char* put(char* p, const char* end, const char* fmt, double a, double b, double c) {
  return p + std::snprintf(p, size_t(end - p), fmt, a, b, c);
}

// The shared wall between consecutive cells i and i + 1 as a PRT portal line "4 a b (...)"
// whose winding is clockwise seen from cell a (vis.h's convention).
std::string portal_line(int i, int a, int b) {
  const int* c0 = kCells[i];
  const int* c1 = kCells[i + 1];
  char buf[256];
  char* p = buf;
  const char* end = buf + sizeof buf;
  p += std::snprintf(p, size_t(end - p), "4 %d %d ", a, b);
  const double z0 = 0, z1 = kCell;
  if (c0[1] == c1[1]) {  // east-west neighbours: plane x = X, right-hand normal towards b
    const double x = std::max(c0[0], c1[0]) * kCell, y0 = c0[1] * kCell, y1 = y0 + kCell;
    const bool east = c1[0] > c0[0];
    const double ys[4] = {east ? y0 : y1, east ? y1 : y0, east ? y1 : y0, east ? y0 : y1};
    const double zs[4] = {z0, z0, z1, z1};
    for (int k = 0; k < 4; ++k) p = put(p, end, "(%g %g %g ) ", x, ys[k], zs[k]);
  } else {  // north-south: plane y = Y
    const double y = std::max(c0[1], c1[1]) * kCell, x0 = c0[0] * kCell, x1 = x0 + kCell;
    const bool north = c1[1] > c0[1];
    const double xs[4] = {north ? x0 : x1, north ? x0 : x1, north ? x1 : x0, north ? x1 : x0};
    const double zs[4] = {z0, z1, z1, z0};
    for (int k = 0; k < 4; ++k) p = put(p, end, "(%g %g %g ) ", xs[k], y, zs[k]);
  }
  return std::string(buf) + "\n";
}

// PRT1: one leaf per cell.
std::string corridor_prt1() {
  std::string s = "PRT1\n" + std::to_string(kNumCells) + "\n" + std::to_string(kNumCells - 1) + "\n";
  for (int i = 0; i + 1 < kNumCells; ++i) s += portal_line(i, i, i + 1);
  return s;
}

// PRT2: every cell is a cluster of two leaves (as if a detail brush split it); leaves are
// numbered so that cluster c holds leaves 2c + 1 and 2c (listed in that order).
std::string corridor_prt2() {
  std::string s = "PRT2\n" + std::to_string(2 * kNumCells) + "\n" + std::to_string(kNumCells) + "\n" +
                  std::to_string(kNumCells - 1) + "\n";
  for (int i = 0; i + 1 < kNumCells; ++i) s += portal_line(i, i, i + 1);
  for (int c = 0; c < kNumCells; ++c) s += std::to_string(2 * c + 1) + " " + std::to_string(2 * c) + " -1\n";
  return s;
}

bool bit(const std::vector<uint8_t>& rows, size_t rb, int row, int col) {
  return (rows[size_t(row) * rb + size_t(col >> 3)] >> (col & 7)) & 1;
}

// Parameter intervals [t0, t1] of the segment a -> b inside the axis-aligned box.
bool clip_box(const double* a, const double* b, const double* lo, const double* hi, double* t0, double* t1) {
  *t0 = 0;
  *t1 = 1;
  for (int k = 0; k < 3; ++k) {
    double d = b[k] - a[k];
    if (std::fabs(d) < 1e-12) {
      if (a[k] < lo[k] || a[k] > hi[k]) return false;
      continue;
    }
    double u0 = (lo[k] - a[k]) / d, u1 = (hi[k] - a[k]) / d;
    if (u0 > u1) std::swap(u0, u1);
    *t0 = std::max(*t0, u0);
    *t1 = std::min(*t1, u1);
  }
  return *t1 > *t0;
}

TEST(SbvisCheck, CorridorLinesOfSightAreInThePvsAndTheBendHides) {
  PortalFile prt;
  ASSERT_TRUE(tools::vis::parse_prt("corridor.prt", corridor_prt1(), &prt).is_ok());
  VisOptions opt;
  opt.quiet = true;
  std::vector<uint8_t> rows, phs;
  VisStats st;
  ASSERT_TRUE(tools::vis::compute_pvs(prt, opt, &rows, &st, &phs).is_ok());
  const size_t rb = (kNumCells + 7) / 8;
  EXPECT_FALSE(bit(rows, rb, 0, kNumCells - 1));
  EXPECT_FALSE(bit(rows, rb, kNumCells - 1, 0));
  EXPECT_TRUE(bit(rows, rb, 0, 3));
  // Brute force: random segments between points in the cells; a segment that stays inside
  // the corridor (the union of its pieces in the cells covers it) must find every cell it
  // crosses in the PVS of its first cell.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.5, kCell - 0.5);
  std::uniform_int_distribution<int> pick(0, kNumCells - 1);
  int clear = 0;
  for (int n = 0; n < 20000; ++n) {
    int ca = pick(rng), cb = pick(rng);
    double a[3] = {kCells[ca][0] * kCell + u(rng), kCells[ca][1] * kCell + u(rng), u(rng)};
    double b[3] = {kCells[cb][0] * kCell + u(rng), kCells[cb][1] * kCell + u(rng), u(rng)};
    std::vector<std::pair<double, double>> pieces;
    std::vector<int> crossed;
    for (int c = 0; c < kNumCells; ++c) {
      double lo[3] = {kCells[c][0] * kCell, kCells[c][1] * kCell, 0};
      double hi[3] = {lo[0] + kCell, lo[1] + kCell, kCell};
      double t0, t1;
      if (clip_box(a, b, lo, hi, &t0, &t1)) {
        pieces.push_back({t0, t1});
        crossed.push_back(c);
      }
    }
    std::sort(pieces.begin(), pieces.end());
    double reach = 0;
    for (auto& pc : pieces)
      if (pc.first <= reach + 1e-9) reach = std::max(reach, pc.second);
    if (reach < 1 - 1e-9) continue;  // leaves the corridor: blocked
    ++clear;
    for (int c : crossed) ASSERT_TRUE(bit(rows, rb, ca, c)) << "cell " << ca << " misses cell " << c;
  }
  EXPECT_GT(clear, 2000);
}

TEST(SbvisCheck, PhsIsTheUnionOfPvsRows) {
  PortalFile prt;
  ASSERT_TRUE(tools::vis::parse_prt("corridor.prt", corridor_prt1(), &prt).is_ok());
  VisOptions opt;
  opt.quiet = true;
  std::vector<uint8_t> rows, phs, phs2;
  VisStats st;
  ASSERT_TRUE(tools::vis::compute_pvs(prt, opt, &rows, &st, &phs).is_ok());
  const size_t rb = (kNumCells + 7) / 8;
  int64_t total = 0;
  for (int a = 0; a < kNumCells; ++a)
    for (int c = 0; c < kNumCells; ++c) {
      bool want = false;
      for (int b = 0; b < kNumCells; ++b) want = want || (bit(rows, rb, a, b) && bit(rows, rb, b, c));
      EXPECT_EQ(bit(phs, rb, a, c), want) << a << " " << c;
      total += want;
    }
  EXPECT_DOUBLE_EQ(st.mean_hearable, double(total) / kNumCells);
  // The far end is hearable from the start (through the bend) though not visible.
  EXPECT_TRUE(bit(phs, rb, 0, 6));
  EXPECT_EQ(tools::vis::compute_phs(rows, kNumCells, &phs2), total);
  EXPECT_EQ(phs2, phs);
}

TEST(SbvisCheck, Prt2ClustersExpandToLeaves) {
  PortalFile p1, p2;
  ASSERT_TRUE(tools::vis::parse_prt("c1.prt", corridor_prt1(), &p1).is_ok());
  ASSERT_TRUE(tools::vis::parse_prt("c2.prt", corridor_prt2(), &p2).is_ok());
  ASSERT_TRUE(p2.clustered());
  EXPECT_EQ(p2.num_leaves, 2 * kNumCells);
  EXPECT_EQ(p2.num_clusters, kNumCells);
  for (int l = 0; l < p2.num_leaves; ++l) EXPECT_EQ(p2.leaf_cluster[size_t(l)], l / 2);
  VisOptions opt;
  opt.quiet = true;
  std::vector<uint8_t> r1, r2;
  VisStats s1, s2;
  ASSERT_TRUE(tools::vis::compute_pvs(p1, opt, &r1, &s1).is_ok());
  ASSERT_TRUE(tools::vis::compute_pvs(p2, opt, &r2, &s2).is_ok());
  const size_t rb1 = (kNumCells + 7) / 8, rb2 = (2 * kNumCells + 7) / 8;
  ASSERT_EQ(r2.size(), size_t(2 * kNumCells) * rb2);
  for (int a = 0; a < 2 * kNumCells; ++a)
    for (int b = 0; b < 2 * kNumCells; ++b) EXPECT_EQ(bit(r2, rb2, a, b), bit(r1, rb1, a / 2, b / 2)) << a << " " << b;
  EXPECT_EQ(s2.clusters, kNumCells);
  EXPECT_DOUBLE_EQ(s2.mean_visible, 2 * s1.mean_visible);
  // Malformed cluster lists are errors.
  PortalFile bad;
  std::string text = corridor_prt2();
  std::string dup = text.substr(0, text.rfind("19 18 -1")) + "19 17 -1\n";  // leaf 17 twice, 18 in none
  EXPECT_FALSE(tools::vis::parse_prt("bad.prt", dup, &bad).is_ok());
  std::string cut = text.substr(0, text.rfind("19 18 -1"));  // the last cluster missing
  EXPECT_FALSE(tools::vis::parse_prt("bad.prt", cut, &bad).is_ok());
  EXPECT_FALSE(tools::vis::parse_prt("bad.prt", "PRT2\n4\n5\n0\n", &bad).is_ok());  // more clusters than leaves
}

// Leaves crossed by the segment a -> b in the BSP tree, with the length of each piece.
void trace(const tools::BspData& bsp, int node, const double* a, const double* b, double len,
           std::vector<std::pair<int, double>>* out) {
  if (node < 0) {
    out->push_back({-node - 1, len});
    return;
  }
  const tools::DNode& n = bsp.nodes[size_t(node)];
  const tools::DPlane& pl = bsp.planes[size_t(n.plane)];
  double da = pl.normal[0] * a[0] + pl.normal[1] * a[1] + pl.normal[2] * a[2] - pl.dist;
  double db = pl.normal[0] * b[0] + pl.normal[1] * b[1] + pl.normal[2] * b[2] - pl.dist;
  if (da >= 0 && db >= 0) return trace(bsp, n.children[0], a, b, len, out);
  if (da < 0 && db < 0) return trace(bsp, n.children[1], a, b, len, out);
  double t = da / (da - db);
  double m[3] = {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
  trace(bsp, n.children[da >= 0 ? 0 : 1], a, m, len * t, out);
  trace(bsp, n.children[da >= 0 ? 1 : 0], m, b, len * (1 - t), out);
}

// Param: PRT2 (start.map has func_detail: sbbsp writes clusters) or PRT1 (forced).
class SbvisStart : public ::testing::TestWithParam<bool> {};

TEST_P(SbvisStart, LinesOfSightAreInThePvsAndPicturesUnchanged) {
  SB_REQUIRE_QUAKE_DATA();
  const bool clusters = GetParam();
  std::string src = quake_dir() + "/lq1/maps/src/misc/start.map";
  std::string out = bsp_scratch_dir() + (clusters ? "/vis_check_start2.bsp" : "/vis_check_start1.bsp");
  std::string novis = out.substr(0, out.size() - 4) + "_novis.bsp";
  tools::bsp::BspOptions bo;
  bo.map_path = src;
  bo.bsp_path = out;
  bo.quiet = true;
  bo.prt1_only = !clusters;
  tools::bsp::CompileReport rep;
  Status cs = tools::bsp::compile_map(bo, &rep);
  ASSERT_TRUE(cs.is_ok()) << cs.message();
  ASSERT_FALSE(rep.leaked) << rep.leak_message;
  std::filesystem::copy_file(out, novis, std::filesystem::copy_options::overwrite_existing);
  VisOptions opt;
  opt.quiet = true;
  VisStats st;
  ASSERT_TRUE(tools::vis::run_vis(out, opt, &st).is_ok());
  PortalFile prt;
  ASSERT_TRUE(tools::vis::read_prt((out.substr(0, out.size() - 4) + ".prt").c_str(), &prt).is_ok());
  // start.map has detail brushes; when the compiler writes clusters they are fewer than leaves.
  if (clusters && prt.clustered()) {
    EXPECT_LT(prt.num_clusters, prt.num_leaves);
  }
  tools::BspData bsp;
  ASSERT_TRUE(tools::read_bsp(out.c_str(), &bsp).is_ok());
  // The portals as run_vis used them: sky is opaque (no portals into sky nodes), leaf boxes.
  EXPECT_GT(tools::vis::prepare_portals(&prt, bsp, opt), 0);
  std::vector<uint8_t> rows;
  VisStats st2;
  ASSERT_TRUE(tools::vis::compute_pvs(prt, opt, &rows, &st2).is_ok());
  EXPECT_EQ(st2.visible_total, st.visible_total);
  const int visleafs = bsp.models[0].visleafs;
  const size_t rb = (size_t(visleafs) + 7) / 8;
  const tools::DModel& m = bsp.models[0];
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ux(m.mins[0], m.maxs[0]), uy(m.mins[1], m.maxs[1]), uz(m.mins[2], m.maxs[2]);
  auto leaf_at = [&](const double* p) {
    std::vector<std::pair<int, double>> hit;
    trace(bsp, m.headnode[0], p, p, 0, &hit);
    return hit[0].first;
  };
  auto random_empty = [&](double* p) {
    for (;;) {
      p[0] = ux(rng);
      p[1] = uy(rng);
      p[2] = uz(rng);
      int l = leaf_at(p);
      if (l > 0 && l <= visleafs && bsp.leaves[size_t(l)].contents == -1) return l;
    }
  };
  int clear = 0, checked = 0;
  for (int n = 0; n < 20000; ++n) {
    double a[3], b[3];
    int la = random_empty(a);
    random_empty(b);
    double len = std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]));
    std::vector<std::pair<int, double>> hit;
    trace(bsp, m.headnode[0], a, b, len, &hit);
    bool open = true;
    for (auto& h : hit) open = open && h.first > 0 && bsp.leaves[size_t(h.first)].contents == -1;
    if (!open) continue;
    ++clear;
    for (auto& h : hit) {
      if (h.second < 0.5) continue;  // a graze shorter than half a unit: below the tools' epsilons
      ++checked;
      ASSERT_TRUE(bit(rows, rb, la - 1, h.first - 1)) << "leaf " << la << " misses leaf " << h.first << " on the line ("
                                                       << a[0] << " " << a[1] << " " << a[2] << ") - (" << b[0] << " "
                                                       << b[1] << " " << b[2] << ")";
    }
  }
  std::printf("[ sbvis ] start (%s, %d leaves, %d clusters): visible leaves per leaf %.1f, PHS %.1f, vis_faces %.1f; "
              "%d clear lines of sight of 20000, %d leaf crossings checked\n",
              prt.clustered() ? "PRT2" : "PRT1", prt.num_leaves, prt.num_clusters, st.mean_visible, st.mean_hearable,
              st.mean_faces, clear, checked);
  EXPECT_GT(clear, 500);
  // The PVS hides nothing that is drawn: the same pictures with and without it.
  LoadedBsp a(out), b(novis);
  ASSERT_NE(a.world(), nullptr) << a.error();
  ASSERT_NE(b.world(), nullptr) << b.error();
  std::vector<uint8_t> colormap = test_colormap();
  size_t diff = 0;
  std::vector<uint8_t> pa, pb, ca, cb;
  for (const ViewParams& v : test_viewpoints(*a.world(), 24)) {
    ASSERT_TRUE(a.render(v, 160, 100, colormap.data(), &pa, &ca).is_ok());
    ASSERT_TRUE(b.render(v, 160, 100, colormap.data(), &pb, &cb).is_ok());
    for (size_t i = 0; i < pa.size(); ++i) diff += pa[i] != pb[i];
  }
  EXPECT_EQ(diff, 0u) << "pixels that differ with the PVS";
}

INSTANTIATE_TEST_SUITE_P(Formats, SbvisStart, ::testing::Values(true, false),
                         [](const ::testing::TestParamInfo<bool>& i) { return i.param ? "Prt2" : "Prt1"; });

}  // namespace
}  // namespace sb::test
