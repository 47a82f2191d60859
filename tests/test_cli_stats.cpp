// `candela render --stats FILE.json` and `--no-bvh`: the statistics file that bench/run reads has
// every key, with sane values, and the brute-force flag changes what the file reports but not
// the ray counts. Runs the real binary (CANDELA_BINARY) in a temporary directory.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "backends/cpu/cpu_engine.h"
#include "render/scene_view.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A sphere and a two-triangle quad (written next to the scene), 16x12 pixels, 4 spp.
const char* kScene = R"({
  "camera": {"width": 16, "height": 12, "spp": 4, "position": [0, 0, 5]},
  "render": {"max_depth": 3},
  "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}],
  "objects": [{"file": "quad.obj", "position": [0, -1, 0], "scale": 4}],
  "lights": [{"position": [0, 3, 3], "intensity": 100}]
})";

const char* kQuad =
    "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\n"
    "f 1 3 2\nf 1 4 3\n";

class CliStatsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("candela_stats_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "scene.json") << kScene;
    std::ofstream(dir_ / "quad.obj") << kQuad;
  }
  void TearDown() override { fs::remove_all(dir_); }

  // `shell` runs first in the same shell (ulimit, trap).
  int run(const std::string& args, const std::string& shell = "") const {
    const std::string command = "cd '" + dir_.string() + "' && " + shell + " '" + CANDELA_BINARY +
                                "' render " + args + " > stdout.txt 2> stderr.txt < /dev/null";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  json readJson(const std::string& name) const {
    std::ifstream in(dir_ / name);
    std::stringstream text;
    text << in.rdbuf();
    return json::parse(text.str());
  }

  std::string stderrText() const {
    std::ifstream in(dir_ / "stderr.txt");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  // With so many samples that a render would last hours: an error that comes back within the
  // minute was found before rendering (`timeout` ends the run with 124 otherwise).
  int runEndless(const std::string& args) const {
    return run(args + " --spp 1000000000", "timeout 60");
  }

  std::string read(const std::string& name) const {
    std::ifstream in(dir_ / name, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  // The entries of the test folder other than the shell's redirections.
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const fs::directory_entry& e : fs::directory_iterator(dir_)) {
      const std::string name = e.path().filename().string();
      if (name != "stdout.txt" && name != "stderr.txt") names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

// Each CPU engine of this build: candela's own BVH, and Embree where the build has it.
class CliStatsEngineTest : public CliStatsTest,
                           public ::testing::WithParamInterface<std::string> {};

TEST_P(CliStatsEngineTest, WritesEveryKeyWithSaneNumbers) {
  const std::string engine = GetParam();
  if (engine == "embree" && !candela::embreeAvailable()) GTEST_SKIP() << "no Embree in this build";
  ASSERT_EQ(run("scene.json -o out.pfm -q --backend cpu --threads 2 --cpu-engine " + engine +
                " --stats stats.json"),
            0)
      << stderrText();
  const json s = readJson("stats.json");
  for (const char* key : {"scene",
                          "backend",
                          "threads",
                          "width",
                          "height",
                          "spp",
                          "max_depth",
                          "integrator",
                          "antialiasing",
                          "filter",
                          "light_paths",
                          "first_hit_light_samples",
                          "use_bvh",
                          "engine",
                          "load_seconds",
                          "flatten_seconds",
                          "bvh_build_seconds",
                          "bvh_mtris_per_second",
                          "triangles",
                          "spheres",
                          "bvh_nodes",
                          "bvh_leaves",
                          "bvh_max_depth",
                          "memory_bytes",
                          "bytes_per_triangle",
                          "render_seconds",
                          "samples",
                          "samples_per_second",
                          "rays",
                          "rays_per_second",
                          "denoise_seconds",
                          "peak_rss_bytes"})
    EXPECT_TRUE(s.contains(key)) << key;

  EXPECT_EQ(s["scene"], "scene.json");
  EXPECT_EQ(s["backend"], "cpu");
  EXPECT_EQ(s["threads"], 2);
  EXPECT_EQ(s["width"], 16);
  EXPECT_EQ(s["height"], 12);
  EXPECT_EQ(s["spp"], 4);
  EXPECT_EQ(s["max_depth"], 3);
  EXPECT_EQ(s["integrator"], "path");
  EXPECT_EQ(s["antialiasing"], true);
  EXPECT_EQ(s["filter"], json({{"type", "box"}}));
  EXPECT_EQ(s["use_bvh"], true);
  EXPECT_EQ(s["denoise_seconds"], 0.0);  // no --denoise
  // Too small a render for the light-path pilot (backends/render_pilot.h): they stay on.
  EXPECT_EQ(s["light_paths"]["setting"], "auto");
  EXPECT_EQ(s["light_paths"]["on"], true);
  EXPECT_EQ(s["light_paths"]["piloted"], false);
  EXPECT_EQ(s["light_paths"]["pilot_rays"], 0);
  EXPECT_EQ(s["triangles"], 2);
  EXPECT_EQ(s["spheres"], 1);
  EXPECT_EQ(s["engine"], engine);
  // The own BVH is built only for the engine that traces it.
  EXPECT_EQ(s["bvh_nodes"].get<int>() >= 1, engine == "bvh");
  EXPECT_EQ(s["bvh_leaves"].get<int>() >= 1, engine == "bvh");

  for (const char* key : {"load_seconds", "flatten_seconds", "bvh_build_seconds", "render_seconds",
                          "bvh_mtris_per_second"}) {
    EXPECT_GE(s[key].get<double>(), 0) << key;
    EXPECT_LT(s[key].get<double>(), 60) << key;
  }
  if (engine == "bvh") {
    EXPECT_LE(s["bvh_build_seconds"].get<double>(), s["flatten_seconds"].get<double>() + 1e-3);
  }

  const json& m = s["memory_bytes"];
  EXPECT_EQ(m["triangles"].get<int>() % 2, 0);
  EXPECT_EQ(m["positions"].get<int>(), 4 * 12);  // four float3 vertices
  EXPECT_EQ(m["total"].get<int>(), m["nodes"].get<int>() + m["prim_indices"].get<int>() +
                                       m["positions"].get<int>() + m["normals"].get<int>() +
                                       m["triangles"].get<int>() + m["engine"].get<int>());
  EXPECT_EQ(m["engine"].get<int>() > 0, engine == "embree");  // Embree's BVH and vertex copy
  EXPECT_EQ(m["nodes"].get<int>(), int(sizeof(candela::BvhNode)) * s["bvh_nodes"].get<int>());
  EXPECT_DOUBLE_EQ(s["bytes_per_triangle"].get<double>(), m["total"].get<double>() / 2);

  const double samples = 16.0 * 12 * 4;
  EXPECT_EQ(s["samples"].get<double>(), samples);
  const json& rays = s["rays"];
  EXPECT_EQ(rays["camera"].get<double>(), samples);  // one camera ray per sample
  EXPECT_EQ(rays["total"].get<uint64_t>(), rays["camera"].get<uint64_t>() +
                                               rays["bounce"].get<uint64_t>() +
                                               rays["shadow"].get<uint64_t>());
  EXPECT_GT(rays["shadow"].get<uint64_t>(), 0u);
  const double seconds = s["render_seconds"];
  if (seconds > 0) {
    EXPECT_NEAR(s["samples_per_second"].get<double>(), samples / seconds, samples / seconds * 1e-6);
    EXPECT_NEAR(s["rays_per_second"].get<double>(), rays["total"].get<double>() / seconds,
                rays["total"].get<double>() / seconds * 1e-6);
  }
  // A running process holds at least a megabyte and, for this scene, far less than 4 GB.
  EXPECT_GT(s["peak_rss_bytes"].get<double>(), 1e6);
  EXPECT_LT(s["peak_rss_bytes"].get<double>(), 4e9);
}

INSTANTIATE_TEST_SUITE_P(Engines, CliStatsEngineTest, ::testing::Values("bvh", "embree"));

TEST_F(CliStatsTest, NoBvhIsReportedAndTracesTheSameRays) {
  ASSERT_EQ(run("scene.json -o a.pfm -q --backend cpu --cpu-engine bvh --stats a.json"), 0)
      << stderrText();
  ASSERT_EQ(run("scene.json -o b.pfm -q --backend cpu --no-bvh --stats b.json"), 0) << stderrText();
  const json a = readJson("a.json"), b = readJson("b.json");
  EXPECT_EQ(a["use_bvh"], true);
  EXPECT_EQ(b["use_bvh"], false);
  // Same closest hits either way, so the same paths and the same ray counts.
  EXPECT_EQ(a["rays"], b["rays"]);
}

TEST_F(CliStatsTest, ReportsThePixelFilterAsTheSceneWritesIt) {
  for (const auto& [filter, expected] :
       {std::pair{R"("tent")", json({{"type", "tent"}, {"radius", 1.0}})},
        std::pair{R"({"type": "gaussian", "stddev": 0.75})",
                  json({{"type", "gaussian"}, {"stddev", 0.75}})}}) {
    std::string scene = kScene;
    scene.replace(scene.find(R"("max_depth": 3)"), 14,
                  std::string(R"("max_depth": 3, "filter": )") + filter);
    std::ofstream(dir_ / "filtered.json") << scene;
    ASSERT_EQ(run("filtered.json -o out.pfm -q --stats stats.json"), 0) << stderrText();
    EXPECT_EQ(readJson("stats.json")["filter"], expected) << filter;
  }
}

// Large enough a render for the light-path pilot, of a scene where it turns them off (a lamp high
// above an open floor: tests/test_render_pilot.cpp).
TEST_F(CliStatsTest, APilotedRenderReportsItsChoiceAndCountsItsTime) {
  std::ofstream(dir_ / "open.json") << R"({
    "camera": {"width": 256, "height": 256, "fov": 50, "position": [0, 3, 8],
               "look_at": [0, 0.8, 0], "spp": 16},
    "render": {"max_depth": 4, "seed": 1},
    "spheres": [{"position": [0, -1000, 0], "radius": 1000, "color": 0.6},
                {"position": [0, 1, 0], "radius": 1, "color": [0.7, 0.5, 0.3]}],
    "lights": [{"position": [0, 50, 0], "intensity": 4000}]})";
  ASSERT_EQ(run("open.json -o out.pfm -q --stats stats.json"), 0) << stderrText();
  const json s = readJson("stats.json");
  const json& lp = s["light_paths"];
  EXPECT_EQ(lp["setting"], "auto");
  EXPECT_EQ(lp["piloted"], true);
  EXPECT_EQ(lp["on"], false);
  EXPECT_GT(lp["pilot_with"].get<double>(), lp["pilot_without"].get<double>());
  EXPECT_GT(lp["pilot_rays"].get<uint64_t>(), 4u * 16384);  // four images' camera rays, and more
  EXPECT_GT(lp["pilot_seconds"].get<double>(), 0);
  EXPECT_GE(s["render_seconds"].get<double>(), lp["pilot_seconds"].get<double>());
  EXPECT_EQ(s["rays"]["camera"], 256 * 256 * 16);  // the image's rays alone
  // Without connections there is no depth of theirs to choose.
  EXPECT_EQ(lp["depth_setting"], "all");
  EXPECT_EQ(lp["depth"], "all");
  EXPECT_EQ(lp["depth_piloted"], false);
  // Its lone point light is sampled without a pick: one light sample, no pilot for them.
  const json& samples = s["first_hit_light_samples"];
  EXPECT_EQ(samples["setting"], "auto");
  EXPECT_EQ(samples["count"], 1);
  EXPECT_EQ(samples["piloted"], false);
}

// The scene's own light path depth is reported as it set it, with no pilot for it.
TEST_F(CliStatsTest, ASetLightPathDepthIsReported) {
  for (const std::string depth : {"3", "\"all\""}) {
    std::ofstream(dir_ / "deep.json") << R"({
      "camera": {"width": 16, "height": 12, "spp": 4},
      "render": {"light_paths": "on", "light_path_depth": )" +
                                             depth + R"(},
      "spheres": [{"position": [0, -1000, 0], "radius": 999, "color": 0.6}],
      "lights": [{"position": [0, 5, 0], "intensity": 40}]})";
    ASSERT_EQ(run("deep.json -o out.pfm -q --stats stats.json"), 0) << stderrText();
    const json lp = readJson("stats.json")["light_paths"];
    EXPECT_EQ(lp["depth_setting"], depth == "3" ? json(3) : json("all"));
    EXPECT_EQ(lp["depth"], lp["depth_setting"]);
    EXPECT_EQ(lp["depth_piloted"], false);
    EXPECT_EQ(lp["on"], true);
  }
}

