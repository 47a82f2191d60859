// backends/backend_report.h: what `candela devices` and candela.devices() print.
#include "backends/backend_report.h"

#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "backends/cpu/cpu_engine.h"
#include "backends/renderer.h"
#include "require_gpu.h"

namespace candela {
namespace {

TEST(BackendReport, TheCpuWithItsThreadsAndEnginesThenTheGpu) {
  const std::vector<BackendReport> reports = reportBackends(1);
  ASSERT_EQ(reports.size(), 2u);
  EXPECT_STREQ(reports[0].backend, "cpu");
  EXPECT_TRUE(reports[0].usable);
  EXPECT_NE(reports[0].summary.find(", 1 thread, "), std::string::npos) << reports[0].summary;
  EXPECT_NE(reports[0].summary.find("candela's own BVH"), std::string::npos);
  EXPECT_EQ(reports[0].summary.find("Embree ") != std::string::npos, embreeAvailable())
      << reports[0].summary;
  EXPECT_STREQ(reports[1].backend, "cuda");
  std::string reason;
  EXPECT_EQ(reports[1].usable, cudaUsable(&reason));
  if (!reports[1].usable) {
    EXPECT_EQ(reports[1].summary, "not usable: " + reason);
  }
  const Backend picked = chooseBackend(Backend::Auto);
  EXPECT_EQ(reports[0].autoPicks, picked == Backend::Cpu);
  EXPECT_EQ(reports[1].autoPicks, picked == Backend::Cuda);
}

TEST(BackendReport, AllCoresByDefault) {
  const unsigned cores = std::thread::hardware_concurrency();
  if (cores < 2) GTEST_SKIP() << "one core: nothing to tell apart from --threads 1";
  const std::string summary = reportBackends(0)[0].summary;
  EXPECT_NE(summary.find(", " + std::to_string(cores) + " threads, "), std::string::npos)
      << summary;
}

TEST(BackendReport, TheGpuByNameOnTheGpu) {
  REQUIRE_GPU();
  const BackendReport gpu = reportBackends(0)[1];
  EXPECT_TRUE(gpu.usable);
  EXPECT_NE(gpu.summary.find("compute capability "), std::string::npos) << gpu.summary;
  EXPECT_NE(gpu.summary.find(" GiB, "), std::string::npos) << gpu.summary;
}

}  // namespace
}  // namespace candela
