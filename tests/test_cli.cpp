// End-to-end tests of the `candela` executable (CANDELA_BINARY): exit codes, messages on
// stderr, the summary on stdout, output files, and Ctrl-C. Each test runs the real binary in its
// own temporary directory.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "backends/renderer.h"
#include "gltf_test_util.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "image_difference.h"
#include "require_gpu.h"
#include "spawn_candela.h"

namespace fs = std::filesystem;

namespace {

struct RunResult {
  int exitCode = -1;  // -1: did not exit normally
  std::string out, err;
};

std::string slurp(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

size_t countLines(const std::string& text) {
  return size_t(std::count(text.begin(), text.end(), '\n'));
}

// A small valid scene: a grey diffuse sphere lit by a point light, 16x12 pixels, 4 spp.
const char* kTinyScene = R"({
  "camera": {"width": 16, "height": 12, "spp": 4, "position": [0, 0, 5]},
  "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}],
  "lights": [{"position": [0, 3, 3], "intensity": 100}]
})";

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("candela_cli_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path path(const std::string& name) const { return dir_ / name; }

  void writeFile(const std::string& name, const std::string& text) const {
    std::ofstream(path(name), std::ios::binary) << text;
  }

  // Runs `candela <args>` with the test directory as working directory; `env` may set
  // environment variables for it ("PATH=/x").
  RunResult run(const std::string& args, const std::string& env = "") const {
    const std::string command = "cd '" + dir_.string() + "' && " + env + " '" + CANDELA_BINARY +
                                "' " + args + " > stdout.txt 2> stderr.txt < /dev/null";
    const int status = std::system(command.c_str());
    RunResult result;
    if (status != -1 && WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    result.out = slurp(path("stdout.txt"));
    result.err = slurp(path("stderr.txt"));
    fs::remove(path("stdout.txt"));
    fs::remove(path("stderr.txt"));
    return result;
  }

  // With so many samples that a render would last hours: an error that comes back within the
  // minute was found before rendering (`timeout` ends the run with 124 otherwise).
  RunResult runEndless(const std::string& args) const {
    return run(args + " --backend cpu --spp 1000000000", "timeout 60");
  }

  void expectSignalsStopTheRender(const std::string& backend) const;

  fs::path dir_;
};

// Width and height from a PNG's IHDR chunk (big-endian at bytes 16 and 20).
bool pngSize(const fs::path& file, uint32_t* width, uint32_t* height) {
  const std::string bytes = slurp(file);
  if (bytes.size() < 24 || bytes.compare(1, 3, "PNG") != 0 || bytes.compare(12, 4, "IHDR") != 0)
    return false;
  auto be32 = [&](size_t at) {
    uint32_t v = 0;
    for (size_t i = 0; i < 4; ++i) v = (v << 8) | uint8_t(bytes[at + i]);
    return v;
  };
  *width = be32(16);
  *height = be32(20);
  return true;
}

TEST_F(CliTest, BadSceneExitsTwoWithTheLoaderMessageAndWritesNothing) {
  writeFile("bad.json", R"({
    "camera": {"width": 16, "height": 16},
    "spheres": [{"position": [0, 0, 0], "radius": -1}]
  })");
  const RunResult r = run("render bad.json");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err.rfind("candela: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("spheres[0].radius"), std::string::npos) << r.err;
  EXPECT_EQ(countLines(r.err), 1u) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(fs::exists(path("out"))) << "nothing may be written for a bad scene";
}

// A glTF file is a scene of its own: `candela render model.glb` renders it framed and lit
// (scene/read/gltf_scene.h), at 960 x 540.
TEST_F(CliTest, AGltfFileRendersAsItsOwnScene) {
  candela::test::GltfFile f;
  const int p = f.addFloats({-1, 0, 0, 1, 0, 0, 0, 1.5f, 0}, "VEC3", 3);
  f.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", p}}}}}}}};
  f.doc["nodes"] = {{{"mesh", 0}}};
  writeFile("tri.glb", f.glb());
  const RunResult r = run("render tri.glb -o tri.png --spp 1 --backend cpu");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  uint32_t width = 0, height = 0;
  ASSERT_TRUE(pngSize(path("tri.png"), &width, &height));
  EXPECT_EQ(width, 960u);
  EXPECT_EQ(height, 540u);
  writeFile("bad.glb", "glTF but not really");
  const RunResult bad = run("render bad.glb -o bad.png --spp 1 --backend cpu");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_EQ(bad.err.rfind("candela: error: bad.glb: ", 0), 0u) << bad.err;
  EXPECT_FALSE(fs::exists(path("bad.png")));
}

TEST_F(CliTest, MaterialWarningsGoToStderrAndTheRenderGoesOn) {
  writeFile("m.obj", "mtllib gone.mtl\nv -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n");
  writeFile("m.json", R"({"camera": {"width": 8, "height": 8, "spp": 1, "position": [0, 0, 5]},
                         "objects": [{"file": "m.obj"}]})");
  for (const char* quiet : {"", " --quiet"}) {
    const RunResult r = run(std::string("render m.json -o m.pfm") + quiet);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err,
              "candela: warning: m.json: objects[0].file: m.obj:1: cannot read the material "
              "library \"gone.mtl\" (No such file or directory); the materials it would define "
              "are diffuse 0.8\n");
    EXPECT_EQ(candela::readImage(path("m.pfm").string()).width, 8u);
  }
}

