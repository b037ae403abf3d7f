// tools/bsp/textures.cpp: see textures.h.
#include "tools/bsp/textures.h"

#include <cmath>
#include <cstring>

#include "engine/formats/wad.h"
#include "memory/arena.h"

namespace sb::tools::bsp {

namespace {

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return r;
}

bool starts_with(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

std::string file_name(const std::string& path) {
  size_t s = path.find_last_of("/\\");
  return s == std::string::npos ? path : path.substr(s + 1);
}

bool file_exists(const std::string& p) {
  FILE* f = std::fopen(p.c_str(), "rb");
  if (!f) return false;
  std::fclose(f);
  return true;
}

}  // namespace

TexClass classify_texture(std::string_view name) {
  std::string n = lower(name);
  if (starts_with(n, "sky")) return TexClass::Sky;
  if (n == "clip" || n == "clipmonster" || n == "clipplayer") return TexClass::Clip;
  if (n == "skip" || n == "nodraw" || n == "*waterskip" || n == "*slimeskip" || n == "*lavaskip")
    return n[0] == '*' ? (n.find("lava") != std::string::npos ? TexClass::Lava
                          : n.find("slime") != std::string::npos ? TexClass::Slime : TexClass::Water)
                       : TexClass::Skip;
  if (n == "hint") return TexClass::Hint;
  if (n == "hintskip") return TexClass::HintSkip;
  if (n == "origin") return TexClass::Origin;
  if (n == "trigger") return TexClass::Trigger;
  if (!n.empty() && n[0] == '*') {
    if (n.find("lava") != std::string::npos) return TexClass::Lava;
    if (n.find("slime") != std::string::npos) return TexClass::Slime;
    return TexClass::Water;
  }
  return TexClass::Normal;
}

void face_texture_vecs(const MapFace& f, const Vec3& normal, double vecs[2][4]) {
  double sx = f.scale[0] == 0 ? 1.0 : f.scale[0];
  double sy = f.scale[1] == 0 ? 1.0 : f.scale[1];
  Vec3 axes[2];
  if (f.valve) {
    axes[0] = f.axis[0];
    axes[1] = f.axis[1];
  } else {
    // The six base projections of the standard format: face normal direction, s axis, t axis.
    static const double kBase[6][3][3] = {
        {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},   // floor
        {{0, 0, -1}, {1, 0, 0}, {0, -1, 0}},  // ceiling
        {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}},   // west wall
        {{-1, 0, 0}, {0, 1, 0}, {0, 0, -1}},  // east wall
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},   // south wall
        {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},  // north wall
    };
    int best = 0;
    double best_dot = -2;
    for (int i = 0; i < 6; ++i) {
      double d = normal.x * kBase[i][0][0] + normal.y * kBase[i][0][1] + normal.z * kBase[i][0][2];
      if (d > best_dot + 1e-9) {
        best_dot = d;
        best = i;
      }
    }
    for (int a = 0; a < 2; ++a) axes[a] = Vec3(kBase[best][a + 1][0], kBase[best][a + 1][1], kBase[best][a + 1][2]);
    // Rotation in the plane of the two axes' nonzero components.
    double rad = f.rotate * (3.14159265358979323846 / 180.0);
    double c = std::cos(rad), s = std::sin(rad);
    double r = std::fmod(f.rotate, 360.0);
    if (r < 0) r += 360.0;
    if (r == 0) { c = 1; s = 0; }
    else if (r == 90) { c = 0; s = 1; }
    else if (r == 180) { c = -1; s = 0; }
    else if (r == 270) { c = 0; s = -1; }
    int si = axes[0].x != 0 ? 0 : (axes[0].y != 0 ? 1 : 2);
    int ti = axes[1].x != 0 ? 0 : (axes[1].y != 0 ? 1 : 2);
    for (int a = 0; a < 2; ++a) {
      double u = axes[a][si], v = axes[a][ti];
      axes[a][si] = c * u - s * v;
      axes[a][ti] = s * u + c * v;
    }
  }
  for (int i = 0; i < 3; ++i) {
    vecs[0][i] = axes[0][i] / sx;
    vecs[1][i] = axes[1][i] / sy;
  }
  vecs[0][3] = f.shift[0];
  vecs[1][3] = f.shift[1];
}

