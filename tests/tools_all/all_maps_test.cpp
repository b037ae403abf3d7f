// tests/tools_all/all_maps_test.cpp: every LibreQuake map source through the whole compiler,
// the built programs as a mapper runs them: sbbsp, sbvis -fast, sblight (default flags).
// One test per map, named after it (LibreQuake/AllStages.Map/e1_lq_e1m1):
//   - each stage exits 0 (a signal is reported as a crash);
//   - no leak: sbbsp wrote no .pts (so there is a .prt and sbvis runs);
//   - the BSP loads through sb::load_bsp (engine/formats) and render_world draws 12 entity
//     viewpoints (tests/support test_viewpoints) at 320x200 that agree with the reference
//     renderer on >= 98% of pixels with < 0.5% unexplained, every pixel written once (the
//     bars of tests/render's agreement test; the engine's PVS is used, the reference draws
//     everything, so a PVS that hides something visible shows up as unexplained pixels).
// brushmodels/ are item prefabs (b_batt0 ...), not levels: compiled as LibreQuake builds them
// (no vis: its build configs say LQ_SKIP). Their only point entities are preview lights
// outside the brushes, so sbbsp has nothing to flood from and keeps the outside; the prefab
// suite checks there is no leak file, the rest as above, and renders four views from outside
// the model's box.
// Work files: <build>/tools_all/<name>.{bsp,prt,pts,*.log}, rewritten on every run; a
// failed render comparison leaves <name>_viewN.png (engine | reference | differences).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "tests/support/build_features.h"
#include "tests/support/png_image.h"
#include "tests/support/quake_data.h"
#include "tests/support/reference_renderer.h"
#include "tests/support/render_compare.h"
#include "tests/support/test_world.h"
#include "tests/tools_bsp/bsp_test_util.h"

