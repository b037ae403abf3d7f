// tools/bsp/textures.h: textures for sbbsp: WAD2 search, texture projection (texinfo) and
// the miptex lump.
//
// WADs: the worldspawn "wad" key lists paths separated by ';' (relative to the map's folder;
// absolute paths also work); each is tried as given, relative to the map's folder, and by its
// file name alone in every -wad directory. A -wad argument naming a file loads that file too.
// Missing WADs are warnings. Lookups are case-insensitive; the first WAD holding a name wins.
//
// Texture projection (texinfo vecs: s = dot(p, vecs[0].xyz) + vecs[0].w, likewise t):
//   standard format: the base axis pair of the face normal (floor/ceiling, the two wall
//     directions), rotated by `rotate` degrees, divided by the scales, offsets = shifts.
//   Valve 220: the explicit axes divided by the scales, offsets = shifts.
// A texture not found in any WAD becomes a 16x16 checker miptex with that name (one warning
// per name). Only textures used by faces (and the frames of their animations) enter the lump.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "tools/bsp/geom.h"
#include "tools/bsp/map_file.h"
#include "tools/common/bsp_data.h"

namespace sb::tools::bsp {

// Hint: faces of hint brushes that become splitters; HintSkip: "hintskip", the other faces of a
// hint brush (ignored).
enum class TexClass { Normal, Sky, Water, Slime, Lava, Clip, Skip, Hint, HintSkip, Origin, Trigger };
// What a texture name means to the compiler (case-insensitive).
TexClass classify_texture(std::string_view name);

// Texture vectors of a .map face (see the header comment); `normal` is the face's outward
// normal. Zero scales count as 1.
void face_texture_vecs(const MapFace& f, const Vec3& normal, double vecs[2][4]);

class TextureSet {
 public:
  TextureSet();
  ~TextureSet();
  // Loads the WADs named by the worldspawn "wad" value and the -wad options. Returns the
  // number of WADs loaded; warnings go to `warnings`.
  int load_wads(std::string_view wad_key, const std::string& map_dir, const std::vector<std::string>& wad_opts,
                std::vector<std::string>* warnings);

  // Index into the final miptex list (added on first use).
  int texture_index(const std::string& name);
  // Deduplicated texinfo index for these vectors and texture.
  int texinfo_index(const double vecs[2][4], const std::string& texture);

  const std::vector<DTexInfo>& texinfo() const { return texinfo_; }
  const std::vector<std::string>& names() const { return names_; }
  // Builds the miptex lump; names missing from every WAD get a placeholder and a warning.
  void build_lump(std::vector<uint8_t>* lump, std::vector<std::string>* warnings);
  int missing_count() const { return missing_; }
  int wad_count() const;

 private:
  struct WadFile;
  const uint8_t* find_lump(const std::string& name, size_t* size) const;
  std::vector<std::unique_ptr<WadFile>> wads_;
  std::vector<std::string> names_;
  std::map<std::string, int> name_index_;  // lower-case name -> index
  std::vector<DTexInfo> texinfo_;
  std::map<std::string, int> texinfo_index_;  // raw bytes -> index
  int missing_ = 0;
};

}  // namespace sb::tools::bsp
