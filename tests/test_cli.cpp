// End-to-end tests of the `candela` executable (CANDELA_BINARY): exit codes, messages on
// stderr, the summary on stdout, output files, and Ctrl-C. Each test runs the real binary in its
// own temporary directory.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "image/image_io.h"

#if defined(CANDELA_HAS_CUDA)
#include "backends/cuda/cuda_renderer.h"
#endif

extern char** environ;  // for posix_spawn

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

  // Runs `candela <args>` with the test directory as working directory.
  RunResult run(const std::string& args) const {
    const std::string command = "cd '" + dir_.string() + "' && '" + CANDELA_BINARY + "' " + args +
                                " > stdout.txt 2> stderr.txt < /dev/null";
    const int status = std::system(command.c_str());
    RunResult result;
    if (status != -1 && WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    result.out = slurp(path("stdout.txt"));
    result.err = slurp(path("stderr.txt"));
    fs::remove(path("stdout.txt"));
    fs::remove(path("stderr.txt"));
    return result;
  }

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
        "render tiny.json --frobnicate", "render", "launch tiny.json"}) {
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
  EXPECT_EQ(r.err.rfind("candela: error: the CUDA backend is not available in this build", 0), 0u)
      << r.err;
  EXPECT_FALSE(fs::exists(path("x.png")));
}
#else
TEST_F(CliTest, CudaBackendWithoutGpuFailsClearly) {
  std::string reason;
  if (candela::cudaBackendAvailable(&reason)) GTEST_SKIP() << "a GPU is present";
  writeFile("tiny.json", kTinyScene);
  const RunResult r = run("render tiny.json --backend cuda -o x.png");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(r.err.rfind("candela: error: --backend cuda: ", 0), 0u) << r.err;
  EXPECT_FALSE(fs::exists(path("x.png")));
}

TEST_F(CliTest, AutoFallsBackToCpuWithANoteWithoutGpu) {
  std::string reason;
  if (candela::cudaBackendAvailable(&reason)) GTEST_SKIP() << "a GPU is present";
  writeFile("tiny.json", kTinyScene);
  const RunResult r = run("render tiny.json -o x.png");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.err.rfind("candela: note: no usable GPU", 0), 0u) << r.err;
  EXPECT_TRUE(fs::exists(path("x.png")));
}
#endif

TEST_F(CliTest, UnwritableOutputExitsOne) {
  writeFile("tiny.json", kTinyScene);
  writeFile("plain", "a file where the output's folder should be");
  // --backend cpu: `auto` may add a one-line note that no GPU was found.
  const RunResult r = run("render tiny.json --backend cpu -o plain/x.png");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(r.err.rfind("candela: error: plain/x.png: ", 0), 0u) << r.err;
  EXPECT_EQ(countLines(r.err), 1u) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST_F(CliTest, InfoPrintsTheSceneCounts) {
  // One quad (two triangles) and one sphere.
  writeFile("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
  writeFile("mesh.json", R"({
    "camera": {"width": 32, "height": 24, "spp": 8, "position": [0, 0, 5]},
    "spheres": [{"position": [0, 0, -2], "radius": 1}],
    "objects": [{"file": "quad.obj"}],
    "lights": [{"position": [0, 3, 3], "intensity": 100}]
  })");
  const RunResult r = run("info mesh.json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("triangles:  2\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("spheres:    1\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("objects:    1\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lights:     1\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("image:      32x24, 8 spp\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bvh:"), std::string::npos) << r.out;
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

TEST_F(CliTest, InterruptStopsWithoutWritingAnImage) {
  // Long enough (about 10^9 samples) that the render is still running after a second.
  writeFile("long.json", R"({
    "camera": {"width": 512, "height": 512, "spp": 4096, "position": [0, 0, 5]},
    "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}],
    "lights": [{"position": [0, 3, 3], "intensity": 100}]
  })");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, path("stdout.txt").c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, path("stderr.txt").c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const std::string binary = CANDELA_BINARY, scene = path("long.json").string(),
                    output = path("long.png").string();
  char* argv[] = {const_cast<char*>(binary.c_str()), const_cast<char*>("render"),
                  const_cast<char*>(scene.c_str()),  const_cast<char*>("-o"),
                  const_cast<char*>(output.c_str()), const_cast<char*>("--backend"),
                  const_cast<char*>("cpu"),          nullptr};
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv, environ), 0);
  posix_spawn_file_actions_destroy(&actions);

  std::this_thread::sleep_for(std::chrono::seconds(1));
  kill(pid, SIGINT);
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      FAIL() << "the render did not stop within 30 s of SIGINT";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal instead of exiting cleanly";
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_EQ(slurp(path("stderr.txt")), "candela: interrupted, no image written\n");
  EXPECT_FALSE(fs::exists(path("long.png")));
}

}  // namespace