// A scene path that is not UTF-8 (Linux allows any bytes) still gives valid JSON: the bad byte
// becomes U+FFFD.
TEST_F(CliStatsTest, ANonUtf8ScenePathStillGivesValidJson) {
  fs::copy_file(dir_ / "scene.json", dir_ / "sc\xffne.json");
  ASSERT_EQ(run("'sc\xffne.json' -o out.pfm -q --stats stats.json"), 0) << stderrText();
  const json stats = readJson("stats.json");
  EXPECT_EQ(stats["scene"], "sc\xef\xbf\xbdne.json");
  EXPECT_EQ(stats["rays"]["camera"], 16 * 12 * 4);
}

TEST_F(CliStatsTest, NoBvhIsHiddenFromHelp) {
  ASSERT_EQ(run("--help"), 0);
  std::ifstream in(dir_ / "stdout.txt");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("--stats"), std::string::npos);
  EXPECT_EQ(text.str().find("--no-bvh"), std::string::npos);
}

TEST_F(CliStatsTest, StatsWithASequenceIsAUsageError) {
  EXPECT_EQ(run("scene.json scene.json -o frames/ -q --stats s.json"), 2);
  EXPECT_NE(stderrText().find("--stats"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "s.json"));
}

TEST_F(CliStatsTest, StatsNeverOverwritesAFileTheRenderReads) {
  std::ofstream(dir_ / "quad.obj") << "mtllib m.mtl\n" << kQuad;
  std::ofstream(dir_ / "m.mtl") << "newmtl grey\nKd 0.5 0.5 0.5\n";
  fs::create_directory(dir_ / "sub");
  fs::create_symlink("scene.json", dir_ / "link.json");
  const std::string scene = read("scene.json");
  const std::pair<const char*, const char*> cases[] = {
      {"scene.json", "the scene file scene.json"},
      {"./scene.json", "the scene file scene.json"},
      {"sub/../scene.json", "the scene file scene.json"},
      {"link.json", "the scene file scene.json"},
      {"quad.obj", "the mesh quad.obj"},
      {"m.mtl", "the material library m.mtl"}};
  for (const auto& [stats, input] : cases) {
    EXPECT_EQ(runEndless(std::string("scene.json -o out.pfm -q --stats ") + stats), 2) << stats;
    EXPECT_EQ(stderrText(), std::string("candela: error: ") + stats + ": --stats would overwrite " +
                                input + ", which the render reads\n");
  }
  EXPECT_EQ(read("scene.json"), scene);
  EXPECT_FALSE(fs::exists(dir_ / "out.pfm"));
}

