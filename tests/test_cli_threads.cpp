// `candela render --threads N` holds the whole run to N threads: the loading (the mesh's
// ordering), the BVH build (Embree's, on oneTBB) and the denoiser too, not only the tiles. Seen
// from outside: the CPU time each of the process's threads has gained, polled from
// /proc/PID/task/*/schedstat (nanoseconds) while it runs, for scenes whose work outside the tiles
// is large: a 500k-triangle mesh seen by 8x8 pixels at 1 spp, and a 256x256 image to denoise.
// Counted are the threads besides the main one that took a share: with one thread, no oneTBB
// worker may work, and the denoiser only on one of Open Image Denoise's.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "spawn_candela.h"

namespace fs = std::filesystem;

namespace {

// A grid of 2 * cells^2 triangles, slightly rippled so that its BVH is not flat.
void writeGridObj(const fs::path& file, int cells) {
  std::string text;
  const int n = cells + 1;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      text += "v " + std::to_string(double(i) / cells - 0.5) + " " +
              std::to_string((i * j % 7) * 1e-3) + " " + std::to_string(double(j) / cells - 0.5) +
              "\n";
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j) {
      const int c = i * n + j + 1;  // OBJ indices from 1
      text += "f " + std::to_string(c) + " " + std::to_string(c + n) + " " + std::to_string(c + 1) +
              "\n";
      text += "f " + std::to_string(c + 1) + " " + std::to_string(c + n) + " " +
              std::to_string(c + n + 1) + "\n";
    }
  std::ofstream(file, std::ios::binary) << text;
}

// CPU nanoseconds of each thread of process `pid` now (threads that ended are not listed).
std::map<std::string, long long> threadCpuNanoseconds(pid_t pid) {
  std::map<std::string, long long> times;
  std::error_code error;
  for (fs::directory_iterator it("/proc/" + std::to_string(pid) + "/task", error), end;
       !error && it != end; it.increment(error)) {
    std::ifstream stat(it->path() / "schedstat");
    long long ns = 0;
    if (stat >> ns) times[it->path().filename().string()] = ns;
  }
  return times;
}

class CliThreads : public ::testing::Test {
 protected:
  void SetUp() override {
    if (std::thread::hardware_concurrency() < 2)
      GTEST_SKIP() << "needs two cores to tell one thread from several";
    if (!fs::exists("/proc/self/task/" + std::to_string(::getpid()) + "/schedstat"))
      GTEST_SKIP() << "needs Linux's /proc/PID/task/*/schedstat to see threads' CPU time";
    dir_ = fs::temp_directory_path() / ("candela_cli_threads_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  void writeGridScene() const {
    writeGridObj(dir_ / "grid.obj", 500);
    std::ofstream(dir_ / "scene.json") << R"({
      "camera": {"width": 8, "height": 8, "fov": 50, "position": [0, 1, 1.5],
                 "look_at": [0, 0, 0], "spp": 1},
      "objects": [{"file": "grid.obj", "color": 0.6}],
      "lights": [{"position": [0, 2, 0], "intensity": 10}]
    })";
  }

  void writeBigImageScene() const {
    std::ofstream(dir_ / "scene.json") << R"({
      "camera": {"width": 256, "height": 256, "fov": 50, "position": [0, 1.5, 6],
                 "look_at": [0, 0.5, 0], "spp": 1},
      "spheres": [{"position": [0, -1000, 0], "radius": 1000, "color": 0.7},
                  {"position": [0, 0.5, 0], "radius": 0.5, "color": [0.8, 0.3, 0.2]}],
      "lights": [{"position": [2, 4, 3], "intensity": 800}]
    })";
  }

  // How many of the process's threads besides the main one took a share of the work (20 ms of
  // CPU or more; what only waited takes a few at most; and, where `share` is above 0, at least
  // that share of the busiest such thread's time) in a render of scene.json with `extraArgs`; -1
  // when the render failed, its message in *error.
  int busyThreads(std::vector<std::string> extraArgs, std::string* error = nullptr,
                  double share = 0.0) const {
    const std::string errors = (dir_ / "stderr.txt").string();
    std::vector<std::string> args = {"render", (dir_ / "scene.json").string(),
                                     "-o",     (dir_ / "out.pfm").string(),
                                     "-q",     "--backend",
                                     "cpu"};
    args.insert(args.end(), extraArgs.begin(), extraArgs.end());
    const pid_t pid = candela::test::spawnCandela(args, "", errors);
    EXPECT_GT(pid, 0);
    if (pid <= 0) return -1;

    std::map<std::string, long long> most;
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (waitpid(pid, &status, WNOHANG) == 0) {
      for (const auto& [thread, ns] : threadCpuNanoseconds(pid))
        most[thread] = std::max(most[thread], ns);
      if (std::chrono::steady_clock::now() > deadline) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        ADD_FAILURE() << "the render did not end within 120 s";
        return -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      std::ifstream in(errors);
      const std::string message((std::istreambuf_iterator<char>(in)), {});
      if (error) *error = message;
      return -1;
    }
    long long busiest = 0;
    for (const auto& [thread, ns] : most)
      if (thread != std::to_string(pid)) busiest = std::max(busiest, ns);
    int busy = 0;
    for (const auto& [thread, ns] : most)
      busy += thread != std::to_string(pid) && ns >= 20'000'000 && ns >= share * double(busiest)
                  ? 1
                  : 0;
    return busy;
  }

  fs::path dir_;
};

TEST_F(CliThreads, OneThreadLoadsAndBuildsOnOne) {
  writeGridScene();
  const int one = busyThreads({"--threads", "1"}), allCores = busyThreads({});
  // The control: given all cores, the load's ordering and the build take a worker, so the scene
  // can tell.
  EXPECT_GT(allCores, 0);
  EXPECT_EQ(one, 0);
}

TEST_F(CliThreads, OneThreadDenoisesOnOne) {
  writeBigImageScene();
  std::string error;
  // A share of the busiest worker's time: TBB's own thread, idle otherwise, at times spins for a
  // few tens of milliseconds while OIDN's one worker filters for a second (seen under load).
  const double share = 0.1;
  const int one = busyThreads({"--threads", "1", "--denoise"}, &error, share);
  if (one < 0 && error.find("needs Intel Open Image Denoise") != std::string::npos)
    GTEST_SKIP() << error;
  ASSERT_GE(one, 0) << error;
  const int allCores = busyThreads({"--denoise"}, nullptr, share);
  EXPECT_GT(allCores, 1);  // the control: OIDN's workers share the filter
  EXPECT_EQ(one, 1);
}

}  // namespace
