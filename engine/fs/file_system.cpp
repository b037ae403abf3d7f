// engine/fs/file_system.cpp: search path, PAK directories, file reading (<cstdio>).
//
// Sections: 1. PAK parsing (pure, memory in / values out)  2. FileSystem
// Directory tests and listing use std::filesystem (standard C++, no OS header)
// through its error_code overloads; they run at load time only.
#include "engine/fs/file_system.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "engine/core/log.h"
#include "engine/fs/padded_push.h"

namespace sb::fs {
namespace {

int32_t read_i32(const uint8_t* p) {
  int32_t v;
  std::memcpy(&v, p, 4);
  return v;
}

bool ends_with(const char* s, const char* suffix) {
  size_t n = std::strlen(s), m = std::strlen(suffix);
  return n >= m && std::memcmp(s + n - m, suffix, m) == 0;
}
bool starts_with(const char* s, const char* prefix) { return std::strncmp(s, prefix, std::strlen(prefix)) == 0; }

// Joins dir + "/" + name into out; false when it does not fit.
bool join_path(char* out, size_t out_size, const char* dir, const char* name) {
  int n = std::snprintf(out, out_size, "%s/%s", dir, name);
  return n >= 0 && size_t(n) < out_size;
}

// Size of an open file, or -1.
long file_size_of(std::FILE* f) {
  if (std::fseek(f, 0, SEEK_END) != 0) return -1;
  long size = std::ftell(f);
  if (std::fseek(f, 0, SEEK_SET) != 0) return -1;
  return size;
}

bool is_directory(const char* path) {
  std::error_code ec;
  return std::filesystem::is_directory(path, ec);
}

}  // namespace

// ---------------------------------------------------------------- 1. PAK parsing

Status parse_pak_header(const char* pak_name, const uint8_t* header, size_t header_size, uint64_t file_size,
                        uint32_t* dir_offset, uint32_t* dir_count) {
  if (header_size < size_t(kPakHeaderBytes))
    return make_error("%s: file is %zu bytes, too short for a PAK header (12)", pak_name, header_size);
  if (std::memcmp(header, "PACK", 4) != 0)
    return make_error("%s: header field 'ident' is not \"PACK\"", pak_name);
  int32_t dirofs = read_i32(header + 4), dirlen = read_i32(header + 8);
  if (dirofs < kPakHeaderBytes || uint64_t(dirofs) > file_size)
    return make_error("%s: header field 'dirofs' = %d outside the file (12..%llu)", pak_name, dirofs,
                      (unsigned long long)file_size);
  if (dirlen < 0 || uint64_t(dirofs) + uint64_t(dirlen) > file_size)
    return make_error("%s: header field 'dirlen' = %d runs past the end of the file (dirofs %d, size %llu)",
                      pak_name, dirlen, dirofs, (unsigned long long)file_size);
  if (dirlen % kPakEntryBytes != 0)
    return make_error("%s: header field 'dirlen' = %d is not a multiple of %d", pak_name, dirlen, kPakEntryBytes);
  uint32_t count = uint32_t(dirlen) / kPakEntryBytes;
  if (count > kMaxPakEntries)
    return make_error("%s: header field 'dirlen' = %d gives %u entries (max %u)", pak_name, dirlen, count,
                      kMaxPakEntries);
  *dir_offset = uint32_t(dirofs);
  *dir_count = count;
  return Status::ok();
}

Status parse_pak_entry(const char* pak_name, uint32_t index, const uint8_t* raw, uint64_t file_size, PakEntry* out) {
  const void* nul = std::memchr(raw, 0, kPakNameBytes);
  if (!nul) return make_error("%s: entry %u field 'name' is not NUL-terminated within 56 bytes", pak_name, index);
  std::memset(out->name, 0, sizeof out->name);
  std::memcpy(out->name, raw, size_t(static_cast<const uint8_t*>(nul) - raw));
  if (out->name[0] == 0) return make_error("%s: entry %u field 'name' is empty", pak_name, index);
  int32_t filepos = read_i32(raw + 56), filelen = read_i32(raw + 60);
  if (filepos < 0 || uint64_t(filepos) > file_size)
    return make_error("%s: entry %u ('%s') field 'filepos' = %d outside the file (size %llu)", pak_name, index,
                      out->name, filepos, (unsigned long long)file_size);
  if (filelen < 0 || uint64_t(filepos) + uint64_t(filelen) > file_size)
    return make_error("%s: entry %u ('%s') field 'filelen' = %d runs past the end of the file (filepos %d, size %llu)",
                      pak_name, index, out->name, filelen, filepos, (unsigned long long)file_size);
  out->offset = uint32_t(filepos);
  out->size = uint32_t(filelen);
  return Status::ok();
}

Result<PakDirectory> parse_pak(const char* pak_name, const uint8_t* data, size_t size, mem::Arena& into) {
  uint32_t dir_offset = 0, dir_count = 0;
  SB_TRY(parse_pak_header(pak_name, data, size, size, &dir_offset, &dir_count));
  PakDirectory dir;
  dir.entries = mem_util::push_array_padded<PakEntry>(into, dir_count ? dir_count : 1, "pak directory");
  if (!dir.entries) {
    Error e = make_error("%s: ", pak_name);
    into.failure_message(e.message + std::strlen(e.message), sizeof e.message - std::strlen(e.message));
    return e;
  }
  for (uint32_t i = 0; i < dir_count; ++i)
    SB_TRY(parse_pak_entry(pak_name, i, data + dir_offset + size_t(i) * kPakEntryBytes, size, &dir.entries[i]));
  dir.count = dir_count;
  return dir;
}

// ---------------------------------------------------------------- 2. FileSystem

Status FileSystem::add_pak(const char* pak_path, mem::Arena& permanent, bool* found) {
  *found = false;
  std::FILE* f = std::fopen(pak_path, "rb");
  if (!f) return Status::ok();  // absent: not an error
  *found = true;
  if (count_ >= kMaxEntries) {
    std::fclose(f);
    return make_error("%s: search path is full (%d entries)", pak_path, kMaxEntries);
  }
  long size = file_size_of(f);
  uint8_t header[kPakHeaderBytes];
  size_t got = size >= 0 ? std::fread(header, 1, sizeof header, f) : 0;
  uint32_t dir_offset = 0, dir_count = 0;
  Status st = size < 0 ? Status(make_error("%s: cannot determine the file size", pak_path))
                       : parse_pak_header(pak_path, header, got, uint64_t(size), &dir_offset, &dir_count);
  if (!st) {
    std::fclose(f);
    return st;
  }
  size_t mark = mem_util::align_mark(permanent);
  Entry& e = entries_[count_];
  e.is_pak = true;
  std::snprintf(e.path, sizeof e.path, "%s", pak_path);
  e.pak.count = 0;
  e.pak.entries = mem_util::push_array_padded<PakEntry>(permanent, dir_count ? dir_count : 1, "pak directory");
  if (!e.pak.entries) {
    std::fclose(f);
    Error err = make_error("%s: ", pak_path);
    permanent.failure_message(err.message + std::strlen(err.message), sizeof err.message - std::strlen(err.message));
    return err;
  }
  if (std::fseek(f, long(dir_offset), SEEK_SET) != 0) st = make_error("%s: cannot seek to the directory", pak_path);
  for (uint32_t i = 0; st && i < dir_count; ++i) {
    uint8_t raw[kPakEntryBytes];
    if (std::fread(raw, 1, sizeof raw, f) != sizeof raw)
      st = make_error("%s: entry %u: read failed", pak_path, i);
    else
      st = parse_pak_entry(pak_path, i, raw, uint64_t(size), &e.pak.entries[i]);
  }
  std::fclose(f);
  if (!st) {
    permanent.pop_to(mark);
    return st;
  }
  e.pak.count = dir_count;
  ++count_;
  log_info("added %s (%u files)", pak_path, dir_count);
  return Status::ok();
}

Status FileSystem::add_game_dir(const char* path, mem::Arena& permanent) {
  if (!is_directory(path)) return make_error("%s: game directory not found", path);
  if (std::strlen(path) + 12 >= size_t(kMaxPathBytes))
    return make_error("%s: path too long (max %d bytes)", path, kMaxPathBytes - 12);
  if (count_ >= kMaxEntries) return make_error("%s: search path is full (%d entries)", path, kMaxEntries);
  int saved_count = count_;
  size_t saved_mark = mem_util::align_mark(permanent);
  Entry& dir = entries_[count_++];
  dir.is_pak = false;
  dir.pak = PakDirectory{};
  std::snprintf(dir.path, sizeof dir.path, "%s", path);
  for (int i = 0; i <= 9; ++i) {
    char pak_path[kMaxPathBytes];
    std::snprintf(pak_path, sizeof pak_path, "%s/pak%d.pak", path, i);
    bool found = false;
    Status st = add_pak(pak_path, permanent, &found);
    if (!st) {
      count_ = saved_count;
      permanent.pop_to(saved_mark);
      return st;
    }
  }
  return Status::ok();
}

Status FileSystem::init_from_args(int argc, const char* const* argv, const char* base_game, mem::Arena& permanent) {
  const char* basedir = ".";
  const char* mod = nullptr;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "-basedir") == 0) basedir = argv[i + 1];
    if (std::strcmp(argv[i], "-game") == 0) mod = argv[i + 1];
  }
  char path[kMaxPathBytes];
  if (!join_path(path, sizeof path, basedir, base_game)) return make_error("%s/%s: path too long", basedir, base_game);
  SB_TRY(add_game_dir(path, permanent));
  if (mod && std::strcmp(mod, base_game) != 0) {
    if (!join_path(path, sizeof path, basedir, mod)) return make_error("%s/%s: path too long", basedir, mod);
    SB_TRY(add_game_dir(path, permanent));
  }
  return Status::ok();
}