TEST_F(CliStatsTest, StatsAndImageNeverNameTheSameFile) {
  for (const char* stats : {"out.png", "./out.png"}) {
    EXPECT_EQ(runEndless(std::string("scene.json -o out.png -q --stats ") + stats), 2);
    EXPECT_EQ(stderrText(), std::string("candela: error: ") + stats +
                                ": -o and --stats name the same file; give each its own\n");
  }
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

TEST_F(CliStatsTest, OutputsThatCannotBeWrittenAreFoundBeforeRendering) {
  std::ofstream(dir_ / "plain") << "a file where a folder should be";
  fs::create_directory(dir_ / "sub");
  const std::pair<const char*, const char*> cases[] = {
      {"plain/s.json", "'plain' is not a folder"},
      {"sub", "is a folder, not a file"},
      {"/dev/null", "is a device, pipe or socket, not a regular file"}};
  for (const auto& [stats, reason] : cases) {
    EXPECT_EQ(runEndless(std::string("scene.json -o out.pfm -q --stats ") + stats), 1);
    EXPECT_EQ(stderrText(),
              std::string("candela: error: ") + stats + ": cannot write there: " + reason + "\n");
  }
  EXPECT_EQ(runEndless("scene.json -o plain/out.pfm -q"), 1);
  EXPECT_EQ(stderrText(),
            "candela: error: plain/out.pfm: cannot write there: 'plain' is not a folder\n");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_FALSE(fs::exists(dir_ / "out.pfm"));
}

// The image is written in full first, but renamed into place only once the statistics are too.
TEST_F(CliStatsTest, AFailedStatsWriteLeavesNoImage) {
  // 512-byte files at most: the 16x12 PNG fits, the statistics do not. SIGXFSZ ignored, so the
  // write fails with EFBIG instead of killing the process.
  EXPECT_EQ(run("scene.json -o out.png -q --stats s.json", "trap '' XFSZ; ulimit -f 1;"), 1);
  EXPECT_EQ(stderrText(), "candela: error: s.json: write failed: File too large\n");
  EXPECT_EQ(files(), (std::vector<std::string>{"quad.obj", "scene.json"}));
}

TEST_F(CliStatsTest, StatsThroughALinkReplaceTheFileItPointsTo) {
  std::ofstream(dir_ / "real.json") << "old";
  fs::create_symlink("real.json", dir_ / "link.json");
  ASSERT_EQ(run("scene.json -o out.png -q --stats link.json"), 0) << stderrText();
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.json"));
  EXPECT_EQ(readJson("real.json")["width"], 16);
}

}  // namespace
