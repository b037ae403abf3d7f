// engine/fs/file_system.h: game directories and PAK archives as one search path.
//
//   search order (first match wins)           added by
//   +--------------------------------------+
//   | <basedir>/<mod>/pak9.pak ... pak0.pak |  add_game_dir("<basedir>/<mod>")   (-game <mod>)
//   | <basedir>/<mod>/  (loose files)       |
//   | <basedir>/id1/pak9.pak ... pak0.pak   |  add_game_dir("<basedir>/id1")     (base game)
//   | <basedir>/id1/   (loose files)        |
//   +--------------------------------------+
// Quake's conventions: a later game dir overrides an earlier one; inside one game
// dir a higher-numbered pak overrides a lower one and every pak overrides loose
// files. pakN.pak files are looked for for N = 0..9 (missing ones are skipped).
//
// Memory: the search path is a fixed table inside FileSystem (kMaxEntries); PAK
// directories are copied into the `permanent` arena passed to add_game_dir() and
// live as long as it does. load() pushes the file's bytes into the caller's arena.
// Reading uses <cstdio> only. Names use '/' and are relative to a game dir,
// e.g. "maps/start.bsp"; names in a PAK are matched exactly (case-sensitive).
#pragma once
#include <cstddef>
#include <cstdint>

#include "engine/core/error.h"
#include "memory/arena.h"

namespace sb::fs {

constexpr int kPakNameBytes = 56;  // name field of a PAK directory entry, NUL-terminated
constexpr int kPakEntryBytes = 64;
constexpr int kPakHeaderBytes = 12;
constexpr uint32_t kMaxPakEntries = 1u << 16;  // sanity cap (Quake used 2048)
constexpr int kMaxPathBytes = 256;

// A file's bytes in the arena given to load(); 16-byte aligned, followed by one
// extra NUL byte (not counted in size) so text files can be parsed as C strings.
struct FileData {
  const uint8_t* data = nullptr;
  size_t size = 0;
};

struct PakEntry {
  char name[kPakNameBytes];  // NUL-terminated (checked)
  uint32_t offset, size;     // bytes inside the pak file (offset + size <= file size, checked)
};

struct PakDirectory {
  PakEntry* entries = nullptr;  // in the arena given to the parser
  uint32_t count = 0;
};

// Validates a PAK header (the first 12 bytes of the file) against the file size.
// On success *dir_offset / *dir_count locate the directory (dir_count * 64 bytes).
// Errors name the pak and the field, e.g. "id1/pak0.pak: header field 'dirlen' = 65 is not a multiple of 64".
Status parse_pak_header(const char* pak_name, const uint8_t* header, size_t header_size, uint64_t file_size,
                        uint32_t* dir_offset, uint32_t* dir_count);
// Validates one 64-byte directory entry; errors name the pak, the entry index and the field.
Status parse_pak_entry(const char* pak_name, uint32_t index, const uint8_t* raw, uint64_t file_size, PakEntry* out);
// Header + directory of a PAK held in memory (tests, archives inside archives).
Result<PakDirectory> parse_pak(const char* pak_name, const uint8_t* data, size_t size, mem::Arena& into);

// One name from list_files().
struct FileName {
  char name[kPakNameBytes];
};

class FileSystem {
 public:
  static constexpr int kMaxEntries = 48;  // directories + paks on the search path

  // Adds `path` (a directory) and its pak0..pak9.pak on top of the search path.
  // A missing directory is an error; a bad pak is an error naming the pak (the
  // search path is left as it was before the call).
  Status add_game_dir(const char* path, mem::Arena& permanent);

  // Quake's command line: -basedir <dir> (default "."), base game folder `base_game`
  // (e.g. "id1" or "lq1"), and -game <mod> on top of it when given.
  Status init_from_args(int argc, const char* const* argv, const char* base_game, mem::Arena& permanent);

  // The first match on the search path, read whole into `into` (see FileData).
  // Errors: "maps/x.bsp: not found on the search path", read failures, arena exhaustion.
  Result<FileData> load(const char* name, mem::Arena& into) const;
  bool exists(const char* name) const;
  // Where `name` would be read from ("<dir>/name" or "<dir>/pak0.pak"), for messages; false if absent.
  bool locate(const char* name, char* where, size_t where_size) const;

  // Names on the search path that start with `prefix` and end with `suffix`
  // (e.g. "maps/", ".bsp"), each once, sorted (byte order). Loose files are
  // found in `prefix`'s directory only (no recursion into deeper folders); pak
  // entries of any depth match. Writes up to `max` names (when more match, the
  // `max` smallest are kept) and returns how many it wrote.
  int list_files(const char* prefix, const char* suffix, FileName* out, int max) const;

  int entry_count() const { return count_; }
  void clear() { count_ = 0; }

 private:
  struct Entry {
    char path[kMaxPathBytes];  // directory, or the pak file's path
    bool is_pak;
    PakDirectory pak;
  };
  const PakEntry* find_in_pak(const Entry& e, const char* name) const;
  Status add_pak(const char* pak_path, mem::Arena& permanent, bool* found);

  Entry entries_[kMaxEntries];  // [0] searched last; [count_ - 1] first
  int count_ = 0;
};

}  // namespace sb::fs