const PakEntry* FileSystem::find_in_pak(const Entry& e, const char* name) const {
  for (uint32_t i = 0; i < e.pak.count; ++i)
    if (std::strcmp(e.pak.entries[i].name, name) == 0) return &e.pak.entries[i];
  return nullptr;
}

bool FileSystem::locate(const char* name, char* where, size_t where_size) const {
  for (int i = count_ - 1; i >= 0; --i) {
    const Entry& e = entries_[i];
    if (e.is_pak) {
      if (find_in_pak(e, name)) return std::snprintf(where, where_size, "%s", e.path), true;
      continue;
    }
    char path[kMaxPathBytes * 2];
    if (!join_path(path, sizeof path, e.path, name)) continue;
    if (std::FILE* f = std::fopen(path, "rb")) {
      std::fclose(f);
      if (is_directory(path)) continue;
      return std::snprintf(where, where_size, "%s", path), true;
    }
  }
  return false;
}

bool FileSystem::exists(const char* name) const {
  char where[kMaxPathBytes * 2];
  return locate(name, where, sizeof where);
}

Result<FileData> FileSystem::load(const char* name, mem::Arena& into) const {
  for (int i = count_ - 1; i >= 0; --i) {
    const Entry& e = entries_[i];
    const char* path = e.path;
    char loose[kMaxPathBytes * 2];
    long offset = 0, size = 0;
    std::FILE* f = nullptr;
    if (e.is_pak) {
      const PakEntry* pe = find_in_pak(e, name);
      if (!pe) continue;
      f = std::fopen(path, "rb");
      if (!f) return make_error("%s: cannot open %s", name, path);
      offset = long(pe->offset);
      size = long(pe->size);
    } else {
      if (!join_path(loose, sizeof loose, e.path, name) || is_directory(loose)) continue;
      f = std::fopen(loose, "rb");
      if (!f) continue;
      path = loose;
      size = file_size_of(f);
      if (size < 0) {
        std::fclose(f);
        return make_error("%s: cannot determine the size of %s", name, path);
      }
    }
    size_t mark = mem_util::align_mark(into);
    auto* bytes = static_cast<uint8_t*>(mem_util::push_padded(into, size_t(size) + 1, "file data"));
    if (!bytes) {
      std::fclose(f);
      Error err = make_error("%s: ", name);
      into.failure_message(err.message + std::strlen(err.message), sizeof err.message - std::strlen(err.message));
      return err;
    }
    bool ok = std::fseek(f, offset, SEEK_SET) == 0 && std::fread(bytes, 1, size_t(size), f) == size_t(size);
    std::fclose(f);
    if (!ok) {
      into.pop_to(mark);
      return make_error("%s: read of %ld bytes at offset %ld in %s failed", name, size, offset, path);
    }
    bytes[size] = 0;
    return FileData{bytes, size_t(size)};
  }
  return make_error("%s: not found on the search path", name);
}