struct TextureSet::WadFile {
  std::string path;
  std::vector<uint8_t> data;
  std::unique_ptr<uint8_t[]> dir_mem;
  mem::Arena arena;
  Wad wad;
};

TextureSet::TextureSet() = default;
TextureSet::~TextureSet() = default;

int TextureSet::wad_count() const { return int(wads_.size()); }

int TextureSet::load_wads(std::string_view wad_key, const std::string& map_dir,
                          const std::vector<std::string>& wad_opts, std::vector<std::string>* warnings) {
  std::vector<std::string> dirs, candidates_files;
  for (const std::string& w : wad_opts) {
    std::string text;
    FILE* f = std::fopen(w.c_str(), "rb");
    bool is_file = false;
    if (f) {
      char magic[4] = {};
      is_file = std::fread(magic, 1, 4, f) == 4 && std::memcmp(magic, "WAD2", 4) == 0;
      std::fclose(f);
    }
    if (is_file) candidates_files.push_back(w);
    else dirs.push_back(w);
  }
  auto load = [&](const std::string& path) -> bool {
    for (const auto& w : wads_)
      if (w->path == path) return true;
    auto wf = std::make_unique<WadFile>();
    std::string bytes;
    if (!read_file(path.c_str(), &bytes)) return false;
    wf->path = path;
    wf->data.resize(bytes.size());
    if (!bytes.empty()) std::memcpy(wf->data.data(), bytes.data(), bytes.size());
    uint32_t count = 0;
    if (wf->data.size() >= 12) std::memcpy(&count, wf->data.data() + 4, 4);
    size_t cap = size_t(std::min<uint32_t>(count, kMaxWadLumps)) * sizeof(WadLump) + 1024;
    wf->dir_mem.reset(new uint8_t[cap]);
    wf->arena.init("wad", wf->dir_mem.get(), cap);
    Result<Wad> r = parse_wad(wf->path.c_str(), wf->data.data(), wf->data.size(), wf->arena);
    if (!r) {
      warnings->push_back(std::string("bad WAD: ") + r.message());
      return true;  // found but unusable: do not try other locations
    }
    wf->wad = r.value();
    wads_.push_back(std::move(wf));
    return true;
  };
  size_t start = 0;
  std::string key(wad_key);
  while (start <= key.size()) {
    size_t end = key.find(';', start);
    if (end == std::string::npos) end = key.size();
    std::string entry = key.substr(start, end - start);
    start = end + 1;
    while (!entry.empty() && (entry.back() == ' ' || entry.back() == '\t')) entry.pop_back();
    while (!entry.empty() && (entry.front() == ' ' || entry.front() == '\t')) entry.erase(entry.begin());
    if (entry.empty()) continue;
    for (char& c : entry)
      if (c == '\\') c = '/';
    std::vector<std::string> tries;
    if (entry[0] == '/') tries.push_back(entry);
    if (!map_dir.empty()) tries.push_back(map_dir + "/" + entry);
    tries.push_back(entry);
    for (const std::string& d : dirs) tries.push_back(d + "/" + file_name(entry));
    bool found = false;
    for (const std::string& t : tries)
      if (file_exists(t) && load(t)) {
        found = true;
        break;
      }
    if (!found) warnings->push_back("WAD '" + entry + "' not found (tried the map's folder and -wad dirs)");
  }
  for (const std::string& f : candidates_files)
    if (!load(f)) warnings->push_back("WAD '" + f + "' cannot be read");
  return int(wads_.size());
}

int TextureSet::texture_index(const std::string& name) {
  std::string key = lower(name);
  auto it = name_index_.find(key);
  if (it != name_index_.end()) return it->second;
  int idx = int(names_.size());
  names_.push_back(name);
  name_index_[key] = idx;
  return idx;
}

