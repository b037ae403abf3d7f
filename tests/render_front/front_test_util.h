// tests/render_front/front_test_util.h: tools for testing the renderer's front end
// (setup_view + build_spans) without the back end.
//
//   HandWorld     a BspWorld built in memory (box rooms, a room with a pillar)
//   FrontRunner   runs setup_view + build_spans in its own frame arena and turns the spans
//                 into a per-pixel face map plus a coverage count, checking the FrameSpans
//                 contract (bounds, grouping) as it goes
//   RayCaster     brute-force reference: for every pixel centre, the nearest front-facing
//                 model-0 face hit by the ray (independent of the BSP, PVS and edge list)
//   compare()     agreement between the two, with mismatches classified as "near an edge"
//                 when the reference itself changes within one pixel
//
// Test code: heap and std containers are fine here.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/formats/bsp.h"
#include "engine/render/render_local.h"
#include "memory/arena.h"

namespace sb::test::front {

constexpr uint32_t kNoFace = render::kBackgroundFace;

// ---- hand-built worlds ---------------------------------------------------------------

struct HandWorld {
  std::vector<Plane> planes;
  std::vector<glm::vec3> vertices;
  std::vector<Edge> edges;
  std::vector<int32_t> surfedges;
  std::vector<TexInfo> texinfo;
  std::vector<Texture> textures;
  std::vector<Face> faces;
  std::vector<uint32_t> marksurfaces;
  std::vector<Node> nodes;
  std::vector<Leaf> leaves;
  std::vector<SubModel> models;
  std::vector<uint8_t> visdata;
  BspWorld world{};

  HandWorld();  // leaf 0 (solid) exists from the start
  uint32_t add_plane(const glm::vec3& normal, float dist);
  // A face on `plane` whose front is the plane's back when `back`; vertices in order.
  uint32_t add_face(uint32_t plane, bool back, const std::vector<glm::vec3>& verts);
  // Returns the child code -(leaf + 1).
  int32_t add_leaf(int32_t contents, const glm::vec3& mins, const glm::vec3& maxs,
                   const std::vector<uint32_t>& marks, int32_t vis_offset = -1);
  // Returns the node index (a child code >= 0).
  int32_t add_node(uint32_t plane, int32_t front, int32_t back, const std::vector<uint32_t>& faces);
  // Sets parents and node boxes (union of non-solid leaf boxes and face vertices below),
  // model 0, and the BspWorld pointers.
  void finish(int32_t head, uint32_t visleafs);
  HandWorld(const HandWorld&) = delete;
  HandWorld& operator=(const HandWorld&) = delete;
};

// An empty box [mins, maxs] with its six walls facing inwards; one empty leaf (1).
// With `with_vis`, leaf 1 has a PVS row (seeing itself) in visdata.
std::unique_ptr<HandWorld> make_box_room(const glm::vec3& mins, const glm::vec3& maxs, bool with_vis);

// Room [-256,256] x [-128,128] x [-64,64] with a full-height pillar [32,64] x [-16,16];
// four empty leaves around the pillar; the pillar is solid (leaf 0).
std::unique_ptr<HandWorld> make_pillar_room();

// ---- running the front end -----------------------------------------------------------

struct FrontFrame {
  int width = 0, height = 0;
  std::vector<uint32_t> face_at;   // per pixel: face index or kNoFace
  std::vector<uint8_t> coverage;   // per pixel: spans covering it (should be 1)
  render::ViewState view{};
  RenderStats stats{};
  uint32_t num_spans = 0, num_surfaces = 0;
  double build_ms = 0;             // build_spans wall time
  std::string contract_error;      // empty when FrameSpans kept its contract
  std::string status;              // "ok" or build_spans' error
  bool ok() const { return status == "ok"; }
  // Pixels with coverage != 1.
  size_t bad_coverage() const;
};

class FrontRunner {
 public:
  explicit FrontRunner(size_t frame_bytes = 8u << 20);
  // setup_view + build_spans with frame number next_frame_++ (stamps must grow).
  FrontFrame run(BspWorld& world, const ViewParams& params, int width, int height);
  mem::Arena& arena() { return arena_; }
  uint32_t next_frame() const { return next_frame_; }

 private:
  std::unique_ptr<uint8_t[]> block_;
  mem::Arena arena_;
  uint32_t next_frame_ = 1;
};

// ---- reference -----------------------------------------------------------------------

class RayCaster {
 public:
  explicit RayCaster(const BspWorld& world);
  // Face seen through every pixel centre of a (width + 2) x (height + 2) grid that also
  // samples one pixel beyond each screen border: entry (y + 1) * (width + 2) + (x + 1)
  // is pixel (x, y), for x in [-1, width], y in [-1, height].
  std::vector<uint32_t> cast(const render::ViewState& view) const;

 private:
  struct RefFace {
    uint32_t index;
    glm::dvec3 normal;  // towards the face's front
    double dist;
    std::vector<glm::dvec3> verts;
    int axis_u, axis_v;            // the plane's two least-steep world axes
    std::vector<double> us, vs;    // vertices projected on them, for a crossing-number test
  };
  std::vector<RefFace> faces_;
};

struct Agreement {
  size_t pixels = 0, agree = 0;
  size_t near_edge = 0;      // mismatches where the reference changes within one pixel
  size_t far_from_edge = 0;  // other mismatches (should be 0)
  size_t reference_empty = 0;  // pixels the reference saw no face through
  double ratio() const { return pixels ? double(agree) / double(pixels) : 1.0; }
  void add(const Agreement& o);
  std::string describe() const;
  // First few far-from-edge mismatches, for failure messages.
  std::string examples;
};

Agreement compare(const FrontFrame& frame, const std::vector<uint32_t>& reference);

}  // namespace sb::test::front
