// tools/content/wad_writer.cpp: see wad_writer.h.
#include "tools/content/wad_writer.h"

#include <cstdio>
#include <cstring>

namespace sb::content {
namespace {

void put32(std::vector<uint8_t>& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
}
void put_name16(std::vector<uint8_t>& out, const std::string& name) {
  char buf[16] = {};
  std::memcpy(buf, name.data(), name.size() < 16 ? name.size() : 16);
  out.insert(out.end(), buf, buf + 16);
}
void set32(std::vector<uint8_t>& out, size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) out[at + size_t(i)] = uint8_t(v >> (8 * i));
}

}  // namespace

std::vector<uint8_t> encode_miptex(const Miptex& tex, std::string* error) {
  if (tex.name.empty() || tex.name.size() > 15) {
    *error = "miptex '" + tex.name + "': name must be 1..15 characters";
    return {};
  }
  if (tex.width < 16 || tex.height < 16 || tex.width > 4096 || tex.height > 4096 || tex.width % 16 || tex.height % 16) {
    *error = "miptex '" + tex.name + "': size " + std::to_string(tex.width) + "x" + std::to_string(tex.height) +
             " is not a multiple of 16 in 16..4096";
    return {};
  }
  std::vector<uint8_t> out;
  put_name16(out, tex.name);
  put32(out, uint32_t(tex.width));
  put32(out, uint32_t(tex.height));
  uint32_t offset = 40;
  for (int m = 0; m < 4; ++m) {
    put32(out, offset);
    offset += uint32_t((tex.width >> m) * (tex.height >> m));
  }
  for (int m = 0; m < 4; ++m) {
    size_t want = size_t(tex.width >> m) * size_t(tex.height >> m);
    if (tex.mips[size_t(m)].size() != want) {
      *error = "miptex '" + tex.name + "': mip " + std::to_string(m) + " has " +
               std::to_string(tex.mips[size_t(m)].size()) + " bytes, expected " + std::to_string(want);
      return {};
    }
    out.insert(out.end(), tex.mips[size_t(m)].begin(), tex.mips[size_t(m)].end());
  }
  return out;
}

std::vector<uint8_t> encode_wad(const std::vector<Miptex>& textures, std::string* error) {
  std::vector<uint8_t> out = {'W', 'A', 'D', '2'};
  put32(out, uint32_t(textures.size()));
  put32(out, 0);  // infotableofs, patched below
  struct Entry {
    uint32_t pos, size;
    std::string name;
  };
  std::vector<Entry> entries;
  for (const Miptex& t : textures) {
    std::vector<uint8_t> lump = encode_miptex(t, error);
    if (lump.empty()) return {};
    while (out.size() % 4) out.push_back(0);
    entries.push_back({uint32_t(out.size()), uint32_t(lump.size()), t.name});
    out.insert(out.end(), lump.begin(), lump.end());
  }
  while (out.size() % 4) out.push_back(0);
  set32(out, 8, uint32_t(out.size()));
  for (const Entry& e : entries) {
    put32(out, e.pos);
    put32(out, e.size);  // disksize
    put32(out, e.size);  // size (uncompressed)
    out.push_back(0x44); // 'D': miptex
    out.push_back(0);    // compression: none
    out.push_back(0);
    out.push_back(0);
    put_name16(out, e.name);
  }
  return out;
}

bool write_file(const std::string& path, const std::vector<uint8_t>& bytes, std::string* error) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) {
    *error = path + ": cannot open for writing";
    return false;
  }
  size_t n = bytes.empty() ? 0 : std::fwrite(bytes.data(), 1, bytes.size(), f);
  bool ok = std::fclose(f) == 0 && n == bytes.size();
  if (!ok) *error = path + ": write failed";
  return ok;
}

}  // namespace sb::content
