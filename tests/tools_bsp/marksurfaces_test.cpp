// tests/tools_bsp/marksurfaces_test.cpp: a leaf's marksurfaces list the face pieces that touch
// it, no more and no fewer. A face cut into pieces (lightmap subdivision, T-junction splits)
// used to be marked, every piece, in every leaf the whole face touched: the PVS's face count
// (vis_faces) grew with it though no more was visible.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "tests/support/quake_data.h"
#include "tests/tools_bsp/bsp_test_util.h"
#include "tools/common/bsp_data.h"

namespace sb::test {
namespace {

int leaf_at(const tools::BspData& bsp, int node, const double* p) {
  while (node >= 0) {
    const tools::DNode& n = bsp.nodes[size_t(node)];
    const tools::DPlane& pl = bsp.planes[size_t(n.plane)];
    double d = pl.normal[0] * p[0] + pl.normal[1] * p[1] + pl.normal[2] * p[2] - pl.dist;
    node = n.children[d >= 0 ? 0 : 1];
  }
  return -node - 1;
}

TEST(SbbspMarksurfaces, FacePiecesMarkOnlyTheLeavesTheyTouch) {
  SB_REQUIRE_QUAKE_DATA();
  std::string out = bsp_scratch_dir() + "/marksurfaces_start.bsp";
  CompileRun r = compile_file(quake_dir() + "/lq1/maps/src/misc/start.map", out);
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  tools::BspData bsp;
  ASSERT_TRUE(tools::read_bsp(out.c_str(), &bsp).is_ok());
  const tools::DModel& m = bsp.models[0];
  const int visleafs = m.visleafs;
  // Faces of the world model, their polygons and the leaves marking them.
  std::vector<std::vector<int>> marked_in(bsp.faces.size());
  for (int l = 1; l <= visleafs; ++l) {
    const tools::DLeaf& leaf = bsp.leaves[size_t(l)];
    for (uint32_t k = 0; k < leaf.num_marksurfaces; ++k)
      marked_in[bsp.marksurfaces[leaf.first_marksurface + k]].push_back(l);
  }
  int missing = 0, far = 0, marks = 0;
  for (int f = m.first_face; f < m.first_face + m.num_faces; ++f) {
    const tools::DFace& d = bsp.faces[size_t(f)];
    std::vector<std::array<double, 3>> pts;
    double lo[3] = {1e30, 1e30, 1e30}, hi[3] = {-1e30, -1e30, -1e30};
    for (int32_t k = 0; k < d.num_edges; ++k) {
      int32_t se = bsp.surfedges[size_t(d.first_edge + k)];
      const tools::DEdge& e = bsp.edges[size_t(std::abs(se))];
      uint32_t v = se < 0 ? e.v[1] : e.v[0];
      std::array<double, 3> p{bsp.vertices[3 * v], bsp.vertices[3 * v + 1], bsp.vertices[3 * v + 2]};
      for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
      pts.push_back(p);
    }
    const tools::DPlane& pl = bsp.planes[size_t(d.plane)];
    double sgn = d.side ? -1.0 : 1.0;
    std::array<double, 3> c{0, 0, 0};
    for (auto& p : pts)
      for (int i = 0; i < 3; ++i) c[i] += p[i] / double(pts.size());
    // Coverage: just in front of points inside the polygon, the leaf there (when it is a
    // world leaf with a PVS row, not solid) marks the face.
    std::vector<std::array<double, 3>> samples{c};
    for (auto& p : pts) samples.push_back({0.7 * c[0] + 0.3 * p[0], 0.7 * c[1] + 0.3 * p[1], 0.7 * c[2] + 0.3 * p[2]});
    for (auto& s : samples) {
      double q[3];
      for (int i = 0; i < 3; ++i) q[i] = s[i] + sgn * 0.05 * pl.normal[i];
      int l = leaf_at(bsp, m.headnode[0], q);
      if (l < 1 || l > visleafs || bsp.leaves[size_t(l)].contents == -2) continue;
      const auto& in = marked_in[size_t(f)];
      if (std::find(in.begin(), in.end(), l) == in.end()) ++missing;
    }
    // Tightness: every leaf marking the face overlaps the face's box (within a unit).
    for (int l : marked_in[size_t(f)]) {
      ++marks;
      const tools::DLeaf& leaf = bsp.leaves[size_t(l)];
      bool overlap = true;
      for (int i = 0; i < 3; ++i) overlap = overlap && lo[i] <= leaf.maxs[i] + 1 && hi[i] >= leaf.mins[i] - 1;
      far += !overlap;
    }
  }
  EXPECT_EQ(missing, 0) << "face points whose leaf does not mark the face";
  EXPECT_EQ(far, 0) << "marks of faces in leaves they do not touch, of " << marks;
  std::printf("[ sbbsp ] start: %d marksurfaces in world leaves (ericw-tools: 1076)\n", marks);
}

}  // namespace
}  // namespace sb::test