namespace sb::test {
namespace {

namespace fs = std::filesystem;

constexpr int kViews = 12, kWidth = 320, kHeight = 200;  // as tests/tools_bsp; rendering is cheap
// tests/render's agreement test asks 98% identical pixels of four maps. Here that bar is on
// the pixels that are identical or exactly the texel the one-divide-per-16-pixels walker
// reaches; identical alone must reach 97%. The difference is lq_e0m7: walls of the noisy
// lava texture drawn turbulent, where the walker's sub-texel error is also fed into the
// warp (97.19% identical, 98.97% counting the interpolated texel, 0.04% unexplained). The
// compiler's faults (a missing face, a crack, a wrong texture vector) are edge and
// unexplained pixels, which keep their bar.
constexpr double kMinAgreement = 0.98;      // identical or the interpolated texel
constexpr double kMinIdentical = 0.97;      // identical palette indices
constexpr double kMaxUnexplained = 0.005;   // unexplained + other-mip pixels, ditto

// Every .map under lq1/maps/src (checked by AllSourcesListed), without ".map".
const char* const kMaps[] = {
    "brushmodels/b_batt0", "brushmodels/b_batt0_lite", "brushmodels/b_batt1", "brushmodels/b_batt1_lite",
    "brushmodels/b_bh10", "brushmodels/b_bh100", "brushmodels/b_bh100_lite", "brushmodels/b_bh10_lite",
    "brushmodels/b_bh25", "brushmodels/b_bh25_lite", "brushmodels/b_exbox2", "brushmodels/b_explob",
    "brushmodels/b_nail0", "brushmodels/b_nail1", "brushmodels/b_rock0", "brushmodels/b_rock1",
    "brushmodels/b_shell0", "brushmodels/b_shell1",
    "dm/lqdm1", "dm/lqdm10", "dm/lqdm11", "dm/lqdm12", "dm/lqdm13", "dm/lqdm2", "dm/lqdm3", "dm/lqdm4",
    "dm/lqdm6", "dm/lqdm7", "dm/lqdm8", "dm/lqdm9",
    "e0/lq_e0m1", "e0/lq_e0m3", "e0/lq_e0m4", "e0/lq_e0m5", "e0/lq_e0m6", "e0/lq_e0m7", "e0/lq_e0m8", "e0/lq_e0m9",
    "e1/lq_e1m1", "e1/lq_e1m2", "e1/lq_e1m3", "e1/lq_e1m6", "e1/lq_e1m7", "e1/lq_e1m8",
    "e2/lq_e2m1", "e2/lq_e2m3", "e2/lq_e2m6", "e2/lq_e2m7",
    "e3/lq_e3m1", "e3/lq_e3m2", "e3/lq_e3m5", "e3/lq_e3m7",
    "e4/lq_e4m2", "e4/lq_e4m3", "e4/lq_e4m6", "e4/lq_e4m7", "e4/lq_e4m8",
    "misc/dev", "misc/lq_end", "misc/old-start", "misc/slope", "misc/start", "misc/start_e0",
};

bool is_prefab(const std::string& m) { return m.rfind("brushmodels/", 0) == 0; }

std::vector<std::string> maps_where(bool prefab) {
  std::vector<std::string> out;
  for (const char* m : kMaps)
    if (is_prefab(m) == prefab) out.push_back(m);
  return out;
}

// "e1/lq_e1m1" -> "e1_lq_e1m1"; "misc/old-start" -> "misc_old_start" (gtest names).
std::string test_name(const std::string& m) {
  std::string s = m;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}
std::string base_name(const std::string& m) { return m.substr(m.rfind('/') + 1); }

std::string work_dir() {
  std::string d = std::string(STARBOW_BINARY_DIR) + "/tools_all";
  std::error_code ec;
  fs::create_directories(d, ec);
  return d;
}

struct StageRun {
  std::string stage;      // "sbbsp"
  int exit_code = -1;     // when it exited
  int signal = 0;         // when a signal ended it (a crash)
  double seconds = 0;
  std::string output;     // stdout + stderr
  bool ok() const { return signal == 0 && exit_code == 0; }
  std::string what() const {
    if (signal) return stage + " crashed: signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
    return stage + " exited with " + std::to_string(exit_code);
  }
  // The last lines of the output, for failure messages.
  std::string tail(size_t lines = 12) const {
    size_t pos = output.size();
    for (size_t n = 0; n <= lines && pos != std::string::npos && pos > 0; ++n) pos = output.rfind('\n', pos - 1);
    return pos == std::string::npos ? output : output.substr(pos + 1);
  }
};

// Runs `program args` with stdout and stderr captured (also written to log_path).
StageRun run_stage(const std::string& stage, const std::string& program, const std::vector<std::string>& args,
                   const std::string& log_path) {
  StageRun r;
  r.stage = stage;
  std::string cmd = "'" + program + "'";
  for (const std::string& a : args) cmd += " '" + a + "'";
  auto t0 = std::chrono::steady_clock::now();
  std::FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  if (!p) {
    r.output = "popen failed: " + cmd;
    return r;
  }
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.output.append(buf, n);
  int status = pclose(p);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (WIFEXITED(status)) {
    r.exit_code = WEXITSTATUS(status);
    if (r.exit_code > 128) r.signal = r.exit_code - 128;  // the shell popen ran reports a child's signal so
  } else if (WIFSIGNALED(status)) {
    r.signal = WTERMSIG(status);
  }
  if (std::FILE* f = std::fopen(log_path.c_str(), "wb")) {
    std::fprintf(f, "$ %s\n%s", cmd.c_str(), r.output.c_str());
    std::fclose(f);
  }
  return r;
}

// The first line of `text` containing `what` (empty when none).
std::string line_with(const std::string& text, const std::string& what) {
  size_t at = text.find(what);
  if (at == std::string::npos) return "";
  size_t b = text.rfind('\n', at);
  size_t e = text.find('\n', at);
  b = b == std::string::npos ? 0 : b + 1;
  return text.substr(b, e == std::string::npos ? std::string::npos : e - b);
}

// One map's files and stage runs.
struct MapRun {
  std::string name, source, bsp, prt, pts, dir;
};

MapRun prepare(const std::string& m) {
  MapRun r;
  r.name = base_name(m);
  r.source = quake_dir() + "/lq1/maps/src/" + m + ".map";
  r.dir = work_dir();
  r.bsp = r.dir + "/" + r.name + ".bsp";
  r.prt = r.dir + "/" + r.name + ".prt";
  r.pts = r.dir + "/" + r.name + ".pts";
  for (const char* ext : {".bsp", ".prt", ".pts", ".lit"}) std::remove((r.dir + "/" + r.name + ext).c_str());
  for (int v = 0; v < kViews; ++v) std::remove((r.dir + "/" + r.name + "_view" + std::to_string(v) + ".png").c_str());
  return r;
}

// Renders `views` with render_world and the reference renderer; a view that misses either
// bar leaves a picture of the differences in the work folder.
RenderCheck compare_views(LoadedBsp& bsp, const std::vector<ViewParams>& views, const std::string& png_prefix) {
  RenderCheck out;
  std::vector<uint8_t> colormap = test_colormap();
  std::vector<uint8_t> palette = load_game_palette();
  MismatchBreakdown total;
  std::vector<uint8_t> pixels, coverage;
  for (size_t i = 0; i < views.size(); ++i) {
    Status s = bsp.render(views[i], kWidth, kHeight, colormap.data(), &pixels, &coverage);
    if (!s) {
      if (out.error.empty()) out.error = s.message();
      continue;
    }
    for (uint8_t c : coverage) out.coverage_errors += c != 1;
    ReferenceRenderer ref(ReferenceInputs{bsp.world(), 0.5, nullptr, colormap.data()});
    ReferenceFrame frame = ref.render(views[i], kWidth, kHeight);
    std::vector<PixelClass> classes;
    MismatchBreakdown b = classify_mismatches(ref, frame, pixels.data(), kWidth, &classes);
    total.add(b);
    out.views++;
#ifndef STARBOW_NO_PNG
    double bad = b.pixels ? double(b.unexplained + b.mip) / double(b.pixels) : 0;
    if ((b.interpolation_agreement() < kMinAgreement || b.agreement() < kMinIdentical || bad >= kMaxUnexplained) &&
        palette.size() == 768) {
      int w = 0;
      std::vector<uint8_t> rgb = comparison_rgb(frame, pixels.data(), kWidth, classes, palette, &w);
      write_rgb_png(png_prefix + "_view" + std::to_string(i) + ".png", w, kHeight, rgb);
    }
#else
    (void)png_prefix;
#endif
  }
  out.agreement = total.agreement();
  out.interpolation_agreement = total.interpolation_agreement();
  out.unexplained = total.pixels ? double(total.unexplained + total.mip) / double(total.pixels) : 0;
  out.summary = total.summary();
  return out;
}

// Four eyes outside a prefab's box (model 0 bounds), looking at its centre from the four
// diagonals, slightly above. Eyes in solid space are dropped.
std::vector<ViewParams> outside_views(const BspWorld& w) {
  std::vector<ViewParams> out;
  glm::vec3 mins = w.models[0].mins, maxs = w.models[0].maxs;
  glm::vec3 c = (mins + maxs) * 0.5f;
  float r = 0.5f * std::sqrt((maxs.x - mins.x) * (maxs.x - mins.x) + (maxs.y - mins.y) * (maxs.y - mins.y) +
                             (maxs.z - mins.z) * (maxs.z - mins.z));
  float dist = 1.6f * r + 16.0f;
  for (int k = 0; k < 4; ++k) {
    float yaw = 45.0f + 90.0f * float(k);
    float rad = yaw * 3.14159265f / 180.0f;
    ViewParams v;
    v.origin = c - glm::vec3(std::cos(rad), std::sin(rad), -0.5f) * dist;
    v.yaw = yaw;
    v.pitch = std::atan2(0.5f, 1.0f) * 180.0f / 3.14159265f;  // looking down at the centre
    v.fov_x = 90.0f;
    if (point_contents(w, v.origin) != kContentsSolid) out.push_back(v);
  }
  return out;
}

void print_line(const std::string& s) { std::cout << "[ tools_all ] " << s << std::endl; }

std::string secs(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f s", s);
  return b;
}

// --- levels: sbbsp, sbvis -fast, sblight, no leak, load, render --------------------------

class LevelMap : public ::testing::TestWithParam<std::string> {};

TEST_P(LevelMap, CompilesWithoutLeakLoadsAndRenders) {
  SB_REQUIRE_NATIVE_PROGRAMS();
  SB_REQUIRE_QUAKE_DATA();
  MapRun m = prepare(GetParam());
  ASSERT_TRUE(fs::exists(m.source)) << m.source;

  StageRun bsp = run_stage("sbbsp", SB_SBBSP_PATH, {m.source, m.bsp}, m.dir + "/" + m.name + ".sbbsp.log");
  ASSERT_TRUE(bsp.ok()) << m.name << ": " << bsp.what() << "\n" << bsp.tail();
  const bool leaked = fs::exists(m.pts);
  ASSERT_FALSE(leaked) << m.name << ": sbbsp reports a leak ("
                       << line_with(bsp.output, "leak:") << "); leak path in " << m.pts;
  ASSERT_TRUE(fs::exists(m.prt)) << m.name << ": no leak but no portal file " << m.prt << "\n" << bsp.tail();

  StageRun vis = run_stage("sbvis -fast", SB_SBVIS_PATH, {"-fast", m.bsp}, m.dir + "/" + m.name + ".sbvis.log");
  ASSERT_TRUE(vis.ok()) << m.name << ": " << vis.what() << "\n" << vis.tail();
  StageRun light = run_stage("sblight", SB_SBLIGHT_PATH, {m.bsp}, m.dir + "/" + m.name + ".sblight.log");
  ASSERT_TRUE(light.ok()) << m.name << ": " << light.what() << "\n" << light.tail();

  auto t0 = std::chrono::steady_clock::now();
  LoadedBsp b(m.bsp, 128);
  ASSERT_NE(b.world(), nullptr) << m.name << ": load_bsp: " << b.error();
  EXPECT_GT(b.world()->visdata_size, 0u) << m.name << ": sbvis wrote no visdata";
  EXPECT_GT(b.world()->lightdata_size, 0u) << m.name << ": sblight wrote no lightmaps";
  std::vector<ViewParams> views = test_viewpoints(*b.world(), kViews);
  RenderCheck rc = compare_views(b, views, m.dir + "/" + m.name);
  double render_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_TRUE(rc.error.empty()) << m.name << ": render_world: " << rc.error;
  EXPECT_EQ(rc.views, kViews) << m.name;
  EXPECT_EQ(rc.coverage_errors, 0u) << m.name << ": pixels not written exactly once";
  EXPECT_GE(rc.interpolation_agreement, kMinAgreement) << m.name << ": " << rc.summary << " (pictures: " << m.dir << "/"
                                         << m.name << "_view*.png)";
  EXPECT_GE(rc.agreement, kMinIdentical) << m.name << ": " << rc.summary << " (pictures: " << m.dir << "/"
                                         << m.name << "_view*.png)";
  EXPECT_LT(rc.unexplained, kMaxUnexplained) << m.name << ": " << rc.summary;

  print_line(m.name + ": faces " + std::to_string(b.world()->num_faces) + ", leaves " +
             std::to_string(b.world()->num_leaves) + "; sbbsp " + secs(bsp.seconds) + ", sbvis -fast " +
             secs(vis.seconds) + ", sblight " + secs(light.seconds) + ", load + " + std::to_string(rc.views) +
             " views " + secs(render_s) + "; " + rc.summary);
  RecordProperty("faces", int(b.world()->num_faces));
  RecordProperty("sbbsp_seconds", secs(bsp.seconds));
  RecordProperty("sbvis_seconds", secs(vis.seconds));
  RecordProperty("sblight_seconds", secs(light.seconds));
  RecordProperty("agreement", std::to_string(rc.agreement));
}

INSTANTIATE_TEST_SUITE_P(LibreQuake, LevelMap, ::testing::ValuesIn(maps_where(false)),
                         [](const ::testing::TestParamInfo<std::string>& p) { return test_name(p.param); });

// --- prefabs (brushmodels/): sbbsp, sblight, load, render; the leak status is reported ----

class PrefabMap : public ::testing::TestWithParam<std::string> {};

TEST_P(PrefabMap, CompilesLightsLoadsAndRendersLeakNotApplicable) {
  SB_REQUIRE_NATIVE_PROGRAMS();
  SB_REQUIRE_QUAKE_DATA();
  MapRun m = prepare(GetParam());
  ASSERT_TRUE(fs::exists(m.source)) << m.source;

  StageRun bsp = run_stage("sbbsp", SB_SBBSP_PATH, {m.source, m.bsp}, m.dir + "/" + m.name + ".sbbsp.log");
  ASSERT_TRUE(bsp.ok()) << m.name << ": " << bsp.what() << "\n" << bsp.tail();
  // A prefab is sealed, or its only point entities are lights outside the brushes: sbbsp then
  // keeps the outside ("no entities to flood from") instead of reporting a leak.
  EXPECT_FALSE(fs::exists(m.pts)) << m.name << ": leaked\n" << bsp.tail();
  std::string leak = line_with(bsp.output, "no entities to flood from").empty()
                         ? "sealed"
                         : "no entities to flood from: outside kept (expected for a prefab)";
  RecordProperty("leak_check", "prefab: " + leak);

  StageRun light = run_stage("sblight", SB_SBLIGHT_PATH, {m.bsp}, m.dir + "/" + m.name + ".sblight.log");
  ASSERT_TRUE(light.ok()) << m.name << ": " << light.what() << "\n" << light.tail();

  LoadedBsp b(m.bsp, 32);
  ASSERT_NE(b.world(), nullptr) << m.name << ": load_bsp: " << b.error();
  EXPECT_GT(b.world()->num_faces, 0u);
  std::vector<ViewParams> views = outside_views(*b.world());
  EXPECT_GE(views.size(), 2u) << m.name << ": too few eyes outside the prefab";
  RenderCheck rc = compare_views(b, views, m.dir + "/" + m.name);
  EXPECT_TRUE(rc.error.empty()) << m.name << ": render_world: " << rc.error;
  EXPECT_EQ(rc.coverage_errors, 0u) << m.name << ": pixels not written exactly once";
  EXPECT_GE(rc.interpolation_agreement, kMinAgreement) << m.name << ": " << rc.summary;
  EXPECT_GE(rc.agreement, kMinIdentical) << m.name << ": " << rc.summary;
  EXPECT_LT(rc.unexplained, kMaxUnexplained) << m.name << ": " << rc.summary;
  print_line(m.name + " (prefab; vis skipped as LibreQuake's build config says; leak check: " +
             leak + "): faces " + std::to_string(b.world()->num_faces) + "; sbbsp " + secs(bsp.seconds) +
             ", sblight " + secs(light.seconds) + "; " + std::to_string(rc.views) + " outside views, " + rc.summary);
}

INSTANTIATE_TEST_SUITE_P(LibreQuake, PrefabMap, ::testing::ValuesIn(maps_where(true)),
                         [](const ::testing::TestParamInfo<std::string>& p) { return test_name(p.param); });

// --- the list above is every source there is -------------------------------------------

TEST(LibreQuakeSources, AllListed) {
  SB_REQUIRE_QUAKE_DATA();
  std::string root = quake_dir() + "/lq1/maps/src";
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    if (!e.is_regular_file() || e.path().extension() != ".map") continue;
    std::string rel = fs::relative(e.path(), root).string();
    if (rel.rfind("-buildconfigs-", 0) == 0) continue;
    found.push_back(rel.substr(0, rel.size() - 4));
  }
  std::sort(found.begin(), found.end());
  std::vector<std::string> listed(std::begin(kMaps), std::end(kMaps));
  std::sort(listed.begin(), listed.end());
  EXPECT_EQ(found, listed) << "a map source was added or removed under " << root << ": update kMaps";
  EXPECT_EQ(listed.size(), 63u);
}

}  // namespace
}  // namespace sb::test