int TextureSet::texinfo_index(const double vecs[2][4], const std::string& texture) {
  DTexInfo ti{};
  for (int a = 0; a < 2; ++a)
    for (int i = 0; i < 4; ++i) ti.vecs[a][i] = float(vecs[a][i]);
  ti.miptex = texture_index(texture);
  TexClass c = classify_texture(texture);
  bool special = c == TexClass::Sky || (!texture.empty() && texture[0] == '*');
  ti.flags = special ? 1 : 0;
  std::string key(reinterpret_cast<const char*>(&ti), sizeof ti);
  auto it = texinfo_index_.find(key);
  if (it != texinfo_index_.end()) return it->second;
  int idx = int(texinfo_.size());
  texinfo_.push_back(ti);
  texinfo_index_[key] = idx;
  return idx;
}

const uint8_t* TextureSet::find_lump(const std::string& name, size_t* size) const {
  for (const auto& w : wads_) {
    const WadLump* l = w->wad.find(name.c_str());
    if (!l || l->type != kWadMiptex) continue;
    MiptexView v;
    if (!decode_miptex(w->path.c_str(), name.c_str(), l->data, l->size, &v) || !v.has_pixels) continue;
    *size = kMiptexHeaderBytes + miptex_pixel_bytes(v.width, v.height);
    if (*size > l->size) continue;
    return l->data;
  }
  return nullptr;
}

void TextureSet::build_lump(std::vector<uint8_t>* lump, std::vector<std::string>* warnings) {
  // Frames of animated textures ("+0name".."+9name", "+aname".."+jname") come along.
  size_t used = names_.size();
  for (size_t i = 0; i < used; ++i) {
    std::string n = names_[i];
    if (n.size() < 2 || n[0] != '+') continue;
    for (const char* set : {"0123456789", "abcdefghij"})
      for (const char* c = set; *c; ++c) {
        std::string f = n;
        f[1] = *c;
        size_t sz;
        if (name_index_.count(lower(f)) == 0 && find_lump(f, &sz)) texture_index(f);
      }
  }
  std::vector<std::vector<uint8_t>> blobs(names_.size());
  missing_ = 0;
  for (size_t i = 0; i < names_.size(); ++i) {
    size_t sz = 0;
    const uint8_t* d = find_lump(names_[i], &sz);
    std::vector<uint8_t>& b = blobs[i];
    if (d) {
      b.assign(d, d + sz);
      continue;
    }
    ++missing_;
    warnings->push_back("texture '" + names_[i] + "' not found in any WAD: using a placeholder");
    // 16x16 checker of 4x4 cells, four mips.
    b.assign(kMiptexHeaderBytes + miptex_pixel_bytes(16, 16), 0);
    std::strncpy(reinterpret_cast<char*>(b.data()), names_[i].c_str(), 15);
    uint32_t hdr[6] = {16, 16, 0, 0, 0, 0};
    uint32_t off = uint32_t(kMiptexHeaderBytes);
    for (int m = 0; m < 4; ++m) {
      hdr[2 + m] = off;
      uint32_t s = 16u >> m;
      uint32_t cell = std::max(1u, 4u >> m);
      for (uint32_t y = 0; y < s; ++y)
        for (uint32_t x = 0; x < s; ++x) b[off + y * s + x] = ((x / cell + y / cell) & 1) ? 15 : 0;
      off += s * s;
    }
    std::memcpy(b.data() + 16, hdr, sizeof hdr);
  }
  lump->clear();
  uint32_t count = uint32_t(names_.size());
  size_t header = 4 + 4 * size_t(count);
  lump->resize(header);
  std::memcpy(lump->data(), &count, 4);
  for (uint32_t i = 0; i < count; ++i) {
    while (lump->size() % 4) lump->push_back(0);
    int32_t off = int32_t(lump->size());
    std::memcpy(lump->data() + 4 + 4 * i, &off, 4);
    lump->insert(lump->end(), blobs[i].begin(), blobs[i].end());
  }
}

}  // namespace sb::tools::bsp