int FileSystem::list_files(const char* prefix, const char* suffix, FileName* out, int max) const {
  int stored = 0;  // names in out (sorted, unique), <= max
  // Inserts name keeping out[0..stored) sorted and unique; when full, keeps the smallest names.
  auto add = [&](const char* name) {
    if (max <= 0 || std::strlen(name) >= size_t(kPakNameBytes)) return;
    FileName* end = out + stored;
    FileName* pos = std::lower_bound(out, end, name,
                                     [](const FileName& a, const char* b) { return std::strcmp(a.name, b) < 0; });
    if (pos != end && std::strcmp(pos->name, name) == 0) return;
    if (stored < max) {
      std::memmove(pos + 1, pos, size_t(end - pos) * sizeof(FileName));
      ++stored;
    } else if (pos != end) {
      std::memmove(pos + 1, pos, size_t(end - pos - 1) * sizeof(FileName));
    } else {
      return;
    }
    std::snprintf(pos->name, sizeof pos->name, "%s", name);
  };
  for (int i = count_ - 1; i >= 0; --i) {
    const Entry& e = entries_[i];
    if (e.is_pak) {
      for (uint32_t k = 0; k < e.pak.count; ++k) {
        const char* n = e.pak.entries[k].name;
        if (starts_with(n, prefix) && ends_with(n, suffix)) add(n);
      }
      continue;
    }
    // Loose files: the directory part of prefix, then match the rest.
    const char* slash = std::strrchr(prefix, '/');
    size_t dir_len = slash ? size_t(slash - prefix) + 1 : 0;
    char dir[kMaxPathBytes * 2];
    std::snprintf(dir, sizeof dir, "%s/%.*s", e.path, int(dir_len), prefix);
    std::error_code ec;
    std::filesystem::directory_iterator it(dir, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
      if (!it->is_regular_file(ec)) continue;
      char name[kMaxPathBytes];
      std::snprintf(name, sizeof name, "%.*s%s", int(dir_len), prefix, it->path().filename().c_str());
      if (starts_with(name, prefix) && ends_with(name, suffix)) add(name);
    }
  }
  return stored;
}

}  // namespace sb::fs