TEST_F(CliTest, MissingSceneFileIsAUsageError) {
  const RunResult r = run("render nowhere.json");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_FALSE(fs::exists(path("out")));
}

TEST_F(CliTest, UnknownOutputExtensionExitsTwo) {
  writeFile("tiny.json", kTinyScene);
  const RunResult r = run("render tiny.json -o image.bmp");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("image.bmp: unsupported image format '.bmp'"), std::string::npos) << r.err;
  EXPECT_EQ(countLines(r.err), 1u) << r.err;
  EXPECT_FALSE(fs::exists(path("image.bmp")));
}

TEST_F(CliTest, BadOptionValuesExitTwo) {
  writeFile("tiny.json", kTinyScene);
  for (const char* args :
       {"render tiny.json --spp 0", "render tiny.json --spp abc", "render tiny.json --spp -4",
        "render tiny.json --max-depth 0", "render tiny.json --seed -1",
        "render tiny.json --threads 0", "render tiny.json --backend metal",
        "render tiny.json --frobnicate", "render", "launch tiny.json",
        // Regressions: a seed past 2^64 - 1 was clamped, and a NaN frame rate accepted.
        "render tiny.json --seed 18446744073709551616", "render tiny.json --spp 4294967296",
        "render tiny.json -o f/ --fps nan", "render tiny.json -o f/ --fps inf"}) {
    const RunResult r = run(args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("candela: error: ", 0), 0u) << args << "\n" << r.err;
  }
  EXPECT_FALSE(fs::exists(path("out")));
}

TEST_F(CliTest, NoSubcommandPrintsHelpAndExitsTwo) {
  const RunResult r = run("");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("render"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("info"), std::string::npos) << r.err;
}

TEST_F(CliTest, VersionAndHelp) {
  RunResult r = run("--version");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.out.rfind("candela ", 0), 0u) << r.out;
  r = run("render --help");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("--backend"), std::string::npos) << r.out;
}

#if !defined(CANDELA_HAS_CUDA)
TEST_F(CliTest, CudaBackendIsRefusedWithoutCuda) {
  writeFile("tiny.json", kTinyScene);
  const RunResult r = run("render tiny.json --backend cuda -o x.png");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(r.err.rfind("candela: error: the CUDA backend cannot run: this build has no CUDA "
                        "backend",
                        0),
            0u)
      << r.err;
  EXPECT_FALSE(fs::exists(path("x.png")));
}
#else
TEST_F(CliTest, CudaBackendWithoutGpuFailsClearly) {
  std::string reason;
  if (candela::cudaUsable(&reason)) GTEST_SKIP() << "a GPU is present";
  writeFile("tiny.json", kTinyScene);
  const RunResult r = run("render tiny.json --backend cuda -o x.png");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(r.err.rfind("candela: error: the CUDA backend cannot run: ", 0), 0u) << r.err;
  EXPECT_FALSE(fs::exists(path("x.png")));
}

#endif

// `candela devices`: a line per backend, then the one `auto` picks.
TEST_F(CliTest, DevicesSaysWhatEachBackendRendersOn) {
  const RunResult r = run("devices --threads 1");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  ASSERT_EQ(countLines(r.out), 3u) << r.out;
  EXPECT_EQ(r.out.rfind("cpu:  ", 0), 0u) << r.out;
  EXPECT_NE(r.out.find(", 1 thread, "), std::string::npos) << r.out;
  std::string reason;
  const std::string cuda =
      candela::cudaUsable(&reason) ? "\ncuda: " : "\ncuda: not usable: " + reason + "\n";
  EXPECT_NE(r.out.find(cuda), std::string::npos) << r.out;
  const std::string picked = candela::cudaUsable(&reason) ? "cuda" : "cpu";
  EXPECT_NE(r.out.find("\nauto: renders on the " + picked + "\n"), std::string::npos) << r.out;
  EXPECT_EQ(run("devices --threads 0").exitCode, 2);
}

