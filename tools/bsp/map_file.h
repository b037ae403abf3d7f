// tools/bsp/map_file.h: .map source files (id's standard format and Valve 220).
//
//   { "key" "value" ... { ( x y z ) ( x y z ) ( x y z ) TEX <texture axes> } ... } ...
//   standard: TEX xoffset yoffset rotation xscale yscale
//   Valve 220: TEX [ ux uy uz uoffset ] [ vx vy vz voffset ] rotation xscale yscale
// Extra numbers after a face on the same line (Quake 2 flags) are ignored; texture names
// longer than 15 characters are cut (a warning). "//" comments run
// to the end of the line. Values may be of any length; they are kept byte for byte.
// A syntax error is an Error naming "file:line". Geometry is not validated here (brushes.h
// turns bad planes into warnings).
#pragma once
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "engine/core/error.h"
#include "tools/bsp/geom.h"

namespace sb::tools::bsp {

struct MapFace {
  Vec3 points[3];
  std::string texture;
  bool valve = false;
  // Standard format:
  double shift[2] = {0, 0};
  double rotate = 0;
  double scale[2] = {1, 1};
  // Valve 220 (shift[] holds the offsets, scale[] the scales, axis[] the U/V axes):
  Vec3 axis[2];
  int line = 0;
};

struct MapBrush {
  std::vector<MapFace> faces;
  int line = 0;  // of the opening '{'
};

struct MapEntity {
  std::vector<std::pair<std::string, std::string>> pairs;  // in file order
  std::vector<MapBrush> brushes;
  int line = 0;
  // Value of the first pair with this key, or nullptr.
  const std::string* find(std::string_view key) const;
  std::string_view get(std::string_view key) const {
    const std::string* v = find(key);
    return v ? std::string_view(*v) : std::string_view();
  }
  void set(std::string_view key, std::string_view value);
  std::string_view classname() const { return get("classname"); }
};

struct MapFile {
  std::string path;  // as given (for messages)
  std::vector<MapEntity> entities;
  int valve_faces = 0, standard_faces = 0;
  std::vector<std::string> warnings;  // "file:line: ..." (texture names cut to 15 characters)
};

Status parse_map(const char* name, std::string_view text, MapFile* out);
Status read_map(const char* path, MapFile* out);

// Whole file into `out`; false when it cannot be read.
bool read_file(const char* path, std::string* out);

}  // namespace sb::tools::bsp
