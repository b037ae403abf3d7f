// engine/fs: PAK round trip, search path precedence, listing, bad paks.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "engine/fs/file_system.h"
#include "tests/formats/fs_test_util.h"
#include "tests/formats/formats_test_util.h"
#include "tests/support/quake_data.h"

namespace sb::test {
namespace {

namespace stdfs = std::filesystem;

std::vector<uint8_t> bytes_of(const std::string& s) { return std::vector<uint8_t>(s.begin(), s.end()); }

std::string load_string(const fs::FileSystem& fsys, const char* name, mem::Arena& a) {
  auto r = fsys.load(name, a);
  if (!r) return std::string("<error> ") + r.message();
  return std::string(reinterpret_cast<const char*>(r.value().data), r.value().size);
}

TEST(FileSystem, PakRoundTripIsByteIdentical) {
  TempDir tmp("pak_round_trip");
  TestArenas arenas(8u << 20, 1u << 20);
  std::vector<PakFileSpec> files;
  std::string q = quake_dir();
  if (!q.empty()) {
    files.push_back({"maps/start.bsp", read_file(q + "/lq1/maps/start.bsp")});
    files.push_back({"gfx/palette.lmp", read_file(q + "/lq1/gfx/palette.lmp")});
  } else {
    std::vector<uint8_t> blob(100000);
    for (size_t i = 0; i < blob.size(); ++i) blob[i] = uint8_t(i * 31 + 7);
    files.push_back({"maps/start.bsp", blob});
    files.push_back({"gfx/palette.lmp", std::vector<uint8_t>(768, 3)});
  }
  files.push_back({"empty.txt", {}});
  stdfs::create_directories(tmp.path / "id1");
  write_pak(tmp.path / "id1" / "pak0.pak", files);

  fs::FileSystem fsys;
  Status st = fsys.add_game_dir((tmp.path / "id1").c_str(), arenas.level);
  ASSERT_TRUE(st.is_ok()) << st.message();
  EXPECT_EQ(fsys.entry_count(), 2);  // the directory and its pak
  for (const PakFileSpec& f : files) {
    auto r = fsys.load(f.name.c_str(), arenas.scratch);
    ASSERT_TRUE(r.is_ok()) << r.message();
    ASSERT_EQ(r.value().size, f.data.size()) << f.name;
    if (!f.data.empty()) {
      EXPECT_EQ(std::memcmp(r.value().data, f.data.data(), f.data.size()), 0) << f.name;
    }
    EXPECT_EQ(r.value().data[r.value().size], 0);  // trailing NUL
    EXPECT_TRUE(fsys.exists(f.name.c_str()));
  }
  EXPECT_FALSE(fsys.exists("maps/none.bsp"));
  auto missing = fsys.load("maps/none.bsp", arenas.scratch);
  ASSERT_FALSE(missing.is_ok());
  EXPECT_NE(std::strstr(missing.message(), "maps/none.bsp"), nullptr);
  // In-memory parse of the same pak agrees.
  auto raw = read_file((tmp.path / "id1" / "pak0.pak").string());
  auto dir = fs::parse_pak("pak0.pak", raw.data(), raw.size(), arenas.scratch);
  ASSERT_TRUE(dir.is_ok()) << dir.message();
  EXPECT_EQ(dir.value().count, files.size());
}

TEST(FileSystem, SearchPathPrecedence) {
  TempDir tmp("precedence");
  TestArenas arenas(4u << 20, 1u << 20);
  stdfs::create_directories(tmp.path / "id1" / "maps");
  stdfs::create_directories(tmp.path / "mod" / "maps");
  write_text(tmp.path / "id1" / "a.txt", "loose-base");
  write_text(tmp.path / "id1" / "c.txt", "loose-only");
  write_text(tmp.path / "id1" / "maps" / "loose.bsp", "x");
  write_pak(tmp.path / "id1" / "pak0.pak", {{"a.txt", bytes_of("pak0-base")}, {"b.txt", bytes_of("pak0")},
                                            {"maps/e1m1.bsp", bytes_of("m")}, {"d.txt", bytes_of("pak0-d")}});
  write_pak(tmp.path / "id1" / "pak1.pak", {{"b.txt", bytes_of("pak1")}, {"maps/e1m2.bsp", bytes_of("m")}});
  write_text(tmp.path / "mod" / "d.txt", "loose-mod");
  write_text(tmp.path / "mod" / "maps" / "e1m1.bsp", "mod-map");
  write_text(tmp.path / "mod" / "maps" / "notes.txt", "not a map");

  std::string base = tmp.path.string();
  const char* argv[] = {"starbow", "-basedir", base.c_str(), "-game", "mod"};
  fs::FileSystem fsys;
  Status st = fsys.init_from_args(5, argv, "id1", arenas.level);
  ASSERT_TRUE(st.is_ok()) << st.message();
  EXPECT_EQ(fsys.entry_count(), 4);  // id1, id1/pak0, id1/pak1, mod
  EXPECT_EQ(load_string(fsys, "a.txt", arenas.scratch), "pak0-base");   // pak over loose in one dir
  EXPECT_EQ(load_string(fsys, "b.txt", arenas.scratch), "pak1");        // higher pak over lower
  EXPECT_EQ(load_string(fsys, "c.txt", arenas.scratch), "loose-only");  // loose when no pak has it
  EXPECT_EQ(load_string(fsys, "d.txt", arenas.scratch), "loose-mod");   // -game over the base game's pak
  EXPECT_EQ(load_string(fsys, "maps/e1m1.bsp", arenas.scratch), "mod-map");
  char where[512];
  ASSERT_TRUE(fsys.locate("b.txt", where, sizeof where));
  EXPECT_NE(std::strstr(where, "pak1.pak"), nullptr) << where;

  fs::FileName names[8];
  int n = fsys.list_files("maps/", ".bsp", names, 8);
  ASSERT_EQ(n, 3);
  EXPECT_STREQ(names[0].name, "maps/e1m1.bsp");
  EXPECT_STREQ(names[1].name, "maps/e1m2.bsp");
  EXPECT_STREQ(names[2].name, "maps/loose.bsp");
  EXPECT_EQ(fsys.list_files("maps/", ".bsp", names, 2), 2);  // the smallest two are kept
  EXPECT_STREQ(names[1].name, "maps/e1m2.bsp");

  // Without -game only the base game is searched.
  fs::FileSystem base_only;
  const char* argv2[] = {"starbow", "-basedir", base.c_str()};
  ASSERT_TRUE(base_only.init_from_args(3, argv2, "id1", arenas.level).is_ok());
  EXPECT_EQ(load_string(base_only, "d.txt", arenas.scratch), "pak0-d");
}

TEST(FileSystem, BadPakIsAnErrorNamingThePakAndLeavesThePathAlone) {
  TempDir tmp("bad_pak");
  TestArenas arenas(4u << 20, 1u << 20);
  stdfs::create_directories(tmp.path / "id1");
  stdfs::create_directories(tmp.path / "mod");
  write_pak(tmp.path / "id1" / "pak0.pak", {{"a.txt", bytes_of("ok")}});
  write_pak(tmp.path / "mod" / "pak0.pak", {{"a.txt", bytes_of("x")}});
  // Corrupt mod's entry 0 'filelen' to run past the end of the file.
  {
    std::fstream f(tmp.path / "mod" / "pak0.pak", std::ios::in | std::ios::out | std::ios::binary);
    int32_t dirofs;
    f.seekg(4);
    f.read(reinterpret_cast<char*>(&dirofs), 4);
    int32_t big = 1 << 20;
    f.seekp(dirofs + 60);
    f.write(reinterpret_cast<const char*>(&big), 4);
  }
  fs::FileSystem fsys;
  ASSERT_TRUE(fsys.add_game_dir((tmp.path / "id1").c_str(), arenas.level).is_ok());
  size_t used = arenas.level.used();
  Status st = fsys.add_game_dir((tmp.path / "mod").c_str(), arenas.level);
  ASSERT_FALSE(st.is_ok());
  EXPECT_NE(std::strstr(st.message(), "mod/pak0.pak"), nullptr) << st.message();
  EXPECT_NE(std::strstr(st.message(), "entry 0"), nullptr) << st.message();
  EXPECT_NE(std::strstr(st.message(), "filelen"), nullptr) << st.message();
  EXPECT_EQ(fsys.entry_count(), 2);
  EXPECT_EQ(arenas.level.used(), used);
  EXPECT_EQ(load_string(fsys, "a.txt", arenas.scratch), "ok");
  Status missing = fsys.add_game_dir((tmp.path / "nope").c_str(), arenas.level);
  EXPECT_FALSE(missing.is_ok());
}

TEST(FileSystem, PakHeaderAndEntryChecks) {
  uint8_t header[12] = {'P', 'A', 'C', 'K'};
  uint32_t off = 0, count = 0;
  auto set = [&](int32_t dirofs, int32_t dirlen) {
    std::memcpy(header + 4, &dirofs, 4);
    std::memcpy(header + 8, &dirlen, 4);
  };
  set(12, 128);
  EXPECT_TRUE(fs::parse_pak_header("p.pak", header, 12, 140, &off, &count).is_ok());
  EXPECT_EQ(count, 2u);
  set(12, 100);
  Status st = fs::parse_pak_header("p.pak", header, 12, 140, &off, &count);
  EXPECT_NE(std::strstr(st.message(), "'dirlen'"), nullptr) << st.message();
  set(100, 64);
  st = fs::parse_pak_header("p.pak", header, 12, 140, &off, &count);
  EXPECT_NE(std::strstr(st.message(), "'dirlen'"), nullptr) << st.message();
  set(-5, 0);
  st = fs::parse_pak_header("p.pak", header, 12, 140, &off, &count);
  EXPECT_NE(std::strstr(st.message(), "'dirofs'"), nullptr) << st.message();
  uint8_t entry[64];
  std::memset(entry, 'a', 56);  // no NUL in the name
  fs::PakEntry e;
  st = fs::parse_pak_entry("p.pak", 3, entry, 1000, &e);
  EXPECT_NE(std::strstr(st.message(), "entry 3 field 'name'"), nullptr) << st.message();
}

}  // namespace
}  // namespace sb::test