// `auto` renders on the GPU where one is usable, else on the CPU, and says nothing of it.
TEST_F(CliTest, AutoRendersOnTheGpuWhereOneIsUsable) {
  writeFile("tiny.json", kTinyScene);
  const RunResult r = run("render tiny.json -o x.png --stats x.json");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  std::ifstream stats(path("x.json"));
  const std::string text((std::istreambuf_iterator<char>(stats)), std::istreambuf_iterator<char>());
  std::string reason;
  const std::string picked = candela::cudaUsable(&reason) ? "cuda" : "cpu";
  EXPECT_NE(text.find(R"("backend": ")" + picked + "\""), std::string::npos) << text;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST_F(CliTest, UnwritableOutputExitsOne) {
  writeFile("tiny.json", kTinyScene);
  writeFile("plain", "a file where the output's folder should be");
  const RunResult r = run("render tiny.json --backend cpu -o plain/x.png");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(r.err.rfind("candela: error: plain/x.png: ", 0), 0u) << r.err;
  EXPECT_EQ(countLines(r.err), 1u) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST_F(CliTest, InfoPrintsTheSceneCounts) {
  // One quad (two triangles, emissive: two lights), one sphere, a point, a spot, a directional and
  // a rectangle light (two triangles more, one light to the user) and the environment (each light
  // type once: a count by type once wrote past its array for the last).
  writeFile("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
  writeFile("mesh.json", R"({
    "camera": {"width": 32, "height": 24, "spp": 8, "position": [0, 0, 5]},
    "spheres": [{"position": [0, 0, -2], "radius": 1}],
    "objects": [{"file": "quad.obj", "material": {"type": "emissive", "radiance": 1}}],
    "lights": [{"position": [0, 3, 3], "intensity": 100},
               {"type": "spot", "position": [0, 3, 3], "direction": [0, -1, 0], "intensity": 9},
               {"type": "directional", "direction": [1, -1, 0], "intensity": 2},
               {"type": "rectangle", "position": [0, 3, 0], "direction": [0, -1, 0], "size": 1,
                "intensity": 5}],
    "environment": {"color": 0.1}
  })");
  const RunResult r = run("info mesh.json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("triangles:  4\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("spheres:    1\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("objects:    1\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(
                "lights:     7 (1 point, 1 spot, 1 directional, 1 rectangle, 0 emissive spheres, 2 "
                "emissive faces, the environment)\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("image:      32x24, 8 spp\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bvh:"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("animation:"), std::string::npos) << r.out;
  // A crop is part of the image, which info names as the whole.
  std::string cropped = candela::readFileBytes(path("mesh.json").string());
  cropped.replace(cropped.find(R"("height": 24)"), 12, R"("height": 24, "crop": [2, 3, 10, 5])");
  writeFile("cropped.json", cropped);
  const RunResult c = run("info cropped.json");
  ASSERT_EQ(c.exitCode, 0) << c.err;
  EXPECT_NE(c.out.find("image:      32x24, 8 spp, crop [2, 3, 10, 5]\n"), std::string::npos)
      << c.out;
}

TEST_F(CliTest, TinyRenderWritesTheImageAndASummary) {
  writeFile("tiny.json", kTinyScene);
  const RunResult r =
      run("render tiny.json --backend cpu -o img/tiny.pfm --spp 2 --seed 7 --max-depth 3");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const candela::ImageRGB image = candela::readImage(path("img/tiny.pfm").string());
  EXPECT_EQ(image.width, 16u);
  EXPECT_EQ(image.height, 12u);
  // One line: path, size, the overridden spp, timing and ray counts.
  EXPECT_EQ(countLines(r.out), 1u) << r.out;
  EXPECT_EQ(r.out.rfind("img/tiny.pfm: 16x12, 2 spp, ", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("Mrays/s (camera "), std::string::npos) << r.out;
  EXPECT_TRUE(r.err.empty()) << "no progress bar when stderr is not a terminal: " << r.err;
}

TEST_F(CliTest, DefaultOutputIsAPngUnderOut) {
  writeFile("tiny.json", kTinyScene);
  const RunResult r = run("render tiny.json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  uint32_t w = 0, h = 0;
  ASSERT_TRUE(pngSize(path("out/tiny.png"), &w, &h));
  EXPECT_EQ(w, 16u);
  EXPECT_EQ(h, 12u);
}

TEST_F(CliTest, QuietPrintsNothing) {
  writeFile("tiny.json", kTinyScene);
  const RunResult r = run("render tiny.json --quiet -o q.exr");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_EQ(candela::readImage(path("q.exr").string()).width, 16u);
}

// SIGINT (Ctrl-C) and SIGTERM (a scheduler, `kill`) both stop a render on `backend` cleanly, and
// soon even when one tile alone would take hours (very many samples per pixel).
void CliTest::expectSignalsStopTheRender(const std::string& backend) const {
  for (const int signal : {SIGINT, SIGTERM})
    for (const char* camera : {R"("width": 512, "height": 512, "spp": 65536)",
                               R"("width": 16, "height": 16, "spp": 1000000000)"}) {
      SCOPED_TRACE(signal == SIGINT ? "SIGINT" : "SIGTERM");
      SCOPED_TRACE(camera);
      // Long enough that the render is still running after a second, on a GPU too (1.7e10 and
      // 2.6e11 samples).
      writeFile("long.json", R"({
      "camera": {)" + std::string(camera) +
                                 R"(, "position": [0, 0, 5]},
      "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}],
      "lights": [{"position": [0, 3, 3], "intensity": 100}]
    })");
      const pid_t pid =
          candela::test::spawnCandela({"render", path("long.json").string(), "-o",
                                       path("long.png").string(), "--backend", backend},
                                      path("stdout.txt").string(), path("stderr.txt").string());
      ASSERT_GT(pid, 0);

      std::this_thread::sleep_for(std::chrono::seconds(1));
      kill(pid, signal);
      int status = 0;
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
      while (waitpid(pid, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > deadline) {
          kill(pid, SIGKILL);
          waitpid(pid, &status, 0);
          FAIL() << "the render did not stop within 10 s of the signal";
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
      ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal instead of exiting cleanly";
      EXPECT_EQ(WEXITSTATUS(status), 130);
      EXPECT_EQ(slurp(path("stderr.txt")), "candela: interrupted, no image written\n");
      EXPECT_FALSE(fs::exists(path("long.png")));
    }
}

TEST_F(CliTest, InterruptStopsWithoutWritingAnImage) { expectSignalsStopTheRender("cpu"); }

// The CLI's own path on the GPU (`--backend cuda`), which the CUDA backend's tests do not reach:
// its summary and statistics, the signals, a sequence's frames. They need a GPU (scripts/
// gpu-check runs them on one) and skip where there is none.

// An image and a CPU render of it agree up to rounding (test_cuda_backend.cpp says why).
void expectSameUpToRounding(const fs::path& cpu, const fs::path& gpu) {
  EXPECT_LT(candela::test::relMseAgainst(candela::readImage(cpu.string()).pixels,
                                         candela::readImage(gpu.string()).pixels),
            1e-4)
      << gpu;
}

TEST_F(CliTest, RendersOnTheGpuAsOnTheCpu) {
  REQUIRE_GPU();
  writeFile("tiny.json", kTinyScene);
  const RunResult gpu = run("render tiny.json --backend cuda -o gpu.pfm --stats gpu.json");
  ASSERT_EQ(gpu.exitCode, 0) << gpu.err;
  EXPECT_TRUE(gpu.err.empty()) << gpu.err;
  EXPECT_EQ(countLines(gpu.out), 1u) << gpu.out;
  EXPECT_EQ(gpu.out.rfind("gpu.pfm: 16x12, 4 spp, ", 0), 0u) << gpu.out;
  EXPECT_NE(slurp(path("gpu.json")).find(R"("backend": "cuda")"), std::string::npos);
  ASSERT_EQ(run("render tiny.json --backend cpu -o cpu.pfm").exitCode, 0);
  expectSameUpToRounding(path("cpu.pfm"), path("gpu.pfm"));
}

TEST_F(CliTest, InterruptStopsTheRenderOnTheGpu) {
  REQUIRE_GPU();
  expectSignalsStopTheRender("cuda");
}

// ---------------------------------------------------------------------------------------------
// Sequences and animations.

// kTinyScene with ids and an animation block of `frames` frames and the given tracks.
std::string animatedScene(int frames, const std::string& tracks) {
  return R"({
  "camera": {"width": 16, "height": 12, "spp": 4, "position": [0, 0, 5]},
  "spheres": [{"id": "ball", "position": [0, 0, 0], "radius": 1, "color": 0.5}],
  "lights": [{"id": "lamp", "position": [0, 3, 3], "intensity": 100}],
  "animation": {"frames": )" +
         std::to_string(frames) + R"(, "tracks": [)" + tracks + "]}}";
}

TEST_F(CliTest, InfoPrintsTheAnimationAndItsShutter) {
  const std::string track =
      R"({"target": "camera", "property": "position", "keys": [[0, [0, 0, 5]], [3, [1, 0, 5]]]})";
  writeFile("anim.json", animatedScene(4, track));
  RunResult r = run("info anim.json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("animation:  4 frames at 24 fps, 1 track\n"), std::string::npos) << r.out;
  std::string blurred = animatedScene(1, track);
  blurred.replace(blurred.find(R"("tracks")"), 0,
                  R"("fps": 30, "shutter": 0.5, "rolling_shutter": {"row_exposure": 0.1}, )");
  writeFile("blurred.json", blurred);
  r = run("info blurred.json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("animation:  1 frame at 30 fps, 1 track; shutter open from -0.25 to +0.25 "
                       "frames, rolling (each row 10% of it); it blurs the camera\n"),
            std::string::npos)
      << r.out;
}

// What an open shutter blurs: the shapes and lights that tracks move, those that emit too.
TEST_F(CliTest, InfoSaysWhatTheShutterBlurs) {
  writeFile("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n");
  writeFile("moving.json", R"({"camera": {"width": 8, "height": 8, "spp": 1},
    "spheres": [{"id": "a", "position": [0, 0, -5], "radius": 1},
                {"id": "b", "position": [2, 0, -5], "radius": 1},
                {"id": "glow", "position": [0, 2, -5], "radius": 1,
                 "material": {"type": "emissive", "radiance": 1}}],
    "objects": [{"id": "q", "file": "quad.obj", "position": [0, -2, -5]}],
    "lights": [{"id": "lamp", "position": [0, 5, 0], "intensity": 10}],
    "animation": {"frames": 2, "shutter": 1, "tracks": [
      {"target": "lamp", "property": "position", "keys": [[0, [0, 5, 0]], [1, [1, 5, 0]]]},
      {"target": "a", "property": "position", "keys": [[0, [0, 0, -5]], [1, [1, 0, -5]]]},
      {"target": "a", "property": "radius", "keys": [[0, 1], [1, 2]]},
      {"target": "b", "property": "radius", "keys": [[0, 1], [1, 2]]},
      {"target": "glow", "property": "position", "keys": [[0, [0, 2, -5]], [1, [1, 2, -5]]]},
      {"target": "q", "property": "rotation", "keys": [[0, [0, 0, 0]], [1, [0, 0, 90]]]}]}})");
  RunResult r = run("info moving.json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("; shutter open from -0.5 to +0.5 frames; it blurs 1 object, 3 "
                       "spheres and 1 light\n"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

// `info` lists a glTF file's animations, and which one the object plays.
TEST_F(CliTest, InfoListsAGltfFilesAnimations) {
  candela::test::GltfFile square = candela::test::stretchingSquare();
  square.doc["animations"][0]["name"] = "stretch";
  square.doc["animations"].push_back(square.doc["animations"][0]);
  square.doc["animations"][1]["name"] = "again";
  writeFile("square.gltf", square.gltf());
  writeFile("played.json", R"({"camera": {"width": 8, "height": 8, "spp": 1},
    "objects": [{"file": "square.gltf", "position": [0, 0, -5], "gltf_animation": "stretch"},
                {"file": "square.gltf", "position": [3, 0, -5]}],
    "animation": {"frames": 2}})");
  RunResult r = run("info played.json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("animations: objects[0]: \"stretch\" (1 s, played), \"again\" (1 s)\n"
                       "animations: objects[1]: \"stretch\" (1 s), \"again\" (1 s)\n"),
            std::string::npos)
      << r.out;
}

// A camera that becomes unusable at the last frame (fov -> 1e-38) is found before any frame is
// written, and `info` reports the same error (regression: frames 0-2 were written, then exit 2).
TEST_F(CliTest, SequenceWithABadLastFrameWritesNothing) {
  writeFile("anim.json", animatedScene(4, R"({"target": "camera", "property": "fov",
                                              "keys": [[0, 60], [3, 1e-38]]})"));
  const RunResult r = run("render anim.json -o f/ --format pfm --backend cpu");
  EXPECT_EQ(r.exitCode, 2);
  const std::string message =
      "candela: error: anim.json: animation: at frame 3 camera.fov expected an invertible matrix "
      "K (the field of view gives none)\n";
  EXPECT_EQ(r.err, message);
  EXPECT_FALSE(fs::exists(path("f/frame_0000.pfm")));
  const RunResult info = run("info anim.json");
  EXPECT_EQ(info.exitCode, 2);
  EXPECT_EQ(info.err, message);
}

// The still that the animation above shows at a frame: the ball at x, the camera's fov.
std::string stillScene(const std::string& x, const std::string& fov) {
  return R"({
  "camera": {"width": 16, "height": 12, "spp": 4, "position": [0, 0, 5], "fov": )" +
         fov + R"(},
  "spheres": [{"position": [)" +
         x + R"(, 0, 0], "radius": 1, "color": 0.5}],
  "lights": [{"position": [0, 3, 3], "intensity": 100}]})";
}

TEST_F(CliTest, SequenceOfFilesAndAnimationBlockGiveBitIdenticalFrames) {
  writeFile("anim.json", animatedScene(3, R"(
      {"target": "ball", "property": "position", "keys": [[0, [0, 0, 0]], [2, [1, 0, 0]]]},
      {"target": "camera", "property": "fov", "keys": [[0, 50], [2, 70]]})"));
  writeFile("s0.json", stillScene("0", "50"));
  writeFile("s1.json", stillScene("0.5", "60"));
  writeFile("s2.json", stillScene("1", "70"));
  const RunResult a = run("render anim.json -o a/ --format pfm --backend cpu");
  ASSERT_EQ(a.exitCode, 0) << a.err;
  const RunResult b = run("render s0.json s1.json s2.json -o b/ --format pfm --backend cpu");
  ASSERT_EQ(b.exitCode, 0) << b.err;
  EXPECT_EQ(countLines(a.out), 4u) << "a line per frame and a total: " << a.out;
  for (const char* name : {"frame_0000.pfm", "frame_0001.pfm", "frame_0002.pfm"}) {
    ASSERT_TRUE(fs::exists(path("a") / name)) << name;
    EXPECT_EQ(slurp(path("a") / name), slurp(path("b") / name)) << name;
  }
  EXPECT_NE(slurp(path("a/frame_0000.pfm")), slurp(path("a/frame_0001.pfm")));
  EXPECT_FALSE(fs::exists(path("a/frame_0003.pfm")));
}

// --frame N renders frame N of an animation as one image, the same as the sequence's frame file
// (its seed render.seed + N, --seed the animation's), with its flow towards frame N + 1 and its
// stats; what it cannot do is a usage error.
TEST_F(CliTest, FrameOfAnAnimationRendersAsTheSequencesFrame) {
  writeFile("anim.json", animatedScene(3, R"(
      {"target": "ball", "property": "position", "keys": [[0, [0, 0, 0]], [2, [1, 0, 0]]]})"));
  const RunResult seq = run("render anim.json -o s/ --format pfm --seed 9 --aov flow -q");
  ASSERT_EQ(seq.exitCode, 0) << seq.err;
  const RunResult one =
      run("render anim.json --frame 1 -o one.pfm --seed 9 --aov flow --stats one.json -q");
  ASSERT_EQ(one.exitCode, 0) << one.err;
  EXPECT_EQ(slurp(path("one.pfm")), slurp(path("s/frame_0001.pfm")));
  EXPECT_EQ(slurp(path("one.flow.pfm")), slurp(path("s/frame_0001.flow.pfm")));
  EXPECT_NE(slurp(path("one.pfm")), slurp(path("s/frame_0000.pfm")));
  EXPECT_TRUE(fs::exists(path("one.json")));

  writeFile("still.json", kTinyScene);
  const std::pair<const char*, const char*> refused[] = {
      {"render anim.json --frame 3 -o x.png",
       "candela: error: --frame 3: anim.json has 3 frames (0 to 2)\n"},
      {"render still.json --frame 0 -o x.png",
       "candela: error: --frame 0: still.json has no animation block\n"},
      {"render anim.json --frame 1 -o x/",
       "candela: error: -o x/: --frame renders one image, to a file (.png, .exr or .pfm)\n"},
      {"render anim.json --frame 1 --frames 0:2 -o x.png",
       "candela: error: --frame renders one image; --frames is for sequences\n"},
      {"render anim.json anim.json --frame 1 -o x.png",
       "candela: error: --frame renders one frame of one scene's animation; several scene "
       "files are a sequence (--frames picks some of its frames)\n"}};
  for (const auto& [command, message] : refused) {
    const RunResult r = run(command);
    EXPECT_EQ(r.exitCode, 2) << command;
    EXPECT_EQ(r.err, message) << command;
  }
  EXPECT_FALSE(fs::exists(path("x.png")));
  EXPECT_FALSE(fs::exists(path("x")));
}

// The device keeps a sequence's scene between frames and moves only what changed
// (render/scene_change.h): an object, a light and the camera here, each frame as on the CPU.
TEST_F(CliTest, SequenceOnTheGpuRendersEachFrameAsTheCpu) {
  REQUIRE_GPU();
  writeFile("anim.json", animatedScene(3, R"(
      {"target": "ball", "property": "position", "keys": [[0, [0, 0, 0]], [2, [1, 0, 0]]]},
      {"target": "lamp", "property": "intensity", "keys": [[0, 100], [2, 300]]},
      {"target": "camera", "property": "fov", "keys": [[0, 50], [2, 70]]})"));
  const RunResult gpu = run("render anim.json -o g/ --format pfm --backend cuda");
  ASSERT_EQ(gpu.exitCode, 0) << gpu.err;
  ASSERT_EQ(run("render anim.json -o c/ --format pfm --backend cpu").exitCode, 0);
  for (const char* name : {"frame_0000.pfm", "frame_0001.pfm", "frame_0002.pfm"})
    expectSameUpToRounding(path("c") / name, path("g") / name);
  EXPECT_NE(slurp(path("g/frame_0000.pfm")), slurp(path("g/frame_0001.pfm")));
}

TEST_F(CliTest, EachFrameHasItsOwnSeedSoNoiseDiffersButTheMeanAgrees) {
  writeFile("static.json", R"({
    "camera": {"width": 48, "height": 36, "spp": 2, "position": [0, 0, 4]},
    "spheres": [{"position": [0, 0, 0], "radius": 1.5, "color": 0.5}],
    "lights": [{"type": "sphere", "position": [0, 3, 3], "radius": 1, "intensity": 400}],
    "environment": {"color": 0.2},
    "animation": {"frames": 2}})");
  const RunResult r = run("render static.json -o f/ --format pfm --backend cpu");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const candela::ImageRGB a = candela::readImage(path("f/frame_0000.pfm").string());
  const candela::ImageRGB b = candela::readImage(path("f/frame_0001.pfm").string());
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  // Per-pixel differences of independent estimates: their mean must be zero within its standard
  // error (5 sigma), while the images themselves differ.
  double sum = 0, sumSquares = 0;
  size_t differing = 0;
  for (size_t i = 0; i + 2 < a.pixels.size(); i += 3) {
    const double d = (double(a.pixels[i]) + a.pixels[i + 1] + a.pixels[i + 2] - b.pixels[i] -
                      b.pixels[i + 1] - b.pixels[i + 2]) /
                     3.0;
    sum += d;
    sumSquares += d * d;
    differing += d != 0;
  }
  const double n = double(a.pixels.size() / 3);
  const double mean = sum / n;
  const double standardError = std::sqrt((sumSquares / n - mean * mean) / n);
  EXPECT_GT(double(differing), n / 4) << "the noise must not be frozen between frames";
  EXPECT_LT(std::fabs(mean), 5 * standardError);
}

TEST_F(CliTest, ExistingFramesAreKeptUnlessOverwrite) {
  writeFile("anim.json", animatedScene(3, ""));
  ASSERT_EQ(run("render anim.json -o f/ --backend cpu").exitCode, 0);
  const std::string first = slurp(path("f/frame_0000.png"));
  writeFile("f/frame_0001.png", first);  // a whole PNG: stands for a frame that must be kept
  fs::remove(path("f/frame_0002.png"));  // stands for a frame an interruption lost

  const RunResult resumed = run("render anim.json -o f/ --backend cpu");
  ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("f/: 2 of 3 frames exist and are kept"), std::string::npos)
      << resumed.out;
  EXPECT_NE(resumed.out.find("f/frame_0002.png: 16x12"), std::string::npos) << resumed.out;
  EXPECT_EQ(resumed.out.find("frame_0001.png: "), std::string::npos) << resumed.out;
  EXPECT_EQ(slurp(path("f/frame_0001.png")), first);
  EXPECT_EQ(slurp(path("f/frame_0000.png")), first);
  uint32_t w = 0, h = 0;
  EXPECT_TRUE(pngSize(path("f/frame_0002.png"), &w, &h));

  const RunResult again = run("render anim.json -o f/ --overwrite --backend cpu");
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_TRUE(pngSize(path("f/frame_0001.png"), &w, &h));
  EXPECT_EQ(slurp(path("f/frame_0000.png")), first) << "the same frame renders the same image";
}

// Resuming counts a frame as done only when its file is whole (regression: any path counted,
// a 0-byte file or a directory included), and clears the temporary files of a killed run.
TEST_F(CliTest, ResumeRendersIncompleteFramesAgainAndClearsStaleTemporaries) {
  writeFile("anim.json", animatedScene(4, ""));
  ASSERT_EQ(run("render anim.json -o f/ --backend cpu").exitCode, 0);
  ASSERT_EQ(run("render anim.json -o p/ --format pfm --backend cpu").exitCode, 0);
  const std::string png = slurp(path("f/frame_0001.png")), pfm = slurp(path("p/frame_0001.pfm"));
  writeFile("f/frame_0001.png", "");                             // empty
  writeFile("f/frame_0002.png", png.substr(0, png.size() / 2));  // cut short
  writeFile("p/frame_0001.pfm", pfm.substr(0, pfm.size() - 4));  // one float short
  writeFile("f/.frame_0003.png.tmp-999999999-0", "half");        // a dead process's
  const RunResult r = run("render anim.json -o f/ --backend cpu");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("f/: 2 of 4 frames exist and are kept"), std::string::npos) << r.out;
  EXPECT_EQ(slurp(path("f/frame_0001.png")), png);
  uint32_t w = 0, h = 0;
  EXPECT_TRUE(pngSize(path("f/frame_0002.png"), &w, &h));
  EXPECT_FALSE(fs::exists(path("f/.frame_0003.png.tmp-999999999-0")));
  const RunResult p = run("render anim.json -o p/ --format pfm --backend cpu");
  ASSERT_EQ(p.exitCode, 0) << p.err;
  EXPECT_NE(p.out.find("p/: 3 of 4 frames exist and are kept"), std::string::npos) << p.out;
  EXPECT_EQ(slurp(path("p/frame_0001.pfm")), pfm);
}

TEST_F(CliTest, FramesRangeEndIsExclusive) {
  writeFile("anim.json", animatedScene(5, ""));
  const RunResult r = run("render anim.json -o f/ --frames 1:3 --format exr --backend cpu");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_FALSE(fs::exists(path("f/frame_0000.exr")));
  EXPECT_TRUE(fs::exists(path("f/frame_0001.exr")));
  EXPECT_TRUE(fs::exists(path("f/frame_0002.exr")));
  EXPECT_FALSE(fs::exists(path("f/frame_0003.exr")));

  const RunResult outside = run("render anim.json -o g/ --frames 3:9");
  EXPECT_EQ(outside.exitCode, 2);
  EXPECT_EQ(outside.err, "candela: error: --frames 3:9: there are 5 frames, numbered 0 to 4\n");
  const RunResult empty = run("render anim.json -o g/ --frames 3:3");
  EXPECT_EQ(empty.exitCode, 2);
  EXPECT_NE(empty.err.find("the range is empty"), std::string::npos) << empty.err;
  const RunResult file = run("render anim.json -o g.png");
  EXPECT_EQ(file.exitCode, 2);
  EXPECT_EQ(file.err,
            "candela: error: -o g.png: a sequence is written to a folder (e.g. -o frames/), not "
            "to one image\n");
  EXPECT_FALSE(fs::exists(path("g")));
}

// A sequence option makes a still scene a sequence of one frame; with -o naming an image the
// error says which option did it, not only that sequences go to folders.
TEST_F(CliTest, SequenceOptionOnAStillImageIsNamed) {
  writeFile("still.json", kTinyScene);
  const RunResult r = run("render still.json -o s.pfm --overwrite");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err,
            "candela: error: --overwrite is an option of sequences (an animated scene or several "
            "scene files), and still.json is one still image (-o s.pfm): leave it out\n");
  const RunResult format = run("render still.json -o s.pfm --format exr");
  EXPECT_EQ(format.exitCode, 2);
  EXPECT_NE(format.err.find("--format is an option of sequences"), std::string::npos) << format.err;
  EXPECT_FALSE(fs::exists(path("s.pfm")));
  EXPECT_EQ(run("render still.json -o s.pfm").exitCode, 0);
}

TEST_F(CliTest, BadSceneInASequenceIsReportedBeforeAnythingRenders) {
  writeFile("a.json", kTinyScene);
  writeFile("b.json", R"({"camera": {}, "spheres": [{"position": [0, 0, 0], "radius": -1}]})");
  writeFile("c.json", kTinyScene);
  const RunResult r = run("render a.json b.json c.json -o f/");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err,
            "candela: error: b.json: spheres[0].radius: expected a positive number, got -1\n");
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(fs::exists(path("f"))) << "nothing may be written";

  writeFile("anim.json", animatedScene(2, ""));
  const RunResult mixed = run("render a.json anim.json -o f/");
  EXPECT_EQ(mixed.exitCode, 2);
  EXPECT_EQ(mixed.err,
            "candela: error: anim.json: animation: a scene with an animation block is rendered "
            "on its own, not in a sequence of scene files\n");
  EXPECT_FALSE(fs::exists(path("f")));
}

// Frames and the video are checked against the files the scenes read before anything renders.
TEST_F(CliTest, SequenceNeverOverwritesItsInputsWithFramesOrTheVideo) {
  writeFile("a.json", kTinyScene);
  writeFile("frame_0001.png", kTinyScene);  // a scene file that is named like a frame
  RunResult r = runEndless("render a.json frame_0001.png -o ./");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err,
            "candela: error: frame_0001.png: frame 1 of the sequence would overwrite the scene "
            "file, which the render reads\n");
  EXPECT_FALSE(fs::exists(path("frame_0000.png")));

  r = runEndless("render a.json a.json -o f/ --video a.json");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err,
            "candela: error: a.json: --video would overwrite the scene file a.json, which the "
            "render reads\n");
  r = runEndless("render a.json a.json -o f/ --video f/frame_0001.png");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err,
            "candela: error: f/frame_0001.png: --video would overwrite frame 1 of the sequence\n");
  r = runEndless("render a.json a.json -o f/ --video f");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "candela: error: f: --video names the folder of the frames\n");
  EXPECT_FALSE(fs::exists(path("f")));
  EXPECT_EQ(slurp(path("a.json")), kTinyScene);
}

