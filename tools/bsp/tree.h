// tools/bsp/tree.h: the BSP tree of one model and hull: build from CSG faces, portals,
// leaf contents, flood fill from entities (outside removal, leaks), face visibility.
//
// Building: hint faces (csg.h) are used as splitters before anything else; then, at each
// node, the splitter is the face plane that splits the fewest faces;
// ties prefer axial planes, then the most even split of face counts. Sets of more than 256
// faces choose among axial planes only while any remain (cheaper, and it split less on the
// LibreQuake maps). Structural faces are
// used before detail faces, and while structural splitters are chosen detail faces are not
// counted (detail does not change the structural tree). A node whose splitter was chosen
// with no structural face left is a detail split; the maximal subtrees of detail splits are
// the vis clusters (build_cluster_portals). Faces on the splitter (either orientation) live on that node;
// the others go to the children, split by the node plane when they cross it. A region with
// no faces left is a leaf.
// Portals: the head node's box (the faces' bounds grown by 32 units) is bounded by six
// portals to the "outside" node; each node's plane is cut into a portal by the portals
// bounding that node, and those portals are split by the node's plane into its children.
// Leaf contents: a point inside the leaf (the mean of its portal vertices) is tested against
// the brushes; the highest-ranked brush holding it gives the contents (solid beats detail on a
// tie), empty otherwise; illusionary and hint brushes are ignored.
// Flood fills pass through detail leaves (detail never seals a map) but never through a portal
// thinner than kThinPortal (a crack that thin seals).
#pragma once
#include <string>
#include <vector>

#include "tools/bsp/csg.h"

