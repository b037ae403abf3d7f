// tests/host/console_test.cpp: command line, console, light styles, camera path.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "engine/formats/entities.h"
#include "engine/host/camera_path.h"
#include "engine/host/cmdline.h"
#include "engine/host/console.h"
#include "engine/host/content.h"
#include "engine/host/lightstyles.h"
#include "engine/world/world.h"
#include "tests/host/host_test_util.h"
#include "tests/support/quake_data.h"

namespace sb::host {
namespace {

Status parse(std::vector<const char*> args, CommandLine* out) {
  args.insert(args.begin(), "starbow");
  return parse_command_line(int(args.size()), args.data(), out);
}

TEST(CommandLine, OptionsAndPlusCommands) {
  CommandLine cl;
  ASSERT_TRUE(parse({"-basedir", "/data/quake", "-game", "mymod", "-mem", "64", "-memstats", "-res", "800x600",
                     "-fov", "100", "+viewmap", "start", "+viewpos", "480", "-352", "88", "90", "0", "+screenshot",
                     "out.png", "+quit"},
                    &cl)
                  .is_ok());
  EXPECT_STREQ(cl.basedir, "/data/quake");
  EXPECT_STREQ(cl.game, "mymod");
  EXPECT_EQ(cl.mem_mib, 64);
  EXPECT_TRUE(cl.memstats);
  EXPECT_EQ(cl.width, 800);
  EXPECT_EQ(cl.height, 600);
  EXPECT_FLOAT_EQ(cl.fov, 100.0f);
  EXPECT_EQ(cl.num_commands, 4);
  EXPECT_TRUE(cl.has_map_command);
  // Negative numbers stay arguments of +viewpos; each + command is one line.
  EXPECT_STREQ(cl.commands, "viewmap start\nviewpos 480 -352 88 90 0\nscreenshot out.png\nquit");
}

TEST(CommandLine, WidthHeightUnknownOptionsAndQuoting) {
  CommandLine cl;
  ASSERT_TRUE(parse({"-width", "1024", "-height", "768", "-frames", "30", "-nosound", "+echo", "two words"}, &cl)
                  .is_ok());
  EXPECT_EQ(cl.width, 1024);
  EXPECT_EQ(cl.height, 768);
  EXPECT_EQ(cl.frames, 30);
  EXPECT_STREQ(cl.ignored, "-nosound");
  EXPECT_FALSE(cl.has_map_command);
  EXPECT_STREQ(cl.commands, "echo \"two words\"");
}

TEST(CommandLine, MalformedValuesAreErrorsNamingTheOption) {
  CommandLine cl;
  Status s = parse({"-mem"}, &cl);
  ASSERT_FALSE(s.is_ok());
  EXPECT_NE(std::string(s.message()).find("-mem"), std::string::npos);
  EXPECT_FALSE(parse({"-mem", "lots"}, &cl).is_ok());
  EXPECT_FALSE(parse({"-res", "640by480"}, &cl).is_ok());
  EXPECT_FALSE(parse({"-fov", "400"}, &cl).is_ok());
  EXPECT_FALSE(parse({"-basedir", "+map", "x"}, &cl).is_ok());
  EXPECT_TRUE(parse({}, &cl).is_ok());
  EXPECT_EQ(cl.num_commands, 0);
}

TEST(Console, TokenizeQuotesCommentsAndLimits) {
  CommandArgs a;
  ASSERT_TRUE(tokenize("  viewpos 1 -2.5  \"three four\" // ignored", &a).is_ok());
  ASSERT_EQ(a.argc, 4);
  EXPECT_STREQ(a.argv[0], "viewpos");
  EXPECT_STREQ(a.argv[2], "-2.5");
  EXPECT_STREQ(a.argv[3], "three four");
  EXPECT_FALSE(tokenize("echo \"open", &a).is_ok());
  EXPECT_FALSE(tokenize(std::string(300, 'x').c_str(), &a).is_ok());
  EXPECT_FALSE(tokenize("a b c d e f g h i j k l m n o p q", &a).is_ok());  // 17 tokens
}

struct Recorder {
  std::vector<std::string> calls;
  Console* console = nullptr;
};
void record(void* user, const CommandArgs& args) {
  auto* r = static_cast<Recorder*>(user);
  std::string s;
  for (int i = 0; i < args.argc; ++i) s += (i ? " " : "") + std::string(args.argv[i]);
  r->calls.push_back(s);
  if (std::strcmp(args.arg(0), "pause") == 0) r->console->wait();
}

TEST(Console, BufferRunsLinesInOrderAndWaitHoldsTheRest) {
  alignas(16) static uint8_t memory[64 * 1024];
  mem::Arena arena;
  arena.init("test", memory, sizeof memory);
  Console c;
  ASSERT_TRUE(c.init(arena, 8, 8, 256).is_ok());
  Recorder r;
  r.console = &c;
  ASSERT_TRUE(c.add_command("a", record, &r, "").is_ok());
  ASSERT_TRUE(c.add_command("pause", record, &r, "").is_ok());
  EXPECT_FALSE(c.add_command("a", record, &r, "").is_ok());  // duplicate
  ASSERT_TRUE(c.append("a 1; a \"2;x\"\npause\na 3").is_ok());
  ASSERT_TRUE(c.insert("a 0").is_ok());
  c.execute();
  ASSERT_EQ(r.calls.size(), 4u);
  EXPECT_EQ(r.calls[0], "a 0");
  EXPECT_EQ(r.calls[2], "a 2;x");  // ';' inside quotes does not split
  EXPECT_FALSE(c.empty());
  c.execute();
  ASSERT_EQ(r.calls.size(), 5u);
  EXPECT_EQ(r.calls[4], "a 3");
  EXPECT_TRUE(c.empty());
  EXPECT_FALSE(c.append(std::string(300, 'x').c_str()).is_ok());  // over capacity: a Status, no crash
}

TEST(Console, CvarsSetAndPrint) {
  alignas(16) static uint8_t memory[64 * 1024];
  mem::Arena arena;
  arena.init("test", memory, sizeof memory);
  Console c;
  ASSERT_TRUE(c.init(arena, 4, 2, 256).is_ok());
  Cvar* v = c.add_cvar("fov", "90", "field of view");
  ASSERT_NE(v, nullptr);
  EXPECT_FLOAT_EQ(v->value, 90.0f);
  c.execute_line("fov 110");
  EXPECT_FLOAT_EQ(v->value, 110.0f);
  EXPECT_STREQ(v->string, "110");
  EXPECT_NE(c.add_cvar("b", "1", ""), nullptr);
  EXPECT_EQ(c.add_cvar("c", "1", ""), nullptr);  // table full
}

TEST(LightStyles, NormalUnanimatedAndPatternsAt10Hz) {
  int s[kMaxLightStyleSlots];
  light_styles_at(12.34, false, s);
  for (int v : s) EXPECT_EQ(v, kLightStyleNormal);
  EXPECT_EQ(light_style_letter_value('a'), 0);
  EXPECT_EQ(light_style_letter_value('m'), kLightStyleNormal);
  EXPECT_EQ(light_style_letter_value('z'), 25 * 256 / 12);
  for (int style = 1; style <= 11; ++style) {
    const char* p = light_style_pattern(style);
    ASSERT_NE(p, nullptr) << style;
    for (const char* c = p; *c; ++c) EXPECT_TRUE(*c >= 'a' && *c <= 'z') << style;
    // The value at step k is the k-th letter (10 steps a second), wrapping.
    size_t len = std::strlen(p);
    for (size_t k = 0; k < 2 * len; ++k) {
      light_styles_at((double(k) + 0.5) / kLightStyleSteps, true, s);
      EXPECT_EQ(s[style], light_style_letter_value(p[k % len])) << "style " << style << " step " << k;
    }
  }
  light_styles_at(3.3, true, s);
  EXPECT_EQ(s[0], kLightStyleNormal);
  for (int style = 12; style < kMaxLightStyleSlots; ++style) EXPECT_EQ(s[style], kLightStyleNormal);
  EXPECT_EQ(light_style_pattern(0), nullptr);
  EXPECT_EQ(light_style_pattern(32), nullptr);
}

// The benchmark mode (r_lightstyles 2): every style's value differs from the frame before,
// near normal brightness, and style i is one frame ahead of style i - 1.
TEST(LightStyles, EveryFrameModeChangesEveryStyleEachFrame) {
  int prev[kMaxLightStyleSlots], s[kMaxLightStyleSlots];
  light_styles_every_frame(0, prev);
  for (unsigned f = 1; f < 9; ++f) {
    light_styles_every_frame(f, s);
    for (int i = 0; i < kMaxLightStyleSlots; ++i) {
      EXPECT_NE(s[i], prev[i]) << "style " << i << " frame " << f;
      EXPECT_GE(s[i], 240);
      EXPECT_LE(s[i], 264);
      if (i > 0) {
        EXPECT_EQ(s[i - 1], prev[i]) << "style " << i << " frame " << f;
      }
    }
    std::memcpy(prev, s, sizeof s);
  }
}

TEST(MapFileName, AddsFolderAndExtensionOnce) {
  char out[64];
  ASSERT_TRUE(map_file_name("start", out, sizeof out));
  EXPECT_STREQ(out, "maps/start.bsp");
  ASSERT_TRUE(map_file_name("maps/e1m1.bsp", out, sizeof out));
  EXPECT_STREQ(out, "maps/e1m1.bsp");
  EXPECT_FALSE(map_file_name("", out, sizeof out));
  EXPECT_FALSE(map_file_name(std::string(100, 'x').c_str(), out, sizeof out));
}

TEST(CameraPath, DeterministicAndBetweenViewpoints) {
  ViewParams pts[2];
  pts[0].origin = glm::vec3(0, 0, 0);
  pts[0].yaw = 0;
  pts[1].origin = glm::vec3(100, 0, 0);
  pts[1].yaw = 90;
  CameraPath path{pts, nullptr, 2};
  ViewParams a = camera_path_view(path, 0, 100, 90.0f);
  ViewParams b = camera_path_view(path, 99, 100, 90.0f);
  ViewParams m = camera_path_view(path, 50, 100, 90.0f);
  EXPECT_FLOAT_EQ(a.origin.x, 0.0f);
  EXPECT_FLOAT_EQ(b.origin.x, 100.0f);
  EXPECT_GT(m.origin.x, 0.0f);
  EXPECT_LT(m.origin.x, 100.0f);
  ViewParams m2 = camera_path_view(path, 50, 100, 90.0f);
  EXPECT_EQ(std::memcmp(&m, &m2, sizeof m), 0);
  for (int f = 0; f < 100; ++f) {
    ViewParams v = camera_path_view(path, f, 100, 90.0f);
    EXPECT_GE(v.yaw, -180.0f);
    EXPECT_LE(v.yaw, 180.0f);
    EXPECT_LT(std::abs(v.pitch), 90.0f);
  }
  // A cut never flies through the space between: each frame is at one end or the other.
  const uint8_t cuts[2] = {0, 1};
  CameraPath jump{pts, cuts, 2};
  for (int f = 0; f < 100; ++f) {
    float x = camera_path_view(jump, f, 100, 90.0f).origin.x;
    EXPECT_TRUE(x == 0.0f || x == 100.0f) << f << ": " << x;
  }
}

TEST(CameraPath, RealMapRouteStartsAtThePlayerStartAndStaysOutOfSolid) {
  SB_REQUIRE_QUAKE_DATA();
  std::vector<uint8_t> block(96u << 20);
  static mem::MemorySystem memory;
  static fs::FileSystem files;
  char error[256];
  ASSERT_TRUE(memory.init(block.data(), block.size(), error, sizeof error)) << error;
  ASSERT_TRUE(open_search_path(files, sb::test::quake_dir().c_str(), "lq1", "lq1", memory.permanent).is_ok());
  for (const char* map : {"start", "lq_e0m1"}) {
    Result<BspWorld*> world = load_world(files, map, memory);
    ASSERT_TRUE(world.is_ok()) << world.message();
    Result<CameraPath> path = build_camera_path(*world.value(), memory.level);
    ASSERT_TRUE(path.is_ok()) << path.message();
    ASSERT_GE(path.value().count, 2) << map;
    glm::vec3 start(0.0f);
    Entity e;
    ASSERT_TRUE(find_entity(std::string_view(world.value()->entities, world.value()->entities_size),
                            "info_player_start", &e));
    ASSERT_TRUE(entity_origin(e, &start));
    EXPECT_FLOAT_EQ(path.value().points[0].origin.x, start.x) << map;
    EXPECT_FLOAT_EQ(path.value().points[0].origin.z, start.z + 22.0f) << map;
    for (int f = 0; f < 300; ++f) {
      ViewParams v = camera_path_view(path.value(), f, 300, 90.0f);
      int leaf = point_in_leaf(*world.value(), v.origin);
      EXPECT_NE(world.value()->leaves[leaf].contents, kContentsSolid) << map << " frame " << f;
    }
  }
}

}  // namespace
}  // namespace sb::host