TEST_F(CliTest, UnwritableFrameFolderIsFoundBeforeRendering) {
  writeFile("a.json", kTinyScene);
  writeFile("plain", "a file where the frame folder should be");
  RunResult r = runEndless("render a.json a.json -o plain/");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(r.err,
            "candela: error: plain/: cannot write the frames there: 'plain' is not a folder\n");
  r = runEndless("render a.json a.json -o plain/f/");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(r.err,
            "candela: error: plain/f/: cannot write the frames there: 'plain' is not a folder\n");
}

TEST_F(CliTest, VideoWithoutFfmpegKeepsTheFramesAndSaysHowToInstallIt) {
  writeFile("anim.json", animatedScene(2, ""));
  const RunResult r = run("render anim.json -o f/ --video v.mp4 --backend cpu", "PATH=/nowhere");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("ffmpeg was not found on PATH"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("apt-get install ffmpeg"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(path("f/frame_0000.png")));
  EXPECT_TRUE(fs::exists(path("f/frame_0001.png")));
  EXPECT_FALSE(fs::exists(path("v.mp4")));
}

// Names that ffmpeg would read as an option ('-'), a protocol (':') or a frame pattern ('%') reach
// it as file names. A stand-in ffmpeg on PATH records its arguments.
TEST_F(CliTest, VideoNamesReachFfmpegAsFileNames) {
  fs::create_directories(path("bin"));
  writeFile("bin/ffmpeg",
            "#!/bin/sh\nfor a in \"$@\"; do printf '%s\\n' \"$a\"; done > args.txt\n");
  fs::permissions(path("bin/ffmpeg"), fs::perms::owner_all);
  writeFile("anim.json", animatedScene(2, ""));
  const RunResult r = run("render anim.json -o '-a%04d:b/' --video=-v:1.mp4 --backend cpu -q",
                          "PATH='" + path("bin").string() + "':/usr/bin:/bin");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::vector<std::string> args;
  std::istringstream lines(slurp(path("args.txt")));
  for (std::string line; std::getline(lines, line);) args.push_back(line);
  ASSERT_FALSE(args.empty());
  const auto input = std::find(args.begin(), args.end(), "-i");
  ASSERT_NE(input, args.end());
  ASSERT_NE(input + 1, args.end());
  EXPECT_EQ(input[1], "file:-a%%04d:b/frame_%04d.png");
  EXPECT_NE(std::find(args.begin(), args.end(), "sequence"), args.end());  // -pattern_type
  EXPECT_EQ(args.back(), "file:-v:1.mp4");
  EXPECT_TRUE(fs::exists(path("-a%04d:b/frame_0001.png")));
}

TEST_F(CliTest, VideoHasOneFramePerRenderedFrame) {
  if (system("command -v ffmpeg > /dev/null 2>&1 && command -v ffprobe > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "ffmpeg and ffprobe are not installed (they are optional)";
  // Odd sizes: the encoder needs even ones, which the scale filter provides.
  writeFile("anim.json", R"({
    "camera": {"width": 17, "height": 13, "spp": 2, "position": [0, 0, 5]},
    "spheres": [{"id": "ball", "position": [0, 0, 0], "radius": 1, "color": 0.5}],
    "lights": [{"position": [0, 3, 3], "intensity": 100}],
    "animation": {"frames": 5, "fps": 10, "tracks": [
      {"target": "ball", "property": "position", "keys": [[0, [-1, 0, 0]], [4, [1, 0, 0]]]}]}})");
  const RunResult r = run("render anim.json -o f/ --video v.mp4 --backend cpu");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const RunResult probe = [&] {
    const std::string command = "cd '" + dir_.string() +
                                "' && ffprobe -v error -count_frames -select_streams v:0 "
                                "-show_entries stream=nb_read_frames,width,height "
                                "-of csv=p=0 v.mp4 > probe.txt";
    RunResult result;
    result.exitCode = WEXITSTATUS(std::system(command.c_str()));
    result.out = slurp(path("probe.txt"));
    return result;
  }();
  ASSERT_EQ(probe.exitCode, 0);
  EXPECT_EQ(probe.out, "16,12,5\n");
}

}  // namespace
