// Bad input: truncations and bit flips of real BSPs, a generated PAK and gfx.wad.
// Every mutation must give an error naming the file (and a lump / header /
// entry) or a world that keeps every promise of bsp.h. Fixed seeds; runs under
// ASan + UBSan in CI (label 'sanitize'), each input copied into an exactly sized
// heap block so reads past its end are caught.
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "engine/core/log.h"
#include "engine/formats/bsp.h"
#include "engine/formats/lmp.h"
#include "engine/formats/wad.h"
#include "engine/fs/file_system.h"
#include "engine/world/viewpoints.h"
#include "engine/world/world.h"
#include "tests/formats/formats_test_util.h"
#include "tests/formats/fs_test_util.h"
#include "tests/support/quake_data.h"

namespace sb::test {
namespace {

// Counts log lines instead of printing thousands of warnings; restored on scope exit.
struct QuietLog {
  static void sink(void* user, LogLevel, const char*) { ++*static_cast<int*>(user); }
  QuietLog() { set_log_sink(sink, &lines); }
  ~QuietLog() { set_log_sink(nullptr, nullptr); }
  int lines = 0;
};

struct Tally {
  int ok = 0, errors = 0;
};

// An exactly sized heap copy of bytes[0..size).
std::unique_ptr<uint8_t[]> exact_copy(const std::vector<uint8_t>& bytes, size_t size) {
  std::unique_ptr<uint8_t[]> p(new uint8_t[size ? size : 1]);
  if (size) std::memcpy(p.get(), bytes.data(), size);
  return p;
}

bool names_a_part(const char* msg) {
  return std::strstr(msg, "lump '") || std::strstr(msg, "header") || std::strstr(msg, "entry ") ||
         std::strstr(msg, "lump ") || std::strstr(msg, "directory");
}

void try_bsp(const char* name, const std::vector<uint8_t>& bytes, size_t size, TestArenas& a, Tally& t) {
  auto data = exact_copy(bytes, size);
  size_t mark = a.level.mark();
  auto r = load_bsp(name, data.get(), size, a.level, a.scratch);
  ASSERT_EQ(a.scratch.used(), 0u);
  if (!r) {
    ++t.errors;
    ASSERT_EQ(a.level.mark(), mark);
    ASSERT_EQ(std::strncmp(r.message(), name, std::strlen(name)), 0) << r.message();
    ASSERT_TRUE(names_a_part(r.message())) << r.message();
    return;
  }
  ++t.ok;
  const BspWorld& w = *r.value();
  ASSERT_EQ(check_world_invariants(w), 0);
  data.reset();  // the world must not point into the input
  size_t row = pvs_row_bytes(w);
  std::vector<uint8_t> pvs(row + 1);
  for (uint32_t l = 0; l < w.num_leaves && l < 4096; ++l) decompress_pvs(w, int(l), pvs.data(), pvs.size());
  ViewParams views[8];
  int n = collect_viewpoints(w, views, 8);
  for (int i = 0; i < n; ++i) ASSERT_LT(uint32_t(point_in_leaf(w, views[i].origin)), w.num_leaves);
  a.level.pop_to(mark);
}

struct Region {
  size_t begin, end;
};

// Lump regions of a BSP29 file (plus the header as region 0).
std::vector<Region> bsp_regions(const std::vector<uint8_t>& b) {
  std::vector<Region> out{{0, 124}};
  for (int i = 0; i < 15; ++i) {
    int32_t ofs, len;
    std::memcpy(&ofs, &b[4 + 8 * i], 4);
    std::memcpy(&len, &b[8 + 8 * i], 4);
    if (len > 0) out.push_back({size_t(ofs), size_t(ofs) + size_t(len)});
  }
  return out;
}

// Flips 1..3 bits, or writes an interesting 32-bit value, inside one region.
void mutate(std::vector<uint8_t>& m, const Region& r, std::mt19937& rng) {
  size_t span = r.end - r.begin;
  if (span == 0) return;
  if (rng() % 4 == 0 && span >= 4) {
    static const int32_t kInteresting[] = {0, -1, 1, 0x7fffffff, int32_t(0x80000000), 0x7fff, 0x8000, 0xffff,
                                           0x10000, -2, 16, 4096, 255};
    int32_t v = kInteresting[rng() % (sizeof kInteresting / sizeof kInteresting[0])];
    size_t at = r.begin + (rng() % (span - 3)) / 2 * 2;
    std::memcpy(&m[at], &v, rng() % 2 ? 4 : 2);
    return;
  }
  int flips = 1 + int(rng() % 3);
  for (int k = 0; k < flips; ++k) m[r.begin + rng() % span] ^= uint8_t(1u << (rng() % 8));
}

void fuzz_bsp(const std::string& path, const char* name, int random_lengths, int flips, uint32_t seed) {
  auto orig = read_file(path);
  ASSERT_GT(orig.size(), 124u);
  TestArenas a(32u << 20, 8u << 20);
  QuietLog quiet;
  std::mt19937 rng(seed);
  Tally t;
  auto t0 = std::chrono::steady_clock::now();
  std::set<size_t> lengths{0, 1, 3, 4, 123, 124, 125, orig.size() - 1};
  for (const Region& r : bsp_regions(orig))
    for (size_t x : {r.begin, r.end})
      for (long d : {-1L, 0L, 1L})
        if (long(x) + d >= 0 && size_t(long(x) + d) < orig.size()) lengths.insert(size_t(long(x) + d));
  for (int i = 0; i < random_lengths; ++i) lengths.insert(rng() % orig.size());
  for (size_t len : lengths) {
    try_bsp(name, orig, len, a, t);
    if (::testing::Test::HasFatalFailure()) return;
  }
  int truncations = t.ok + t.errors;
  auto regions = bsp_regions(orig);
  std::vector<uint8_t> m;
  for (int i = 0; i < flips; ++i) {
    m = orig;
    const Region& r = regions[rng() % 3 == 0 ? 0 : rng() % regions.size()];
    mutate(m, r, rng);
    if (rng() % 4 == 0) mutate(m, regions[rng() % regions.size()], rng);
    try_bsp(name, m, m.size(), a, t);
    if (::testing::Test::HasFatalFailure()) return;
  }
  double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%s: %d truncations + %d mutations: %d loaded, %d rejected, %d log lines (%.2f s)\n", name, truncations,
              flips, t.ok, t.errors, quiet.lines, s);
  EXPECT_GT(t.errors, 0);
}

TEST(Fuzz, StartBsp) {
  SB_REQUIRE_QUAKE_DATA();
  fuzz_bsp(quake_dir() + "/lq1/maps/start.bsp", "maps/start.bsp", 200, 1500, 1234);
}

TEST(Fuzz, ItemBsp) {
  SB_REQUIRE_QUAKE_DATA();
  fuzz_bsp(quake_dir() + "/lq1/maps/b_batt0.bsp", "maps/b_batt0.bsp", 200, 1500, 99);
}

TEST(Fuzz, GeneratedPak) {
  std::vector<PakFileSpec> files;
  std::string q = quake_dir();
  std::vector<uint8_t> palette = q.empty() ? std::vector<uint8_t>(768, 9) : read_file(q + "/lq1/gfx/palette.lmp");
  files.push_back({"gfx/palette.lmp", palette});
  files.push_back({"maps/tiny.bsp", std::vector<uint8_t>(300, 1)});
  files.push_back({"progs/a.mdl", std::vector<uint8_t>(40, 2)});
  files.push_back({"readme.txt", std::vector<uint8_t>{'h', 'i'}});
  auto orig = build_pak(files);
  TestArenas a(4u << 20, 1u << 20);
  QuietLog quiet;
  std::mt19937 rng(7);
  Tally t;
  auto check = [&](const std::vector<uint8_t>& bytes, size_t size) {
    auto data = exact_copy(bytes, size);
    size_t mark = a.scratch.mark();
    auto r = fs::parse_pak("gen.pak", data.get(), size, a.scratch);
    if (!r) {
      ++t.errors;
      ASSERT_EQ(std::strncmp(r.message(), "gen.pak: ", 9), 0) << r.message();
      ASSERT_TRUE(names_a_part(r.message())) << r.message();
    } else {
      ++t.ok;
      for (uint32_t i = 0; i < r.value().count; ++i) {
        const fs::PakEntry& e = r.value().entries[i];
        ASSERT_LE(uint64_t(e.offset) + e.size, size);
        ASSERT_LT(std::strlen(e.name), size_t(fs::kPakNameBytes));
        if (e.size) {
          ASSERT_GE(int(data[e.offset]) + int(data[e.offset + e.size - 1]), 0);
        }
      }
    }
    a.scratch.pop_to(mark);
  };
  for (size_t len = 0; len < orig.size(); ++len) check(orig, len);
  std::vector<uint8_t> m;
  size_t dirofs = orig.size() - 64 * files.size();
  for (int i = 0; i < 600; ++i) {
    m = orig;
    Region r = rng() % 3 == 0 ? Region{0, 12} : Region{dirofs, orig.size()};
    mutate(m, r, rng);
    check(m, m.size());
  }
  // A few mutated paks through the real search path (files on disk).
  TempDir tmp("fuzz_pak");
  std::filesystem::create_directories(tmp.path / "g");
  for (int i = 0; i < 30; ++i) {
    m = orig;
    mutate(m, Region{dirofs, orig.size()}, rng);
    {
      std::ofstream f(tmp.path / "g" / "pak0.pak", std::ios::binary | std::ios::trunc);
      f.write(reinterpret_cast<const char*>(m.data()), std::streamsize(m.size()));
    }
    fs::FileSystem fsys;
    size_t mark = a.level.mark();
    Status st = fsys.add_game_dir((tmp.path / "g").c_str(), a.level);
    if (!st) {
      EXPECT_NE(std::strstr(st.message(), "pak0.pak"), nullptr) << st.message();
      EXPECT_EQ(a.level.mark(), mark);
      continue;
    }
    for (const PakFileSpec& f : files)
      if (fsys.exists(f.name.c_str())) {
        auto r = fsys.load(f.name.c_str(), a.scratch);
        EXPECT_TRUE(r.is_ok()) << r.message();
      }
    a.scratch.reset();
    a.level.pop_to(mark);
  }
  std::printf("gen.pak: %zu truncations + 600 mutations: %d parsed, %d rejected\n", orig.size(), t.ok, t.errors);
}

TEST(Fuzz, GfxWad) {
  SB_REQUIRE_QUAKE_DATA();
  auto orig = read_file(quake_dir() + "/lq1/gfx.wad");
  ASSERT_GT(orig.size(), 12u);
  TestArenas a(4u << 20, 1u << 20);
  std::mt19937 rng(4242);
  Tally t;
  auto check = [&](const std::vector<uint8_t>& bytes, size_t size) {
    auto data = exact_copy(bytes, size);
    size_t mark = a.scratch.mark();
    auto r = parse_wad("gfx.wad", data.get(), size, a.scratch);
    if (!r) {
      ++t.errors;
      ASSERT_EQ(std::strncmp(r.message(), "gfx.wad: ", 9), 0) << r.message();
      ASSERT_TRUE(names_a_part(r.message())) << r.message();
    } else {
      ++t.ok;
      for (uint32_t i = 0; i < r.value().count; ++i) {
        const WadLump& l = r.value().lumps[i];
        ASSERT_GE(l.data, data.get());
        ASSERT_LE(l.data + l.size, data.get() + size);
        if (l.type == kWadQpic) {
          QpicView pic;
          if (parse_qpic(l.name, l.data, l.size, &pic)) {
            ASSERT_GE(int(pic.pixels[size_t(pic.width) * pic.height - 1]), 0);
          }
        } else if (l.type == kWadMiptex) {
          MiptexView mt;
          if (decode_miptex("gfx.wad", l.name, l.data, l.size, &mt) && mt.has_pixels) {
            ASSERT_GE(int(mt.mips[3][(mt.width >> 3) * (mt.height >> 3) - 1]), 0);
          }
        }
      }
    }
    a.scratch.pop_to(mark);
  };
  int32_t infotableofs;
  std::memcpy(&infotableofs, &orig[8], 4);
  std::set<size_t> lengths{0, 4, 11, 12, 13, size_t(infotableofs), size_t(infotableofs) + 1, orig.size() - 1};
  for (size_t k = size_t(infotableofs); k < orig.size(); k += 32) lengths.insert(k);
  for (int i = 0; i < 100; ++i) lengths.insert(rng() % orig.size());
  for (size_t len : lengths) check(orig, len);
  std::vector<uint8_t> m;
  for (int i = 0; i < 600; ++i) {
    m = orig;
    int pick = int(rng() % 4);
    Region r = pick == 0 ? Region{0, 12} : pick == 3 ? Region{12, size_t(infotableofs)} : Region{size_t(infotableofs), orig.size()};
    mutate(m, r, rng);
    check(m, m.size());
  }
  std::printf("gfx.wad: %zu truncations + 600 mutations: %d parsed, %d rejected\n", lengths.size(), t.ok, t.errors);
  EXPECT_GT(t.errors, 0);
}

}  // namespace
}  // namespace sb::test
