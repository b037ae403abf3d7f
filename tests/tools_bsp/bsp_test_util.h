// tests/tools_bsp/bsp_test_util.h: helpers for sbbsp tests: hand-made .map text, a tiny WAD
// writer, compiling into a scratch folder, loading the result the engine's way and checking
// that render_world draws it and agrees with the reference renderer.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "engine/formats/bsp.h"
#include "engine/render/render.h"
#include "memory/memory_system.h"
#include "tools/bsp/compile.h"

namespace sb::test {

// A folder under the build tree for this test's files (created, emptied of nothing).
std::string bsp_scratch_dir();
bool write_text_file(const std::string& path, const std::string& text);

// Standard-format axis-aligned box brush: "{ six faces }" with the given texture.
std::string box_brush(double x0, double y0, double z0, double x1, double y1, double z1, const std::string& tex,
                      const std::string& tex_params = "0 0 0 1 1");
// A closed room: six 16-unit walls around the inner box (inner box from mins to maxs).
std::string room_brushes(double x0, double y0, double z0, double x1, double y1, double z1, const std::string& tex,
                         bool open_east_wall = false);
std::string entity(const std::string& keys, const std::string& brushes = "");

// WAD2 with 16x16 (or given size) textures filled with a pattern derived from the name.
std::vector<uint8_t> make_wad(const std::vector<std::string>& names, uint32_t size = 32);

struct CompileRun {
  Status status;
  tools::bsp::CompileReport report;
  std::string bsp_path, map_path;
};
// Writes <scratch>/<name>.map and compiles it to <scratch>/<name>.bsp.
CompileRun compile_text(const std::string& name, const std::string& map_text,
                        const std::vector<std::string>& wads = {});
// The same with `base` options (map, bsp and wads are filled in; quiet is set).
CompileRun compile_text(const std::string& name, const std::string& map_text, const std::vector<std::string>& wads,
                        const tools::bsp::BspOptions& base);
// Compiles a map file with default options except prt1_only: the .prt stays PRT1 (leaf
// portals) even for maps with func_detail, for PRT1-only readers (sbvis tests use this).
CompileRun compile_file(const std::string& map_path, const std::string& bsp_path);

// A compiled BSP loaded with sb::load_bsp into its own memory block.
class LoadedBsp {
 public:
  explicit LoadedBsp(const std::string& path, size_t block_mib = 64);
  BspWorld* world() const { return world_; }
  const std::string& error() const { return error_; }
  Status render(const ViewParams& view, int w, int h, const uint8_t* colormap, std::vector<uint8_t>* pixels,
                std::vector<uint8_t>* coverage);

 private:
  std::unique_ptr<uint8_t[]> block_;
  mem::MemorySystem memory_;
  std::vector<uint8_t> file_;
  BspWorld* world_ = nullptr;
  std::string error_;
};

// The real colormap when the Quake data is there, else an identity ramp.
std::vector<uint8_t> test_colormap();

struct RenderCheck {
  int views = 0;
  double agreement = 0;  // over all views
  double interpolation_agreement = 0;  // identical or the 16-pixel-interpolated texel (render_compare.h)
  double unexplained = 0;  // fraction of pixels differing for no known reason (render_compare.h)
  std::string summary;
  uint64_t coverage_errors = 0;
  std::string error;     // first render failure
  std::vector<uint32_t> faces_drawn;  // faces render_world's reference saw at least once
};
// Renders `count` viewpoints with render_world and the reference renderer.
RenderCheck check_render(LoadedBsp& bsp, int count, int width = 160, int height = 100);

}  // namespace sb::test