namespace sb::tools::bsp {

struct TreeNode {
  int plane = -1;  // canonical (even) PlaneSet index; -1 for leaves
  int children[2] = {-1, -1};
  std::vector<int> faces;  // Tree::faces lying on this plane
  int contents = kContentsEmpty;  // leaves
  Bounds bounds;                   // leaves: of the portals; nodes: of the children
  std::vector<int> portals;        // leaves (and, while cutting, nodes)
  bool detail_split = false;       // nodes: splitter chosen among detail faces only
  bool reached = false;            // flood fill
  int flood_parent_portal = -1;    // leak path
  bool is_leaf() const { return plane < 0; }
};

struct Portal {
  Winding w;       // normal (winding_normal) == planes[plane].normal
  int plane = -1;  // oriented index
  int nodes[2] = {-1, -1};  // [0] in front of the plane, [1] behind
  bool alive = true;
};

struct TreeStats {
  int faces_in = 0, faces_after = 0, nodes = 0, leaves = 0, portals = 0, max_depth = 0;
  double split_percent() const { return faces_in ? 100.0 * (faces_after - faces_in) / faces_in : 0; }
};

struct Tree {
  std::vector<TreeNode> nodes;
  std::vector<Face> faces;
  std::vector<Portal> portals;
  int root = -1;
  int outside = -1;  // index of the outside pseudo-leaf in nodes
  Bounds box;
};

// `progress` (optional): build_tree advances by one per input face placed on a node (total:
// the number of faces); build_portals by one per node (total: tree.nodes.size()).
void build_tree(std::vector<Face> faces, const PlaneSet& planes, Tree* tree, TreeStats* stats,
                Progress* progress = nullptr);
// Builds portals between all leaves (and the outside pseudo-leaf).
void build_portals(Tree* tree, const PlaneSet& planes, TreeStats* stats, Progress* progress = nullptr);
// Vis clusters: the tree with every detail-split node taken as a leaf. `root_of[n]` is, for
// every node n at or below a cluster root, that root (-1 above); `roots` lists the roots in
// tree order (front first); `portals` are the portals of that structural tree, their nodes[]
// being cluster roots or tree.outside. Works on a pruned tree (prune_solid) too.
struct ClusterPortals {
  std::vector<int> root_of;
  std::vector<int> roots;
  std::vector<Portal> portals;
};
// A detail subtree with more than max_leaves PVS leaves whose PVS leaves span more than
// max_extent units on some axis is not one cluster: its top split is portalled like a
// structural node (its children are tested in turn). A cluster's leaves all share one PVS
// row, so a big cluster makes every leaf that sees part of it see all of it; smaller
// clusters give a tighter PVS for more vis work. max_leaves 0: every detail subtree is one
// cluster (the classic func_detail clusters; sbbsp's default, see BspOptions).
struct ClusterLimits {
  int max_leaves = 0;
  double max_extent = 512;
};
bool has_detail_splits(const Tree& tree);
void build_cluster_portals(const Tree& tree, const PlaneSet& planes, const ClusterLimits& limits, ClusterPortals* out);

// Leaf contents from the brushes (see the header comment).
void set_leaf_contents(Tree* tree, const std::vector<Brush>& brushes, const PlaneSet& planes);

// Whether the flood passes through a leaf of these contents.
inline bool passable(int contents) {
  return contents == kContentsEmpty || contents == kContentsWater || contents == kContentsSlime ||
         contents == kContentsLava;
}

// Leaf holding a point (points on a plane go to the front).
int point_leaf(const Tree& tree, const PlaneSet& planes, const Vec3& p);

struct LeakInfo {
  bool leaked = false;
  int entity = -1;                // index into the caller's list of origins
  std::vector<Vec3> path;         // entity origin .. a point outside
};

// Floods never cross a portal narrower than this (winding_min_width, units): a crack thinner
// than this between brushes (e.g. angled brushes whose vertices miss by a unit, leaving a
// wedge 0.18 units wide) seals like solid, and its leaves are filled with the outside.
constexpr double kThinPortal = 0.25;
// A point entity touches every leaf within this distance of its origin.
constexpr double kEntityTouchEpsilon = 0.01;

// The leaves a point entity touches (sorted): one, or several when its origin lies on node
// planes (an entity on a wall's outer face touches the wall and the outside).
void entity_leaves(const Tree& tree, const PlaneSet& planes, const Vec3& p, std::vector<int>* out);

// Marks leaves reachable from `origins` through open portals (kThinPortal) between passable
// leaves. An origin touching no passable leaf (inside solid) is ignored; one touching any leaf
// the outside does not reach (solid counts) is inside and seeds the flood from its passable
// unreached leaves; one whose every touched leaf the outside reaches is a leak, reported
// (path through portal centres) instead, and nothing is filled. Sky leaves next to a reached
// leaf are kept too, and so are slivers: unreached leaves all of whose floodable neighbours
// were reached (only thin portals kept the flood out). With fill_unreached, every other
// leaf becomes solid. Returns the number of leaves filled.
int flood_fill_entities(Tree* tree, const PlaneSet& planes, const std::vector<Vec3>& origins, bool fill_unreached,
                        LeakInfo* leak);
// Clip hulls: every leaf reachable from the outside (through open portals) becomes solid;
// returns false (and fills nothing) when the outside reaches one of the origins.
bool fill_from_outside(Tree* tree, const PlaneSet& planes, const std::vector<Vec3>& origins);

// For every node face: the non-solid leaves in front of it that it touches. Faces touching
// none (or with texinfo -1) get an empty list.
void face_front_leaves(const Tree& tree, const PlaneSet& planes, std::vector<std::vector<int>>* leaves_of_face);
// The non-solid leaves that polygon `w` (a piece of a face on some node) touches, walking
// down from `start`, the child of that node the face points into (sorted, unique).
void polygon_front_leaves(const Tree& tree, const PlaneSet& planes, int start, const Winding& w,
                          std::vector<int>* out);

// Collapses nodes whose children are both solid leaves and that keep no visible face
// (`face_visible[f]`). Returns the number of nodes removed.
int prune_solid(Tree* tree, const std::vector<bool>& face_visible);
// Clip hulls: collapses nodes whose children are leaves of equal output contents.
int prune_equal(Tree* tree);

}  // namespace sb::tools::bsp
