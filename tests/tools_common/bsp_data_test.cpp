#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "engine/formats/bsp.h"
#include "memory/memory_system.h"
#include "tests/support/quake_data.h"
#include "tools/common/bsp_data.h"

namespace sb::tools {
namespace {

std::vector<uint8_t> slurp(const std::string& path) {
  std::vector<uint8_t> bytes;
  if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
    uint8_t buf[65536];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) bytes.insert(bytes.end(), buf, buf + n);
    std::fclose(f);
  }
  return bytes;
}

// The engine's loader (every index checked) accepts the bytes and sees the same counts.
void expect_engine_loads(const std::vector<uint8_t>& bytes, const BspData& want) {
  std::vector<uint8_t> block(64 * mem::kMiB);
  mem::MemorySystem m;
  char err[256];
  ASSERT_TRUE(m.init(block.data(), block.size(), err, sizeof err)) << err;
  Result<BspWorld*> w = load_bsp("roundtrip.bsp", bytes.data(), bytes.size(), m.level, m.scratch);
  ASSERT_TRUE(w.is_ok()) << w.message();
  EXPECT_EQ(w.value()->num_faces, want.faces.size());
  EXPECT_EQ(w.value()->num_nodes, want.nodes.size());
  EXPECT_EQ(w.value()->num_leaves, want.leaves.size());
  EXPECT_EQ(w.value()->num_clipnodes, want.clipnodes.size());
}

TEST(BspData, RoundTripsRealMapsThroughEveryFormat) {
  SB_REQUIRE_QUAKE_DATA();
  for (const char* map : {"start", "b_batt0"}) {
    SCOPED_TRACE(map);
    std::vector<uint8_t> original = slurp(test::quake_dir() + "/lq1/maps/" + map + ".bsp");
    BspData a;
    ASSERT_TRUE(parse_bsp(map, original.data(), original.size(), &a).is_ok());
    EXPECT_EQ(a.format, BspFormat::Bsp29);
    EXPECT_TRUE(fits_bsp29(a, nullptr));
    for (BspFormat f : {BspFormat::Bsp29, BspFormat::Bsp2, BspFormat::Bsp2rmq}) {
      std::vector<uint8_t> once, twice;
      BspFormat used;
      ASSERT_TRUE(serialize_bsp(a, f, &once, &used).is_ok());
      EXPECT_EQ(used, f);
      BspData b;
      ASSERT_TRUE(parse_bsp("once", once.data(), once.size(), &b).is_ok());
      EXPECT_EQ(b.format, f);
      ASSERT_TRUE(serialize_bsp(b, f, &twice, nullptr).is_ok());
      EXPECT_EQ(once, twice) << "serialise(parse(serialise(x))) differs";
      expect_engine_loads(once, a);
    }
  }
}

TEST(BspData, AutoMovesToBsp2PastABsp29Limit) {
  BspData b;
  b.nodes.resize(40000);
  std::string why;
  EXPECT_FALSE(fits_bsp29(b, &why));
  EXPECT_NE(why.find("nodes"), std::string::npos) << why;
  std::vector<uint8_t> bytes;
  BspFormat used = BspFormat::Auto;
  ASSERT_TRUE(serialize_bsp(b, BspFormat::Auto, &bytes, &used).is_ok());
  EXPECT_EQ(used, BspFormat::Bsp2);
  EXPECT_FALSE(serialize_bsp(b, BspFormat::Bsp29, &bytes, &used).is_ok());
}

TEST(BspData, TruncatedAndForeignFilesAreErrors) {
  const uint8_t junk[8] = {'I', 'B', 'S', 'P', 0, 0, 0, 0};
  BspData b;
  Status s = parse_bsp("junk.bsp", junk, sizeof junk, &b);
  EXPECT_FALSE(s.is_ok());
  EXPECT_NE(std::string(s.message()).find("junk.bsp"), std::string::npos);
  std::vector<uint8_t> bytes;
  ASSERT_TRUE(serialize_bsp(BspData{}, BspFormat::Bsp29, &bytes, nullptr).is_ok());
  for (size_t cut : {size_t(3), size_t(60), size_t(123)}) {  // inside the 124-byte header
    EXPECT_FALSE(parse_bsp("cut.bsp", bytes.data(), cut, &b).is_ok()) << cut;
  }
  // A lump that runs past the end: the entities lump (one NUL byte) cut off.
  EXPECT_FALSE(parse_bsp("cut.bsp", bytes.data(), bytes.size() - 1, &b).is_ok());
}

}  // namespace
}  // namespace sb::tools
